#!/usr/bin/env python3
"""Figures of docs/lammps.md from runs of lmp_ellc and ellc.

  plot_figures.py two-particle --ellc BUILD/apps/ellc --lmp BUILD/integrations/lammps/lmp_ellc -o out.png
  plot_figures.py calendering LAMMPS_CSV [--engine ENGINE_CSV] -o out.png
      LAMMPS_CSV: timeseries.csv of examples/lammps/in.calendering; ENGINE_CSV: that of
      `ellc dem examples/calendering.toml` (the same packing, model, walls and protocol)
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
    """Columns of a CSV: numbers as floats, text columns (regime, phase) as strings."""
    with open(path) as handle:
        rows = list(csv.DictReader(handle))

    def column(key):
        try:
            return [float(row[key]) for row in rows]
        except ValueError:
            return [row[key] for row in rows]

    return {key: column(key) for key in rows[0]}


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
    """Plate pressure against time and against the layer's thickness, and the coordination number,
    of the LAMMPS run and (with --engine) of the built-in engine on the same scenario: both write
    the engine's column names."""
    runs = [("LAMMPS (lmp_ellc)", read(args.csv), "tab:blue")]
    if args.engine:
        runs.append(("built-in engine (ellc dem)", read(args.engine), "tab:orange"))
    fig, (by_time, by_thickness, coordination) = plt.subplots(1, 3, figsize=(13.5, 3.8))
    pressing_starts = None  # the first time the plate pressure reaches 1 MPa, in either run
    pressing_thickness = None  # the layer's thickness then
    for label, data, colour in runs:
        style = {"color": colour, "lw": 1.0, "label": label}
        by_time.plot(data["time"], data["plate_pressure"], **style)
        loading = [k for k, phase in enumerate(data["phase"]) if phase in ("load", "hold") and data["plate_pressure"][k] > 0]
        by_thickness.plot([data["thickness"][k] for k in loading], [data["plate_pressure"][k] for k in loading],
                          **style)
        coordination.plot(data["time"], data["coordination_number"], **style)
        first = next((k for k, p in enumerate(data["plate_pressure"]) if p >= 1.0), None)
        if first is not None:
            time, thickness = data["time"][first], data["thickness"][first]
            pressing_starts = time if pressing_starts is None else min(pressing_starts, time)
            pressing_thickness = thickness if pressing_thickness is None else max(pressing_thickness, thickness)
    if pressing_starts is not None:  # the pressing and what follows; before it the pressure is ~0
        by_time.set_xlim(left=pressing_starts - 0.3 * (by_time.get_xlim()[1] - pressing_starts))
    by_time.set(xlabel="time [µs]", ylabel="plate pressure [MPa]", title="pressing, hold, release")
    by_thickness.set(xlabel="layer thickness [µm]", ylabel="plate pressure [MPa]", title="pressing and hold")
    if pressing_thickness is not None:
        thinnest = min(min(data["thickness"]) for _, data, _ in runs)
        by_thickness.set_xlim(pressing_thickness + 0.3 * (pressing_thickness - thinnest), thinnest - 0.5)
    else:
        by_thickness.invert_xaxis()
    coordination.set(xlabel="time [µs]", ylabel="coordination number")
    coordination.legend(frameon=False, loc="upper left")
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="figure", required=True)
    two = sub.add_parser("two-particle")
    two.add_argument("--ellc", required=True)
    two.add_argument("--lmp", required=True)
    two.add_argument("-o", "--output", required=True)
    cal = sub.add_parser("calendering")
    cal.add_argument("csv")
    cal.add_argument("--engine", help="the built-in engine's timeseries.csv of the same scenario")
    cal.add_argument("--title", default="examples/calendering.toml in LAMMPS (examples/lammps/in.calendering) "
                                        "and in the built-in engine")
    cal.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    {"two-particle": two_particle, "calendering": calendering}[args.figure](args)


if __name__ == "__main__":
    main()
