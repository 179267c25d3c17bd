"""TEST ORACLE ONLY -- the Becker-Kamlah law re-stated from docs/model.md, for the FE write-up.

The production implementation is the C++ library; this copy exists so the FE data can be
checked before `ellc curve` is available, and to cross-check the library.  Aligned bodies only
(twist 0), semi-axis a along the compression axis x.  Units: um, MPa, uN.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .elliptic import ellipke

PAPER = {"m": 1.05, "o": -4.62, "p": 2.42, "s": 8.19, "t": -6.14, "u": 1.14, "n": 1.8}


def curvature_sums(semi_i, semi_j) -> tuple[float, float]:
    """A, B (eq. 5, B >= A) for two aligned ellipsoids touching at their x tips."""
    (ai, bi, ci), (aj, bj, cj) = semi_i, semi_j
    k_y = ai / bi**2 + aj / bj**2
    k_z = ai / ci**2 + aj / cj**2
    return 0.5 * min(k_y, k_z), 0.5 * max(k_y, k_z)


def hale_factors(a_sum: float, b_sum: float) -> tuple[float, float]:
    r = b_sum / a_sum
    return 1.0 - (r**0.0602 - 1.0) ** 1.456, 1.0 - (r**0.0684 - 1.0) ** 1.531


def _ratio_for_k(k: float) -> float:
    """B/A of the exact solution for contact-ellipse axis ratio k = b_c/a_c."""
    m = 1.0 - k * k
    kk, ee = ellipke(m)
    return (ee / (k * k) - kk) / (kk - ee)


def exact_shape(a_sum: float, b_sum: float) -> tuple[float, float, float]:
    """(f1, f2, k) of the exact elliptic-integral Hertz solution (docs/model.md §1)."""
    target = b_sum / a_sum
    if target <= 1.0 + 1e-12:
        return 1.0, 1.0, 1.0
    lo, hi = 1e-6, 1.0 - 1e-9  # _ratio_for_k falls from large to 1 as k goes 0 -> 1
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _ratio_for_k(mid) > target else (lo, mid)
    k = 0.5 * (lo + hi)
    m = 1.0 - k * k
    kk, ee = ellipke(m)
    r_e = 1.0 / (2.0 * math.sqrt(a_sum * b_sum))
    # per unit overlap and E*: a_c^2 = (K - E)/(A m K), F = 2/3 pi A m a_c^3 / (K - E)
    ac2 = (kk - ee) / (a_sum * m * kk)
    force = 2.0 / 3.0 * math.pi * a_sum * m * ac2**1.5 / (kk - ee)
    f2 = (force / (4.0 / 3.0 * math.sqrt(r_e))) ** (-2.0 / 3.0)
    f1 = math.sqrt(k * ac2 * f2 / r_e)
    return f1, f2, k


@dataclass(frozen=True)
class Contact:
    e_star: float
    yield_stress: float
    r_e: float
    r_hat: float
    f1: float
    f2: float
    lam_max: float
    eps_max: float
    n: float

    @property
    def p_y(self) -> float:
        return 1.6 * self.yield_stress

    @property
    def c_y(self) -> float:
        return self.p_y * math.pi * self.r_e * self.f1**3 / (2.0 * self.e_star)

    @property
    def delta_y(self) -> float:
        return self.c_y**2 * self.f2 / (self.r_e * self.f1**2)

    @property
    def f_py(self) -> float:
        return 2.0 / 3.0 * math.pi * self.c_y**2 * self.p_y

    def c2(self, delta):
        """Equivalent contact radius squared from the overlap, eq. (9)."""
        return self.r_e * np.asarray(delta, float) * self.f1**2 / self.f2

    def hertz(self, delta, r_e=None):
        r = self.r_e if r_e is None else r_e
        d = np.maximum(np.asarray(delta, float), 0.0)
        return 4.0 / 3.0 * self.e_star * np.sqrt(r) * d**1.5 * self.f2**-1.5

    def lam(self, delta):
        """lambda(c_c) of eq. (28), held at lam_max beyond c_max."""
        c = np.sqrt(self.c2(delta))
        frac = np.clip((self.eps_max * self.c_y - c) / ((self.eps_max - 1.0) * self.c_y), 0.0, 1.0)
        return self.lam_max - (self.lam_max - 1.6) * frac**self.n

    def loading(self, delta):
        d = np.asarray(delta, float)
        plastic = math.pi * self.lam(d) * self.yield_stress * (self.c2(d) - self.c_y**2) + self.f_py
        return np.where(d <= self.delta_y, self.hertz(d), plastic)

    def unloading(self, delta, delta_star: float):
        """Eq. (49) below the largest overlap reached, delta_star (> delta_Y)."""
        f_pmax = float(self.loading(delta_star))
        f_spy = math.pi * self.p_y * (float(self.c2(delta_star)) - self.c_y**2) + self.f_py
        r_ep = float(self.hertz(delta_star)) * self.r_e / f_spy
        delta_p = delta_star * (1.0 - self.r_e / r_ep)
        beta = f_pmax / f_spy
        d = np.asarray(delta, float)
        return self.hertz(d - delta_p, r_e=beta**2 * r_ep)

    def force_history(self, deltas) -> np.ndarray:
        """Forces along an overlap path; delta_* is kept through delta <= 0 (one contact spot
        whose dent persists, as in the FE load-unload-reload runs)."""
        out, star = [], 0.0
        for d in np.asarray(deltas, float):
            if d <= 0.0:
                out.append(0.0)
                continue
            if d >= star:
                star = d
                out.append(float(self.loading(d)))
            elif star <= self.delta_y:
                out.append(float(self.hertz(d)))
            else:
                out.append(float(self.unloading(d, star)))
        return np.asarray(out)


def make_contact(semi_i, semi_j, youngs: float, poisson: float, yield_stress: float,
                 exact: bool = False, constants: dict | None = None) -> Contact:
    k = dict(PAPER, **(constants or {}))
    a_sum, b_sum = curvature_sums(semi_i, semi_j)
    f1, f2 = exact_shape(a_sum, b_sum)[:2] if exact else hale_factors(a_sum, b_sum)
    r_e = 1.0 / (2.0 * math.sqrt(a_sum * b_sum))
    r_hat = sum((s[0] * s[1] * s[2]) ** (1.0 / 3.0) for s in (semi_i, semi_j))
    x = r_e / r_hat
    return Contact(e_star=youngs / (2.0 * (1.0 - poisson**2)), yield_stress=yield_stress, r_e=r_e,
                   r_hat=r_hat, f1=f1, f2=f2, lam_max=k["m"] * math.exp(k["o"] * x) + k["p"],
                   eps_max=k["s"] * math.exp(k["t"] * x) + k["u"], n=k["n"])
