"""The figures render (Agg) from Python objects and from the CLI's CSV tables."""

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import ellc  # noqa: E402
from ellc import figures, plots  # noqa: E402
from conftest import SOURCE_DIR, run_cli, synthetic_cases  # noqa: E402


def test_figures_from_python_objects(tmp_path):
    case = ellc.read_curve_case(str(SOURCE_DIR / "examples" / "paper_case2.toml"))
    contact = ellc.Contact.from_case(case)
    path = case.overlap_path()
    constants = contact.constants
    figure, axes = plt.subplots(2, 3, figsize=(14, 8))
    figures.plot_normalized_force(path, contact.force(path), constants.yield_overlap, constants.yield_force,
                                  axes=axes[0][0])
    loading = np.linspace(constants.yield_overlap * 1.01, path.max(), 50)
    figures.plot_lambda_profile(loading / constants.yield_overlap, contact.lambda_profile(loading), axes=axes[0][1])
    patches, labels = figures.contact_states(contact, path)
    assert len(patches) == 4 and patches[-1].pressure_cap == np.inf  # the unloading state is Hertz
    assert patches[1].pressure_cap < patches[1].field_peak_pressure  # truncated in the transition
    figures.plot_pressure_profiles(patches, labels, constants.yield_stress, axes_pair=axes[1][:2])
    figures.plot_contact_ellipses(patches, labels, axes=axes[1][2])
    result = ellc.calibrate(synthetic_cases(noise=0.0, names=["sphere", "flat", "slim"]))
    x = np.linspace(0, 0.7, 20)
    figures.plot_radius_fits([c.radius_ratio for c in result.cases], [c.shared.lambda_max for c in result.cases],
                             [c.shared.epsilon_max for c in result.cases], x, result.fit.lambda_max(x),
                             result.fit.epsilon_max(x), axes_pair=[axes[0][2], axes[0][2].twinx()])
    figure.savefig(tmp_path / "all.png")
    assert (tmp_path / "all.png").stat().st_size > 10000


def test_pressure_cap_truncates_hertz():
    class Patch:
        semi_axis_major, semi_axis_minor, field_peak_pressure, pressure_cap = 2.0, 1.0, 10.0, 6.0

    x, p_x, y, p_y = figures.pressure_along_axes(Patch())
    assert p_x.max() == 6.0 and p_x[0] == 0.0 and x[-1] == 2.0 and y[-1] == 1.0


def test_plots_command_line(cli, tmp_path):
    run_cli(cli, "curve", SOURCE_DIR / "examples" / "paper_case2.toml", "-o", tmp_path / "c.csv",
            "--plot", tmp_path / "c.png")
    assert (tmp_path / "c.png").stat().st_size > 0
    assert plots.main(["pressure", str(SOURCE_DIR / "examples" / "paper_case1.toml"), str(tmp_path / "p.png")]) == 0
    assert (tmp_path / "p.png").stat().st_size > 0
    result = ellc.calibrate(synthetic_cases(noise=0.01, names=["sphere", "flat", "slim"]))
    result.write_tables(str(tmp_path / "fit"))
    assert plots.main(["fit", str(tmp_path / "fit")]) == 0
    assert (tmp_path / "fit_lambda.png").stat().st_size > 0 and (tmp_path / "fit_radius.png").stat().st_size > 0


def test_calibration_figures_from_the_result(tmp_path):
    result = ellc.calibrate(synthetic_cases(noise=0.01, names=["sphere", "flat", "slim", "fig10"]))
    lambda_figure, radius_figure = figures.plot_calibration(result)
    assert len([axes for axes in lambda_figure.axes if axes.get_visible()]) == 4
    lambda_figure.savefig(tmp_path / "lambda.png")
    radius_figure.savefig(tmp_path / "radius.png")
    assert (tmp_path / "radius.png").stat().st_size > 0


def test_cli_figures_from_arrays(tmp_path):
    """The figures of `ellc curve --plot`, `ellc dem` and `plots pressure` from arrays (docs/python.md)."""
    case = ellc.read_curve_case(str(SOURCE_DIR / "examples" / "paper_case2.toml"))
    contact = ellc.Contact.from_case(case)
    path = case.overlap_path()
    c = contact.constants

    def sphere(body):
        return ellc.Body(np.full(3, ellc.mean_radius(body.semi_axes)), body.material)

    spheres = ellc.Contact.between(sphere(case.body_i), sphere(case.body_j))
    figure = plots.curve_figure(path / c.yield_overlap, contact.force(path) / c.yield_force,
                                equal_volume_spheres=spheres.force(path) / c.yield_force, title="paper case 2")
    assert [len(axes.lines) for axes in figure.axes] == [2]
    figure.savefig(tmp_path / "curve.png")
    assert (tmp_path / "curve.png").stat().st_size > 0

    phase = ["load"] * 6 + ["hold"] * 3 + ["unload"] * 4
    count = len(phase)
    figure = plots.dem_figure(np.linspace(100.0, 80.0, count), np.linspace(0.0, 50.0, count), phase,
                              np.arange(count, dtype=float), np.ones(count), np.linspace(0.0, 5.0, count))
    assert [len(axes.lines) for axes in figure.axes] == [3, 2]
    energies = {name: np.linspace(0.0, 1.0, count) for name in plots.ENERGY_COLUMNS}
    figure = plots.dem_figure(np.linspace(100.0, 80.0, count), np.linspace(0.0, 50.0, count), phase,
                              np.arange(count, dtype=float), np.ones(count), np.linspace(0.0, 5.0, count),
                              title="with the energy balance", energies=energies)
    assert [len(axes.lines) for axes in figure.axes] == [3, 7]  # kinetic, plastic, the balance's five
    assert plots.pressure_figure(contact, path).axes[2].get_aspect() == 1.0
    plt.close("all")
