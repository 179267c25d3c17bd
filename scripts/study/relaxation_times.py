#!/usr/bin/python3
"""How long the released layer of a scenario takes to settle, over packing seeds: the evidence for
an example's `calendering.max_relax_time` (docs/engine.md, "Relaxation budgets").

    scripts/study/relaxation_times.py SCENARIO.toml --seeds 2026-2049 [--compare hertz] \
        [--ellc build/apps/ellc] [--jobs 2] [--out DIR]

Each seed runs `ellc dem` with `max_relax_time` lifted to 20000 µs, so that no run stops for want
of time; the relaxation time of a run is its `released_time_us` (summary.txt) minus the time of its
first `relax` row (timeseries.csv). Prints every run's time and, per law, the median and the
largest, beside the scenario's own budget. A run that fails for another reason is listed as such.
"""
import argparse
import concurrent.futures
import csv
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import tomllib

UNLIMITED = 20000.0  # µs


def seeds_of(text):
    first, _, last = text.partition("-")
    return range(int(first), int(last or first) + 1)


def relaxation_time(run_dir):
    """µs from the first relax row to the released state, or None if the run has no released state."""
    summary = run_dir / "summary.txt"
    series = run_dir / "timeseries.csv"
    if not summary.exists() or not series.exists():
        return None
    with open(summary, "rb") as handle:
        released = tomllib.load(handle).get("released_time_us")
    with open(series) as handle:
        relax = [row for row in csv.DictReader(handle) if row["phase"] == "relax"]
    if released is None or not relax:
        return None
    return released - float(relax[0]["time"])


def run_seed(args, text, seed, out):
    path = out / f"seed{seed}.toml"
    path.write_text(re.sub(r"^seed = \d+", f"seed = {seed}", text, count=1, flags=re.MULTILINE))
    run_dir = out / f"seed{seed}"
    command = [args.ellc, "dem", str(path), "-o", str(run_dir), "--no-plot", "-q",
               "--set", f"calendering.max_relax_time={UNLIMITED}"]
    if args.compare:
        command += ["--compare", args.compare]
    code = subprocess.run(command, capture_output=True, text=True).returncode
    laws = {"becker_kamlah": relaxation_time(run_dir)}
    for law in (args.compare.split(",") if args.compare else []):
        laws[law] = relaxation_time(run_dir / law)
    return seed, code, laws


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenario")
    parser.add_argument("--seeds", default="2026-2049", help="FIRST-LAST, inclusive")
    parser.add_argument("--compare", default="", help="laws for ellc dem --compare, e.g. hertz,thornton")
    parser.add_argument("--ellc", default="build/apps/ellc")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default="", help="keep the runs here (default: a temporary directory)")
    args = parser.parse_args()
    text = pathlib.Path(args.scenario).read_text()
    seed_line = re.search(r"^seed = (\d+)", text, re.MULTILINE)
    budget_line = re.search(r"^max_relax_time = ([0-9.eE+]+)", text, re.MULTILINE)
    if seed_line is None:
        sys.exit(f"{args.scenario}: no 'seed = N' line in [packing]")
    budget = float(budget_line.group(1)) if budget_line else None
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(args.out or scratch)
        out.mkdir(parents=True, exist_ok=True)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = list(pool.map(lambda seed: run_seed(args, text, seed, out), seeds_of(args.seeds)))
    by_law = {}
    for seed, code, laws in results:
        for law, time in laws.items():
            shown = f"{time:8.1f} µs" if time is not None else "   no released state"
            print(f"seed {seed}  {law:14s} {shown}" + (f"  (exit {code})" if code != 0 else ""))
            if time is not None:
                by_law.setdefault(law, []).append(time)
    print(f"\nbudget in {args.scenario}: " + (f"max_relax_time = {budget:g} µs" if budget else "the default"))
    for law, times in by_law.items():
        over = sum(1 for time in times if budget is not None and time > budget)
        print(f"{law:14s} {len(times)} runs: median {statistics.median(times):.0f} µs, largest {max(times):.0f} µs"
              + (f", {over} over the budget" if budget is not None else ""))


if __name__ == "__main__":
    main()
