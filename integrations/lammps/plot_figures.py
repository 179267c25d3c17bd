#!/usr/bin/env python3
"""Figures of docs/lammps.md from runs of lmp_ellc and ellc.

  plot_figures.py two-particle --ellc BUILD/apps/ellc --lmp BUILD/integrations/lammps/lmp_ellc -o out.png
  plot_figures.py calendering CSV -o out.png      (CSV written by examples/lammps/in.calendering)
"""
import argparse
import csv
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def read(path):
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(row[key]) if key != "regime" else row[key] for row in rows] for key in rows[0]}


def two_particle(args):
    with tempfile.TemporaryDirectory() as work:
        curve = os.path.join(work, "curve.csv")
        subprocess.run([args.ellc, "curve", os.path.join(ROOT, "examples", "paper_case2.toml"), "-o", curve],
                       check=True, stdout=subprocess.DEVNULL)
        runs = {}
        for w2 in ("-0.01", "0.01"):
            out = os.path.join(work, f"lammps_{w2}.csv")
            subprocess.run([args.lmp, "-in", os.path.join(ROOT, "examples", "lammps", "in.two_particle_case2"),
                            "-log", "none", "-screen", "none", "-var", "out", out, "-var", "w2", w2],
                           check=True, cwd=work, env={**os.environ, "OMPI_ALLOW_RUN_AS_ROOT": "1",
                                                      "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
            runs[w2] = read(out)
        reference = read(curve)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(reference["overlap"], reference["force"], color="black", lw=2.5, label="ellc curve (history kept)")
    ax.plot(runs["-0.01"]["overlap"], [f * 1e-3 for f in runs["-0.01"]["force"]], color="tab:red", lw=1.2,
            label="LAMMPS, unload past contact (-1 %): history deleted")
    ax.plot(runs["0.01"]["overlap"], [f * 1e-3 for f in runs["0.01"]["force"]], "--", color="tab:blue", lw=1.2,
            label="LAMMPS, unload to 1 % (test protocol)")
    ax.set_xlabel("overlap δ [µm]")
    ax.set_xlim(left=0.0)
    ax.set_ylabel("normal force [µN]")
    ax.set_title("Paper case 2 in LAMMPS (pair_style ellipsoid/bk)")
    ax.legend(frameon=False, fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)


def calendering(args):
    data = read(args.csv)
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.6, 3.8))
    left.plot(data["time"], data["plate_stress_mpa"], label="top plate")
    left.plot(data["time"], data["bottom_stress_mpa"], label="bottom wall")
    left.set_xlabel("time [µs]")
    left.set_ylabel("stress [MPa]")
    left.legend(frameon=False)
    start = data["plate_z"][0]
    right.plot([start - z for z in data["plate_z"]], data["plate_stress_mpa"], color="tab:blue")
    right.set_xlabel("plate travel [µm]")
    right.set_ylabel("plate stress [MPa]")
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="figure", required=True)
    two = sub.add_parser("two-particle")
    two.add_argument("--ellc", required=True)
    two.add_argument("--lmp", required=True)
    two.add_argument("-o", "--output", required=True)
    cal = sub.add_parser("calendering")
    cal.add_argument("csv")
    cal.add_argument("--title", default="Calendering in LAMMPS (examples/lammps/in.calendering)")
    cal.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    {"two-particle": two_particle, "calendering": calendering}[args.figure](args)


if __name__ == "__main__":
    main()
