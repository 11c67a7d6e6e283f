# cmake -DSCHEMA_DIR=… -DOUT=… -P embed_schemas.cmake: writes a C++ file that defines
# camopt::studies::EmbeddedSchemas(), the map kind → schema text of every <kind>.schema.json.
file(GLOB files ${SCHEMA_DIR}/*.schema.json)
list(SORT files)
set(body "")
foreach(f ${files})
  get_filename_component(name ${f} NAME)
  string(REPLACE ".schema.json" "" kind ${name})
  file(READ ${f} text)
  string(APPEND body "      {\"${kind}\", R\"camopt_schema(${text})camopt_schema\"},\n")
endforeach()
file(WRITE ${OUT}.new "// Generated from studies/schema/*.schema.json by cmake/embed_schemas.cmake.
#include \"studies/schemas.h\"

namespace camopt::studies {

const std::map<std::string, std::string>& EmbeddedSchemas() {
  static const std::map<std::string, std::string> schemas = {
${body}  };
  return schemas;
}

}  // namespace camopt::studies
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
file(REMOVE ${OUT}.new)
