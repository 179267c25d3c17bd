"""Checks on the committed FE reference data (data/fea): no FE tools needed.

- every CSV in data/fea has a complete manifest record (command, mesh, CalculiX version);
- the elastic runs at medium and fine mesh are close to exact elliptical Hertz (test oracle in
  fea/validation/law_oracle.py) at overlaps past the first increment: spheres within 1.5 %,
  ellipsoid pairs within 5 % (the FE overlap is the approach of the body centres; slender
  bodies are softer and flat ones stiffer than Hertz's half-spaces, see docs/validation.md);
- the mesh-convergence evidence: the fine sphere run differs from medium by less than 1 %.
"""
import glob
import os

import numpy as np
import pytest

from ellc_fea.manifest import read_manifest
from validation.data import DATA, load_run

HERTZ_TOLERANCE = {"e_sphere": 0.015, "e_case2": 0.05, "e_case1": 0.05}


def test_every_csv_has_a_manifest_record():
    manifest = read_manifest(os.path.join(DATA, "manifest.json"))
    for path in glob.glob(os.path.join(DATA, "*.csv")):
        name = os.path.basename(path).removesuffix(".csv").removesuffix(".incomplete")
        record = manifest[name]
        assert record["command"].startswith("fea/run_case ")
        assert record["mesh_level"] in ("coarse", "medium", "fine")
        assert record["calculix"].startswith("CalculiX")
        assert (record["status"] == "complete") == (not path.endswith(".incomplete.csv"))


@pytest.mark.parametrize("pair", ["e_sphere", "e_case2", "e_case1"])
@pytest.mark.parametrize("level", ["medium", "fine"])
def test_elastic_runs_match_exact_hertz(pair, level):
    run = load_run(f"{pair}_elastic_{level}")
    if run is None:
        pytest.skip(f"no complete {pair}_elastic_{level} run in data/fea")
    contact = run.contact(exact=True)
    err = run.force[1:] / contact.hertz(run.overlap[1:]) - 1.0
    assert np.all(np.abs(err) < HERTZ_TOLERANCE[pair]), err


def test_sphere_mesh_convergence():
    medium, fine = load_run("e_sphere_elastic_medium"), load_run("e_sphere_elastic_fine")
    if medium is None or fine is None:
        pytest.skip("sphere elastic medium/fine runs not in data/fea")
    assert np.allclose(medium.overlap, fine.overlap)
    assert np.all(np.abs(medium.force / fine.force - 1.0) < 0.01)
