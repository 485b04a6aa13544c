# Fails when the codec's link line (the probe program's, which links softtune_codec alone) names Box2D,
# libpng, Mesa, or the scene and render libraries that bring them. Run: cmake -DLINK_TXT=... -P this file.
file(READ "${LINK_TXT}" line)
foreach(forbidden box2d png OSMesa GL softtune_scene softtune_render softtune_app)
  string(REGEX MATCH "[^ ]*${forbidden}[^ ]*" hit "${line}")
  if(hit)
    message(FATAL_ERROR "the codec library links ${hit}: it must stay on core (issue 14)")
  endif()
endforeach()
message(STATUS "codec link line holds no Box2D, libpng or Mesa")
