# What the camopt binary carries besides its code: the templates of `camopt init` and the version.
# (The study schemas are emitted from the kinds' declarations, studies/archive.h: nothing to embed.)

# The examples `camopt init KIND` starts from, compiled in so that an installed binary writes them:
# every study of studies/examples/ (each kind names its own, KindDescriptor::init_example).
file(GLOB _templates CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/studies/examples/*.json)
set(CAMOPT_INIT_TEMPLATES "")
foreach(_file ${_templates})
  file(READ ${_file} _text LIMIT 4096)
  if(_text MATCHES "\"study\"")  # data files (a roller catalogue) are not studies
    get_filename_component(_name ${_file} NAME_WE)
    list(APPEND CAMOPT_INIT_TEMPLATES ${_name})
  endif()
endforeach()
set(CAMOPT_TEMPLATES_CC ${PROJECT_BINARY_DIR}/generated/init_templates.cc)
add_custom_command(
  OUTPUT ${CAMOPT_TEMPLATES_CC}
  COMMAND ${CMAKE_COMMAND} -DEXAMPLES_DIR=${PROJECT_SOURCE_DIR}/studies/examples "-DNAMES=${CAMOPT_INIT_TEMPLATES}"
          -DOUT=${CAMOPT_TEMPLATES_CC} -P ${PROJECT_SOURCE_DIR}/cmake/embed_templates.cmake
  DEPENDS ${_templates} ${PROJECT_SOURCE_DIR}/cmake/embed_templates.cmake
  COMMENT "Embedding the templates of camopt init"
  VERBATIM)
target_sources(camopt_studies PRIVATE ${CAMOPT_TEMPLATES_CC})

# The version recorded in every result.json and printed by `camopt --version`.
set_source_files_properties(${PROJECT_SOURCE_DIR}/studies/provenance.cc PROPERTIES
  COMPILE_DEFINITIONS CAMOPT_VERSION_STRING="${PROJECT_VERSION}")
