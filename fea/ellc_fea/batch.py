"""fea/run_grid: run many case files one after the other, skipping finished ones.

Each case writes its CSV as soon as it finishes, so a batch cut short still leaves
usable results.  One CalculiX job at a time, one thread.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from .cli import EXIT_OK, main as run_one


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="fea/run_grid", description=__doc__)
    p.add_argument("cases", nargs="+", help="case TOML files, run in this order")
    p.add_argument("--mesh", default="medium")
    p.add_argument("--points", type=int, help="override points_per_segment")
    p.add_argument("--elastic", action="store_true")
    p.add_argument("--suffix", default="", help="appended to each output name, e.g. _elastic_fine")
    p.add_argument("--out", default="data/fea")
    p.add_argument("--work", default="out/fea/work")
    p.add_argument("--manifest", default="data/fea/manifest.json")
    p.add_argument("--contact-slope", help="passed to fea/run_case (default: run_case's)")
    p.add_argument("--force", action="store_true", help="rerun cases whose CSV exists")
    p.add_argument("--reparse", action="store_true", help="collect existing ccx output again, no runs")
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    failures = 0
    for path in args.cases:
        name = os.path.basename(path).removesuffix(".toml") + args.suffix
        if not (args.force or args.reparse) and os.path.exists(os.path.join(args.out, f"{name}.csv")):
            print(f"run_grid: {name}: already done, skipped", flush=True)
            continue
        one = [path, "--mesh", args.mesh, "--name", name, "--out", args.out,
               "--work", os.path.join(args.work, name), "--manifest", args.manifest]
        one += ["--points", str(args.points)] if args.points else []
        one += ["--elastic"] if args.elastic else []
        one += ["--reparse"] if args.reparse else []
        one += ["--contact-slope", args.contact_slope] if args.contact_slope else []
        start = time.monotonic()
        print(f"run_grid: {name}: start {time.strftime('%H:%M:%S')}", flush=True)
        code = run_one(one)
        print(f"run_grid: {name}: exit {code} after {time.monotonic() - start:.0f} s", flush=True)
        failures += code != EXIT_OK
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
