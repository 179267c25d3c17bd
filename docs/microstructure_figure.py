"""The tortuosity-porosity figure and the resolution-convergence table of docs/microstructure.md.

Runs the calendering example (examples/calendering.toml) with an [analysis] table, so that
`ellc dem` analyses its loaded and released states, then `ellc analyse` on the two saved packings
at several voxel sizes (through-plane tortuosity only), and writes

  docs/img/microstructure_tortuosity_porosity_EXAMPLE.png   tau_z against porosity, with Bruggeman
  data/microstructure/EXAMPLE_convergence.csv               tau_z and porosity per state and voxel size

Usage (from the repository root; the DEM run takes ~10+ minutes on a loaded 2-core machine):

  nice -n 10 /usr/bin/python3 docs/microstructure_figure.py --cli build/apps/ellc --out out/microstructure
  # the quick example (100 particles; what docs/microstructure.md shows, see there):
  nice -n 10 /usr/bin/python3 docs/microstructure_figure.py --example calendering_quick --out out/microstructure_quick \
      --spacings 1.6,1.2,0.8,0.6,0.4
  # again without the DEM run (reuses OUT/run):
  /usr/bin/python3 docs/microstructure_figure.py --cli build/apps/ellc --out out/microstructure --skip-run
"""

import argparse
import csv
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "python"))

from ellc import microstructure  # noqa: E402  (the figure functions need only matplotlib)

ANALYSIS = '\n[analysis]              # docs/microstructure_figure.py\nspacing = 0.8\ncoarse_factor = 2.0\naxes = "z"\n'
SPACINGS = [1.6, 1.2, 0.8, 0.6, 0.5]  # um; the mean particle radius is 4 um


def run(command):
    print("+", " ".join(str(part) for part in command), flush=True)
    subprocess.run([str(part) for part in command], check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default=str(ROOT / "build/apps/ellc"))
    parser.add_argument("--out", default=str(ROOT / "out/microstructure"))
    parser.add_argument("--skip-run", action="store_true", help="reuse OUT/run from an earlier call")
    parser.add_argument("--spacings", default=",".join(str(s) for s in SPACINGS))
    parser.add_argument("--example", default="calendering", help="calendering or calendering_quick (examples/NAME.toml)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    run_directory = out / "run"
    if not args.skip_run:
        scenario = out / "calendering_analysis.toml"
        scenario.write_text((ROOT / f"examples/{args.example}.toml").read_text() + ANALYSIS)
        run([args.cli, "dem", scenario, "-o", run_directory, "-q"])

    rows = []
    for state in ("loaded", "released"):
        packing = run_directory / f"analysis_{state}" / "packing.csv"
        for spacing in (float(s) for s in args.spacings.split(",")):
            folder = out / "convergence" / f"{state}_{spacing:g}"
            run([args.cli, "analyse", packing, "--spacing", spacing, "--axes", "z", "--coarse-factor", "1",
                 "--no-plot", "-o", folder])
            summary = microstructure.read_summary(folder)
            with open(folder / "tortuosity.csv", newline="") as handle:
                solve = next(csv.DictReader(line for line in handle if not line.startswith("#")))
            rows.append({"state": state, "voxel_size_um": spacing, "grid": summary["grid"],
                         "porosity_voxels": summary["porosity_voxels"], "porosity_analytic": summary["porosity_analytic"],
                         "tortuosity_z": summary["tortuosity_z"], "iterations": solve["iterations"],
                         "seconds": solve["seconds"]})

    table = ROOT / f"data/microstructure/{args.example}_convergence.csv"
    table.parent.mkdir(parents=True, exist_ok=True)
    with open(table, "w", newline="") as handle:
        handle.write(f"# docs/microstructure_figure.py --example {args.example}: tau_z of the loaded and released "
                     "states at several voxel sizes (ellc analyse --axes z)\n")
        writer = csv.DictWriter(handle, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {table}")
    print("| state | voxel size (um) | grid | porosity (voxels) | tau_z | CG iterations | seconds |")
    print("|---|---|---|---|---|---|---|")
    for row in rows:
        print(f"| {row['state']} | {row['voxel_size_um']:g} | {row['grid']} | {float(row['porosity_voxels']):.4f} | "
              f"{float(row['tortuosity_z']):.4f} | {row['iterations']} | {float(row['seconds']):.1f} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    states = [(state, microstructure.read_summary(run_directory / f"analysis_{state}"))
              for state in ("loaded", "released")]
    figure = microstructure.tortuosity_porosity_figure(
        states, title=f"examples/{args.example}.toml: through-plane tortuosity of the loaded and released states")
    axes = figure.axes[0]
    for index, state in enumerate(("loaded", "released")):
        chosen = [row for row in rows if row["state"] == state]
        axes.plot([float(r["porosity_voxels"]) for r in chosen], [float(r["tortuosity_z"]) for r in chosen], "x:",
                  color=plt.get_cmap("tab10")(index), ms=5, lw=0.8,
                  label=f"{state}: voxel sizes {min(r['voxel_size_um'] for r in chosen):g}-"
                        f"{max(r['voxel_size_um'] for r in chosen):g} um")
    axes.legend(fontsize=7)
    image = ROOT / f"docs/img/microstructure_tortuosity_porosity_{args.example}.png"
    figure.savefig(image)
    print(f"wrote {image}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
