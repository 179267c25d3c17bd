#!/usr/bin/env python3
"""Weak- and strong-scaling tables of pair ellipsoid/bk at np 1 and 2 (docs/lammps.md, "Scaling").

  scaling.py --lmp build/integrations/lammps/lmp_ellc [--repeats 3] [--mpirun mpirun]

Strong: the same 8 x 8 x 8 packing (512 ellipsoids) on 1 and 2 ranks. Weak: 6 x 6 x 6 cells
(216 ellipsoids) per rank, the box doubled along x on 2 ranks. Each configuration runs --repeats
times, interleaved, so that the ratios compare runs taken side by side on a shared machine; the
tables give particle-steps/s (median, range) and the efficiency ranges.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def rate(args, np, cells):
    command = [args.mpirun, "--oversubscribe", "-np", str(np), args.lmp, "-in", os.path.join(HERE, "in.scaling"),
               "-log", "none", "-var", "nx", str(cells[0]), "-var", "ny", str(cells[1]), "-var", "nz", str(cells[2]),
               "-var", "steps", str(args.steps)]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    output = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env).stdout
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", output)
    if len(loops) < 2:
        sys.exit(f"no timing in the output of {' '.join(command)}:\n{output[-2000:]}")
    seconds, steps, atoms = loops[-1]
    return int(atoms) * int(steps) / float(seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--steps", type=int, default=200)
    args = parser.parse_args()
    configurations = {"strong np 1": (1, (8, 8, 8)), "strong np 2": (2, (8, 8, 8)),
                      "weak np 1": (1, (6, 6, 6)), "weak np 2": (2, (12, 6, 6))}
    rates = {name: [] for name in configurations}
    for _ in range(args.repeats):
        for name, (np, cells) in configurations.items():
            rates[name].append(rate(args, np, cells))
    def cell(values):
        return f"{statistics.median(values):.3g} ({min(values):.3g}–{max(values):.3g})"
    strong = [b / a / 2 for a, b in zip(rates["strong np 1"], rates["strong np 2"])]
    weak = [b / a / 2 for a, b in zip(rates["weak np 1"], rates["weak np 2"])]
    print("| strong: 512 ellipsoids | particle-steps/s | parallel efficiency |\n|---|---|---|")
    print(f"| np 1 | {cell(rates['strong np 1'])} | 1 |\n| np 2 | {cell(rates['strong np 2'])} | {cell(strong)} |")
    print("\n| weak: 216 ellipsoids per rank | particle-steps/s | efficiency |\n|---|---|---|")
    print(f"| np 1 (216) | {cell(rates['weak np 1'])} | 1 |\n| np 2 (432) | {cell(rates['weak np 2'])} | {cell(weak)} |")


if __name__ == "__main__":
    main()
