#!/usr/bin/env python3
"""Weak- and strong-scaling tables of pair ellipsoid/bk at np 1 and 2 (docs/lammps.md, "Scaling").

  scaling.py --lmp build/integrations/lammps/lmp_ellc [--repeats 3] [--mpirun mpirun] [--bind core]

Strong: the same 8 x 8 x 8 packing (512 ellipsoids) on 1 and 2 ranks, and 16 x 16 x 8 (2048).
Weak: 6 x 6 x 6 cells (216 ellipsoids) per rank, the box doubled along x on 2 ranks. Each
configuration runs --repeats times, interleaved, so that the ratios compare runs taken side by
side on a shared machine; the tables give particle-steps/s (median, range) and the efficiency
ranges, then LAMMPS's timing breakdown (average over ranks, medians over the repeats), and the
load average before and after: np 2 timings mean nothing while another job holds a core.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


SECTIONS = ("Pair", "Neigh", "Comm", "Modify", "Other")


def load_average():
    with open("/proc/loadavg") as handle:
        return " ".join(handle.read().split()[:3])


def rate(args, np, cells):
    """Particle-steps/s of the timed run, and its breakdown {section: average seconds per rank}."""
    binding = ["--bind-to", args.bind] if args.bind else []
    command = [args.mpirun, "--oversubscribe", *binding, "-np", str(np), args.lmp, "-in", os.path.join(HERE, "in.scaling"),
               "-log", "none", "-var", "nx", str(cells[0]), "-var", "ny", str(cells[1]), "-var", "nz", str(cells[2]),
               "-var", "steps", str(args.steps)]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    output = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env).stdout
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", output)
    if len(loops) < 2:
        sys.exit(f"no timing in the output of {' '.join(command)}:\n{output[-2000:]}")
    seconds, steps, atoms = loops[-1]
    timed = output[output.rfind("Loop time of"):]
    breakdown = {}
    for section in SECTIONS:  # "Pair | min | avg | max | %varavg | %total", or "Other | | avg | ..."
        found = re.search(rf"^{section}\s*\|[^|]*\|\s*([0-9.eE+-]+)", timed, re.MULTILINE)
        if found:
            breakdown[section] = float(found.group(1))
    return int(atoms) * int(steps) / float(seconds), breakdown


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--bind", default="", help="mpirun --bind-to value (core, none); default: mpirun's own")
    args = parser.parse_args()
    configurations = {"strong np 1": (1, (8, 8, 8)), "strong np 2": (2, (8, 8, 8)),
                      "2048 np 1": (1, (16, 16, 8)), "2048 np 2": (2, (16, 16, 8)),
                      "weak np 1": (1, (6, 6, 6)), "weak np 2": (2, (12, 6, 6))}
    rates = {name: [] for name in configurations}
    breakdowns = {name: [] for name in configurations}
    load_before = load_average()
    for _ in range(args.repeats):
        for name, (np, cells) in configurations.items():
            value, breakdown = rate(args, np, cells)
            rates[name].append(value)
            breakdowns[name].append(breakdown)
    def cell(values):
        return f"{statistics.median(values):.3g} ({min(values):.3g}–{max(values):.3g})"
    def efficiency(name):
        return [b / a / 2 for a, b in zip(rates[f"{name} np 1"], rates[f"{name} np 2"])]
    print(f"load average before: {load_before}, after: {load_average()}\n")
    print("| strong: 512 ellipsoids | particle-steps/s | parallel efficiency |\n|---|---|---|")
    print(f"| np 1 | {cell(rates['strong np 1'])} | 1 |\n| np 2 | {cell(rates['strong np 2'])} | {cell(efficiency('strong'))} |")
    print("\n| strong: 2048 ellipsoids | particle-steps/s | parallel efficiency |\n|---|---|---|")
    print(f"| np 1 | {cell(rates['2048 np 1'])} | 1 |\n| np 2 | {cell(rates['2048 np 2'])} | {cell(efficiency('2048'))} |")
    print("\n| weak: 216 ellipsoids per rank | particle-steps/s | efficiency |\n|---|---|---|")
    print(f"| np 1 (216) | {cell(rates['weak np 1'])} | 1 |\n| np 2 (432) | {cell(rates['weak np 2'])} | {cell(efficiency('weak'))} |")
    print(f"\n| LAMMPS breakdown, s per rank (median) | {' | '.join(SECTIONS)} |\n|---|{'---|' * len(SECTIONS)}")
    for name in configurations:
        values = [statistics.median(b.get(section, float("nan")) for b in breakdowns[name]) for section in SECTIONS]
        print(f"| {name} | {' | '.join(f'{v:.3g}' for v in values)} |")


if __name__ == "__main__":
    main()
