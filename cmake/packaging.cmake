# The Debian package: `cpack -G DEB` in the build folder writes ellc_<version>_amd64.deb with
# everything cmake/install.cmake installs, under /usr (docs/install.md, scripts/check_deb.sh).
#
# Depends: the shared libraries the installed ELF files link (ellc, lmp_ellc, _ellc*.so), found by
# dpkg-shlibdeps (libtomlplusplus3, libgomp1, libstdc++6; liblammps0 and libopenmpi3 for lmp_ellc;
# libceres3 for `ellc fit` and ellc.calibrate), plus what dpkg-shlibdeps cannot see: the Python
# interpreter the module was built for, numpy and matplotlib (plots), and Open MPI's programs for
# lmp_ellc (mpi-default-bin).
# Recommends: what a program built against libellc needs (Eigen and toml++ headers, pkg-config).
set(CPACK_PACKAGE_NAME ellc)
set(CPACK_PACKAGE_VENDOR "ellc")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "Normal contact force between two elastoplastic ellipsoids (Becker-Kamlah model) for DEM:
the ellc command-line tool (curve, geometry, dem, fit), lmp_ellc (LAMMPS with
pair_style ellipsoid/bk), the Python package ellc, and the static library libellc with
its headers, CMake package (find_package(ellc)) and pkg-config file.")
set(ELLC_PACKAGE_MAINTAINER "ellc developers <ellc@localhost>" CACHE STRING "Maintainer field of the .deb")
set(CPACK_PACKAGE_CONTACT "${ELLC_PACKAGE_MAINTAINER}")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Every component but PythonPath (ellc.pth, cmake/install.cmake): /usr/lib/python3/dist-packages
# is on the path already.
set(CPACK_INSTALL_CMAKE_PROJECTS)
foreach(component Development Runtime Python)
  list(APPEND CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR}" ellc ${component} /)
endforeach()

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # ellc_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(_ellc_depends python3-numpy python3-matplotlib)
if(ELLC_BUILD_PYTHON)
  # The compiled module is for one Python minor version, as Debian's python3-* extensions are.
  execute_process(COMMAND ${ELLC_PYTHON} -c "import sys; print('%d.%d;%d.%d' % (sys.version_info[:2] + (sys.version_info[0], sys.version_info[1] + 1)))"
                  OUTPUT_VARIABLE _ellc_python_range OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _ellc_python_status)
  if(_ellc_python_status EQUAL 0)
    list(GET _ellc_python_range 0 _ellc_python_low)
    list(GET _ellc_python_range 1 _ellc_python_high)
    list(PREPEND _ellc_depends "python3 (>= ${_ellc_python_low}~)" "python3 (<< ${_ellc_python_high})")
  else()
    list(PREPEND _ellc_depends python3)
  endif()
else()
  list(PREPEND _ellc_depends python3)
endif()
if(TARGET lmp_ellc)
  # Open MPI starts even a single lmp_ellc process through its orted (openmpi-bin); Debian's own
  # lammps package depends on mpi-default-bin for the same reason.
  list(APPEND _ellc_depends mpi-default-bin)
endif()
list(JOIN _ellc_depends ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libeigen3-dev, libtomlplusplus-dev, pkg-config")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
  ${CMAKE_CURRENT_LIST_DIR}/debian/postinst ${CMAKE_CURRENT_LIST_DIR}/debian/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
