"""The law's force at the FE overlaps: from `ellc curve` (ELLC_BIN) or, until that is built,
from the test oracle.  Every result says which one produced it."""
from __future__ import annotations

import os
import subprocess
import tempfile

import numpy as np

from ellc_fea.case import Case

from .law_oracle import make_contact

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def ellc_binary() -> str | None:
    """ELLC_BIN if set, else a built CLI in the repo's build directories."""
    env = os.environ.get("ELLC_BIN")
    if env:
        return env if os.access(env, os.X_OK) else None
    for build in ("build", "build-fea", "build-release"):
        for path in (os.path.join(REPO, build, "apps", "ellc"), os.path.join(REPO, build, "apps", "ellc", "ellc")):
            if os.path.isfile(path) and os.access(path, os.X_OK):
                return path
    return None


def _case_toml(case: Case, overlaps: np.ndarray) -> str:
    m = case.material
    body = lambda b: f"semi_axes = [{b.a!r}, {b.b!r}, {b.c!r}]\n"  # noqa: E731
    points = ", ".join(repr(float(v)) for v in np.concatenate([[0.0], overlaps]))
    return (f"[material]\nyoungs_modulus = {m.youngs_modulus!r}\npoisson_ratio = {m.poisson_ratio!r}\n"
            f"yield_stress = {m.yield_stress!r}\n[body_I]\n{body(case.body_i)}[body_J]\n{body(case.body_j)}"
            f"[protocol]\nwaypoints = [{points}]\npoints_per_segment = 1\n")


def _cli_forces(binary: str, case: Case, overlaps: np.ndarray, mode: str) -> np.ndarray:
    with tempfile.TemporaryDirectory() as tmp:
        toml, csv = os.path.join(tmp, "case.toml"), os.path.join(tmp, "law.csv")
        with open(toml, "w") as fh:
            fh.write(_case_toml(case, overlaps))
        subprocess.run([binary, "curve", toml, "-o", csv, "--hertz", mode], check=True,
                       capture_output=True, text=True)
        data = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding="utf-8")
    force = np.asarray(data["force"], float)
    if len(force) != len(overlaps) + 1:
        raise RuntimeError(f"ellc curve gave {len(force)} rows for {len(overlaps) + 1} waypoints")
    return force[1:]


def law_forces(case: Case, overlaps, mode: str = "hale", constants: dict | None = None,
               use_cli: bool = True) -> tuple[np.ndarray, str]:
    """(forces, source) for the overlap path; source is 'ellc curve' or 'python oracle'."""
    overlaps = np.asarray(overlaps, float)
    binary = ellc_binary() if use_cli and constants is None else None
    if binary:
        return _cli_forces(binary, case, overlaps, mode), "ellc curve"
    m = case.material
    semi = lambda b: (b.a, b.b, b.c)  # noqa: E731
    contact = make_contact(semi(case.body_i), semi(case.body_j), m.youngs_modulus, m.poisson_ratio,
                           m.yield_stress, exact=(mode == "exact"), constants=constants)
    return contact.force_history(overlaps), "python oracle"
