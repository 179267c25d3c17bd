"""The installed Python package, imported with only the install prefix on the path.

    PYTHONPATH=PREFIX/lib/python3/dist-packages /usr/bin/python3 -P check_python.py \
        PREFIX/lib/python3/dist-packages CURVE.csv SOURCE_DIR

Runs in a fresh temporary folder (outside the source and build trees) and checks that
* ``ellc`` and its compiled ``ellc._ellc`` are imported from the prefix, nothing from SOURCE_DIR;
* paper case 2, built from its numbers, gives the force column of CURVE.csv (``ellc curve
  examples/paper_case2.toml -o CURVE.csv``) along the same path to 1e-12 relative;
* ``ellc.figures`` and ``ellc.plots`` draw from numpy arrays (the figures of the CLI's plots);
* ``ellc.dem`` builds a scenario from a dict and steps it.
``-P`` keeps the folder of this script off ``sys.path``.
"""

import csv
import os
import shutil
import sys
import tempfile


def inside(path, folder):
    path, folder = os.path.realpath(path), os.path.realpath(folder)
    return os.path.commonpath([path, folder]) == folder


def main(package_root, curve_csv, source_dir):
    scratch = tempfile.mkdtemp(prefix="ellc-downstream-python-")
    os.chdir(scratch)
    try:
        import numpy as np

        import ellc
        from ellc import figures, plots

        for module in (ellc, ellc._ellc, figures, plots):
            assert inside(module.__file__, package_root), f"{module.__name__} from {module.__file__}"
        assert ellc.HAVE_CORE, "the compiled module ellc._ellc did not import"
        # (The prefix itself may lie in the source tree when the build folder does.)
        leaked = [entry for entry in sys.path
                  if entry and inside(entry, source_dir) and not inside(entry, package_root)]
        assert not leaked, f"sys.path reaches into the source tree: {leaked}"

        with open(curve_csv, newline="") as handle:
            rows = list(csv.DictReader(handle))
        overlap = np.array([float(row["overlap"]) for row in rows])
        reference = np.array([float(row["force"]) for row in rows])

        nmc = ellc.Material(youngs_modulus=142000.0, poisson_ratio=0.25, yield_stress=7900.0)

        def body(aspect, mean_radius):
            aspect = np.asarray(aspect, dtype=float)
            return ellc.Body(aspect * (mean_radius / np.cbrt(aspect.prod())), nmc)

        contact = ellc.Contact.between(body([1.0, 1.0, 0.8], 10.0), body([1.0, 1.25, 1.25], 10.0))
        force = contact.evaluate_path(overlap).force
        scale = np.where(reference == 0.0, 1.0, np.abs(reference))
        worst = float(np.max(np.abs(force - reference) / scale))
        assert worst <= 1e-12, f"force differs from ellc curve by {worst:.3g} relative"

        # The CLI's force-overlap figure, from arrays instead of its CSV.
        constants = contact.constants
        axes = figures.plot_normalized_force(overlap, force, constants.yield_overlap, constants.yield_force)
        axes.figure.savefig(os.path.join(scratch, "case2.png"))
        assert os.path.getsize(os.path.join(scratch, "case2.png")) > 0
        # ellc.dem: a scenario from a dict, a few steps, the state as arrays.
        scenario = {"material": {"youngs_modulus": 142000.0, "poisson_ratio": 0.25, "yield_stress": 7900.0},
                    "box": {"size": [42.0, 42.0]},
                    "packing": {"count": 10, "mean_radius": 4.0, "density": 4.7e-3, "seed": 3},
                    "time": {"mass_scaling": 1e4}, "settle": {"time": 0.0},
                    "calendering": {"speed": 0.05, "lift_speed": 0.05, "target_pressure": 50.0}}
        run = ellc.dem.Run(scenario, write_files=False)
        run.run(50)
        assert run.step == 50 and run.particles.position.shape == (10, 3), run
        assert np.isfinite(run.particles.position).all()
        print(f"ellc {ellc.__file__}: paper case 2 over {len(overlap)} points equals ellc curve "
              f"(max relative difference {worst:.2g}); figure drawn")
    finally:
        os.chdir("/")
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
