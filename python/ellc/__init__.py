"""ellc: the Becker-Kamlah elastoplastic ellipsoid contact law from Python.

The compiled core lives in ``ellc._ellc`` (built by CMake for /usr/bin/python3). Plotting in
``ellc.plots`` needs only numpy and matplotlib, so the command-line tools can use it without
the compiled module.
"""

try:
    from ellc._ellc import *  # noqa: F401,F403
except ImportError:  # plots only; the bindings are not built or not on the path
    pass
