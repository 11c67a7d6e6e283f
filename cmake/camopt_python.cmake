# The Python module `camopt` (pybind11, python/camopt_module.cc and camopt_models.cc; its stub
# python/camopt.pyi is copied next to it and installed with it), built for Debian's Python
# /usr/bin/python3 (which has python3-numpy, -matplotlib and -jsonschema from Debian) — not for a
# python that may come first on PATH (e.g. pyenv's). Change with -DCAMOPT_PYTHON=/path/to/python3.
# The module lands in build/python/ (PYTHONPATH=build/python); its tests and the example script
# run through ctest with that python. The `wheel` target (part of the default build) packs that same
# module into build/dist/camopt-<version>-<tag>.whl for `pip install` (docs/api.md, "Python wheel").
set(CAMOPT_PYTHON_DEFAULT ON)
if(CAMOPT_SANITIZE OR CAMOPT_FUZZ)
  set(CAMOPT_PYTHON_DEFAULT OFF)  # a sanitized module cannot be loaded into an unsanitized python
endif()
option(CAMOPT_BUILD_PYTHON "Build the Python module (needs pybind11-dev, python3-dev)" ${CAMOPT_PYTHON_DEFAULT})
if(NOT CAMOPT_BUILD_PYTHON)
  return()
endif()
set(CAMOPT_PYTHON /usr/bin/python3 CACHE FILEPATH "The Python the module is built for and tested with")
set(Python_EXECUTABLE ${CAMOPT_PYTHON})
set(PYBIND11_FINDPYTHON ON)
find_package(Python 3.9 REQUIRED COMPONENTS Interpreter Development.Module)
find_package(pybind11 2.6 CONFIG)
if(NOT pybind11_FOUND)
  message(FATAL_ERROR "The Python module needs pybind11 (Debian pybind11-dev; scripts/install_deps.sh);"
                      " or configure with -DCAMOPT_BUILD_PYTHON=OFF")
endif()

# NO_EXTRAS: without pybind11's link-time optimisation (its default), which compiled the module's
# code a second time at the link, serially ("using serial compilation of 9 LTRANS jobs"), for
# bindings whose time is the engine's, not theirs; stripped as pybind11 would.
pybind11_add_module(camopt_python MODULE NO_EXTRAS ${PROJECT_SOURCE_DIR}/python/camopt_module.cc
                    ${PROJECT_SOURCE_DIR}/python/camopt_models.cc)
if(NOT CMAKE_BUILD_TYPE MATCHES "^(Debug|RelWithDebInfo)$")
  pybind11_strip(camopt_python)
endif()
set_target_properties(camopt_python PROPERTIES OUTPUT_NAME camopt
                      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/python)
target_compile_options(camopt_python PRIVATE ${CAMOPT_WARNINGS})
target_link_libraries(camopt_python PRIVATE camopt_lib)
set_target_properties(camopt_python PROPERTIES INSTALL_RPATH "$ORIGIN/../..")
# The wheel's copy of the module finds the library in camopt.libs/ beside it: the wheel target sets
# its RUNPATH to this one entry in place, which needs a build RUNPATH at least as long — this entry
# (which finds nothing in build/python) guarantees that whatever the build folder's path.
set_target_properties(camopt_python PROPERTIES BUILD_RPATH "$ORIGIN/camopt.libs")
install(TARGETS camopt_python LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/python3/dist-packages)
# The type stub beside the module (PEP 561 stub for an extension module: same name, .pyi).
add_custom_command(TARGET camopt_python POST_BUILD
                   COMMAND ${CMAKE_COMMAND} -E copy_if_different ${PROJECT_SOURCE_DIR}/python/camopt.pyi
                           ${PROJECT_BINARY_DIR}/python/camopt.pyi)
install(FILES ${PROJECT_SOURCE_DIR}/python/camopt.pyi DESTINATION ${CMAKE_INSTALL_LIBDIR}/python3/dist-packages)

# The wheel, from the module built above (no second compile): cmake/camopt_wheel_stage.cmake copies
# the module, its stub and libcamopt.so.N (into camopt.libs/) and sets their RUNPATHs;
# python/make_wheel.py adds the metadata and zips them. The tag is the interpreter's (cp311-cp311-
# linux_x86_64 for Debian 12's python3); the version is the project's.
execute_process(COMMAND ${CAMOPT_PYTHON} ${PROJECT_SOURCE_DIR}/python/make_wheel.py --tag
                OUTPUT_VARIABLE CAMOPT_WHEEL_TAG OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
set(CAMOPT_WHEEL ${PROJECT_BINARY_DIR}/dist/camopt-${PROJECT_VERSION}-${CAMOPT_WHEEL_TAG}.whl)
add_custom_command(OUTPUT ${CAMOPT_WHEEL}
  COMMAND ${CMAKE_COMMAND} -DMODULE=$<TARGET_FILE:camopt_python> -DSTUB=${PROJECT_SOURCE_DIR}/python/camopt.pyi
          -DLIBRARY=$<TARGET_SONAME_FILE:camopt_lib> -DOCCT=$<TARGET_FILE:camopt_occt> -DSTAGE=${PROJECT_BINARY_DIR}/wheel-stage
          -P ${PROJECT_SOURCE_DIR}/cmake/camopt_wheel_stage.cmake
  COMMAND ${CAMOPT_PYTHON} ${PROJECT_SOURCE_DIR}/python/make_wheel.py --stage ${PROJECT_BINARY_DIR}/wheel-stage
          --version ${PROJECT_VERSION} --out ${CAMOPT_WHEEL}
  DEPENDS camopt_python camopt_lib camopt_occt ${PROJECT_SOURCE_DIR}/python/camopt.pyi
          ${PROJECT_SOURCE_DIR}/python/make_wheel.py ${PROJECT_SOURCE_DIR}/cmake/camopt_wheel_stage.cmake
  COMMENT "Packing the Python module into ${CAMOPT_WHEEL}" VERBATIM)
add_custom_target(wheel ALL DEPENDS ${CAMOPT_WHEEL})
# For `pip install .` (python/camopt_build_backend.py): which file the wheel target writes.
file(WRITE ${PROJECT_BINARY_DIR}/python/wheel-path.txt "${CAMOPT_WHEEL}\n")

if(CAMOPT_BUILD_TESTS)
  set(CAMOPT_PY_ENV "PYTHONPATH=${PROJECT_BINARY_DIR}/python" "MPLBACKEND=Agg"
      "CAMOPT_SOURCE_DIR=${PROJECT_SOURCE_DIR}" "CAMOPT_BINARY=$<TARGET_FILE:camopt>"
      "CAMOPT_TEST_TMP=${PROJECT_BINARY_DIR}/python-test-tmp")
  foreach(t module schemas example objects interrupt)
    add_test(NAME Python.${t}
             COMMAND ${CAMOPT_PYTHON} -m unittest -v test_${t}
             WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/python/tests)
    set_tests_properties(Python.${t} PROPERTIES ENVIRONMENT "${CAMOPT_PY_ENV}" TIMEOUT 600)
  endforeach()
  # Every example's result.json against its result schema (python/tests/test_result_examples.py):
  # every example run through the command line, 4.5 min of CPU in all, so in six shards of about
  # 35 s each (the one test it was took 210 s and ran last on a fresh clone, one core idle).
  set(camopt_result_example_shards 6)
  math(EXPR last "${camopt_result_example_shards} - 1")
  foreach(shard RANGE ${last})
    add_test(NAME Python.result_examples/shard${shard}
             COMMAND ${CAMOPT_PYTHON} -m unittest -v test_result_examples
             WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/python/tests)
    set_tests_properties(Python.result_examples/shard${shard} PROPERTIES TIMEOUT 300 COST 35 ENVIRONMENT
      "${CAMOPT_PY_ENV};CAMOPT_EXAMPLE_SHARD=${shard}/${camopt_result_example_shards}")
  endforeach()
  # The wheel in a fresh venv, without PYTHONPATH, and `pip install .` (python/tests/test_wheel.py).
  add_test(NAME Python.wheel COMMAND ${CAMOPT_PYTHON} -m unittest -v test_wheel
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/python/tests)
  set_tests_properties(Python.wheel PROPERTIES TIMEOUT 120 ENVIRONMENT
    "CAMOPT_WHEEL=${CAMOPT_WHEEL};CAMOPT_VERSION=${PROJECT_VERSION};CAMOPT_SOURCE_DIR=${PROJECT_SOURCE_DIR};CAMOPT_BINARY=$<TARGET_FILE:camopt>;CAMOPT_TEST_TMP=${PROJECT_BINARY_DIR}/python-test-tmp;CAMOPT_BUILD_DIR=${PROJECT_BINARY_DIR}")
endif()
