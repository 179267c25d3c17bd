"""ellc: the Becker-Kamlah elastoplastic ellipsoid contact law from Python.

The compiled core lives in ``ellc._ellc`` (built by CMake for /usr/bin/python3 into
``build/python/ellc``; see docs/python.md). Plotting in ``ellc.plots`` and ``ellc.figures`` needs
only numpy and matplotlib for the CSV-based figures, so the command-line tools can use it
without the compiled module.

Quick start::

    import numpy as np, ellc
    nmc = ellc.Material(youngs_modulus=142000.0, poisson_ratio=0.25, yield_stress=7900.0)
    body_i = ellc.Body([10.0, 10.0, 8.0], nmc)
    body_j = ellc.Body([10.0, 12.5, 12.5], nmc)
    contact = ellc.Contact.between(body_i, body_j)
    path = np.concatenate([np.linspace(0, 2, 100), np.linspace(2, 0, 100)])
    result = contact.evaluate_path(path)      # numpy arrays: force, max_overlap, plastic_overlap, regime

The DEM engine of ``ellc dem``: ``ellc.dem`` (scenarios, staged runs, state as numpy arrays).
"""

# The compiled module may sit in another `ellc` folder on sys.path (the build tree) than these
# .py files (the source tree): let the package span both.
from pkgutil import extend_path

__path__ = extend_path(__path__, __name__)

try:
    from ellc._ellc import *  # noqa: F401,F403
    from ellc._ellc import __doc__ as _core_doc  # noqa: F401
    HAVE_CORE = True
except ImportError:  # plots only; the bindings are not built or not on the path
    HAVE_CORE = False

if HAVE_CORE:
    import importlib

    from ellc import dem  # noqa: E402,F401  (the DEM engine: ellc.dem.Scenario, ellc.dem.Run)

    # The star import bound the compiled submodule ellc._ellc.microstructure to this name; the
    # Python module ellc/microstructure.py wraps it (and adds the figures), so it takes the name.
    microstructure = importlib.import_module("ellc.microstructure")


def calibrate_files(data, hertz="hale", **options):
    """Calibrates from CSV files as ``ellc fit DATA...`` does.

    ``data`` is a list of DATA arguments: ``"case.csv"`` (geometry from ``case.toml`` next to it or a
    ``# case = X.toml`` line) or ``"case.csv:geometry.toml"``. Keyword options are those of
    :func:`ellc.calibrate`. Returns a :class:`ellc.CalibrationResult`.
    """
    if isinstance(data, str):
        raise ValueError("data: expected a list of CSV paths, got a single string")
    return calibrate([read_calibration_case(item) for item in data], hertz=hertz, **options)  # noqa: F405
