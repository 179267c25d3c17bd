#!/usr/bin/python3
"""The README's performance plot from bench/scaling.py's JSON: particle-steps/s against N (one and
two threads, ellipsoids and spheres), CPU time per particle-step against N (steadier than wall
time on a loaded machine), and two threads over one thread against N when the JSON has both.

  /usr/bin/python3 bench/plot_scaling.py bench/results/scaling.json docs/img/performance_scaling.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    rows = json.load(open(sys.argv[1]))
    title = sys.argv[3] if len(sys.argv) > 3 else ""
    has_two_threads = any(r["threads"] == 2 for r in rows)
    fig, axes = plt.subplots(1, 3 if has_two_threads else 2, figsize=(14 if has_two_threads else 10, 4))
    rate_ax, cpu_ax = axes[0], axes[1]
    scale_ax = axes[2] if has_two_threads else None
    labels = {"BM_dem_ellipsoids_becker_kamlah": "ellipsoids (Becker–Kamlah)", "BM_dem_spheres_hertz": "spheres (Hertz)"}
    for bench, label in labels.items():
        for threads, style in ((1, "o-"), (2, "s--")):
            points = sorted((r["particles"], r["particle_steps_per_s"]) for r in rows
                            if r["benchmark"] == bench and r["threads"] == threads)
            if points:
                rate_ax.plot(*zip(*points), style, label=f"{label}, {threads} thread{'s' if threads > 1 else ''}")
            cpu = sorted((r["particles"], r["cpu_ns_per_particle_step"]) for r in rows
                         if r["benchmark"] == bench and r["threads"] == threads and r.get("cpu_ns_per_particle_step"))
            if cpu:
                cpu_ax.plot(*zip(*cpu), style, label=f"{label}, {threads} thread{'s' if threads > 1 else ''}")
        one = {r["particles"]: r["particle_steps_per_s"] for r in rows if r["benchmark"] == bench and r["threads"] == 1}
        two = {r["particles"]: r["particle_steps_per_s"] for r in rows if r["benchmark"] == bench and r["threads"] == 2}
        common = sorted(set(one) & set(two))
        if common and scale_ax is not None:
            scale_ax.plot(common, [two[n] / one[n] for n in common], "o-", label=label)
    rate_ax.set(xscale="log", yscale="log", xlabel="particles N", ylabel="particle-steps / s",
                title="bench_dem throughput")
    cpu_ax.set(xscale="log", xlabel="particles N", ylabel="CPU ns per particle-step", title="cost per particle-step")
    cpu_ax.set_ylim(bottom=0)
    if scale_ax is not None:
        scale_ax.axhline(1.0, color="grey", lw=0.8)
        scale_ax.set(xscale="log", xlabel="particles N", ylabel="2 threads / 1 thread", title="thread scaling")
        scale_ax.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=9)
    # One legend for the first two panels, below them: inside either it covered a curve.
    handles, labels_of = rate_ax.get_legend_handles_labels()
    fig.legend(handles, labels_of, loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0.0, 0.07, 1.0, 1.0))
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
