"""One case end to end: mesh, deck, CalculiX, parse, CSV + manifest record."""
from __future__ import annotations

import dataclasses
import os
import platform
import time

from .case import Case
from .curve import rows, write_csv
from .datfile import parse_dat
from .deck import CONTACT_SLOPE, write_deck
from .manifest import read_manifest, update_manifest
from .mesh import build_mesh
from .runner import ccx_version, read_log, run_ccx


@dataclasses.dataclass
class Outcome:
    complete: bool
    csv_path: str
    message: str


def _status(case: Case, table: list[tuple], finished: bool) -> tuple[bool, str]:
    segments = len(case.waypoints) - 1
    if not table:
        return False, "no converged increment"
    seg, t, d = table[-1][2], table[-1][3], table[-1][0]
    last = f"last converged increment: segment {seg}/{segments}, step time {t:.4g}, overlap {d:.6g} um"
    complete = finished and seg == segments and abs(t - 1.0) < 1e-6
    return complete, last


def _run_info(manifest: str, name: str, seconds: float, command: str, reparse: bool) -> dict:
    """Command and run time for the record; a reparse keeps those of the run it reparses."""
    if not reparse:
        return {"command": command, "ccx_seconds": round(seconds, 1)}
    old = read_manifest(manifest).get(name, {})
    return {"command": old.get("command", command), "ccx_seconds": old.get("ccx_seconds"),
            "reparsed_by": command}


def run_case(case: Case, level: str, out_dir: str, work_dir: str, ccx: str, *,
             elastic_only: bool = False, command: str = "", manifest: str | None = None,
             reparse: bool = False, contact_slope: float = CONTACT_SLOPE) -> Outcome:
    """Mesh, write the deck, run ccx and collect.  reparse=True skips the ccx run and collects
    the existing output in work_dir again (the mesh is rebuilt: gmsh numbering is deterministic)."""
    os.makedirs(out_dir, exist_ok=True)
    os.makedirs(work_dir, exist_ok=True)
    t0 = time.monotonic()
    mesh = build_mesh(case.body_i, case.body_j, level)
    deck = os.path.join(work_dir, f"{case.name}.inp" if not reparse else f"{case.name}.reparse.inp")
    summary = write_deck(deck, case, mesh, elastic_only, contact_slope)
    mesh_seconds = time.monotonic() - t0
    result = read_log(work_dir, case.name) if reparse else run_ccx(ccx, work_dir, case.name)
    table = rows(parse_dat(os.path.join(work_dir, f"{case.name}.dat")), mesh.nodes)
    complete, last = _status(case, table, result.finished and result.returncode == 0)
    good = os.path.join(out_dir, f"{case.name}.csv")
    bad = os.path.join(out_dir, f"{case.name}.incomplete.csv")
    csv_path = good if complete else bad
    for stale in (good, bad):
        if os.path.exists(stale):
            os.remove(stale)
    if table:
        write_csv(csv_path, table)
    message = "complete" if complete else f"NOT CONVERGED ({result.error or 'ccx exit ' + str(result.returncode)}); {last}"
    if manifest:
        update_manifest(manifest, case.name, {
            **_run_info(manifest, case.name, result.seconds, command, reparse), "mesh_level": level, "elastic_only": elastic_only,
            "calculix": ccx_version(ccx), "status": "complete" if complete else "incomplete",
            "last_increment": last,
            "mesh_seconds": round(mesh_seconds, 1), "threads": 1, "host_cores": os.cpu_count(),
            "python": platform.python_version(), "csv": os.path.basename(csv_path),
            "points": len(table), **summary,
            "semi_axes_I": [case.body_i.a, case.body_i.b, case.body_i.c],
            "semi_axes_J": [case.body_j.a, case.body_j.b, case.body_j.c],
            "waypoints": list(case.waypoints), "points_per_segment": case.points_per_segment,
        })
    return Outcome(complete, csv_path if table else "", message)
