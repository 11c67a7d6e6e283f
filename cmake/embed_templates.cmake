# cmake -DEXAMPLES_DIR=… -DNAMES="a;b" -DOUT=… -P embed_templates.cmake: writes a C++ file that
# defines camopt::studies::EmbeddedTemplates(), the map example name → text of the examples that
# `camopt init KIND` starts from (CAMOPT_INIT_TEMPLATES in cmake/camopt_schemas.cmake).
set(body "")
foreach(name ${NAMES})
  file(READ ${EXAMPLES_DIR}/${name}.json text)
  string(APPEND body "      {\"${name}\", R\"camopt_template(${text})camopt_template\"},\n")
endforeach()
file(WRITE ${OUT}.new "// Generated from studies/examples/ by cmake/embed_templates.cmake.
#include \"studies/init.h\"

namespace camopt::studies {

const std::map<std::string, std::string>& EmbeddedTemplates() {
  static const std::map<std::string, std::string> templates = {
${body}  };
  return templates;
}

}  // namespace camopt::studies
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
file(REMOVE ${OUT}.new)
