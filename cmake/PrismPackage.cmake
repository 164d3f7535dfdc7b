# Install tree: headers, libanari, device libraries, and a package config
# exporting anari::anari so find_package(anari) works as with the SDK.
include(CMakePackageConfigHelpers)
set(PRISM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/anari-${PRISM_ANARI_API_VERSION})

install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/anari
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT anari_Exports
  NAMESPACE anari::
  DESTINATION ${PRISM_CMAKE_DIR})
configure_package_config_file(cmake/anariConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/anariConfig.cmake
  INSTALL_DESTINATION ${PRISM_CMAKE_DIR})
write_basic_package_version_file(
  ${CMAKE_CURRENT_BINARY_DIR}/anariConfigVersion.cmake
  VERSION ${PRISM_ANARI_API_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/anariConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/anariConfigVersion.cmake
  DESTINATION ${PRISM_CMAKE_DIR})

configure_file(cmake/anari.pc.in ${CMAKE_CURRENT_BINARY_DIR}/anari.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/anari.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
