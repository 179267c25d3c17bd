"""Mesh two ellipsoid octants (C3D10) that touch at the origin, graded toward the contact.

Body I is centred at (-a_I, 0, 0), body J at (+a_J, 0, 0); both keep y >= 0, z >= 0 and the
half toward the contact, so the cut planes x = -a_I and x = +a_J are the driven planes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .case import Body

# level -> (size at the contact / smallest semi-axis, growth per unit distance,
#           largest size / largest semi-axis).  The paper's mesh is about "fine".
MESH_LEVELS = {
    "coarse": (0.03, 0.35, 0.25),
    "medium": (0.015, 0.22, 0.18),
    "fine": (0.008, 0.15, 0.12),
    # Ductile materials: the contact radius at first yield is ~0.1 um for r = 10 um, so the
    # contact size is cut 5x below "medium"; the element count grows only ~ log(1/h0).
    "ductile": (0.003, 0.22, 0.18),
    "ductile_coarse": (0.006, 0.22, 0.18),  # plastic mesh check of "ductile", one level down
    "ductile_fine": (0.0015, 0.15, 0.12),
}

# gmsh 10-node tetrahedron -> CalculiX C3D10: swap the 9th and 10th node (edges 3-4 and 2-4).
GMSH_TO_C3D10 = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]


@dataclass
class BodyMesh:
    tets: np.ndarray        # (n, 10) node ids, C3D10 order
    driven: np.ndarray      # node ids on the cut plane perpendicular to x
    sym_y: np.ndarray       # node ids on y = 0
    sym_z: np.ndarray       # node ids on z = 0
    tip_x: float            # x of the cut plane


@dataclass
class PairMesh:
    nodes: np.ndarray       # (n, 3) coordinates, row k is node id k+1
    body_i: BodyMesh
    body_j: BodyMesh
    level: str


def _octant(gmsh, body: Body, side: int) -> int:
    """side = -1: body I (left of the origin), +1: body J."""
    occ = gmsh.model.occ
    tag = occ.addSphere(0, 0, 0, 1.0, -1, 0.0, math.pi / 2, math.pi / 2)
    occ.dilate([(3, tag)], 0, 0, 0, body.a, body.b, body.c)
    if side > 0:
        occ.mirror([(3, tag)], 1, 0, 0, 0)
    occ.translate([(3, tag)], side * body.a, 0, 0)
    return tag


def _size_field(gmsh, level: str, bodies: tuple[Body, Body]) -> None:
    frac0, growth, frac_max = MESH_LEVELS[level]
    h0 = frac0 * min(min(b.a, b.b, b.c) for b in bodies)
    hmax = frac_max * max(max(b.a, b.b, b.c) for b in bodies)
    field = gmsh.model.mesh.field
    f = field.add("MathEval")
    field.setString(f, "F", f"Min({hmax}, {h0} + {growth}*Sqrt(x*x+y*y+z*z))")
    field.setAsBackgroundMesh(f)
    for opt in ("Mesh.MeshSizeFromPoints", "Mesh.MeshSizeFromCurvature",
                "Mesh.MeshSizeExtendFromBoundary"):
        gmsh.option.setNumber(opt, 0)


def _on_plane(coords: np.ndarray, ids: np.ndarray, axis: int, value: float, tol: float) -> np.ndarray:
    return ids[np.abs(coords[ids - 1, axis] - value) < tol]


def _body_mesh(gmsh, tag: int, coords: np.ndarray, tip_x: float, tol: float) -> BodyMesh:
    types, _, conn = gmsh.model.mesh.getElements(3, tag)
    tets = np.asarray(conn[list(types).index(11)], dtype=np.int64).reshape(-1, 10)
    tets = tets[:, GMSH_TO_C3D10]
    ids = np.unique(tets)
    return BodyMesh(tets=tets, driven=_on_plane(coords, ids, 0, tip_x, tol),
                    sym_y=_on_plane(coords, ids, 1, 0.0, tol),
                    sym_z=_on_plane(coords, ids, 2, 0.0, tol), tip_x=tip_x)


def build_mesh(body_i: Body, body_j: Body, level: str, msh_path: str | None = None) -> PairMesh:
    if level not in MESH_LEVELS:
        raise ValueError(f"mesh level {level!r} not in {sorted(MESH_LEVELS)}")
    import gmsh  # Debian's python3-gmsh: only /usr/bin/python3 sees it

    gmsh.initialize(["-noenv"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)  # deterministic node numbering
        gmsh.model.add("pair")
        tag_i, tag_j = _octant(gmsh, body_i, -1), _octant(gmsh, body_j, +1)
        gmsh.model.occ.synchronize()
        _size_field(gmsh, level, (body_i, body_j))
        gmsh.model.mesh.generate(3)
        gmsh.model.mesh.setOrder(2)
        if msh_path:
            gmsh.write(msh_path)
        node_tags, xyz, _ = gmsh.model.mesh.getNodes()
        coords = np.zeros((int(node_tags.max()), 3))
        coords[node_tags.astype(np.int64) - 1] = xyz.reshape(-1, 3)
        tol = 1e-6 * max(body_i.a, body_i.b, body_i.c, body_j.a, body_j.b, body_j.c)
        mesh_i = _body_mesh(gmsh, tag_i, coords, -body_i.a, tol)
        mesh_j = _body_mesh(gmsh, tag_j, coords, body_j.a, tol)
    finally:
        gmsh.finalize()
    return PairMesh(nodes=coords, body_i=mesh_i, body_j=mesh_j, level=level)
