# What the camopt binary carries besides its code: the templates of `camopt init` and the version.
# (The study schemas are emitted from the kinds' declarations, studies/archive.h: nothing to embed.)

# The example each study kind's `camopt init KIND` starts from (one per kind: a light, typical
# design that needs no other file, with the limits a designer sets where the kind's own defaults
# depend on the design — disc_cam's pressure angle and radius margin, and a contact stress),
# compiled in so that an installed binary writes them.
set(CAMOPT_INIT_TEMPLATES cycloid_crowning_tuning_nnm cycloid_ltca_nnm_lcm cycloid_min_size_quick
    disc_cam_min_size disc_cam_motion disc_cam_dynamics globoidal_cam_paper lcr_crowning_tuning lcr_friction_fit
    lcr_ii lcr_min_size rigidity_gearbox)
set(CAMOPT_TEMPLATES_CC ${PROJECT_BINARY_DIR}/generated/init_templates.cc)
list(TRANSFORM CAMOPT_INIT_TEMPLATES PREPEND ${PROJECT_SOURCE_DIR}/studies/examples/ OUTPUT_VARIABLE _templates)
list(TRANSFORM _templates APPEND .json)
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
