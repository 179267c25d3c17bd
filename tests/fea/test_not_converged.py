"""A CalculiX run that stops early is reported with its last converged increment and never
written out as a complete curve.  Uses a stand-in for ccx that prints two increments, fails."""
import os
import stat

import pytest

from ellc_fea.case import parse_case
from ellc_fea.pipeline import run_case

FAKE_CCX = r"""#!/bin/sh
# stand-in for ccx: two converged increments of segment 1, then a convergence failure
[ "$1" = "-i" ] || { echo "This is Version 0.0 (stand-in)"; exit 0; }
job="$2"
for t in 0.25 0.5; do
  d=$(echo "$t" | awk '{print $1*0.05}')
  printf ' displacements (vx,vy,vz) for set PILOTI and time %s\n\n 1 %s 0 0\n\n' $t $d
  printf ' displacements (vx,vy,vz) for set PILOTJ and time %s\n\n 2 -%s 0 0\n\n' $t $d
  printf ' total force (fx,fy,fz) for set XI and time %s\n\n 100.0 0 0\n\n' $t
done > "$job.dat"
echo " *ERROR: too many cutbacks" > /dev/stdout
exit 201
"""


def test_failed_run_is_marked_incomplete(tmp_path):
    pytest.importorskip("gmsh")
    ccx = tmp_path / "fake_ccx"
    ccx.write_text(FAKE_CCX)
    ccx.chmod(ccx.stat().st_mode | stat.S_IEXEC)
    data = {"material": {"youngs_modulus": 142000.0, "poisson_ratio": 0.25, "yield_stress": 7900.0},
            "body_I": {"semi_axes": [10, 10, 10]}, "body_J": {"semi_axes": [10, 10, 10]},
            "protocol": {"waypoints": [0.0, 0.2, 0.0], "points_per_segment": 4}}
    out, work = str(tmp_path / "out"), str(tmp_path / "work")
    outcome = run_case(parse_case(data, "fails"), "coarse", out, work, str(ccx),
                       manifest=str(tmp_path / "manifest.json"))
    assert not outcome.complete
    assert "NOT CONVERGED" in outcome.message and "too many cutbacks" in outcome.message
    assert "segment 1/2, step time 0.5" in outcome.message
    assert not os.path.exists(os.path.join(out, "fails.csv"))
    assert outcome.csv_path.endswith("fails.incomplete.csv")
    with open(outcome.csv_path) as fh:
        assert len(fh.readlines()) == 3  # header + two increments
