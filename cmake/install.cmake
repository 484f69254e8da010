# nbscope's install tree (GNU layout), its CMake package and the .deb (docs/install.md):
#   bin/nbscope                       the binary; it finds ../share/nbscope itself (src/io/data_dir.cpp)
#   libexec/nbscope/nbscope-plugin-host  the process a detector plugin runs in (src/io/plugin_host.hpp)
#   share/nbscope/assets/{scenes,examples}, share/nbscope/shaders   what it reads at run time
#   include/nbscope/detector.h        the plugin API
#   share/doc/nbscope/examples/       the example plugins' sources (examples/), to copy from (their
#                                     CMakeLists.txt build in this tree only: not installed)
#   lib/cmake/nbscope/                find_package(nbscope): nbscope::detector_api, nbscope_add_detector(),
#                                     nbscope_EXECUTABLE
include(CMakePackageConfigHelpers)

set(NBSCOPE_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/nbscope")
set(NBSCOPE_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/nbscope")

install(TARGETS nbscope RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(TARGETS nbscope-plugin-host RUNTIME DESTINATION "${CMAKE_INSTALL_LIBEXECDIR}/nbscope")
# Only what the binary reads at run time: the golden screenshots are the tests' own.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/assets/scenes" "${PROJECT_SOURCE_DIR}/assets/examples"
        DESTINATION "${NBSCOPE_INSTALL_DATADIR}/assets")
if(NBSCOPE_GUI)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/shaders" DESTINATION "${NBSCOPE_INSTALL_DATADIR}")
endif()

# The plugin API as a header-only target: nbscope::detector_api here and once installed.
add_library(nbscope_detector_api INTERFACE)
add_library(nbscope::detector_api ALIAS nbscope_detector_api)
target_include_directories(nbscope_detector_api INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
set_target_properties(nbscope_detector_api PROPERTIES EXPORT_NAME detector_api)
install(TARGETS nbscope_detector_api EXPORT nbscopeTargets)
install(FILES "${PROJECT_SOURCE_DIR}/include/nbscope/detector.h" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/nbscope")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/" DESTINATION "${CMAKE_INSTALL_DOCDIR}/examples"
        FILES_MATCHING PATTERN "*.c" PATTERN "*.h" PATTERN "*.md")
install(EXPORT nbscopeTargets NAMESPACE nbscope:: DESTINATION "${NBSCOPE_INSTALL_CMAKEDIR}")

configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/nbscopeConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/nbscopeConfig.cmake" INSTALL_DESTINATION "${NBSCOPE_INSTALL_CMAKEDIR}"
  PATH_VARS CMAKE_INSTALL_BINDIR)
# 0.x: a new minor version may change the plugin API, so only the same minor version matches.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/nbscopeConfigVersion.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/nbscopeConfig.cmake" "${PROJECT_BINARY_DIR}/nbscopeConfigVersion.cmake"
        "${CMAKE_CURRENT_LIST_DIR}/nbscope_add_detector.cmake" DESTINATION "${NBSCOPE_INSTALL_CMAKEDIR}")

include("${CMAKE_CURRENT_LIST_DIR}/cpack.cmake")
