# The rooms' layering, checked on every build before camopt_core compiles (cmake/check_layers.cmake):
# a file that includes a header of a room above its own (a model/ file an objectives/ or optimizers/
# header, an objectives/ file a sizing/ driver) fails the build.
file(GLOB_RECURSE CAMOPT_LAYERED_FILES CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/model/*.h ${PROJECT_SOURCE_DIR}/model/*.cc ${PROJECT_SOURCE_DIR}/cad/*.h
     ${PROJECT_SOURCE_DIR}/cad/*.cc ${PROJECT_SOURCE_DIR}/objectives/*.h ${PROJECT_SOURCE_DIR}/objectives/*.cc
     ${PROJECT_SOURCE_DIR}/optimizers/*.h ${PROJECT_SOURCE_DIR}/optimizers/*.cc ${PROJECT_SOURCE_DIR}/sizing/*.h
     ${PROJECT_SOURCE_DIR}/sizing/*.cc)
set(CAMOPT_LAYERS_STAMP ${PROJECT_BINARY_DIR}/layers.stamp)
add_custom_command(
  OUTPUT ${CAMOPT_LAYERS_STAMP}
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -P ${PROJECT_SOURCE_DIR}/cmake/check_layers.cmake
  COMMAND ${CMAKE_COMMAND} -E touch ${CAMOPT_LAYERS_STAMP}
  DEPENDS ${CAMOPT_LAYERED_FILES} ${PROJECT_SOURCE_DIR}/cmake/check_layers.cmake
  COMMENT "Checking the layering of model/, cad/, objectives/, optimizers/, sizing/")
add_custom_target(camopt_layers DEPENDS ${CAMOPT_LAYERS_STAMP})
add_dependencies(camopt_core camopt_layers)
add_dependencies(camopt_cad camopt_layers)
