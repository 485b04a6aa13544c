# The page loads uPlot from web/vendor/ (no CDN). Every build copies the npm package's two browser files
# there (git-ignored), so a fresh clone gets them from `scripts/setup.sh` (npm ci) + the build, in test.sh
# and run.sh alike, and a build made before `npm ci` picks them up on the next build without reconfiguring.
# Included from the root CMakeLists.txt it defines the target; run with -P it does the copy.
if(CMAKE_SCRIPT_MODE_FILE)
  set(dist ${SOURCE_DIR}/node_modules/uplot/dist)
  if(NOT EXISTS ${dist}/uPlot.iife.min.js OR NOT EXISTS ${dist}/uPlot.min.css)
    message(WARNING "node_modules/uplot is missing: run scripts/setup.sh (npm ci) so the page gets its plots")
    return()
  endif()
  file(MAKE_DIRECTORY ${SOURCE_DIR}/web/vendor)
  file(COPY_FILE ${dist}/uPlot.iife.min.js ${SOURCE_DIR}/web/vendor/uPlot.iife.min.js ONLY_IF_DIFFERENT)
  file(COPY_FILE ${dist}/uPlot.min.css ${SOURCE_DIR}/web/vendor/uPlot.min.css ONLY_IF_DIFFERENT)
else()
  add_custom_target(web_vendor ALL
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -P ${CMAKE_CURRENT_LIST_FILE}
    COMMENT "Copying uPlot from node_modules into web/vendor/")
endif()
