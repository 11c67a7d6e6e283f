# camopt as a CMake package: the library camopt::camopt, the executable, the headers and
# the exported targets, so that an installed camopt is used with
#   find_package(camopt 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE camopt::camopt)
# The library is shared: every object of the engine's rooms is in it, so the self-registering study kinds
# are always there (a static archive would drop them unless linked whole).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

add_library(camopt_lib SHARED)
add_library(camopt::camopt ALIAS camopt_lib)
set_target_properties(camopt_lib PROPERTIES OUTPUT_NAME camopt EXPORT_NAME camopt
                      VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
# The objects and private dependencies come from the rooms; what a user of the headers needs is
# public: the include root (headers are included as "model/…", "studies/…") and the libraries the
# headers include (Eigen, Ceres' Jet, nlohmann::json).
target_link_libraries(camopt_lib PRIVATE ${CAMOPT_ENGINE})
target_include_directories(camopt_lib PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/camopt>)
target_link_libraries(camopt_lib PUBLIC Eigen3::Eigen Ceres::ceres nlohmann_json::nlohmann_json)
target_compile_features(camopt_lib PUBLIC cxx_std_20)
set_target_properties(camopt_lib PROPERTIES INSTALL_RPATH "$ORIGIN")
set_target_properties(camopt PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

install(TARGETS camopt RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The OpenCASCADE module beside the library (cad/solid.cc looks for it there, and in the library
# folder seen from bin/).
install(TARGETS camopt_occt LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS camopt_lib EXPORT camoptTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Every header of the rooms, each at its path under include/camopt (cad/ too: studies/ headers
# include it). Listed file by file, not by directory, so that no empty folder is installed.
# Each installed header compiles on its own against the install tree (scripts/test_consumer.sh).
foreach(room model objectives optimizers sizing studies cad)
  file(GLOB_RECURSE room_headers RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${room}/*.h)
  foreach(header ${room_headers})
    get_filename_component(header_dir ${header} DIRECTORY)
    install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/camopt/${header_dir})
  endforeach()
endforeach()
# Every kind is declared once (studies/archive.h): its schema exists only as `camopt schema KIND`,
# written here from the built binary into share/camopt/schema/ (created first).
install(DIRECTORY DESTINATION ${CMAKE_INSTALL_DATADIR}/camopt/schema)
install(CODE "
  execute_process(COMMAND $<TARGET_FILE:camopt> kinds --names OUTPUT_VARIABLE camopt_kinds COMMAND_ERROR_IS_FATAL ANY)
  string(REPLACE \"\\n\" \";\" camopt_kinds \"\${camopt_kinds}\")
  foreach(k \${camopt_kinds})
    if(k)
      execute_process(COMMAND $<TARGET_FILE:camopt> schema \${k}
        OUTPUT_FILE \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/camopt/schema/\${k}.schema.json\"
        COMMAND_ERROR_IS_FATAL ANY)
    endif()
  endforeach()")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/studies/examples DESTINATION ${CMAKE_INSTALL_DATADIR}/camopt
        FILES_MATCHING PATTERN "*.json")

set(CAMOPT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/camopt)
install(EXPORT camoptTargets NAMESPACE camopt:: DESTINATION ${CAMOPT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/camoptConfig.cmake.in
  ${PROJECT_BINARY_DIR}/camoptConfig.cmake INSTALL_DESTINATION ${CAMOPT_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/camoptConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/camoptConfig.cmake ${PROJECT_BINARY_DIR}/camoptConfigVersion.cmake
        DESTINATION ${CAMOPT_CMAKE_DIR})

if(CAMOPT_BUILD_TESTS AND NOT CAMOPT_SANITIZE AND NOT CAMOPT_FUZZ)
  # (not in the sanitizer build: an unsanitized consumer cannot load the sanitized library)
  # Installs this build into build/consumer-install, then configures and builds
  # examples/consumer against it and runs it (scripts/test_consumer.sh).
  add_test(NAME ConsumerProject.BuildsAndRunsAgainstTheInstallTree
           COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/test_consumer.sh ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(ConsumerProject.BuildsAndRunsAgainstTheInstallTree PROPERTIES TIMEOUT 600)
  # Every installed header on its own against the install tree, in shards of under a minute each
  # (one test of all 145 took 190 s; the LCR study headers alone 78 s cold beside other tests); the install test checks
  # that no empty folder is installed, that every source header is, and that each falls in exactly
  # one shard.
  set(shards
      "model_common_contact_motion=^model/(common|contact|motion)/"
      "model_cycloid=^model/cycloid/"
      "model_disc_cam_globoidal_rigidity=^model/(disc_cam|globoidal|rigidity)/"
      "model_lcr=^model/lcr/"
      "objectives_optimizers_sizing_cad=^(objectives|optimizers|sizing|cad)/"
      "studies_a_to_co=^studies/([ab]|c[a-o])"
      "studies_cycloid_a_to_l=^studies/cycloid_[a-l]"
      "studies_cycloid_m_to_z=^studies/cycloid_[m-z]"
      "studies_d_to_k=^studies/[d-k]"
      "studies_lcr_a_to_h=^studies/lcr_[a-h]"
      "studies_lcr_i_to_z_lubrication=^studies/l(cr_[i-z]|u)"
      "studies_m_to_r=^studies/[m-r]"
      "studies_s_to_z=^studies/[s-z]")
  set(regexes)
  foreach(shard ${shards})
    string(REGEX REPLACE "^[^=]*=" "" regex "${shard}")
    list(APPEND regexes "${regex}")
  endforeach()
  add_test(NAME InstalledHeaders.InstallTreeIsComplete
           COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/test_installed_headers.sh ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR} install ${regexes})
  set_tests_properties(InstalledHeaders.InstallTreeIsComplete PROPERTIES TIMEOUT 300
                       FIXTURES_SETUP camopt_installed_headers)
  foreach(shard ${shards})
    string(REGEX REPLACE "=.*$" "" name "${shard}")
    string(REGEX REPLACE "^[^=]*=" "" regex "${shard}")
    add_test(NAME InstalledHeaders.EachCompilesOnItsOwn/${name}
             COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/test_installed_headers.sh ${PROJECT_BINARY_DIR}
                     ${PROJECT_SOURCE_DIR} compile ${name} "${regex}")
    set_tests_properties(InstalledHeaders.EachCompilesOnItsOwn/${name} PROPERTIES TIMEOUT 300
                         FIXTURES_REQUIRED camopt_installed_headers)
  endforeach()
endif()
