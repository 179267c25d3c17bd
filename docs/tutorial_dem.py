#!/usr/bin/python3
"""Tutorial: calendering with ellc.dem, then porosity against pressure (notebook-style cells).

Run from the repository root after building (docs/python.md, "The DEM engine: ellc.dem"):

    cmake --build build --target ellc_python
    PYTHONPATH=build/python /usr/bin/python3 docs/tutorial_dem.py

It calenders examples/calendering_quick.toml (100 ellipsoids; about 15 minutes on one core) and
writes into --out DIR (default out/tutorial_dem): the run's files, porosity_pressure.png and
state_at_hold.png. --tiny runs a 32-particle version in seconds (the ctest python.tutorial_dem).
Each `# %%` cell can be pasted into a notebook or an interactive session as it is.
"""

# %% Setup: the scenario file, changed from Python
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # in a notebook, leave the backend alone and drop this line
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ellc import dem  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
parser.add_argument("--out", default="out/tutorial_dem", help="output directory")
parser.add_argument("--tiny", action="store_true", help="32 particles, a low target: a run of seconds")
options = parser.parse_args()
out = pathlib.Path(options.out)

scenario = dem.Scenario.from_file(ROOT / "examples" / "calendering_quick.toml")
print(scenario)
print("target pressure in the file:", scenario["calendering.target_pressure"], "MPa")
if options.tiny:
    # The same protocol on fewer particles of smaller aspect ratios, in a smaller box, to a lower target.
    scenario = scenario.with_changes({"packing": {"count": 32, "aspect": [0.8, 1.25]}, "box": {"size": [26.0, 26.0]},
                                      "calendering": {"target_pressure": 60.0, "hold_time": 5.0,
                                                      "approach_solid_fraction": 0.3,
                                                      # 32 particles do not settle under the servo release
                                                      "release": "contact_lost", "relax_time": 0.0}})
# A change is checked by the reader of `ellc dem`: a wrong key or type names itself.
try:
    scenario.with_changes({"calendering": {"target_presure": 100.0}})
except dem.InputError as error:
    print("rejected:", error)

# %% Build the packing and run the loading, stage by stage
run = dem.Run(scenario, out / "run")
print(run, "dt =", run.dt, "µs")
pressures, porosities = [], []


def record(current):
    """Called back every 50 steps: the live curve (the time series has it too)."""
    pressures.append(current.plate_pressure)
    porosities.append(current.porosity)


run.run_until("hold", callback=record, every=50)  # the plate has reached the target pressure
print(f"hold reached at step {run.step}, t = {run.time:.4g} µs: p = {run.plate_pressure:.4g} MPa, "
      f"porosity {run.porosity:.4f}")

# %% The state at the hold, as numpy arrays
particles = run.particles  # views onto the engine's arrays: no copies, read-only, always current
contacts = run.contacts()
print(len(particles), "particles; positions", particles.position.shape, "quaternions (x, y, z, w)",
      particles.orientation.shape)
regimes, counts = np.unique(contacts.regime_name[contacts.pairs], return_counts=True)
print("pair contacts by regime:", dict(zip(regimes, counts.tolist())))
print(f"largest overlap delta_* = {contacts.max_overlap.max():.4g} µm, largest c_c/r^ = "
      f"{contacts.size_ratio.max():.3g}")

figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.6), constrained_layout=True)
left.scatter(particles.position[:, 0], particles.position[:, 2], s=8 * particles.mean_radius ** 2, alpha=0.6)
left.set(xlabel="x [µm]", ylabel="z [µm]", title="particles at the hold (x–z)")
pairs = contacts.pairs
right.scatter(contacts.max_overlap[pairs], contacts.normal_force[pairs], c=contacts.regime[pairs], s=10, cmap="viridis")
right.set(xlabel="δ_* [µm]", ylabel="normal force [µN]", title="pair contacts (colour: regime)")
figure.savefig(out / "state_at_hold.png", dpi=120)

# %% A checkpoint: the loaded state, to come back to
checkpoint = run.save_checkpoint(out / "run" / "at_hold.bin")

# %% Hold, unload and relax to the end; the summary
run.run(callback=record, every=50)
summary = run.summary()
print(f"finished after {summary['steps']} steps: loaded porosity {summary['loaded_porosity']:.4f}, "
      f"released {summary['final_porosity']:.4f}, springback {summary['springback_percent']:.3g} %")

# %% Porosity against pressure, from the time series
series = run.timeseries()  # the columns of timeseries.csv
figure, axes = plt.subplots(figsize=(5.5, 4), constrained_layout=True)
for phase, colour in (("load", "C0"), ("hold", "C1"), ("unload", "C2")):
    rows = series["phase"] == phase
    axes.plot(series["plate_pressure"][rows], series["porosity"][rows], ".-", color=colour, ms=3, label=phase)
axes.set(xlabel="plate pressure [MPa]", ylabel="porosity", title="calendering: porosity against pressure")
axes.legend()
figure.savefig(out / "porosity_pressure.png", dpi=120)
print("figures:", out / "porosity_pressure.png", out / "state_at_hold.png")

# %% Back to the loaded state: the checkpoint continues the run exactly
again = dem.Run.from_checkpoint(scenario, checkpoint, out / "again", write_files=False)
again.run()
assert again.step == run.step and np.array_equal(again.particles.position, run.particles.position)
print("from the checkpoint: the same end state, bit for bit, at step", again.step)
