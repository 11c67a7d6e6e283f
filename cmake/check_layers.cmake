# cmake -DSOURCE_DIR=… -P check_layers.cmake: fails (exit 1, one line per include) when a source
# file includes a header of a room above its own. The rooms, lowest first (README.md "Layout"):
#   model/       physics only: includes model/ only
#   cad/         geometry files: cad/, model/
#   objectives/  problems, their checks and verification: objectives/, model/
#   optimizers/  solvers over objectives/problem.h: optimizers/, objectives/, model/
#   sizing/      the sizing drivers, which pose problems and call solvers: sizing/, optimizers/,
#                objectives/, model/
#   studies/     everything below
# Run by the build before camopt_core compiles (cmake/camopt_layers.cmake), so a wrong include
# fails the build; the test Layers.* plants one and checks that it does.
set(allowed_model "model")
set(allowed_cad "cad;model")
set(allowed_objectives "objectives;model")
set(allowed_optimizers "optimizers;objectives;model")
set(allowed_sizing "sizing;optimizers;objectives;model")
set(violations "")
foreach(room model cad objectives optimizers sizing)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${room}/*.h ${SOURCE_DIR}/${room}/*.cc)
  list(SORT files)
  foreach(f ${files})
    file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"[a-z_]+/")
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" header "${line}")
      string(REGEX REPLACE "/.*$" "" target_room "${header}")
      if(NOT target_room MATCHES "^(model|cad|objectives|optimizers|sizing|studies)$")
        continue()  # a library's header
      endif()
      list(FIND allowed_${room} ${target_room} found)
      if(found EQUAL -1)
        string(APPEND violations "${rel} includes ${header}: ${room}/ may include only ${allowed_${room}}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "layering (cmake/check_layers.cmake):\n${violations}")
endif()
