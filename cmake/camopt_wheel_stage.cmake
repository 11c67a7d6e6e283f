# Stages the files of the wheel (cmake -P, run by the `wheel` target in cmake/camopt_python.cmake):
#   -DMODULE=<built camopt.cpython-*.so> -DSTUB=<camopt.pyi> -DLIBRARY=<libcamopt.so.N, the SONAME
#   file> -DOCCT=<libcamopt_occt.so, the OpenCASCADE module the library opens from its folder>
#   -DSTAGE=<empty folder>
# Copies (no rebuild) and sets the copies' RUNPATHs with CMake's own ELF editor (as `cmake
# --install` does; no patchelf): the module finds the library in camopt.libs/ beside it wherever
# pip puts them, and the library needs only system libraries (the build-tree RUNPATHs name the build
# folder and must not leak into an installed file).
foreach(v MODULE STUB LIBRARY OCCT STAGE)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "camopt_wheel_stage.cmake: -D${v}=... is needed")
  endif()
endforeach()
file(REMOVE_RECURSE ${STAGE})
file(MAKE_DIRECTORY ${STAGE}/camopt.libs)
get_filename_component(module_name ${MODULE} NAME)
get_filename_component(library_name ${LIBRARY} NAME)
file(COPY_FILE ${MODULE} ${STAGE}/${module_name})
file(COPY_FILE ${STUB} ${STAGE}/camopt.pyi)
file(COPY_FILE ${LIBRARY} ${STAGE}/camopt.libs/${library_name})  # follows the SONAME symlink
get_filename_component(occt_name ${OCCT} NAME)
file(COPY_FILE ${OCCT} ${STAGE}/camopt.libs/${occt_name})
file(CHMOD ${STAGE}/${module_name} ${STAGE}/camopt.libs/${library_name} ${STAGE}/camopt.libs/${occt_name}
     PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
# The build gives the module room for this RUNPATH (BUILD_RPATH in cmake/camopt_python.cmake).
file(RPATH_SET FILE ${STAGE}/${module_name} NEW_RPATH "$ORIGIN/camopt.libs")
file(RPATH_REMOVE FILE ${STAGE}/camopt.libs/${library_name})
file(RPATH_REMOVE FILE ${STAGE}/camopt.libs/${occt_name})
