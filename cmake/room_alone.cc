// The one source of the camopt_ROOM_alone libraries (CMakeLists.txt): their code is the room's
// objects, linked with no undefined symbol to prove the room needs nothing from a room above.
