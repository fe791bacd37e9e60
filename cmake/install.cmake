# What `cmake --install` puts where, the CMake package (find_package(cgtmo) -> cgtmo::cgtmo) and
# the Debian package (cpack -G DEB). docs/install.md describes the result for users.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The library under its package name: cgtmo::cgtmo here as in a consumer of the installed package.
set_target_properties(cgtmo_lib PROPERTIES EXPORT_NAME cgtmo)
add_library(cgtmo::cgtmo ALIAS cgtmo_lib)

# The public API: the apply pipeline (pipeline/apply_file.h), the operator registry, errors,
# version and thread count, and the headers those include. Every other header is internal and
# stays out of include/cgtmo (tests/install checks both ways).
set(CGTMO_PUBLIC_HEADERS
  errors.h
  color/chromaticities.h color/input_space.h color/matrix.h
  display/display.h display/profile.h
  io/image_io.h io/input_file.h io/read_options.h
  operators/apply.h operators/operator.h operators/registry.h
  pipeline/apply_file.h pipeline/request.h
  scene/frame.h scene/passes.h scene/sanitize.h
  util/parallel.h util/progress.h util/version.h)
foreach(h IN LISTS CGTMO_PUBLIC_HEADERS)
  get_filename_component(dir ${h} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/cgtmo/${h} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cgtmo/${dir} COMPONENT cgtmo)
endforeach()

install(TARGETS cgtmo RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cgtmo)
# The Slurm front end and the scripts it runs, beside cgtmo (docs/farm.md).
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/slurm/cgtmo-slurm ${PROJECT_SOURCE_DIR}/scripts/slurm/cgtmo-slurm-submit
                 ${PROJECT_SOURCE_DIR}/scripts/slurm/cgtmo-slurm-task ${PROJECT_SOURCE_DIR}/scripts/slurm/cgtmo-slurm-report
        DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cgtmo)
install(TARGETS cgtmo_lib EXPORT cgtmoTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT cgtmo
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set(CGTMO_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/cgtmo)
install(EXPORT cgtmoTargets NAMESPACE cgtmo:: DESTINATION ${CGTMO_CMAKE_DIR} COMPONENT cgtmo)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cgtmoConfig.cmake.in ${PROJECT_BINARY_DIR}/cgtmoConfig.cmake
                              INSTALL_DESTINATION ${CGTMO_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cgtmoConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cgtmoConfig.cmake ${PROJECT_BINARY_DIR}/cgtmoConfigVersion.cmake
        DESTINATION ${CGTMO_CMAKE_DIR} COMPONENT cgtmo)

# The OCIO config and its LUTs side by side, as in the source tree (its search_path is ../luts).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/ocio_config/ DESTINATION ${CMAKE_INSTALL_DATADIR}/cgtmo/ocio_config COMPONENT cgtmo)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/luts/ DESTINATION ${CMAKE_INSTALL_DATADIR}/cgtmo/luts COMPONENT cgtmo)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cgtmo)

if(TARGET cgtmo_python)
  # Where the interpreter the module is built for looks: lib/python3.X/dist-packages is on Debian's
  # python3 path under /usr and under /usr/local alike.
  execute_process(COMMAND ${CGTMO_PYTHON_INTERPRETER} -c "import sys; print('%d.%d' % sys.version_info[:2])"
                  OUTPUT_VARIABLE CGTMO_PYTHON_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(CGTMO_PYTHON_INSTALL_DIR lib/python${CGTMO_PYTHON_VERSION}/dist-packages
      CACHE STRING "install folder of the Python module, relative to the prefix")
  install(TARGETS cgtmo_python LIBRARY DESTINATION ${CGTMO_PYTHON_INSTALL_DIR} COMPONENT cgtmo)
  install(FILES ${CGTMO_ADDON_ZIP} DESTINATION ${CMAKE_INSTALL_DATADIR}/cgtmo/blender COMPONENT cgtmo)
endif()

# cpack -G DEB (in the build folder): one package with all of the above under /usr. The library
# dependencies come from dpkg-shlibdeps; Python and numpy are the module's.
set(CPACK_PACKAGE_NAME cgtmo)
set(CPACK_PACKAGE_VENDOR "cgtmo")
set(CPACK_PACKAGE_CONTACT "cgtmo maintainers <cgtmo@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "tone mapping for CG and VFX renders: CLI, library, OCIO config, Python module, Blender add-on")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(TARGET cgtmo_python)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${CGTMO_PYTHON_VERSION}), python3 (<< ${CGTMO_PYTHON_VERSION}.999), python3-numpy")
endif()
# The package runs on its shared-library dependencies alone; building a program against its CMake
# package (find_package(cgtmo), a static library) also needs their headers: suggested, not required.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "cmake, g++, pkg-config, libopenimageio-dev, libopencolorio-dev, libopenexr-dev, libimath-dev, nlohmann-json3-dev, libeigen3-dev, liblcms2-dev")
include(CPack)
