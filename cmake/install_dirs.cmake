# Where `cmake --install` puts things, relative to the prefix (GNU layout). Included by
# cmake/install.cmake, apps/CMakeLists.txt (the CLI finds its installed Python package from these)
# and tests/downstream; safe to include more than once.
include(GNUInstallDirs)
set(ELLC_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/ellc" CACHE STRING
    "Where ellcConfig.cmake goes, relative to the install prefix")
# Debian's layout for Python packages of any Python 3 version: /usr/bin/python3 reads
# /usr/lib/python3/dist-packages and /usr/local/lib/python3/dist-packages.
set(ELLC_INSTALL_PYTHONDIR "lib/python3/dist-packages" CACHE STRING
    "Where the Python package ellc/ goes, relative to the install prefix")
