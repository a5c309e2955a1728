# SPDX-License-Identifier: BSL-1.0
# Installation: the headers, a CMake package (find_package(influence2d)
# giving influence2d::influence2d, and influence2d::cgal with the CGAL
# component) with its version file, and a pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(INFLUENCE2D_CMAKE_DIR ${CMAKE_INSTALL_DATADIR}/cmake/influence2d)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/influence2d DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS influence2d EXPORT influence2d_targets)
install(EXPORT influence2d_targets NAMESPACE influence2d:: FILE influence2dTargets.cmake
    DESTINATION ${INFLUENCE2D_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/influence2dConfig.cmake.in
    ${PROJECT_BINARY_DIR}/influence2dConfig.cmake INSTALL_DESTINATION ${INFLUENCE2D_CMAKE_DIR})
# Header-only: any architecture may use the package.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/influence2dConfigVersion.cmake
    COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${PROJECT_BINARY_DIR}/influence2dConfig.cmake ${PROJECT_BINARY_DIR}/influence2dConfigVersion.cmake
    DESTINATION ${INFLUENCE2D_CMAKE_DIR})

# Built with oneTBB: its workers run the parallel calls.
set(INFLUENCE2D_PC_CFLAGS "")
set(INFLUENCE2D_PC_LIBS "")
if(INFLUENCE2D_WITH_TBB)
    set(INFLUENCE2D_PC_CFLAGS " -DINFLUENCE2D_USE_TBB")
    set(INFLUENCE2D_PC_LIBS " -ltbb")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/influence2d.pc.in ${PROJECT_BINARY_DIR}/influence2d.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/influence2d.pc DESTINATION ${CMAKE_INSTALL_DATADIR}/pkgconfig)
