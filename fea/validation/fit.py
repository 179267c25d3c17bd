"""INTERIM fit of the transition constants from FE curves (until `ellc fit` exists).

Per case: lambda_FEM from eq. (51); lambda_max, eps_max (and n) of eq. (28) by least squares
on the relative force error of the loading points past delta_Y.  For fixed (eps_max, n) the
force is linear in lambda_max, so lambda_max is solved in closed form and (eps_max, n) are
found by a grid search refined twice.  Across cases: eq. (52), y = m exp(o x) + p, with m, p
linear for fixed o and o scanned.  Formulas come from the test oracle (law_oracle).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .law_oracle import Contact


def loading_points(overlap: np.ndarray, force: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The virgin-loading part of a history: points at or above the running maximum overlap."""
    keep = overlap >= np.maximum.accumulate(overlap) - 1e-12
    return overlap[keep], force[keep]


def lambda_fem(contact: Contact, overlap, force) -> np.ndarray:
    """Eq. (51) solved for lambda: (F - F_pY) / (pi Y (c_c^2 - c_Y^2)); NaN at or below delta_Y."""
    overlap, force = np.asarray(overlap, float), np.asarray(force, float)
    denom = math.pi * contact.yield_stress * (contact.c2(overlap) - contact.c_y**2)
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = (force - contact.f_py) / denom
    return np.where(overlap > contact.delta_y, lam, np.nan)


@dataclass(frozen=True)
class CaseFit:
    lam_max: float
    eps_max: float
    n: float
    rms: float          # relative force error of the fit (loading points past delta_Y)
    plateau: bool       # the data reach c_max = eps_max c_Y (eps_max is then measured, not extrapolated)


def _lam_max_for(contact: Contact, d: np.ndarray, f: np.ndarray, eps: float, n: float) -> tuple[float, float]:
    c = replace(contact, lam_max=1.0, eps_max=eps, n=n)
    base = math.pi * c.yield_stress * (c.c2(d) - c.c_y**2)
    g = (c.lam(d) - 1.0) / 0.6  # with lam_max = 1: lam = 1 + 0.6 g, and lam = lam_max (1 - g) + 1.6 g
    a = base * (1.0 - g) / f
    b = (base * 1.6 * g + c.f_py) / f - 1.0
    lam_max = max(1.6, float(-(a @ b) / (a @ a))) if a @ a > 0.0 else 1.6
    rms = float(np.sqrt(np.mean((a * lam_max + b) ** 2)))
    return lam_max, rms


def fit_case(contact: Contact, overlap, force, n_fixed: float | None = None) -> CaseFit:
    d, f = loading_points(np.asarray(overlap, float), np.asarray(force, float))
    keep = d > 1.05 * contact.delta_y
    d, f = d[keep], f[keep]
    if len(d) < 3:
        raise ValueError("fewer than 3 loading points past delta_Y")
    eps_grid = np.linspace(1.05, 15.0, 140)
    n_grid = np.array([n_fixed]) if n_fixed else np.linspace(0.8, 5.0, 43)
    best = None
    for _ in range(3):
        for eps in eps_grid:
            for n in n_grid:
                lam_max, rms = _lam_max_for(contact, d, f, eps, n)
                if best is None or rms < best[3]:
                    best = (lam_max, eps, n, rms)
        de = eps_grid[1] - eps_grid[0]
        eps_grid = np.linspace(max(1.01, best[1] - de), best[1] + de, 21)
        if not n_fixed:
            dn = n_grid[1] - n_grid[0]
            n_grid = np.linspace(max(0.3, best[2] - dn), best[2] + dn, 21)
    lam_max, eps, n, rms = best
    c_last = math.sqrt(float(contact.c2(d.max())))
    return CaseFit(lam_max, eps, n, rms, plateau=c_last >= eps * contact.c_y)


def fit_exponential(x, y, o_range=(-15.0, 0.0)) -> tuple[float, float, float, float]:
    """(m, o, p, rms) of y = m exp(o x) + p (eq. 52); o is scanned over o_range (a single
    value fixes the decay rate and leaves m, p as a linear least-squares problem)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    best = None
    lo, hi = o_range
    for o in np.linspace(lo, hi, 3001 if hi > lo else 1):
        basis = np.column_stack([np.exp(o * x), np.ones_like(x)])
        (m, p), *_ = np.linalg.lstsq(basis, y, rcond=None)
        rms = float(np.sqrt(np.mean((basis @ [m, p] - y) ** 2)))
        if best is None or rms < best[3]:
            best = (float(m), float(o), float(p), rms)
    return best
