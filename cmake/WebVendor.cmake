# The page loads uPlot from web/vendor/ (no CDN): copy the npm package's browser files there on every
# build, so a fresh clone gets them from `scripts/setup.sh` (npm ci) + the build, in test.sh and run.sh alike.
set(SOFTTUNE_UPLOT_DIST ${CMAKE_SOURCE_DIR}/node_modules/uplot/dist)
set(SOFTTUNE_WEB_VENDOR ${CMAKE_SOURCE_DIR}/web/vendor)
if(EXISTS ${SOFTTUNE_UPLOT_DIST}/uPlot.iife.min.js)
  add_custom_command(
    OUTPUT ${SOFTTUNE_WEB_VENDOR}/uPlot.iife.min.js ${SOFTTUNE_WEB_VENDOR}/uPlot.min.css
    COMMAND ${CMAKE_COMMAND} -E make_directory ${SOFTTUNE_WEB_VENDOR}
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${SOFTTUNE_UPLOT_DIST}/uPlot.iife.min.js
            ${SOFTTUNE_UPLOT_DIST}/uPlot.min.css ${SOFTTUNE_WEB_VENDOR}/
    DEPENDS ${SOFTTUNE_UPLOT_DIST}/uPlot.iife.min.js ${SOFTTUNE_UPLOT_DIST}/uPlot.min.css
    COMMENT "Copying uPlot into web/vendor/")
  add_custom_target(web_vendor ALL DEPENDS ${SOFTTUNE_WEB_VENDOR}/uPlot.iife.min.js ${SOFTTUNE_WEB_VENDOR}/uPlot.min.css)
else()
  message(WARNING "node_modules/uplot is missing: run scripts/setup.sh (npm ci) so the page gets its plots")
endif()
