# prism_install_package_config(NAME VERSION COMPATIBILITY DESTINATION): the
# export set NAME_Exports (namespace NAME::), cmake/NAMEConfig.cmake.in and
# a version file, installed to DESTINATION, so find_package(NAME) works for
# an installed Prism (anari: PrismPackage.cmake; nsi: PrismNsiPackage.cmake).
include(CMakePackageConfigHelpers)

function(prism_install_package_config name version compatibility destination)
  install(EXPORT ${name}_Exports
    NAMESPACE ${name}::
    DESTINATION ${destination})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/${name}Config.cmake.in
    ${PROJECT_BINARY_DIR}/${name}Config.cmake
    INSTALL_DESTINATION ${destination})
  write_basic_package_version_file(
    ${PROJECT_BINARY_DIR}/${name}ConfigVersion.cmake
    VERSION ${version}
    COMPATIBILITY ${compatibility})
  install(FILES
    ${PROJECT_BINARY_DIR}/${name}Config.cmake
    ${PROJECT_BINARY_DIR}/${name}ConfigVersion.cmake
    DESTINATION ${destination})
endfunction()
