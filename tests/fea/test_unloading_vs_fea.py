"""The law's unloading/reloading (eq. 34, 44-49) against the committed FE protocol runs, held
separately from its loading (docs/validation.md, Sec. 2 "Loading versus unloading").

The whole-protocol mean in test_law_vs_fea.py is dominated by the loading points; here each
part of the paper cases' protocols has its own bound, so a regression in either shows:

  virgin loading   points with delta >= delta_* before the step (the envelope, eq. 10/25/31)
  below delta_*    unloading and reloading points (eq. 49)
  delta_p          the law's residual overlap (eq. 34, `ellc curve` column plastic_overlap)
                   against the FE's, estimated by extrapolating F^(2/3) linearly through the
                   last two unloading increments with a positive force (Hertz-like unloading)

Errors: "rel" = |F_law - F_FE| / F_FE over points with F_FE > 10 % of the peak; "of peak" =
|F_law - F_FE| / max F_FE over all points of the part.  The bounds are the measured values
(docs/validation.md) with some headroom.  They describe the law as the paper defines it (the
unloading error is a property of eq. 34/44, not of the implementation or the FE mesh), so a
change that lowers them is welcome and should tighten them.
"""
import os
import subprocess
import tempfile

import numpy as np
import pytest

from validation.curves import REPO, law_forces
from validation.data import load_run

#            measured (Hale): loading mean rel | below delta_*: mean rel, max of peak | |delta_p error|/delta_*
BOUNDS = {
    "paper_case1": dict(loading_mean_rel=0.010, unloading_mean_rel=0.13, unloading_max_of_peak=0.065,
                        delta_p=0.065),  # 0.48 % | 10.6 %, 5.2 % | 0.052, 0.030
    "paper_case2": dict(loading_mean_rel=0.015, unloading_mean_rel=0.045, unloading_max_of_peak=0.055,
                        delta_p=0.055),  # 1.04 % | 3.5 %, 4.6 % | 0.017, 0.045
}
FLOOR = 0.1  # of the peak FE force, for relative errors


def _run(name):
    run = load_run(name)
    if run is None:
        pytest.skip(f"no complete {name} run in data/fea")
    return run


def _virgin(overlap):
    """True where the step loads along the envelope (delta >= the largest earlier delta)."""
    earlier_max = np.maximum.accumulate(np.concatenate([[0.0], overlap]))[:-1]
    return overlap >= earlier_max - 1e-12


def _unloading_segments(run):
    """(delta_*, overlaps, forces) of every FE segment that unloads from a new maximum."""
    segment = np.asarray(run.table["segment"], int)
    out = []
    for s in np.unique(segment):
        d, f = run.overlap[segment == s], run.force[segment == s]
        before = run.overlap[segment < s]
        if len(before) and d[-1] < d[0] and before.max() >= run.overlap.max() * 0.1:
            out.append((float(before.max()), d, f))
    return out


def fe_residual_overlap(d, f, peak):
    """FE delta_p: F^(2/3) extrapolated linearly to zero through the last two positive points."""
    positive = f > 1e-3 * peak
    assert positive.sum() >= 2 and not positive[-1], "unloading must end separated"
    (d1, d2), (g1, g2) = d[positive][-2:], f[positive][-2:] ** (2.0 / 3.0)
    return d2 - g2 * (d1 - d2) / (g1 - g2)


def law_residual_overlaps(binary, run):
    """{delta_*: delta_p} from `ellc curve` on the case file the FE run used."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "law.csv")
        subprocess.run([binary, "curve", os.path.join(REPO, run.case_file), "-o", out, "--hertz", "hale"],
                       check=True, capture_output=True, text=True)
        data = np.genfromtxt(out, delimiter=",", names=True, dtype=None, encoding="utf-8")
    pairs = {}
    for max_overlap, plastic in zip(data["max_overlap"], data["plastic_overlap"]):
        if plastic > 0.0:
            pairs[float(max_overlap)] = float(plastic)
    return pairs


def _errors(law, fe, peak):
    sel = fe > FLOOR * peak
    return np.abs(law[sel] - fe[sel]) / fe[sel], np.abs(law - fe) / peak


@pytest.mark.parametrize("name", sorted(BOUNDS))
def test_loading_and_unloading_each_within_their_bound(cli, name):
    run, bound = _run(name), BOUNDS[name]
    law, source = law_forces(run.case, run.overlap, "hale")
    assert source == "ellc curve"
    peak = float(run.force.max())
    virgin = _virgin(run.overlap)
    rel_load, _ = _errors(law[virgin], run.force[virgin], peak)
    rel_unload, of_peak_unload = _errors(law[~virgin], run.force[~virgin], peak)
    print(f"{name}: loading mean rel {rel_load.mean():.4f}; below delta_* mean rel {rel_unload.mean():.4f}, "
          f"max rel {rel_unload.max():.4f}, max of peak {of_peak_unload.max():.4f}")
    assert rel_load.mean() < bound["loading_mean_rel"]
    assert rel_unload.mean() < bound["unloading_mean_rel"]
    assert of_peak_unload.max() < bound["unloading_max_of_peak"]


@pytest.mark.parametrize("name", sorted(BOUNDS))
def test_residual_overlap_against_fe(cli, name):
    run, bound = _run(name), BOUNDS[name]
    law_dp = law_residual_overlaps(cli, run)
    peak = float(run.force.max())
    segments = _unloading_segments(run)
    assert len(segments) == 2  # the paper's protocol: two unloadings
    for max_overlap, d, f in segments:
        key = min(law_dp, key=lambda k: abs(k - max_overlap))
        assert abs(key - max_overlap) < 1e-9 * max_overlap
        fe_dp = fe_residual_overlap(d, f, peak)
        print(f"{name}: delta_* {max_overlap:.4f}  delta_p law {law_dp[key]:.4f}  FE {fe_dp:.4f}")
        assert 0.0 < fe_dp < max_overlap
        assert abs(law_dp[key] - fe_dp) < bound["delta_p"] * max_overlap
