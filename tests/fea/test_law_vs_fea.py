"""The law (C++ `ellc curve`) against the committed FE curves in data/fea.

The CLI is taken from ELLC_BIN, else from build*/apps/ellc/ellc; without it the test skips
with a SKIP line.  Tolerances (relative force error, points with F > 2 % of the peak):
  grid cases, loading only     mean < LOADING_MEAN, max < LOADING_MAX
  paper cases, whole protocol  mean < PROTOCOL_MEAN
They are set from the measured errors (docs/validation.md) with some headroom; the paper's
own errors against its ABAQUS runs were 1.01 % and 0.59 % (mean).

Cases whose FE force departs from Hertz already below delta_Y by more than 5 % (flat bodies
whose contact is not small against their thickness, see docs/validation.md) are outside what
the law can represent; they are held to a looser, stated bound so that regressions still show.
"""
import pytest

from validation.calibration_report import HERTZ_CONSISTENT, grid_runs, pre_yield_deviation
from validation.curves import law_forces
from validation.data import complete_runs
from validation.errors import force_errors
from validation.fit import loading_points

LOADING_MEAN, LOADING_MAX = 0.05, 0.12
PROTOCOL_MEAN = 0.08
OUTSIDE_MEAN, OUTSIDE_MAX = 0.25, 0.40  # cases with HERTZ_CONSISTENT violated below delta_Y


GRID = [r.name for r in grid_runs()]
PAPER = [r.name for r in complete_runs("paper_case")]


@pytest.mark.parametrize("name", GRID)
def test_loading_curve_within_tolerance(cli, name):
    run = next(r for r in grid_runs() if r.name == name)
    d, f = loading_points(run.overlap, run.force)
    law, source = law_forces(run.case, d, "hale")
    assert source == "ellc curve"
    err = force_errors(law, f)
    deviation = pre_yield_deviation(run, run.contact())
    if abs(deviation) < HERTZ_CONSISTENT:
        assert err["mean_rel"] < LOADING_MEAN and err["max_rel"] < LOADING_MAX, err
    else:
        assert err["mean_rel"] < OUTSIDE_MEAN and err["max_rel"] < OUTSIDE_MAX, (deviation, err)


@pytest.mark.parametrize("name", PAPER)
def test_paper_protocol_within_tolerance(cli, name):
    run = next(r for r in complete_runs(name) if r.name == name)
    law, source = law_forces(run.case, run.overlap, "hale")
    assert source == "ellc curve"
    err = force_errors(law, run.force)
    assert err["mean_rel"] < PROTOCOL_MEAN, err
