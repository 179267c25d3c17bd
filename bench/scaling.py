#!/usr/bin/python3
"""bench_dem over N (particles) and thread counts: particle-steps/s and memory per particle, as
JSON for plot_scaling.py (issue 16, item 5). Each (N, threads) is one bench_dem process; the
N = 10^5 setup (packing and compression, ~1800 steps) takes minutes.

  nice -n 10 /usr/bin/python3 bench/scaling.py --bench build/bench/bench_dem \
      --sizes 1000 10000 100000 --threads 1 2 --out bench/results/scaling.json
"""
import argparse
import json
import os
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench", default="build/bench/bench_dem")
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--adaptive", type=int, default=1, help="0: ELLC_BENCH_DEM_FIXED_THREADS=1")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    rows = []
    for size in args.sizes:
        for threads in args.threads:
            env = dict(os.environ, OMP_NUM_THREADS=str(threads), ELLC_BENCH_DEM_PARTICLES=str(size),
                       ELLC_BENCH_DEM_STEPS=str(args.steps))
            if not args.adaptive:
                env["ELLC_BENCH_DEM_FIXED_THREADS"] = "1"
            out = subprocess.run([args.bench, "--benchmark_filter=BM_dem_(ellipsoids|spheres)",
                                  "--benchmark_format=json"], env=env, check=True, capture_output=True,
                                 text=True).stdout
            for bench in json.loads(out)["benchmarks"]:
                row = {"particles": size, "threads": threads, "benchmark": bench["name"].split("/")[0]}
                for key in ("particle_steps_per_s", "simulation_bytes_per_particle", "peak_rss_bytes_per_particle",
                            "contacts_per_particle", "candidate_pairs_per_particle", "threads_at_end",
                            "cpu_ns_per_particle_step"):
                    row[key] = bench.get(key)
                rows.append(row)
                print(json.dumps(row), file=sys.stderr, flush=True)
            with open(args.out, "w") as f:  # after every run: a partial result survives
                json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
