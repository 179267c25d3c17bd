"""The tortuosity-porosity figure and the resolution-convergence table of docs/microstructure.md.

Runs the calendering example (examples/calendering.toml) with an [analysis] table, so that
`ellc dem` analyses its loaded and released states, then `ellc analyse` on the two saved packings
at several voxel sizes (through-plane tortuosity only), and writes

  docs/img/microstructure_tortuosity_porosity_EXAMPLE.png   tau_z against porosity, with Bruggeman
  data/microstructure/EXAMPLE_convergence.csv               tau_z and porosity per state and voxel size

The voxel sizes run from coarse to fine, both states at each size, and the table is rewritten
after each analysis, so an interrupted call leaves the sizes it finished; a second call reuses
every finished analysis folder (OUT/convergence/STATE_SIZE/analysis.txt); with --finished-only
(and --skip-run) it runs nothing and draws what is finished.

Usage (from the repository root):

  # the full example (2000 particles): the DEM run takes ~3-5 min on 2 idle cores (25 min under load);
  # the 0.5 um analyses (200 x 200 x 170 voxels) several minutes each
  nice -n 5 /usr/bin/python3 docs/microstructure_figure.py --example calendering --out out/microstructure
  # the quick example (100 particles):
  nice -n 10 /usr/bin/python3 docs/microstructure_figure.py --example calendering_quick --out out/microstructure_quick \
      --spacings 1.6,1.2,0.8,0.6
  # again without the DEM run (reuses OUT/run):
  /usr/bin/python3 docs/microstructure_figure.py --out out/microstructure --skip-run
"""

import argparse
import csv
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


def write_table(table, example, rows):
    table.parent.mkdir(parents=True, exist_ok=True)
    with open(table, "w", newline="") as handle:
        handle.write(f"# docs/microstructure_figure.py --example {example}: tau_z of the loaded and released "
                     "states at several voxel sizes (ellc analyse --axes z --coarse-factor 1)\n")
        writer = csv.DictWriter(handle, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
        for state in ("loaded", "released"):
            bracket = converged_bracket([row for row in rows if row["state"] == state])
            if bracket:
                handle.write(f"# {state}: {bracket[2]}\n")
            fit = power_law_extrapolation([row for row in rows if row["state"] == state])
            if fit:
                handle.write(f"# {state}: tau_z = tau_0 + C h^p through the three finest sizes: p = {fit[1]:.2f}, "
                             f"tau_0 = {fit[0]:.3f} (an estimate, not a bound)\n")


def converged_bracket(rows):
    """(low, high, sentence) bounding the converged tau_z from the finest sizes, or None.

    Where tau falls monotonically as the voxels shrink and its slope d tau / d h shrinks too (as
    measured), the converged value lies between the straight line through the two finest sizes,
    extrapolated to h = 0, and the finest value. Otherwise no bracket is claimed."""
    points = sorted((float(r["voxel_size_um"]), float(r["tortuosity_z"])) for r in rows)
    if len(points) < 3:
        return None
    slopes = [(t2 - t1) / (h2 - h1) for (h1, t1), (h2, t2) in zip(points, points[1:])]
    (h1, t1), (h2, _) = points[0], points[1]
    extrapolated = t1 - slopes[0] * h1
    monotone_convex = all(s > 0 for s in slopes) and all(a <= b for a, b in zip(slopes, slopes[1:]))
    if not monotone_convex:
        return None
    return (extrapolated, t1, f"tau_z falls with a shrinking slope as the voxels shrink; if it goes on so below "
            f"{h1:g} um, the converged value lies between {extrapolated:.3f} (the line through {h2:g} and {h1:g} um "
            f"extrapolated to 0) and {t1:.3f} (at {h1:g} um): the finest value is at most "
            f"{100 * (t1 / extrapolated - 1):.0f} % high")


def power_law_extrapolation(rows):
    """(tau_0, p) of tau_z = tau_0 + C h^p through the three finest sizes, or None.

    An estimate of the converged value, not a bound: it assumes the three finest sizes already
    follow one power of h."""
    points = sorted((float(r["voxel_size_um"]), float(r["tortuosity_z"])) for r in rows)[:3]
    if len(points) < 3:
        return None
    (h1, t1), (h2, t2), (h3, t3) = points
    if not (t1 < t2 < t3):
        return None
    target = (t3 - t2) / (t2 - t1)

    def ratio(p):
        return (h3 ** p - h2 ** p) / (h2 ** p - h1 ** p)

    low, high = 0.05, 10.0  # ratio(p) grows with p
    if not ratio(low) < target < ratio(high):
        return None
    for _ in range(200):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if ratio(middle) < target else (low, middle)
    p = 0.5 * (low + high)
    c = (t2 - t1) / (h2 ** p - h1 ** p)
    return t1 - c * h1 ** p, p


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default=str(ROOT / "build/apps/ellc"))
    parser.add_argument("--out", default=str(ROOT / "out/microstructure"))
    parser.add_argument("--skip-run", action="store_true", help="reuse OUT/run from an earlier call")
    parser.add_argument("--finished-only", action="store_true",
                        help="run no analysis: table and figure from the finished folders of an earlier call")
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

    spacings = sorted((float(s) for s in args.spacings.split(",")), reverse=True)  # coarse first
    table = ROOT / f"data/microstructure/{args.example}_convergence.csv"
    rows = []
    for spacing in spacings:
        for state in ("loaded", "released"):
            packing = run_directory / f"analysis_{state}" / "packing.csv"
            folder = out / "convergence" / f"{state}_{spacing:g}"
            if not (folder / "analysis.txt").exists():
                if args.finished_only:
                    print(f"not finished, left out: {folder}")
                    continue
                run([args.cli, "analyse", packing, "--spacing", spacing, "--axes", "z", "--coarse-factor", "1",
                     "--no-plot", "-o", folder])
            summary = microstructure.read_summary(folder)
            with open(folder / "tortuosity.csv", newline="") as handle:
                solve = next(csv.DictReader(line for line in handle if not line.startswith("#")))
            rows.append({"state": state, "voxel_size_um": spacing, "grid": " x ".join(map(str, summary["grid"])),
                         "porosity_voxels": summary["porosity_voxels"], "porosity_analytic": summary["porosity_analytic"],
                         "tortuosity_z": summary["tortuosity_z"], "iterations": solve["iterations"],
                         "seconds": solve["seconds"]})
            write_table(table, args.example, rows)
    print(f"wrote {table}")
    print("| state | voxel size (um) | grid | porosity (voxels) | tau_z | CG iterations | seconds |")
    print("|---|---|---|---|---|---|---|")
    for row in rows:
        print(f"| {row['state']} | {row['voxel_size_um']:g} | {row['grid']} | {float(row['porosity_voxels']):.4f} | "
              f"{float(row['tortuosity_z']):.4f} | {row['iterations']} | {float(row['seconds']):.1f} |")
    for state in ("loaded", "released"):
        bracket = converged_bracket([row for row in rows if row["state"] == state])
        if bracket:
            print(f"{state}: {bracket[2]}")
        fit = power_law_extrapolation([row for row in rows if row["state"] == state])
        if fit:
            print(f"{state}: tau_z = tau_0 + C h^p through the three finest sizes: p = {fit[1]:.2f}, tau_0 = {fit[0]:.3f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    states = [(state, microstructure.read_summary(run_directory / f"analysis_{state}"))
              for state in ("loaded", "released")]
    figure = microstructure.tortuosity_porosity_figure(
        states, title=f"examples/{args.example}.toml:\nthrough-plane tortuosity of the loaded and released states")
    axes = figure.axes[0]
    for index, state in enumerate(("loaded", "released")):
        chosen = [row for row in rows if row["state"] == state]
        axes.plot([float(r["porosity_voxels"]) for r in chosen], [float(r["tortuosity_z"]) for r in chosen], "x:",
                  color=plt.get_cmap("tab10")(index), ms=5, lw=0.8,
                  label=f"{state}: voxel sizes {min(r['voxel_size_um'] for r in chosen):g}-"
                        f"{max(r['voxel_size_um'] for r in chosen):g} um")
        bracket = converged_bracket(chosen)
        if bracket:
            porosity = float(min(chosen, key=lambda r: float(r["voxel_size_um"]))["porosity_voxels"])
            axes.plot([porosity, porosity], bracket[:2], "-", color=plt.get_cmap("tab10")(index), lw=3, alpha=0.35,
                      label=f"{state}: bracket of the converged value")
        fit = power_law_extrapolation(chosen)
        if fit:
            porosity = float(min(chosen, key=lambda r: float(r["voxel_size_um"]))["porosity_voxels"])
            axes.plot(porosity, fit[0], "*", color=plt.get_cmap("tab10")(index), ms=9,
                      label=f"{state}: tau_0 + C h^p extrapolated, p = {fit[1]:.2f}")
    axes.legend(fontsize=7)
    image = ROOT / f"docs/img/microstructure_tortuosity_porosity_{args.example}.png"
    figure.savefig(image)
    print(f"wrote {image}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
