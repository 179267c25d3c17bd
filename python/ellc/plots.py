"""Plots for the ellc tools. Run as ``python3 -m ellc.plots curve IN.csv OUT.png``."""

import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    """Reads a CSV with a header into a dict of column name -> list (floats where possible)."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    columns = {}
    for name in rows[0].keys() if rows else []:
        values = [row[name] for row in rows]
        try:
            columns[name] = [float(v) for v in values]
        except ValueError:
            columns[name] = values
    return columns


def plot_force_overlap(columns, axes, title=None):
    """F/F_pY against delta/delta_Y as in the paper's Fig. 13 and 15."""
    x = columns["overlap_over_yield"]
    axes.plot(x, columns["force_over_yield"], color="tab:blue", lw=2, label="ellipsoids (Becker-Kamlah)")
    if "force_equal_volume_spheres_over_yield" in columns:
        axes.plot(x, columns["force_equal_volume_spheres_over_yield"], "--", color="tab:green",
                  label="equal-volume spheres")
    if "force_elastic_fully_plastic_over_yield" in columns:
        axes.plot(x, columns["force_elastic_fully_plastic_over_yield"], ":", color="tab:gray",
                  label="elastic-fully plastic (Thornton)")
    axes.set_xlabel(r"$\delta_n / \delta_Y$")
    axes.set_ylabel(r"$F_n / F_{pY}$")
    axes.set_xlim(left=0)
    axes.set_ylim(bottom=0)
    axes.grid(alpha=0.3)
    axes.legend(loc="upper left")
    if title:
        axes.set_title(title, fontsize=9)


def curve_command(args):
    columns = read_columns(args.csv)
    figure, axes = plt.subplots(figsize=(6.4, 4.8), dpi=120)
    plot_force_overlap(columns, axes, args.title)
    figure.tight_layout()
    figure.savefig(args.png)
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m ellc.plots")
    sub = parser.add_subparsers(dest="command", required=True)
    curve = sub.add_parser("curve", help="force-overlap curve from `ellc curve -o` CSV")
    curve.add_argument("csv")
    curve.add_argument("png")
    curve.add_argument("--title")
    curve.set_defaults(run=curve_command)
    args = parser.parse_args(argv)
    return args.run(args)


if __name__ == "__main__":
    sys.exit(main())
