# A Debian package of the installed tree (CPack's DEB generator):
#   cmake --build build --target api_docs && (cd build && cpack)   →   build/camopt_<version>_<arch>.deb
# It holds what `cmake --install` installs — the program, the shared library and its CMake
# package, the headers, the schemas and examples, the Python module (lib/python3/dist-packages)
# and the docs with the API reference — under /usr. Its Depends come from dpkg-shlibdeps (the
# Debian libraries the program and the module link) plus python3 and python3-numpy for the module.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME camopt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "camopt")
set(CPACK_PACKAGE_CONTACT "camopt developers <camopt@example.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "design optimisation of cam reducers and cam mechanisms")
set(CPACK_PACKAGE_DESCRIPTION "camopt analyses and sizes lobe cam reducers, cycloid drives, disc cams and globoidal cams from JSON study files, with exact gradients and verified answers.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libcamopt.so is in the package itself: dpkg-shlibdeps looks for it in the staging tree.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_INSTALL_LIBDIR})
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy")
include(CPack)
