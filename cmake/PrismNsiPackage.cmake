# Install tree for libnsi: a package config exporting nsi::nsi, so
# find_package(nsi) works for an installed Prism as find_package(anari)
# does (PrismPackage.cmake). libnsi's own install(TARGETS ... EXPORT
# nsi_Exports) is in src/nsi; anari::anari comes from anari's package.
include(PrismPackageConfig)
prism_install_package_config(nsi ${PROJECT_VERSION} SameMajorVersion
  ${CMAKE_INSTALL_LIBDIR}/cmake/nsi-${PROJECT_VERSION})
