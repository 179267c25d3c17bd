"""Turn parsed increments into overlap/force rows and write them as CSV.

Columns (documented in fea/README.md):
  overlap         approach of the two driven planes (body centres), um
  force           normal contact force on the full bodies (octant reaction x 4), uN
  segment         protocol segment index, 1 = from waypoint 0 to waypoint 1
  step_time       CalculiX step time of the increment, 0..1 within the segment
  contact_semi_y  contact semi-axis along y from the deformed gap on the z = 0 line, um
  contact_semi_z  contact semi-axis along z from the deformed gap on the y = 0 line, um
  peak_pressure   largest contact pressure at any active slave integration point, MPa; spiky
                  (penalty surface-to-surface contact): an upper bound, not the smooth p0
"""
from __future__ import annotations

import math

import numpy as np

from .datfile import Increment

COLUMNS = ("overlap", "force", "segment", "step_time", "contact_semi_y", "contact_semi_z",
           "peak_pressure")
OCTANT_FACTOR = 4.0  # an octant model carries a quarter of the contact force


def _deformed(u: np.ndarray, nodes: np.ndarray, axis: int) -> tuple[np.ndarray, np.ndarray]:
    """(coordinate along `axis`, x) of the deformed line, sorted along `axis`."""
    ids = u[:, 0].astype(np.int64)
    pos = nodes[ids - 1] + u[:, 1:4]
    order = np.argsort(pos[:, axis])
    return pos[order, axis], pos[order, 0]


def contact_semi_axis(inc: Increment, nodes: np.ndarray, axis: int) -> float:
    """Where the deformed gap x_J - x_I along a symmetry line turns positive (0 if open).

    Resolution is about one surface node spacing near the contact; coarse meshes underestimate.
    """
    tag = "Y" if axis == 1 else "Z"
    if f"L{tag}I" not in inc.u or f"L{tag}J" not in inc.u:
        return float("nan")
    s_i, x_i = _deformed(inc.u[f"L{tag}I"], nodes, axis)
    s_j, x_j = _deformed(inc.u[f"L{tag}J"], nodes, axis)
    gap = x_j - np.interp(s_j, s_i, x_i)
    # the penalty contact lets closed points penetrate by p/slope; a node whose gap is no
    # larger than the deepest penetration counts as closed
    gap = gap - max(0.0, -float(gap.min()))
    closed = np.nonzero(gap <= 0.0)[0]
    if len(closed) == 0:
        return 0.0
    k = closed[-1]
    if k + 1 >= len(gap):
        return float(s_j[k])
    g0, g1 = gap[k], gap[k + 1]
    return float(s_j[k] + (s_j[k + 1] - s_j[k]) * (-g0) / (g1 - g0))


def rows(incs: list[Increment], nodes: np.ndarray) -> list[tuple]:
    """One row per converged increment.  The .dat time is the total time: protocol segment k
    (one *STEP of period 1) covers (k-1, k]."""
    out = []
    for inc in incs:
        overlap = inc.u["PILOTI"][0, 1] - inc.u["PILOTJ"][0, 1]
        if out and abs(inc.time - out[-1][3] - (out[-1][2] - 1)) < 1e-9:
            out.pop()  # CalculiX prints a step's last increment twice: keep the later copy
        segment = max(1, math.ceil(inc.time - 1e-6))
        force = OCTANT_FACTOR * inc.rf["XI"][0]
        peak = float(inc.pressure.max()) if len(inc.pressure) else 0.0
        out.append((overlap, force, segment, inc.time - (segment - 1), contact_semi_axis(inc, nodes, 1),
                    contact_semi_axis(inc, nodes, 2), peak))
    return out


def write_csv(path: str, table: list[tuple]) -> None:
    with open(path, "w") as fh:
        fh.write(",".join(COLUMNS) + "\n")
        for r in table:
            fh.write(f"{r[0]:.8g},{r[1]:.8g},{r[2]:d},{r[3]:.6g},{r[4]:.6g},{r[5]:.6g},{r[6]:.6g}\n")


def read_csv(path: str) -> dict[str, np.ndarray]:
    data = np.genfromtxt(path, delimiter=",", names=True)
    return {name: np.atleast_1d(data[name]) for name in data.dtype.names}
