"""CI smoke run: coarse elastic sphere pair through the whole pipeline, against Hertz.

Runs in about 10 s on one core.  Skips (with a SKIP line) only if gmsh or ccx is missing.
"""
import math
import subprocess

from ellc_fea.curve import read_csv

E, NU, R = 142000.0, 0.25, 10.0
TOLERANCE = 0.05  # coarse mesh: measured +1.5 %; medium +0.4 %


def hertz_spheres(delta):
    e_star = E / (2.0 * (1.0 - NU**2))
    return 4.0 / 3.0 * e_star * math.sqrt(R / 2.0) * delta**1.5


def test_coarse_sphere_pair_matches_hertz(needs_fe_tools, tmp_path, repo):
    proc = subprocess.run([f"{repo}/fea/run_case", f"{repo}/fea/cases/elastic/e_sphere.toml",
                           "--mesh", "coarse", "--elastic", "--out", str(tmp_path)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    data = read_csv(str(tmp_path / "e_sphere.csv"))
    assert len(data["overlap"]) == 4
    assert data["overlap"][-1] == __import__("pytest").approx(0.4, rel=1e-6)
    for d, f in zip(data["overlap"], data["force"]):
        assert abs(f / hertz_spheres(d) - 1.0) < TOLERANCE, (d, f, hertz_spheres(d))
