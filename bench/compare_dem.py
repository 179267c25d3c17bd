#!/usr/bin/python3
"""Interleaved bench_dem runs: a baseline binary and a new one, on 1 and 2 threads, with or without
a busy companion process (one core kept busy by a spinning process, issue 16). Rounds alternate
the binaries so that both see the same machine load; the table gives each case's particle-steps/s
(median, min–max over rounds) and the new/baseline ratio.

  /usr/bin/python3 bench/compare_dem.py --baseline /work/wt/perf-baseline/bench_dem \
      --new build/bench/bench_dem --rounds 3 --threads 1 2 --busy 0 1 --json out.json

Environment: ELLC_BENCH_DEM_PARTICLES, ELLC_BENCH_DEM_STEPS and ELLC_BENCH_DEM_STATE (a file
that keeps the pressed packing, so that each run skips the pressing and both builds time the same
packing; both builds must read it) pass through to bench_dem.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys


def run_once(binary, threads, busy, pattern):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    companion = None
    if busy:  # the companion: a process that keeps one core busy for the whole run
        companion = subprocess.Popen(["/bin/sh", "-c", "while :; do :; done"])
    try:
        out = subprocess.run([binary, f"--benchmark_filter={pattern}", "--benchmark_format=json"], env=env,
                             check=True, capture_output=True, text=True).stdout
    finally:
        if companion is not None:
            companion.kill()
            companion.wait()
    rates = {}
    for bench in json.loads(out)["benchmarks"]:
        if "particle_steps_per_s" in bench:
            rates[bench["name"].split("/")[0]] = bench["particle_steps_per_s"]
    return rates


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--new", required=True)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--busy", type=int, nargs="+", default=[0])
    parser.add_argument("--filter", default="BM_dem_(ellipsoids|spheres)")
    parser.add_argument("--json")
    args = parser.parse_args()
    results = {}  # (binary label, threads, busy, benchmark) -> [rates]
    for round_ in range(args.rounds):
        for busy in args.busy:
            for threads in args.threads:
                order = [("baseline", args.baseline), ("new", args.new)]
                if round_ % 2:
                    order.reverse()
                for label, binary in order:
                    for name, rate in run_once(binary, threads, busy, args.filter).items():
                        results.setdefault((label, threads, busy, name), []).append(rate)
                        print(f"round {round_} {label:8} threads {threads} busy {busy} {name}: {rate:.4g}",
                              file=sys.stderr, flush=True)
    rows = []
    print("| benchmark | threads | busy core | baseline (median, min–max) | new (median, min–max) | new/baseline |")
    print("|---|---|---|---|---|---|")
    for (label, threads, busy, name), rates in sorted(results.items()):
        if label != "new":
            continue
        base = results.get(("baseline", threads, busy, name), [])
        if not base:
            continue
        ratios = [n / b for n in rates for b in base]
        fmt = lambda xs: f"{statistics.median(xs):.3g} ({min(xs):.3g}–{max(xs):.3g})"
        print(f"| {name} | {threads} | {'yes' if busy else 'no'} | {fmt(base)} | {fmt(rates)} | "
              f"{statistics.median(ratios):.2f} ({min(ratios):.2f}–{max(ratios):.2f}) |")
        rows.append({"benchmark": name, "threads": threads, "busy": busy, "baseline": base, "new": rates})
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
