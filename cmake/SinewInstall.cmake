# cmake --install: headers under include/sinew/<folder>/, the library, the
# sinew executable and a CMake package so that find_package(sinew) gives
# sinew::sinew to a downstream project (examples/downstream).
include(CMakePackageConfigHelpers)

install(TARGETS sinew EXPORT sinewTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS sinew_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# strict_json.hpp (the scene reader's), result_json.hpp and
# comparison_report.hpp (the runs' JSON, shared with the CLI) include nlohmann/json, which the library links
# privately: they are not installed, and no installed header includes them.
foreach(dir ${SINEW_PUBLIC_HEADER_DIRS})
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sinew/${dir}
          FILES_MATCHING PATTERN "*.hpp"
          PATTERN "strict_json.hpp" EXCLUDE
          PATTERN "result_json.hpp" EXCLUDE
          PATTERN "comparison_report.hpp" EXCLUDE)
endforeach()

set(SINEW_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/sinew)
install(EXPORT sinewTargets NAMESPACE sinew:: DESTINATION ${SINEW_CMAKE_DIR})
configure_package_config_file(cmake/sinewConfig.cmake.in
  "${PROJECT_BINARY_DIR}/sinewConfig.cmake" INSTALL_DESTINATION ${SINEW_CMAKE_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/sinewConfig.cmake" "${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake"
  DESTINATION ${SINEW_CMAKE_DIR})
