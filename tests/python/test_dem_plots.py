"""The plots of `ellc dem` ensembles over packing seeds: from Python arrays and from members' CSVs."""

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ellc import plots  # noqa: E402


def synthetic_member(offset):
    """A load, hold and unload branch shaped like a calendering run, shifted by `offset` um."""
    load = np.linspace(40.0, 25.0, 60) + offset
    unload = np.linspace(25.0, 27.0, 30) + offset
    thickness = np.concatenate([load, [25.0 + offset] * 5, unload])
    pressure = np.concatenate([200.0 * np.exp(-(load - load[-1])), np.linspace(200.0, 180.0, 5),
                               180.0 * np.exp(-3.0 * (unload - unload[0]))])
    phase = ["load"] * load.size + ["hold"] * 5 + ["unload"] * unload.size
    return {"thickness": thickness, "plate_pressure": pressure, "phase": phase}


def test_ensemble_plot_from_arrays(tmp_path):
    members = [(f"seed_{seed}", synthetic_member(0.3 * k)) for k, seed in enumerate(range(2026, 2029))]
    figure, axes = plt.subplots()
    returned = plots.plot_pressure_thickness_ensemble(members, axes, title="three seeds")
    assert returned is axes
    assert len(axes.get_lines()) == 6  # load + hold solid, unload dashed, per member
    assert [text.get_text() for text in axes.get_legend().get_texts()] == ["seed_2026", "seed_2027", "seed_2028"]
    low, high = axes.get_xlim()
    assert 24.0 < low < 25.0 and high < 30.0  # zoomed on the calendering, not the loose deposit
    # Without phases every row is one line; many members share a note instead of a legend.
    bare = [(str(k), {"thickness": [30.0, 26.0, 25.0], "plate_pressure": [0.0, 50.0, 200.0]}) for k in range(12)]
    axes_many = plots.plot_pressure_thickness_ensemble(bare)
    assert len(axes_many.get_lines()) == 12 and axes_many.get_legend() is None
    figure.savefig(tmp_path / "ensemble.png")
    assert (tmp_path / "ensemble.png").stat().st_size > 10000
    plt.close("all")


def test_ensemble_plot_command_line(tmp_path):
    paths = []
    for k in range(2):
        member = synthetic_member(0.5 * k)
        folder = tmp_path / f"seed_{2026 + k}"
        folder.mkdir()
        path = folder / "timeseries.csv"
        with open(path, "w") as handle:
            handle.write("step,phase,thickness,plate_pressure\n")
            for row, (t, p, phase) in enumerate(zip(member["thickness"], member["plate_pressure"], member["phase"])):
                handle.write(f"{row},{phase},{t},{p}\n")
        paths.append(str(path))
    png = tmp_path / "pressure_thickness_ensemble.png"
    assert plots.main(["dem-ensemble", str(png), *paths, "--title", "quick"]) == 0
    assert png.stat().st_size > 10000
    assert plots.main(["dem-ensemble", str(png), *paths, "--labels", "a,b"]) == 0
    with pytest.raises(SystemExit):
        plots.main(["dem-ensemble", str(png), *paths, "--labels", "only_one"])
    # ellc dem --compare: one packing under several laws, the same curves labelled by law.
    compare = tmp_path / "pressure_thickness_compare.png"
    assert plots.main(["dem-compare", str(compare), *paths, "--labels", "becker_kamlah,hertz", "--title", "q"]) == 0
    assert compare.stat().st_size > 10000
    with pytest.raises(SystemExit):
        plots.main(["dem-compare", str(compare), *paths, "--labels", "hertz"])
