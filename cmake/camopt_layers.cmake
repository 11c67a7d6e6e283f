# The rooms' include directories as each room's library compiles with them (its include root,
# camopt_room_root in CMakeLists.txt, and what the libraries it links bring), one per line in
# build/rooms/ROOM.includes: tests/layers_test.cc compiles planted includes with them, so that it
# checks the build's own flags, not a copy of the rules.
foreach(room model cad objectives optimizers sizing)
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/rooms/${room}.includes
       CONTENT "$<JOIN:$<TARGET_PROPERTY:camopt_${room},INCLUDE_DIRECTORIES>,\n>\n")
endforeach()
