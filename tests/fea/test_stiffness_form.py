"""The E/Y-dependent constants (form stiffness_ratio, issue 14) against both materials' FE data.

data/fea/aluminium/model_stiffness_ratio.toml is written by `ellc fit --form stiffness_ratio`
on the aluminium fit cases (docs/validation.md Sec. 6, command in data/fea/aluminium/README.md).
  * At NMC's E_e/Y it must stay within the NMC bounds of test_law_vs_fea.py (same tolerances).
  * On every committed aluminium run (fit and held-out) the loading error stays below
    AL_LOADING_MEAN / AL_LOADING_MAX, and below the paper's constants' error (what a user gains).
  * On the held-out runs that stopped early (their converged loading increments) the same, except
    where a known miss is marked xfail(strict): it fails once the miss is gone, so the docs get
    updated.
"""
import os
import tomllib

import numpy as np
import pytest

from test_law_vs_fea import LOADING_MAX, LOADING_MEAN, PROTOCOL_MEAN
from validation.aluminium_report import DATA, MESH, law_curve, partial_held_out_runs
from validation.calibration_report import HERTZ_CONSISTENT, grid_runs, pre_yield_deviation
from validation.data import complete_runs
from validation.errors import force_errors
from validation.fit import loading_points

MODEL = os.path.join(DATA, "model_stiffness_ratio.toml")
AL_LOADING_MEAN, AL_LOADING_MAX = 0.05, 0.12


def stiffness_model() -> dict:
    with open(MODEL, "rb") as fh:
        model = tomllib.load(fh)["model"]
    assert model["form"] == "stiffness_ratio"
    return {k: v for k, v in model.items() if k not in ("form", "hertz")}


NMC_GRID = [r.name for r in grid_runs() if abs(pre_yield_deviation(r, r.contact())) < HERTZ_CONSISTENT]
NMC_PAPER = [r.name for r in complete_runs("paper_case")]
ALUMINIUM = [r.name for r in complete_runs("g", DATA) if r.record["mesh_level"] == MESH]


@pytest.mark.parametrize("name", NMC_GRID)
def test_nmc_grid_within_the_nmc_bounds(cli, name):
    run = next(r for r in grid_runs() if r.name == name)
    d, f = loading_points(run.overlap, run.force)
    err = force_errors(law_curve(run, d, stiffness_model())["force"], f)
    assert err["mean_rel"] < LOADING_MEAN and err["max_rel"] < LOADING_MAX, err


@pytest.mark.parametrize("name", NMC_PAPER)
def test_nmc_paper_protocols_within_the_nmc_bounds(cli, name):
    run = next(r for r in complete_runs(name) if r.name == name)
    err = force_errors(law_curve(run, run.overlap, stiffness_model())["force"], run.force)
    assert err["mean_rel"] < PROTOCOL_MEAN, err


# g16 (two flat faces, R_e/r^ = 0.41): the anchored form (eq. 52 kept, only the E/Y exponents
# fitted) gives 5.2 % mean / 15.3 % max; the joint fit, which refits eq. 52 over both materials,
# gives 1.8 % / 7.2 % (docs/validation.md Sec. 6). Known miss: strict, so it fails once it is gone.
ALUMINIUM_MISSES = {"g16_flat_pair"}


def with_known_misses(names, misses) -> list:
    """The names as pytest parameters, those in `misses` marked xfail(strict=True)."""
    return [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason="known miss, documented"))
            if n in misses else n for n in names]


def loading_errors(run) -> tuple[dict, dict]:
    """Loading error of the committed model and of the paper's constants (no [model])."""
    d, f = loading_points(run.overlap, run.force)
    ours = force_errors(law_curve(run, d, stiffness_model())["force"], f)
    return ours, force_errors(law_curve(run, d, None)["force"], f)


@pytest.mark.parametrize("name", with_known_misses(ALUMINIUM, ALUMINIUM_MISSES))
def test_aluminium_loading_within_bounds_and_better_than_nmc_constants(cli, name):
    ours, paper = loading_errors(next(r for r in complete_runs(name, DATA) if r.name == name))
    assert ours["mean_rel"] < AL_LOADING_MEAN and ours["max_rel"] < AL_LOADING_MAX, ours
    assert ours["mean_rel"] < paper["mean_rel"], (ours, paper)


def test_model_is_the_paper_law_at_nmc(cli):
    """At NMC's E_e/Y the form is eq. (52) exactly: the same curve as without [model]."""
    run = next(r for r in grid_runs() if r.name == "g01_sphere")
    d = np.asarray(run.overlap, float)
    np.testing.assert_allclose(law_curve(run, d, stiffness_model())["force"], law_curve(run, d, None)["force"],
                               rtol=1e-12)


PARTIAL = {r.name: r for r in partial_held_out_runs()}
# g24 (stopped at 49 delta_Y): the anchored law is low through the transition, mean 10 % (docs/validation.md Sec. 6).
PARTIAL_MEAN_MISSES = {"g24_prolate_oblate"}


@pytest.mark.parametrize("name", sorted(PARTIAL))
def test_aluminium_partial_held_out_max_within_bounds_and_better_than_nmc_constants(cli, name):
    ours, paper = loading_errors(PARTIAL[name])
    assert ours["max_rel"] < AL_LOADING_MAX, ours
    assert ours["mean_rel"] < paper["mean_rel"], (ours, paper)


@pytest.mark.parametrize("name", with_known_misses(sorted(PARTIAL), PARTIAL_MEAN_MISSES))
def test_aluminium_partial_held_out_mean_within_bounds(cli, name):
    ours, _ = loading_errors(PARTIAL[name])
    assert ours["mean_rel"] < AL_LOADING_MEAN, ours
