"""The calibration grid (like the paper's Tab. 2) and the case-file writer for it.

Aspect ratios 1:[0.5..2]:[0.5..2], mean radii 1..10 um, loading only to 15 % of r^{I,J}.
Waypoints are denser early, so the elastic-plastic transition (delta_Y is 0.5-4 % of r^{I,J})
gets enough increments.  The contact problem has no material length, so only the radius ratio
r^I/r^J and the aspect ratios matter; the absolute radii are spread over 1..10 um anyway.
For unequal radii the largest overlap is cut to 15 % of 2 min(r^I, r^J), so the smaller body
is not crushed (15 % of r^{I,J} would be 37 % of a 2.5 um sphere against a 10 um one).
"""
from __future__ import annotations

import os

# name: (aspect I, r^I, aspect J, r^J)
GRID = {
    "g01_sphere": ((1, 1, 1), 10.0, (1, 1, 1), 10.0),
    "g02_prolate": ((1, 0.5, 0.5), 5.0, (1, 0.5, 0.5), 5.0),
    "g03_oblate": ((1, 2, 2), 5.0, (1, 2, 2), 5.0),
    "g04_sphere_2_10": ((1, 1, 1), 2.5, (1, 1, 1), 10.0),
    "g05_paper_fig10": ((1, 0.66, 0.66), 10.0, (1, 0.66, 0.66), 10.0),
    "g06_oblate15": ((1, 1.5, 1.5), 3.0, (1, 1.5, 1.5), 3.0),
    "g07_crossed": ((1, 0.5, 2), 4.0, (1, 2, 0.5), 4.0),
    "g08_elongated": ((1, 0.5, 2), 4.0, (1, 0.5, 2), 4.0),
    "g09_mixed_2_8": ((1, 1, 2), 2.0, (1, 1, 1), 8.0),
    "g10_mixed_6_3": ((1, 2, 1), 6.0, (1, 0.5, 1), 3.0),
    "g11_mixed_7_2": ((1, 1.25, 0.8), 7.0, (1, 0.8, 1.25), 2.0),
    "g12_oblate_prolate": ((1, 2, 2), 8.0, (1, 0.5, 0.5), 3.0),
    "g13_small": ((1, 1.5, 0.75), 1.0, (1, 1.5, 0.75), 1.0),
    "g14_mixed_2_5": ((1, 0.75, 1.5), 2.0, (1, 1, 1), 5.0),
    "g15_prolate_sphere": ((1, 0.66, 0.66), 8.0, (1, 1, 1), 8.0),
    "g16_flat_pair": ((1, 2, 1.25), 6.0, (1, 1.25, 2), 6.0),
    "g17_prolate_sphere_4": ((1, 0.5, 0.5), 4.0, (1, 1, 1), 4.0),
    "g18_elongated_aligned": ((1, 2, 0.5), 5.0, (1, 2, 0.5), 5.0),
    "g19_prolate075": ((1, 0.75, 0.75), 1.5, (1, 0.75, 0.75), 1.5),
    "g20_oblate125": ((1, 1.25, 1.25), 9.0, (1, 1.25, 1.25), 9.0),
    "g21_oblate_sphere": ((1, 2, 2), 6.0, (1, 1, 1), 6.0),
    "g22_crossed_moderate": ((1, 0.5, 1), 3.0, (1, 1, 0.5), 3.0),
    "g23_mixed_8_4": ((1, 1.5, 1), 8.0, (1, 0.66, 1), 4.0),
    "g24_prolate_oblate": ((1, 0.5, 0.5), 7.0, (1, 2, 2), 7.0),
    "g25_mixed_small": ((1, 1, 1.5), 2.0, (1, 1.5, 1), 2.0),
}
WAYPOINTS_RELATIVE = (0.0, 0.02, 0.05, 0.09, 0.15)
POINTS_PER_SEGMENT = 4

# material -> (E MPa, nu, Y MPa, waypoints relative to r^{I,J}).  delta_Y / r^{I,J} scales as
# (Y/E*)^2: NMC's transition (delta_Y ~ 1e-2 r) is resolved by the first segment of the NMC grid,
# aluminium's (delta_Y ~ 1e-4 r, delta_max ~ 8 delta_Y) needs segments two decades earlier; it is
# loaded to 4 % of r^{I,J} (c_c/r^ ~ 0.08 for spheres, deep in the fully plastic regime), since
# the last segment of a deeper protocol cost CalculiX most of an hour per case.  It is then unloaded
# to 3.7 % and 3.4 %: the law puts aluminium's residual overlap delta_p at ~0.93 delta_max, so
# these two segments hold the whole unloading branch (for the unloading error and delta_p of the
# held-out cases).  g01_sphere was run before the unloading was added and keeps its loading-only
# case file (ALUMINIUM_LOADING_ONLY).
# Sources of the material data: docs/materials.md.
MATERIALS = {
    "nmc": (142000.0, 0.25, 7900.0, WAYPOINTS_RELATIVE),
    "aluminium": (68900.0, 0.33, 276.0, (0.0, 0.0002, 0.001, 0.005, 0.02, 0.04, 0.037, 0.034)),
}
ALUMINIUM_LOADING_ONLY = ("g01_sphere",)
# Geometries run for aluminium (a reduced grid: hours of CalculiX on one core), in the order
# fea/queue_aluminium.sh runs them: first those that widen the fit's R_e/r^ range (g05) and the
# sphere-like held-out pair (g04), then the rest; the flat 1:2:2 pairs the law cannot follow
# (g03, docs/validation.md) and the slender g02 (the two that stalled) last.
# g22 and g23 were added as held-out cases when g04 and g07 had stalled (2026-12-03), g20 when g22 had
# stalled too (a blunt pair, like the cases that have finished). g18_elongated_aligned
# is not run: it is g08 turned 90 degrees about the contact axis and scaled by 5/4, the same problem in
# delta/delta_Y and F/F_pY, since the contact has no material length.
ALUMINIUM_GRID = ("g01_sphere", "g05_paper_fig10", "g04_sphere_2_10", "g15_prolate_sphere",
                  "g07_crossed", "g10_mixed_6_3", "g16_flat_pair", "g21_oblate_sphere",
                  "g22_crossed_moderate", "g23_mixed_8_4", "g20_oblate125", "g08_elongated", "g24_prolate_oblate",
                  "g12_oblate_prolate", "g02_prolate", "g03_oblate")


def material_table(material: str) -> str:
    e, nu, y, _ = MATERIALS[material]
    return f"[material]\nyoungs_modulus = {e!r}\npoisson_ratio = {nu!r}\nyield_stress = {y!r}\n"


MATERIAL_NMC = material_table("nmc")


def _fmt(v: float) -> str:
    return repr(float(v))


def case_text(name: str, material: str = "nmc") -> str:
    asp_i, r_i, asp_j, r_j = GRID[name]
    cut = min(1.0, 2.0 * min(r_i, r_j) / (r_i + r_j))
    # Six decimals as the committed NMC cases were written; finer waypoints keep their digits.
    relative = MATERIALS[material][3]
    if material == "aluminium" and name in ALUMINIUM_LOADING_ONLY:
        relative = relative[:relative.index(max(relative)) + 1]
    waypoints = [round(w * cut, 6 if w == 0 or w >= 0.01 else 9) for w in relative]
    return (f"# FE calibration grid case {name} (generated by fea/ellc_fea/grid.py)\n"
            f"{material_table(material)}"
            f"[body_I]\naspect = [{', '.join(map(_fmt, asp_i))}]\nmean_radius = {_fmt(r_i)}\n"
            f"[body_J]\naspect = [{', '.join(map(_fmt, asp_j))}]\nmean_radius = {_fmt(r_j)}\n"
            f"[protocol]\nwaypoints_relative = [{', '.join(map(_fmt, waypoints))}]\n"
            f"points_per_segment = {POINTS_PER_SEGMENT}\n")


def write_grid(directory: str, material: str = "nmc", names=None) -> list[str]:
    os.makedirs(directory, exist_ok=True)
    paths = []
    for name in names or GRID:
        path = os.path.join(directory, f"{name}.toml")
        with open(path, "w") as fh:
            fh.write(case_text(name, material))
        paths.append(path)
    return paths
