# The JSON Schemas of the study kinds (studies/schema/<kind>.schema.json) are compiled into camopt
# (`camopt schema KIND`, camopt.schema(kind) in Python), so an installed binary carries them.
# The generated file is rebuilt whenever a schema changes.
file(GLOB CAMOPT_SCHEMA_FILES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/studies/schema/*.schema.json)
set(CAMOPT_SCHEMA_CC ${PROJECT_BINARY_DIR}/generated/study_schemas.cc)
add_custom_command(
  OUTPUT ${CAMOPT_SCHEMA_CC}
  COMMAND ${CMAKE_COMMAND} -DSCHEMA_DIR=${PROJECT_SOURCE_DIR}/studies/schema -DOUT=${CAMOPT_SCHEMA_CC}
          -P ${PROJECT_SOURCE_DIR}/cmake/embed_schemas.cmake
  DEPENDS ${CAMOPT_SCHEMA_FILES} ${PROJECT_SOURCE_DIR}/cmake/embed_schemas.cmake
  COMMENT "Embedding the study schemas")
target_sources(camopt_core PRIVATE ${CAMOPT_SCHEMA_CC})

# The version recorded in every result.json and printed by `camopt --version`.
set_source_files_properties(${PROJECT_SOURCE_DIR}/studies/provenance.cc PROPERTIES
  COMPILE_DEFINITIONS CAMOPT_VERSION_STRING="${PROJECT_VERSION}")
