"""Command line of fea/run_case."""
from __future__ import annotations

import argparse
import dataclasses
import math
import os
import shlex
import sys

from .case import CaseError, load_case
from .deck import CONTACT_SLOPE
from .mesh import MESH_LEVELS
from .pipeline import run_case
from .runner import find_ccx

EXIT_OK, EXIT_REFUSED, EXIT_NOT_CONVERGED, EXIT_NO_TOOLS = 0, 2, 3, 4


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="fea/run_case", description=(
        "Build, run and parse the CalculiX model of one ellipsoid pair. Writes OUT/NAME.csv "
        "(complete) or OUT/NAME.incomplete.csv (CalculiX did not converge)."))
    p.add_argument("case", help="case TOML ([material], [body_I], [body_J], [protocol])")
    p.add_argument("--mesh", choices=sorted(MESH_LEVELS), default="medium",
                   help="mesh level (default medium)")
    p.add_argument("--points", type=int, help="override protocol points_per_segment")
    p.add_argument("--elastic", action="store_true", help="purely elastic material (Hertz checks)")
    p.add_argument("--name", help="output name (default: case file stem)")
    p.add_argument("--out", default="out/fea", help="directory of the result CSV (default out/fea)")
    p.add_argument("--work", help="CalculiX work directory (default OUT/work/NAME)")
    p.add_argument("--contact-slope", type=float, default=CONTACT_SLOPE, metavar="MPA_PER_UM",
                   help=f"penalty slope of the contact, pressure per overclosure (default {CONTACT_SLOPE:g}; "
                        "fea/README.md, 'Contact penalty')")
    p.add_argument("--manifest", help="JSON manifest to record the run in")
    p.add_argument("--reparse", action="store_true",
                   help="do not run CalculiX; collect the existing output in the work directory")
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        case = load_case(args.case)
    except (CaseError, OSError) as err:
        print(f"run_case: refused: {err}", file=sys.stderr)
        return EXIT_REFUSED
    if not (math.isfinite(args.contact_slope) and args.contact_slope > 0.0):
        print(f"run_case: refused: --contact-slope = {args.contact_slope:g}: expected a positive, finite "
              "pressure per overclosure (MPa/um)", file=sys.stderr)
        return EXIT_REFUSED
    if args.points:
        case = dataclasses.replace(case, points_per_segment=args.points)
    if args.name:
        case = dataclasses.replace(case, name=args.name)
    level = args.mesh
    ccx = find_ccx()
    if ccx is None:
        print("run_case: CalculiX (ccx) not found; install calculix-ccx", file=sys.stderr)
        return EXIT_NO_TOOLS
    work = args.work or os.path.join(args.out, "work", case.name)
    command = "fea/run_case " + " ".join(shlex.quote(a) for a in (argv if argv is not None else sys.argv[1:]))
    outcome = run_case(case, level, args.out, work, ccx, elastic_only=args.elastic,
                       command=command, manifest=args.manifest, reparse=args.reparse,
                       contact_slope=args.contact_slope)
    print(f"run_case: {case.name}: {outcome.message}; csv: {outcome.csv_path or 'none'}")
    return EXIT_OK if outcome.complete else EXIT_NOT_CONVERGED
