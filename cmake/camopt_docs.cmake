# The API reference from the headers' comments (Doxygen, Debian's doxygen):
#   cmake --build build --target api_docs   →   build/api/html/index.html
# Installed under share/doc/camopt/api when it has been built (the .deb builds it first). The
# test ApiReference.BuildsWithoutWarnings builds it with warnings as errors.
option(CAMOPT_BUILD_DOCS "The API reference target api_docs (needs doxygen)" ON)
if(NOT CAMOPT_BUILD_DOCS)
  return()
endif()
find_package(Doxygen REQUIRED)
set(DOXYGEN_PROJECT_NAME camopt)
set(DOXYGEN_PROJECT_NUMBER ${PROJECT_VERSION})
set(DOXYGEN_PROJECT_BRIEF "Design optimisation of cam reducers and cam mechanisms")
set(DOXYGEN_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/api)
set(DOXYGEN_FILE_PATTERNS *.h)
set(DOXYGEN_RECURSIVE YES)
set(DOXYGEN_EXTRACT_ALL YES)
set(DOXYGEN_QUIET YES)
# Parameters are described in the prose of each comment, not one @param each.
set(DOXYGEN_WARN_IF_INCOMPLETE_DOC NO)
set(DOXYGEN_WARN_AS_ERROR FAIL_ON_WARNINGS)
set(DOXYGEN_STRIP_FROM_PATH ${PROJECT_SOURCE_DIR})
set(DOXYGEN_STRIP_FROM_INC_PATH ${PROJECT_SOURCE_DIR})
set(DOXYGEN_FULL_PATH_NAMES YES)
set(DOXYGEN_USE_MDFILE_AS_MAINPAGE ${PROJECT_SOURCE_DIR}/docs/api.md)
set(DOXYGEN_HAVE_DOT NO)
doxygen_add_docs(api_docs
  ${PROJECT_SOURCE_DIR}/docs/api.md ${PROJECT_SOURCE_DIR}/model ${PROJECT_SOURCE_DIR}/objectives
  ${PROJECT_SOURCE_DIR}/optimizers ${PROJECT_SOURCE_DIR}/sizing ${PROJECT_SOURCE_DIR}/studies ${PROJECT_SOURCE_DIR}/cad
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMENT "API reference (Doxygen) in ${PROJECT_BINARY_DIR}/api/html")
install(DIRECTORY ${PROJECT_BINARY_DIR}/api/html DESTINATION ${CMAKE_INSTALL_DOCDIR}/api OPTIONAL)

if(CAMOPT_BUILD_TESTS AND NOT CAMOPT_SANITIZE AND NOT CAMOPT_FUZZ)
  add_test(NAME ApiReference.BuildsWithoutWarnings
           COMMAND bash -c "rm -rf '${PROJECT_BINARY_DIR}/api' && '${CMAKE_COMMAND}' --build '${PROJECT_BINARY_DIR}' --target api_docs \
&& test -f '${PROJECT_BINARY_DIR}/api/html/index.html' \
&& grep -q EllipticalContactMaxOrthogonalShear '${PROJECT_BINARY_DIR}/api/html/subsurface_8h.html' \
&& grep -q 'study file' '${PROJECT_BINARY_DIR}/api/html/index.html'")
  set_tests_properties(ApiReference.BuildsWithoutWarnings PROPERTIES TIMEOUT 600)
endif()

# The user documentation beside the API reference.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "*.svg")
