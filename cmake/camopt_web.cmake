# The studio's front end (`camopt serve`, docs/studio.md): web/*.html, *.js, *.css and uPlot's
# files from web/node_modules (npm ci in web/, scripts/install_deps.sh) copied into build/web and
# installed as share/camopt/web. Nothing is fetched at run time. Without web/node_modules the
# studio works without its charts (a warning here says so).
file(GLOB CAMOPT_WEB_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/web/*.html ${PROJECT_SOURCE_DIR}/web/*.js
     ${PROJECT_SOURCE_DIR}/web/*.css)
set(CAMOPT_UPLOT_DIR ${PROJECT_SOURCE_DIR}/web/node_modules/uplot/dist)
# ON while scripts/setup.sh installs the npm packages beside the build (it configures again after).
option(CAMOPT_WEB_PENDING "web/node_modules is being installed: no warning for its absence" OFF)
if(EXISTS ${CAMOPT_UPLOT_DIR}/uPlot.iife.min.js)
  list(APPEND CAMOPT_WEB_SOURCES ${CAMOPT_UPLOT_DIR}/uPlot.iife.min.js ${CAMOPT_UPLOT_DIR}/uPlot.min.css)
elseif(CAMOPT_WEB_PENDING)
  message(STATUS "web/node_modules/uplot: being installed (scripts/setup.sh configures again when it is)")
else()
  message(WARNING "web/node_modules/uplot is missing (run `npm ci` in web/): the studio's charts are left out")
endif()
set(CAMOPT_WEB_OUTPUTS "")
foreach(src ${CAMOPT_WEB_SOURCES})
  get_filename_component(name ${src} NAME)
  set(dest ${PROJECT_BINARY_DIR}/web/${name})
  add_custom_command(OUTPUT ${dest} COMMAND ${CMAKE_COMMAND} -E copy_if_different ${src} ${dest}
                     DEPENDS ${src} COMMENT "studio: ${name}" VERBATIM)
  list(APPEND CAMOPT_WEB_OUTPUTS ${dest})
endforeach()
add_custom_target(camopt_web ALL DEPENDS ${CAMOPT_WEB_OUTPUTS})
add_dependencies(camopt camopt_web)
install(FILES ${CAMOPT_WEB_OUTPUTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/camopt/web)

# The studio end to end in headless Chromium (web/test/studio_e2e.mjs, puppeteer-core): load an
# example, a field error (and a cross-field one), runs, the crank slider against the closed form,
# the drawing a frame after each verdict, Play under 200 ms of latency, Compare; its screenshot is
# docs/images/studio.png (written into the build tree here; copy it over when the page changes).
# Skipped (exit 77, with the reason) only without Chromium or web/node_modules.
if(CAMOPT_BUILD_TESTS)
  find_program(CAMOPT_NODE node)
  if(CAMOPT_NODE)
    add_test(NAME Studio.browser_end_to_end
             COMMAND ${CAMOPT_NODE} ${PROJECT_SOURCE_DIR}/web/test/studio_e2e.mjs $<TARGET_FILE:camopt>
                     ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/studio-test/studio.png)
    set_tests_properties(Studio.browser_end_to_end PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
  else()
    message(WARNING "node not found: the studio's browser test (Studio.browser_end_to_end) is left out "
                    "(scripts/install_deps.sh installs nodejs)")
  endif()
endif()
