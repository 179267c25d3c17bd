"""Complete elliptic integrals K(m), E(m) (parameter m = k^2) by the AGM; numpy only."""
from __future__ import annotations

import math


def ellipke(m: float) -> tuple[float, float]:
    if not 0.0 <= m < 1.0:
        raise ValueError("parameter m must be in [0, 1)")
    a, b = 1.0, math.sqrt(1.0 - m)
    c2_sum, power = 0.5 * m, 0.5  # sum of 2^(n-1) c_n^2, starting with n = 0: c_0^2 = m
    while abs(a - b) > 1e-15 * a:
        c = 0.5 * (a - b)
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        power *= 2.0
        c2_sum += power * c * c
    k_int = math.pi / (2.0 * a)
    return k_int, k_int * (1.0 - c2_sum)
