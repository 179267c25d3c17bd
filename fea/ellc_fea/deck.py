"""Write the CalculiX input deck for a meshed pair and a displacement protocol.

Choices (see fea/README.md, "The model", and docs/validation.md):
  C3D10; bilinear elastic / ideally-plastic material with tangent modulus E/1000;
  frictionless surface-to-surface contact with a LINEAR pressure-overclosure law (slope
  1e7 MPa/um, the measured stand-in for HARD); symmetry on y = 0 and z = 0; each protocol
  segment is one NLGEOM step that moves the driven planes by +-overlap/2.
"""
from __future__ import annotations

from typing import TextIO

import numpy as np

from .case import Case
from .mesh import PairMesh
from .surface import contact_faces, surface_line

# MPa/um, pressure per unit overclosure: the default, and every run started before 2026-12-03 09:45 UTC. A
# sharp aluminium contact (c_Y ~ 0.01 um) needs a stiffer one (`--contact-slope`, fea/README.md,
# "Contact penalty"): the penalty must stay much stiffer than the Hertz contact itself, 2 E* c.
CONTACT_SLOPE = 1.0e7
CONTACT_CONTROLS = "0.05,0.1,100,60"
# surface nodes on the symmetry lines: body I/J, along y (z = 0) and along z (y = 0)
LINE_SETS = ("LYI", "LYJ", "LZI", "LZJ")


def _ids(fh: TextIO, name: str, ids: np.ndarray) -> None:
    fh.write(f"*NSET, NSET={name}\n")
    for k in range(0, len(ids), 12):
        fh.write(", ".join(str(int(i)) for i in ids[k:k + 12]) + ",\n")


def _nodes(fh: TextIO, nodes: np.ndarray) -> None:
    fh.write("*NODE, NSET=NALL\n")
    for k, (x, y, z) in enumerate(nodes, start=1):
        fh.write(f"{k}, {x:.10g}, {y:.10g}, {z:.10g}\n")


def _elements(fh: TextIO, tets: np.ndarray, first: int, elset: str) -> None:
    fh.write(f"*ELEMENT, TYPE=C3D10, ELSET={elset}\n")
    for k, tet in enumerate(tets, start=first):
        fh.write(f"{k}, " + ", ".join(str(int(n)) for n in tet) + "\n")


def _surface(fh: TextIO, name: str, faces: list[tuple[int, int]]) -> None:
    fh.write(f"*SURFACE, NAME={name}, TYPE=ELEMENT\n")
    for elem, face in faces:
        fh.write(f"{elem}, S{face}\n")


def _material(fh: TextIO, case: Case, elastic_only: bool) -> None:
    m = case.material
    fh.write(f"*MATERIAL, NAME=MAT\n*ELASTIC\n{m.youngs_modulus:.10g}, {m.poisson_ratio:.10g}\n")
    if not elastic_only:
        e = m.youngs_modulus
        tangent = e / 1000.0
        hardening = e * tangent / (e - tangent)
        fh.write(f"*PLASTIC\n{m.yield_stress:.10g}, 0.0\n{m.yield_stress + hardening:.10g}, 1.0\n")
    fh.write("*SOLID SECTION, ELSET=EI, MATERIAL=MAT\n*SOLID SECTION, ELSET=EJ, MATERIAL=MAT\n")


def _step(fh: TextIO, target: float, points: int) -> None:
    inc = 1.0 / points
    fh.write("*STEP, NLGEOM, INC=10000\n*STATIC\n")
    fh.write(f"{inc:.6g}, 1.0, {inc * 1e-4:.6g}, {inc:.6g}\n")
    fh.write(f"*CONTROLS, PARAMETERS=CONTACT\n{CONTACT_CONTROLS}\n")
    fh.write(f"*BOUNDARY\nXI, 1, 1, {target / 2:.10g}\nXJ, 1, 1, {-target / 2:.10g}\n")
    fh.write("*NODE PRINT, NSET=PILOTI\nU\n*NODE PRINT, NSET=PILOTJ\nU\n")
    fh.write("*NODE PRINT, NSET=XI, TOTALS=ONLY\nRF\n*NODE PRINT, NSET=XJ, TOTALS=ONLY\nRF\n")
    for name in LINE_SETS:
        fh.write(f"*NODE PRINT, NSET={name}\nU\n")
    fh.write("*CONTACT PRINT\nCSTR\n*END STEP\n")


def _lines(fh: TextIO, case: Case, mesh: PairMesh, reach: float) -> None:
    for along, axis in ((1, "Y"), (2, "Z")):
        for tag, body, bm, side in (("I", case.body_i, mesh.body_i, -1), ("J", case.body_j, mesh.body_j, 1)):
            ids = np.unique(bm.tets)
            line = surface_line(mesh.nodes, ids, side * body.a, (body.a, body.b, body.c), along, reach)
            _ids(fh, f"L{axis}{tag}", line)


def contact_reach(case: Case) -> float:
    """How far (in x) from a tip the contact can spread: the undeformed gap must close."""
    return 1.5 * max(case.waypoints) + 0.02 * min(case.body_i.a, case.body_j.a)


def write_deck(path: str, case: Case, mesh: PairMesh, elastic_only: bool = False,
               contact_slope: float = CONTACT_SLOPE) -> dict:
    """Write the deck; return a summary (node/element/face counts, the penalty slope) for the manifest."""
    n_i = len(mesh.body_i.tets)
    tol = 1e-6 * float(np.abs(mesh.nodes).max())
    reach = contact_reach(case)
    faces_i = contact_faces(mesh.body_i.tets, 1, mesh.nodes, reach, tol)
    faces_j = contact_faces(mesh.body_j.tets, n_i + 1, mesh.nodes, reach, tol)
    with open(path, "w") as fh:
        fh.write(f"** ellc FE reference: case {case.name}, mesh {mesh.level}\n")
        _nodes(fh, mesh.nodes)
        _elements(fh, mesh.body_i.tets, 1, "EI")
        _elements(fh, mesh.body_j.tets, n_i + 1, "EJ")
        _ids(fh, "XI", mesh.body_i.driven)
        _ids(fh, "XJ", mesh.body_j.driven)
        _ids(fh, "PILOTI", mesh.body_i.driven[:1])
        _ids(fh, "PILOTJ", mesh.body_j.driven[:1])
        _ids(fh, "SY", np.concatenate([mesh.body_i.sym_y, mesh.body_j.sym_y]))
        _ids(fh, "SZ", np.concatenate([mesh.body_i.sym_z, mesh.body_j.sym_z]))
        _lines(fh, case, mesh, reach)
        _surface(fh, "SURFI", faces_i)
        _surface(fh, "SURFJ", faces_j)
        _material(fh, case, elastic_only)
        fh.write(f"*SURFACE INTERACTION, NAME=FRICTIONLESS\n"
                 f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{contact_slope:.6g}\n")
        fh.write("*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=SURFACE TO SURFACE\nSURFJ, SURFI\n")
        fh.write("*BOUNDARY\nSY, 2, 2, 0.0\nSZ, 3, 3, 0.0\n")
        for target in case.waypoints[1:]:
            _step(fh, target, case.points_per_segment)
    n_nodes = int(len(np.unique(np.concatenate([mesh.body_i.tets.ravel(), mesh.body_j.tets.ravel()]))))
    return {"nodes": n_nodes, "elements": n_i + len(mesh.body_j.tets),
            "contact_faces": [len(faces_i), len(faces_j)], "contact_slope": contact_slope}
