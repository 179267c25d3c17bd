"""ellc.dem: a Python run is `ellc dem` bit for bit; staged runs and checkpoint round trips equal one
run; the state arrays are views with the right lifetime; bad input raises named errors."""

import filecmp
import math
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import ellc
from conftest import SOURCE_DIR
from ellc import dem

QUICK = SOURCE_DIR / "examples" / "calendering_quick.toml"
# The quick example's protocol (approach, calendering to a target pressure, servo hold,
# unload) on 32 particles in a smaller box: ~6900 steps, a second or two. These tests compare
# Python with the CLI, not the release physics: the release ends when the plate leaves the layer
# (a 32-particle layer does not settle to the servo release's equilibrium ratio in 300 µs).
TINY_CHANGES = {"packing": {"count": 32, "aspect": [0.8, 1.25]}, "box": {"size": [26.0, 26.0]},
                "calendering": {"target_pressure": 60.0, "hold_time": 5.0, "approach_solid_fraction": 0.3,
                                "release": "contact_lost", "relax_time": 0.0},
                "output": {"csv_every": 10}}
N = TINY_CHANGES["packing"]["count"]
OUTPUTS = ("timeseries.csv", "summary.txt", "checkpoint.bin")


def tiny_scenario():
    return dem.Scenario.from_file(QUICK).with_changes(TINY_CHANGES)


def same_bytes(a, b, names=OUTPUTS):
    for name in names:
        assert filecmp.cmp(pathlib.Path(a) / name, pathlib.Path(b) / name, shallow=False), f"{name} differs"


@pytest.fixture(scope="module")
def tiny_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenario") / "tiny.toml"
    path.write_text("# the tiny scenario of tests/python/test_dem.py\n" + tiny_scenario().text)
    return str(path)


@pytest.fixture(scope="module")
def whole(tiny_file, tmp_path_factory):
    """The tiny scenario run to the end in one call, from its file."""
    directory = tmp_path_factory.mktemp("whole")
    run = dem.Run(tiny_file, directory)
    run.run()
    return run, directory


# ------------------------------------------------------------------------------------------------
# Determinism: the CLI, stages, checkpoints
# ------------------------------------------------------------------------------------------------

def test_python_run_equals_ellc_dem_bit_for_bit(cli, tiny_file, whole, tmp_path):
    run, directory = whole
    assert run.done and run.phase == "done" and run.step > 500
    completed = subprocess.run([cli, "dem", tiny_file, "-o", str(tmp_path), "--no-plot", "--quiet"],
                               capture_output=True, text=True, timeout=120)
    assert completed.returncode == 0, completed.stderr
    same_bytes(directory, tmp_path)
    frames = sorted(os.listdir(directory / "vtk"))
    assert frames == sorted(os.listdir(tmp_path / "vtk")) and frames
    same_bytes(directory / "vtk", tmp_path / "vtk", frames)


def test_staged_run_equals_one_run(tiny_file, whole, tmp_path):
    run, directory = whole
    staged = dem.Run(tiny_file, tmp_path)
    assert staged.run(37) == 37 and staged.step == 37
    assert staged.run_until("load")  # already there (no settling): no step
    assert staged.step == 37
    assert staged.run_until(time=staged.time + 10 * staged.dt + 1e-9 * staged.dt) and staged.step == 48
    assert staged.run_until(step=301) and staged.step == 301
    assert staged.run_until(lambda r: r.plate_pressure > 5.0, check_every=7)
    assert staged.plate_pressure > 5.0 and (staged.step - 301) % 7 == 0
    assert staged.run_until("hold") and staged.phase == "hold"
    assert staged.run_until("unload") and staged.phase == "unload"
    assert not staged.run_until("relax")  # relax_time = 0: the run ends first
    assert staged.done and staged.step == run.step
    same_bytes(directory, tmp_path)


def test_checkpoint_round_trip_equals_uninterrupted_run(tiny_file, whole, tmp_path):
    run, directory = whole
    first = dem.Run(tiny_file, tmp_path)
    first.run_until("hold")
    checkpoint = first.save_checkpoint(tmp_path / "at_hold.bin")
    held_step = first.step
    first.run(25)  # the continued run rewinds the time series to the checkpoint's step
    del first
    second = dem.Run.from_checkpoint(tiny_file, checkpoint, tmp_path)
    assert second.step == held_step and second.phase == "hold"
    second.run()
    same_bytes(directory, tmp_path)
    # Elsewhere and in memory: the same final state.
    third = dem.Run.from_checkpoint(tiny_file, checkpoint, write_files=False)
    third.run()
    for name in dem.Particles.FIELDS:
        assert np.array_equal(getattr(third.particles, name), getattr(run.particles, name)), name
    assert third.summary() == run.summary()


def test_dict_scenario_runs_as_its_file(tiny_file, tmp_path):
    import tomllib
    data = tomllib.loads(pathlib.Path(tiny_file).read_text())
    from_dict = dem.Run(data, write_files=False)
    from_file = dem.Run(tiny_file, write_files=False)
    from_dict.run(200)
    from_file.run(200)
    assert from_dict.scenario.text != from_file.scenario.text  # the file has a comment...
    for name in dem.Particles.FIELDS:  # ...the run does not
        assert np.array_equal(getattr(from_dict.particles, name), getattr(from_file.particles, name)), name


# ------------------------------------------------------------------------------------------------
# State as arrays
# ------------------------------------------------------------------------------------------------

def test_particles_are_read_only_views_tied_to_the_run():
    run = dem.Run(tiny_scenario(), write_files=False)
    particles = run.particles
    position = particles.position
    shapes = {"id": (N,), "position": (N, 3), "orientation": (N, 4), "semi_axes": (N, 3), "velocity": (N, 3),
              "angular_velocity": (N, 3), "force": (N, 3), "torque": (N, 3), "mass": (N,), "mean_radius": (N,),
              "inertia": (N, 3), "species": (N,)}
    assert set(shapes) == set(dem.Particles.FIELDS)
    dtypes = {"id": np.uint32, "species": np.uint16}
    for name, shape in shapes.items():
        array = getattr(particles, name)
        assert array.shape == shape and not array.flags.writeable, name
        assert array.dtype == dtypes.get(name, np.float64), name
    assert run.species_names == [""] and not particles.species.any()  # one unnamed species
    assert sorted(particles.id.tolist()) == list(range(N))
    np.testing.assert_allclose(np.linalg.norm(particles.orientation, axis=1), 1.0, rtol=1e-12)
    np.testing.assert_allclose(np.prod(particles.semi_axes, axis=1) ** (1 / 3), particles.mean_radius, rtol=1e-12)
    with pytest.raises(ValueError):
        position[0, 0] = 1.0
    # No copy: two reads share the engine's memory, which stays put while the run steps.
    address = position.__array_interface__["data"][0]
    assert np.shares_memory(position, particles.position)
    before = position.copy()
    run.run(400)
    assert particles.position.__array_interface__["data"][0] == address
    assert not np.array_equal(before, position)  # the view shows the live state
    assert np.array_equal(position, run.particles.position)
    # The view keeps the run alive.
    del run, particles
    assert position.base is not None and np.isfinite(position).all()


def test_species_of_a_blend_have_their_own_counts_shapes_and_densities():
    # tests/lammps/tiny_blend.toml: 24 particles, 3/4 NMC ellipsoids (4.7e-3 ng/µm³) and 1/4 spheres
    # of an additive (1.8e-3 ng/µm³), both × mass_scaling 1e4.
    run = dem.Run(SOURCE_DIR / "tests" / "lammps" / "tiny_blend.toml", write_files=False)
    run.run(20)
    particles = run.particles
    assert run.species_names == ["NMC", "additive"]
    assert np.bincount(particles.species, minlength=2).tolist() == [18, 6]
    volume = 4.0 / 3.0 * math.pi * np.prod(particles.semi_axes, axis=1)
    density = particles.mass / volume
    additive = particles.species == 1
    np.testing.assert_allclose(density[additive], 18.0, rtol=1e-12)
    np.testing.assert_allclose(density[~additive], 47.0, rtol=1e-12)
    axes = particles.semi_axes[additive]
    np.testing.assert_allclose(axes, np.repeat(axes[:, :1], 3, axis=1), rtol=1e-15)  # spheres
    assert np.ptp(particles.semi_axes[~additive], axis=1).min() > 0.0  # ellipsoids


def test_contacts_are_consistent(whole):
    run, _ = whole
    loaded = dem.Run(tiny_scenario(), write_files=False)
    loaded.run_until("hold")
    contacts = loaded.contacts()
    n = len(contacts)
    assert n > N
    for name in ("wall", "id_i", "id_j", "overlap", "max_overlap", "regime", "normal_force", "size_ratio"):
        assert getattr(contacts, name).shape == (n,), name
    for name in ("normal", "force", "tangential_force", "centre_i", "other"):
        assert getattr(contacts, name).shape == (n, 3), name
    pairs = contacts.pairs
    assert pairs.any() and (contacts.wall[~pairs] >= 0).all() and (contacts.id_j[~pairs] == -1).all()
    assert (contacts.id_i[pairs] < contacts.id_j[pairs]).all()
    active = contacts.max_overlap > 0
    assert (contacts.overlap[active] <= contacts.max_overlap[active] * (1 + 1e-12)).all()
    np.testing.assert_allclose(np.linalg.norm(contacts.normal, axis=1), 1.0, rtol=1e-12)
    # The force splits into its normal part and a tangential part in the contact plane.
    np.testing.assert_allclose(np.einsum("ij,ij->i", contacts.force, contacts.normal), contacts.normal_force,
                               rtol=1e-12, atol=1e-12 * np.abs(contacts.force).max())
    np.testing.assert_allclose(np.einsum("ij,ij->i", contacts.tangential_force, contacts.normal), 0.0,
                               atol=1e-9 * np.abs(contacts.force).max())
    assert set(contacts.regime_name) <= set(dem.REGIMES)
    # The plate's contacts carry its pressure: Σ F_z over the box area.
    box = loaded.scenario["box.size"]
    plate = contacts.wall == 1
    assert plate.any()
    np.testing.assert_allclose(contacts.force[plate, 2].sum() / (box[0] * box[1]), loaded.plate_pressure, rtol=1e-9)
    # And so does the time series of the finished run.
    series = run.timeseries()
    assert series["step"][0] == 0 and series["step"][-1] == run.step
    assert set(series["phase"]) == {"settle", "load", "hold", "unload"}  # a row is labelled with the phase it ends
    assert np.all(np.diff(series["step"]) >= 0) and series["plate_pressure"].max() >= 60.0
    assert run.summary()["finished"] is True and run.summary()["particles"] == N


def test_cli_figure_from_the_run_arrays(whole, tmp_path):
    from ellc import plots
    run, _ = whole
    series = run.timeseries()
    figure = plots.dem_figure(*(series[name] for name in ("thickness", "plate_pressure", "phase", "time",
                                                           "kinetic_energy", "plastic_dissipation")),
                              energies={name: series[name] for name in plots.ENERGY_COLUMNS})
    figure.savefig(tmp_path / "pressure_thickness.png")
    assert (tmp_path / "pressure_thickness.png").stat().st_size > 0


# ------------------------------------------------------------------------------------------------
# Progress, callbacks, the GIL
# ------------------------------------------------------------------------------------------------

def test_callback_and_progress_bar(capsys):
    run = dem.Run(tiny_scenario(), write_files=False)
    seen = []
    run.run(250, callback=lambda r: seen.append(r.step), every=100)
    assert seen == [100, 200, 250]
    assert capsys.readouterr().err == ""  # not a terminal: no bar
    run.run(20, progress=True)
    err = capsys.readouterr().err
    assert err.startswith("\r[") and "step 270" in err and err.endswith("\n")


def test_stepping_releases_the_gil():
    run = dem.Run(tiny_scenario(), write_files=False)
    window = {}

    def step():
        window["start"] = time.monotonic()
        run._core.advance(6000)  # one call (0.06–0.15 s): the GIL is released for all of it or held
        window["end"] = time.monotonic()

    ticks, refused = [], []
    worker = threading.Thread(target=step)
    worker.start()
    while worker.is_alive():
        ticks.append(time.monotonic())
        if "start" in window and not refused:
            # Reading what the step rewrites is refused while it runs (or the step is over).
            try:
                run.contacts()
                refused.append("end" in window or not worker.is_alive())
            except RuntimeError as error:
                refused.append("another thread" in str(error))
    worker.join()
    assert refused == [True]
    inside = [t for t in ticks if window["start"] < t < window["end"]]
    # Long enough for the main thread's loop to tick thousands of times if the GIL is free (a
    # tick takes well under a microsecond); no tick at all lands inside while it is held.
    assert window["end"] - window["start"] > 0.01
    assert len(inside) > 1000, "the main thread did not run while the engine stepped"


# ------------------------------------------------------------------------------------------------
# Bad input
# ------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("changes, field", [
    ({"packing": {"cout": 32}}, "cout"),
    ({"packing": {"count": "32"}}, "packing.count"),
    ({"packing": {"count": 2.5}}, "packing.count"),
    ({"calendering": {"target_pressure": -1.0}}, "calendering.target_pressure"),
    ({"calendering": {"target_pressure": None}}, "calendering.target_pressure"),
    ({"calendering": {"target_pressure": object()}}, "calendering.target_pressure"),
    ({"box": {"size": np.zeros((2, 2))}}, "box.size"),
    ({"box": {"size": np.array([42.0, 42.0, 1.0])}}, "box.size"),
    ({"box": {"size": np.array([1 + 2j, 3.0])}}, "box.size[0]"),
    ({"packing": {1: 32}}, "packing"),
    ({"packings": {"count": 32}}, "packings"),
])
def test_bad_dict_raises_input_error_naming_the_key(changes, field):
    base = dem.Scenario.from_file(QUICK)
    with pytest.raises(ellc.InputError, match=field.replace("[", r"\[").replace("]", r"\]")):
        base.with_changes(changes)
    data = base.copy().data
    for table, values in changes.items():
        data.setdefault(table, {}).update(values)
    with pytest.raises(ellc.InputError, match=field.replace("[", r"\[").replace("]", r"\]")):
        dem.Run(data, write_files=False)
    assert issubclass(ellc.InputError, ValueError)


def test_bad_scenarios_and_arguments(tmp_path):
    with pytest.raises(ellc.InputError, match="cannot read"):
        dem.Scenario.from_file(tmp_path / "missing.toml")
    with pytest.raises(ellc.InputError, match="<dict>"):
        dem.Scenario.from_dict([1, 2])
    with pytest.raises(TypeError, match="scenario"):
        dem.Run(42)
    with pytest.raises(ellc.InputError):
        dem.Scenario.from_toml("[packing\ncount = 3")
    run = dem.Run(tiny_scenario(), write_files=False)
    for call, error, message in [
        (lambda: run.run(-1), ValueError, "steps"),
        (lambda: run.run(1.5), ValueError, "steps"),
        (lambda: run.run(1, every=0), ValueError, "every"),
        (lambda: run.run(1, callback=3), TypeError, "callback"),
        (lambda: run.run_until("squeeze"), ValueError, "phase = 'squeeze'"),
        (lambda: run.run_until(), TypeError, "exactly one"),
        (lambda: run.run_until("hold", time=3.0), TypeError, "exactly one"),
        (lambda: run.run_until(time=math.nan), ValueError, "time"),
        (lambda: run.run_until(step=-2), ValueError, "step"),
        (lambda: run.run_until(3.0), TypeError, "callable"),
        (lambda: run.run_until(lambda r: False, check_every=0), ValueError, "check_every"),
        (lambda: run._core.particle_field("colour"), ValueError, "colour"),
        (lambda: run.timeseries(), RuntimeError, "write_files=False"),
    ]:
        with pytest.raises(error, match=message):
            call()
    assert run.step == 0  # nothing above stepped


def test_checkpoint_of_another_scenario_is_refused(tmp_path):
    run = dem.Run(tiny_scenario(), write_files=False)
    run.run(10)
    checkpoint = run.save_checkpoint(tmp_path / "c.bin")
    other = tiny_scenario().with_changes({"calendering": {"target_pressure": 61.0}})
    with pytest.raises(ellc.InputError, match="checkpoint"):
        dem.Run.from_checkpoint(other, checkpoint, write_files=False)
    with pytest.raises(ellc.InputError, match="cannot open"):
        dem.Run.from_checkpoint(tiny_scenario(), tmp_path / "none.bin", write_files=False)


def test_stepping_a_finished_run_raises(whole):
    run, _ = whole
    for call in (run.run, lambda: run.run(1), lambda: run.run_until(step=run.step + 5)):
        with pytest.raises(dem.RunFinished, match="finished"):
            call()
    assert run.run_until("done")  # a condition that holds needs no step


def test_stepping_a_failed_run_raises():
    # Settling under gravity with a runaway threshold the first steps already pass.
    # The plate speeds stay below max_speed, which the reader checks; the settling particles do not.
    slow = {"approach_speed": 1e-5, "speed": 1e-5, "lift_speed": 1e-5}
    scenario = tiny_scenario().with_changes({"time": {"max_speed": 1e-4}, "settle": {"time": 10.0}, "calendering": slow})
    run = dem.Run(scenario, write_files=False)
    with pytest.raises(dem.RunFailed) as failure:
        run.run()
    assert isinstance(failure.value, RuntimeError) and run.failed and not run.done
    step = run.step
    with pytest.raises(dem.RunFailed, match=f"failed at step {step}"):
        run.run(1)
    assert run.step == step
