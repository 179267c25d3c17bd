"""Contact surfaces: the outer tet faces of one body near its tip, as (element, face) pairs."""
from __future__ import annotations

import numpy as np

# C3D10 faces by corner-node index: S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1.
FACE_CORNERS = ((0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0))


def contact_faces(tets: np.ndarray, first_elem: int, nodes: np.ndarray, reach: float,
                  plane_tol: float) -> list[tuple[int, int]]:
    """Faces on the curved surface of a body whose corners all lie within `reach` (in x) of the tip.

    tets: (n, 10) node ids; element k has id first_elem + k.  Boundary faces are those that
    belong to one element only; faces on the symmetry/driven planes (all corners on y = 0,
    z = 0 or a plane x = const) are dropped.  Returns (element id, face number 1..4).
    """
    count: dict[tuple[int, ...], tuple[int, int]] = {}
    seen_twice: set[tuple[int, ...]] = set()
    for k, tet in enumerate(tets):
        for f, corners in enumerate(FACE_CORNERS):
            key = tuple(sorted(int(tet[c]) for c in corners))
            if key in count:
                seen_twice.add(key)
            else:
                count[key] = (first_elem + k, f + 1)
    tip_x = _tip_x(tets, nodes)
    out = []
    for key, ef in count.items():
        if key in seen_twice:
            continue
        xyz = nodes[np.asarray(key) - 1]
        if _on_a_plane(xyz, plane_tol):
            continue
        if np.all(np.abs(xyz[:, 0] - tip_x) <= reach):
            out.append(ef)
    return sorted(out)


def surface_line(nodes: np.ndarray, ids: np.ndarray, centre_x: float, semi: tuple[float, float, float],
                 along: int, reach: float) -> np.ndarray:
    """Node ids on the ellipsoid surface in the symmetry plane of `along` (1: y-line with z = 0,
    2: z-line with y = 0) within `reach` in x of the tip, sorted by distance from the tip."""
    xyz = nodes[ids - 1]
    a, b, c = semi
    rho = ((xyz[:, 0] - centre_x) / a) ** 2 + (xyz[:, 1] / b) ** 2 + (xyz[:, 2] / c) ** 2
    other = 3 - along
    tol = 1e-7 * max(semi)
    keep = (np.abs(rho - 1.0) < 1e-6) & (np.abs(xyz[:, other]) < tol) \
        & (np.abs(np.abs(xyz[:, 0] - centre_x) - a) <= reach)
    sel = ids[keep]
    return sel[np.argsort(nodes[sel - 1, along])]


def _tip_x(tets: np.ndarray, nodes: np.ndarray) -> float:
    """x of the body's tip: the node nearest the origin."""
    ids = np.unique(tets[:, :4])
    xyz = nodes[ids - 1]
    return float(xyz[np.argmin(np.einsum("ij,ij->i", xyz, xyz)), 0])


def _on_a_plane(xyz: np.ndarray, tol: float) -> bool:
    if np.all(np.abs(xyz[:, 1]) < tol) or np.all(np.abs(xyz[:, 2]) < tol):
        return True
    return bool(np.ptp(xyz[:, 0]) < tol)
