"""ellc.microstructure from Python: voxels against the analytic volume, tortuosity of exact cases,
bad rows refused by name, and `ellc analyse` with its PNGs (docs/microstructure.md)."""

import math
import subprocess

import numpy as np
import pytest

import ellc
from ellc import microstructure as ms

pytestmark = pytest.mark.skipif(not ms.HAVE_CORE, reason="needs the compiled module")


def one_sphere(radius=0.3, periodic=(True, True, True)):
    return ms.Packing([[0.5, 0.5, 0.5]], [[radius] * 3], [[1, 0, 0, 0]], [0, 0, 0], [1, 1, 1], periodic=periodic)


def test_voxels_of_a_sphere_approach_its_volume():
    solid, spacing = ms.voxelise(one_sphere(), spacing=1.0 / 60)
    assert solid.dtype == np.uint8 and solid.shape == (60, 60, 60)
    assert np.allclose(spacing, 1.0 / 60)
    assert abs(solid.mean() - 4.0 / 3.0 * math.pi * 0.3 ** 3) < 2e-3


def test_straight_channels_have_tortuosity_one():
    solid = np.zeros((6, 7, 20), dtype=np.uint8)  # [iz, iy, ix]: channels along x
    solid[::2, 1::3, :] = 1
    result = ms.tortuosity_of_grid(solid, [1.0, 1.0, 1.0], (False, True, True), axis=0)
    assert result["percolating"] and abs(result["tortuosity"] - 1.0) < 1e-6
    closed = solid.copy()
    closed[:, :, 10] = 1
    blocked = ms.tortuosity_of_grid(closed, [1.0, 1.0, 1.0], (False, True, True), axis=0)
    assert math.isinf(blocked["tortuosity"]) and "no pore path" in blocked["reason"]


def test_sphere_array_against_maxwell():
    result = ms.tortuosity(one_sphere(), axis=2, spacing=1.0 / 32)
    f = 1.0 - result["porosity"]
    assert abs(result["effective_diffusivity"] / (1 - 3 * f / (2 + f)) - 1) < 0.03


def test_bad_rows_are_refused_by_name():
    with pytest.raises(ellc.InputError, match="row 2 semi-axis b"):
        ms.Packing([[0, 0, 0], [1, 1, 1]], [[1, 1, 1], [1, float("nan"), 1]], [[1, 0, 0, 0]] * 2, [0, 0, 0],
                   [2, 2, 2])
    with pytest.raises(ellc.InputError, match="GiB"):
        ms.voxelise(one_sphere(), spacing=1e-4)
    with pytest.raises(ValueError, match="shape"):
        ms.Packing([[0, 0]], [[1, 1, 1]], [[1, 0, 0, 0]], [0, 0, 0], [1, 1, 1])


def test_analyse_writes_the_files_and_the_cli_draws_them(tmp_path, cli):
    rng = np.random.default_rng(1)
    centres = rng.uniform(0, 12, size=(10, 3))
    semi_axes = rng.uniform(1, 2, size=(10, 3))
    packing = ms.Packing(centres, semi_axes, np.tile([1.0, 0, 0, 0], (10, 1)), [0, 0, 0], [12, 12, 12])
    summary = ms.analyse(packing, str(tmp_path / "py"), spacing=0.4)
    assert summary["grid"] == [30, 30, 30]
    assert 0 < summary["porosity_voxels"] < 1
    ms.write_packing(str(tmp_path / "p.csv"), packing)
    subprocess.run([cli, "analyse", str(tmp_path / "p.csv"), "--spacing", "0.4", "-o", str(tmp_path / "cli")],
                   check=True)
    for name in ("profile.png", "pore_size_distribution.png", "solid.vti", "solid.npy"):
        assert (tmp_path / "cli" / name).exists(), name
    solid = np.load(tmp_path / "cli" / "solid.npy")
    assert solid.shape == (30, 30, 30)
    assert abs(solid.mean() - (1 - summary["porosity_voxels"])) < 1e-12
    from_file = ms.read_summary(tmp_path / "cli")  # analysis.txt, a TOML document
    assert from_file["tortuosity_z"] == summary["tortuosity_z"]
    # The resolution check: tau at 2h, and the first-order extrapolation of the two to h = 0, given
    # only where the coarse grid (0.8 um here) has 2.5 voxels per smallest semi-axis, else a note.
    smallest = float(np.min(semi_axes))
    for axis in "xyz":
        tau, coarse = summary[f"tortuosity_{axis}"], summary[f"tortuosity_{axis}_coarse"]
        assert abs(ms.extrapolated_tortuosity(tau, coarse) - (2 * tau - coarse)) < 1e-12
        if f"tortuosity_{axis}_extrapolated" in summary:
            assert summary[f"tortuosity_{axis}_extrapolated"] == ms.extrapolated_tortuosity(tau, coarse, 2.0)
        else:
            assert "voxels per smallest semi-axis" in summary[f"tortuosity_{axis}_extrapolated_note"]
            assert smallest / 0.8 < 2.5
    assert math.isnan(ms.extrapolated_tortuosity(math.inf, 2.0))
    assert 0 < summary["pore_radius_median_um_coarse"] < summary["pore_radius_largest_um_coarse"]
    assert from_file["grid"] == [30, 30, 30]
