# The codec, scene codec and app libraries share one precompiled nlohmann-json: nearly every one of
# their sources includes it, and parsing it was a large part of each one's compile. Same compiler and flags
# as the libraries (the build type's), so REUSE_FROM holds; no header in it depends on a target's own
# definitions.
add_library(softtune_server_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/pch_anchor.cpp)
target_link_libraries(softtune_server_pch PRIVATE nlohmann_json::nlohmann_json)
target_precompile_headers(softtune_server_pch PRIVATE <nlohmann/json.hpp> <functional> <optional> <string> <vector>)

function(softtune_server_compile)
  foreach(t IN LISTS ARGN)
    target_precompile_headers(${t} REUSE_FROM softtune_server_pch)
  endforeach()
endfunction()
