# Install tree: headers, libanari, device libraries, and a package config
# exporting anari::anari so find_package(anari) works as with the SDK.
include(PrismPackageConfig)
set(PRISM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/anari-${PRISM_ANARI_API_VERSION})

install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/anari
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
prism_install_package_config(anari ${PRISM_ANARI_API_VERSION} SameMinorVersion
  ${PRISM_CMAKE_DIR})

configure_file(cmake/anari.pc.in ${CMAKE_CURRENT_BINARY_DIR}/anari.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/anari.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
