"""Shared fixtures: the CLI path, the source tree, and synthetic calibration data made by the law."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import ellc

SOURCE_DIR = pathlib.Path(os.environ.get("ELLC_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
NMC = dict(youngs_modulus=142000.0, poisson_ratio=0.25, yield_stress=7900.0)

# Known constants, deliberately different from the paper's eq. (53).
TRUE_FIT = dict(m=1.3, o=-3.5, p=2.2, s=6.5, t=-5.0, u=1.4, n=2.2)

# Aspect ratios of bodies I and J (r^ = 10 µm each), spanning R_e/r^ = 0.10 .. 0.63.
GEOMETRIES = {
    "sphere": ((1, 1, 1), (1, 1, 1)),
    "paper_case2": ((1, 1, 0.8), (1, 1.25, 1.25)),
    "fig10": ((1, 0.66, 0.66), (1, 0.66, 0.66)),
    "flat": ((1, 2, 2), (1, 2, 2)),
    "slim": ((1, 0.5, 0.5), (1, 0.5, 0.5)),
    "mixed": ((1, 1.5, 1.5), (1, 0.8, 0.8)),
}


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("ELLC_CLI", str(SOURCE_DIR / "build-py" / "apps" / "ellc"))
    if not os.path.exists(path):
        pytest.skip(f"ellc CLI not built at {path}")
    return path


def run_cli(cli, *arguments, check=True):
    completed = subprocess.run([cli, *map(str, arguments)], capture_output=True, text=True, timeout=60)
    if check and completed.returncode != 0:
        raise AssertionError(f"ellc {' '.join(map(str, arguments))} failed ({completed.returncode}):\n"
                             f"{completed.stderr}")
    return completed


def body(aspect, mean_radius=10.0):
    aspect = np.asarray(aspect, dtype=float)
    return ellc.Body(aspect * mean_radius / np.cbrt(aspect.prod()), ellc.Material(**NMC))


def case_toml(aspect_i, aspect_j, mean_radius=10.0):
    """A sidecar case file with the same bodies as body()."""
    return (f"[material]\nyoungs_modulus = {NMC['youngs_modulus']}\npoisson_ratio = {NMC['poisson_ratio']}\n"
            f"yield_stress = {NMC['yield_stress']}\n"
            f"[body_I]\naspect = {[float(v) for v in aspect_i]}\nmean_radius = {mean_radius}\n"
            f"[body_J]\naspect = {[float(v) for v in aspect_j]}\nmean_radius = {mean_radius}\n")


def synthetic_cases(noise=0.01, seed=0, points=40, reach=1.5, law=None, names=None):
    """Loading curves made by the law itself with known constants, times (1 + noise N(0, 1))."""
    law = law or ellc.LawParameters(ellc.TransitionFit(**TRUE_FIT))
    rng = np.random.default_rng(seed)
    cases = []
    for name in names or GEOMETRIES:
        aspect_i, aspect_j = GEOMETRIES[name]
        body_i, body_j = body(aspect_i), body(aspect_j)
        contact = ellc.Contact.between(body_i, body_j, law=law)
        overlaps = np.linspace(0.0, reach * contact.constants.plastic_limit_overlap, points + 1)[1:]
        forces = contact.loading_force(overlaps) * (1.0 + noise * rng.standard_normal(points))
        cases.append(ellc.CalibrationCase(name, body_i, body_j, overlaps, forces))
    return cases
