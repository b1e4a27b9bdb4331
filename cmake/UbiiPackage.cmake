# find_package(ubii) config files and pkg-config files (ubii: the shared library; ubii-static:
# libubii.a), installed beside the libraries.
include(CMakePackageConfigHelpers)

set(UBII_CMAKE_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/ubii")
install(EXPORT ubiiTargets NAMESPACE ubii:: DESTINATION "${UBII_CMAKE_INSTALL_DIR}")
configure_package_config_file(cmake/ubiiConfig.cmake.in "${CMAKE_CURRENT_BINARY_DIR}/ubiiConfig.cmake"
                              INSTALL_DESTINATION "${UBII_CMAKE_INSTALL_DIR}")
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/ubiiConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/ubiiConfig.cmake" "${CMAKE_CURRENT_BINARY_DIR}/ubiiConfigVersion.cmake"
        DESTINATION "${UBII_CMAKE_INSTALL_DIR}")

# Relocatable: the prefix is found from where the .pc file lies, so `cmake --install --prefix` works.
file(RELATIVE_PATH UBII_PC_TO_PREFIX "/root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/root")
string(REGEX REPLACE "/$" "" UBII_PC_TO_PREFIX "${UBII_PC_TO_PREFIX}")
list(JOIN UBII_SANITIZE_LINK_FLAGS " " UBII_PC_LINK_FLAGS)
configure_file(cmake/ubii.pc.in "${CMAKE_CURRENT_BINARY_DIR}/ubii.pc" @ONLY)
configure_file(cmake/ubii-static.pc.in "${CMAKE_CURRENT_BINARY_DIR}/ubii-static.pc" @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/ubii.pc" "${CMAKE_CURRENT_BINARY_DIR}/ubii-static.pc"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")

# pkg-config for the C++ layer: the shared layer on the shared libubii, and libprotobuf.
if(UBII_WITH_CPP)
  configure_file(cmake/ubii-cpp.pc.in "${CMAKE_CURRENT_BINARY_DIR}/ubii-cpp.pc" @ONLY)
  install(FILES "${CMAKE_CURRENT_BINARY_DIR}/ubii-cpp.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
endif()
