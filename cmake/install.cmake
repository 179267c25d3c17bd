# `cmake --install BUILD [--prefix P]`: what goes where (docs/install.md).
#
#   P/lib/libellc.a                              the library (static, position-independent)
#   P/include/ellc/<layer>/*.hpp                 the public headers: ELLC_PUBLIC_HEADER_LAYERS
#   P/lib/cmake/ellc/                            find_package(ellc CONFIG) -> ellc::ellc
#   P/lib/pkgconfig/ellc.pc                      pkg-config --cflags --libs ellc
#   P/bin/ellc, P/bin/lmp_ellc                   the CLI; lmp_ellc when LAMMPS was found
#   P/lib/python3/dist-packages/ellc/            the Python package: _ellc module + python/ellc/*.py
#   P/lib/python3.X/dist-packages/ellc.pth       puts the folder above on /usr/bin/python3's path
#   P/share/ellc/examples/                       the example case, scenario and LAMMPS input files
#
# Components: Development (library, headers, CMake and pkg-config files), Runtime (programs,
# examples), Python (the package), PythonPath (ellc.pth). Included from the root CMakeLists.txt
# after every target exists.
include(${CMAKE_CURRENT_LIST_DIR}/install_dirs.cmake)
include(CMakePackageConfigHelpers)

# The public headers, by layer. A layer is public when programs outside ellc are meant to include
# it; its headers may then include only public layers (checked by the ctest downstream.headers).
# engine, scenario and calibration are compiled into the libraries but not installed: the DEM
# engine and the `ellc dem` runner are used through the CLI, and calibration needs Ceres.
set(ELLC_PUBLIC_HEADER_LAYERS io material hertz law geometry contact cases)

install(TARGETS ellc EXPORT ellcTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(layer ${ELLC_PUBLIC_HEADER_LAYERS})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ellc/${layer}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ellc/${layer}
          COMPONENT Development FILES_MATCHING PATTERN "*.hpp")
endforeach()
# Headers directly in src/ellc/ are shared by every layer (none today).
file(GLOB ELLC_SHARED_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/ellc/*.hpp)
if(ELLC_SHARED_HEADERS)
  install(FILES ${ELLC_SHARED_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ellc COMPONENT Development)
endif()

# CMake package: ellcTargets.cmake (ellc::ellc), ellcConfig.cmake (finds the dependencies first),
# ellcConfigVersion.cmake (0.x: only the same minor version is compatible).
install(EXPORT ellcTargets NAMESPACE ellc:: DESTINATION ${ELLC_INSTALL_CMAKEDIR} COMPONENT Development)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ellcConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/ellcConfig.cmake INSTALL_DESTINATION ${ELLC_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/ellcConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/ellcConfig.cmake ${PROJECT_BINARY_DIR}/cmake/ellcConfigVersion.cmake
        DESTINATION ${ELLC_INSTALL_CMAKEDIR} COMPONENT Development)

# pkg-config file, relocatable (prefix=${pcfiledir}/../..).
file(RELATIVE_PATH ELLC_PC_PREFIX_FROM_PCDIR /_prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /_prefix)
configure_file(${CMAKE_CURRENT_LIST_DIR}/ellc.pc.in ${PROJECT_BINARY_DIR}/cmake/ellc.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/cmake/ellc.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT Development)

# Programs. The CLI finds the Python package for its plots next to itself
# (ELLC_PYTHON_INSTALL_DIR in apps/CMakeLists.txt, apps/ellc/plot_runner.cpp).
install(TARGETS ellc_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
if(TARGET lmp_ellc)
  install(TARGETS lmp_ellc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ellc/examples
        COMPONENT Runtime)

# Python package. The .py files are installed even without the compiled module: the CLI's plots
# need only them, numpy and matplotlib.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/ellc/ DESTINATION ${ELLC_INSTALL_PYTHONDIR}/ellc
        COMPONENT Python FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
if(TARGET ellc_python_module)
  install(TARGETS ellc_python_module LIBRARY DESTINATION ${ELLC_INSTALL_PYTHONDIR}/ellc COMPONENT Python)
endif()
# Debian's /usr/bin/python3 reads lib/python3/dist-packages of the prefix /usr only; under
# /usr/local (where pip puts packages too) it reads lib/python3.X/dist-packages. The path file
# lib/python3.X/dist-packages/ellc.pth adds the package folder there, as a path relative to the
# file itself, so it follows --prefix and DESTDIR. Component PythonPath: not in the Debian package,
# whose /usr/lib/python3/dist-packages is on the path already.
if(NOT IS_ABSOLUTE "${ELLC_INSTALL_PYTHONDIR}")
  execute_process(COMMAND ${ELLC_PYTHON} -c "import sys; print('python%d.%d' % sys.version_info[:2])"
                  OUTPUT_VARIABLE _ellc_python_versioned OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE _ellc_python_status ERROR_QUIET)
  if(_ellc_python_status EQUAL 0)
    set(_ellc_versioned_site lib/${_ellc_python_versioned}/dist-packages)
    file(RELATIVE_PATH _ellc_from_site /_prefix/${_ellc_versioned_site} /_prefix/${ELLC_INSTALL_PYTHONDIR})
    file(WRITE ${PROJECT_BINARY_DIR}/cmake/ellc.pth
         "# ellc: the package folder ${ELLC_INSTALL_PYTHONDIR} of this prefix (cmake/install.cmake)\n"
         "${_ellc_from_site}\n")
    install(FILES ${PROJECT_BINARY_DIR}/cmake/ellc.pth DESTINATION ${_ellc_versioned_site} COMPONENT PythonPath)
  endif()
endif()
