# `cmake --install` for C++ users, in two components beside the Python one (python/):
#   cpp  the static library, the public headers and the CMake package, so that another project
#        can write find_package(drange) and target_link_libraries(app PRIVATE drange::drange);
#   cli  the `drange` command.
# The package lies in <prefix>/lib/cmake/drange (CMAKE_INSTALL_LIBDIR), where find_package
# looks when <prefix> is in CMAKE_PREFIX_PATH. tests/consumer checks it from outside the tree.
include(CMakePackageConfigHelpers)
set(DRANGE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/drange)

install(TARGETS drange EXPORT drangeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT cpp
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT cpp)
install(DIRECTORY include/drange DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT cpp
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS drange_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)

install(EXPORT drangeTargets NAMESPACE drange:: DESTINATION ${DRANGE_CMAKE_DIR} COMPONENT cpp)
configure_package_config_file(cmake/drangeConfig.cmake.in ${PROJECT_BINARY_DIR}/drangeConfig.cmake
                              INSTALL_DESTINATION ${DRANGE_CMAKE_DIR})
# Before 1.0 a new minor version may change the API: only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/drangeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/drangeConfig.cmake ${PROJECT_BINARY_DIR}/drangeConfigVersion.cmake
              cmake/drangeGmp.cmake
        DESTINATION ${DRANGE_CMAKE_DIR} COMPONENT cpp)
