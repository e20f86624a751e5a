# Install rules and the CMake package: find_package(brdflut CONFIG) gives
# brdflut::brdflut (the library), brdflut::brdflut_cli (the tool) and
# brdflut_add_luts().
include(CMakePackageConfigHelpers)

set(BRDFLUT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/brdflut)

set_target_properties(brdflut_cli PROPERTIES EXPORT_NAME brdflut_cli)
install(TARGETS brdflut brdflut_cli EXPORT brdflutTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/brdflut DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT brdflutTargets NAMESPACE brdflut:: DESTINATION ${BRDFLUT_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/brdflutConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/brdflutConfig.cmake
                              INSTALL_DESTINATION ${BRDFLUT_CMAKE_DIR})
# 0.x: a minor version may break the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/brdflutConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/brdflutConfig.cmake
              ${PROJECT_BINARY_DIR}/brdflutConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/BrdflutLuts.cmake
        DESTINATION ${BRDFLUT_CMAKE_DIR})
