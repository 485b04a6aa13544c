# `cmake --install build` and the Debian package (`cd build && cpack`; scripts/test-package.sh installs it
# into a scratch root and serves from there). What is installed, under CMAKE_INSTALL_PREFIX (/usr in the
# package):
#   bin/softtune, bin/softtune-raster        the binary and its raster helper (found beside the binary)
#   share/softtune/web/, share/softtune/presets/   the page (with uPlot from web/vendor/) and the scenes
#   share/softtune/engines/, share/softtune/node_modules/   the node worker and its Jolt and Rapier modules
#   share/doc/softtune/                      README.md and docs/
#   lib/systemd/system/softtune.service      `softtune serve` on 127.0.0.1:8080 (packaging/softtune.service.in)
include(GNUInstallDirs)
# `cpack` and `make install` install what the build made; they do not build everything again first
# (scripts/test.sh's build stage did).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(SOFTTUNE_INSTALL_WEBDIR ${CMAKE_INSTALL_DATADIR}/softtune/web)
set(SOFTTUNE_INSTALL_PRESETSDIR ${CMAKE_INSTALL_DATADIR}/softtune/presets)

install(TARGETS softtune softtune-raster RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/web/ DESTINATION ${SOFTTUNE_INSTALL_WEBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/presets/ DESTINATION ${SOFTTUNE_INSTALL_PRESETSDIR})
# The node worker and the JavaScript scene engines it loads (engines/node_worker/node_worker.cpp finds the
# worker in share/softtune/engines/; node resolves the engines' packages from share/softtune/node_modules/).
foreach(room node_worker rapier jolt)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/engines/${room}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/softtune/engines/${room}
          FILES_MATCHING PATTERN "*.mjs")
endforeach()
foreach(package jolt-physics @dimforge/rapier2d-compat)
  if(EXISTS ${PROJECT_SOURCE_DIR}/node_modules/${package})
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/node_modules/${package}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/softtune/node_modules/${package})
  endif()
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/package.json DESTINATION ${CMAKE_INSTALL_DATADIR}/softtune)  # "type": "module"
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
# The unit names the installed paths, so it is written at install time, when the prefix is known (/usr in
# the package, whatever `cmake --install --prefix` says otherwise).
install(CODE "
  set(SOFTTUNE_BINDIR \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}\")
  set(SOFTTUNE_WEBDIR \"\${CMAKE_INSTALL_PREFIX}/${SOFTTUNE_INSTALL_WEBDIR}\")
  set(SOFTTUNE_PRESETSDIR \"\${CMAKE_INSTALL_PREFIX}/${SOFTTUNE_INSTALL_PRESETSDIR}\")
  configure_file(\"${PROJECT_SOURCE_DIR}/packaging/softtune.service.in\" \"${CMAKE_BINARY_DIR}/softtune.service\" @ONLY)
")
install(FILES ${CMAKE_BINARY_DIR}/softtune.service DESTINATION lib/systemd/system)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME softtune)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "softtune maintainers <softtune@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "designer words to soft-constraint numbers for game physics engines")
set(CPACK_PACKAGE_DESCRIPTION "softtune turns a designer's words (respond in 12 frames, some oscillation) into the spring and soft-constraint numbers of Box2D, Jolt, Rapier, MuJoCo, ODE, Bullet and PhysX, proves them by simulation and renders preview frames off screen: an HTTP service with a web page (softtune serve, also a systemd unit) and a command line.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the two programs link (libosmesa6, libpng16, libbox2d, libode, ...) come from
# dpkg-shlibdeps; the preview text's font is read at run time through fontconfig.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_STRIP_FILES ON)
include(CPack)
