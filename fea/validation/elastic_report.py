"""Elastic check: FE force against exact elliptical Hertz, three mesh levels."""
from __future__ import annotations

import numpy as np

from .data import complete_runs
from .plotting import figure, save

PAIRS = {"e_sphere": "spheres 10/10 um", "e_case2": "case-2 pair (1:1:0.8 / 1:1.25:1.25)",
         "e_case1": "case-1 pair (1:1.25:1.5 / 1:0.5:0.8)"}
LEVELS = ("coarse", "medium", "fine")


def elastic_errors() -> dict:
    """{pair: {level: {"overlap", "error" (relative, vs exact Hertz), "nodes", "seconds"}}}"""
    out: dict = {}
    for run in complete_runs("e_"):
        pair, level = run.name.split("_elastic_")
        contact = run.contact(exact=True)
        err = run.force / contact.hertz(run.overlap) - 1.0
        out.setdefault(pair, {})[level] = {"overlap": run.overlap, "error": err,
                                           "nodes": run.record["nodes"],
                                           "seconds": run.record["ccx_seconds"],
                                           "delta_y": contact.delta_y}
    return out


def plot_elastic(errors: dict) -> str:
    fig, axes = figure(len(PAIRS), width=4.2)
    for ax, (pair, label) in zip(axes, PAIRS.items()):
        for level in LEVELS:
            entry = errors.get(pair, {}).get(level)
            if entry:
                ax.plot(entry["overlap"], 100 * entry["error"], "o-",
                        label=f"{level} ({entry['nodes']} nodes)")
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set(title=label, xlabel="overlap δ (µm)", ylabel="FE / exact Hertz − 1 (%)")
        ax.legend(fontsize=8)
    return save(fig, "elastic_hertz_error.png")


def elastic_table(errors: dict) -> list[str]:
    lines = ["| pair | mesh | nodes | ccx time (s) | error at δ_end | max abs error |",
             "| --- | --- | ---: | ---: | ---: | ---: |"]
    for pair, label in PAIRS.items():
        for level in LEVELS:
            e = errors.get(pair, {}).get(level)
            if e:
                lines.append(f"| {label} | {level} | {e['nodes']} | {e['seconds']:.0f} | "
                             f"{100 * e['error'][-1]:+.2f} % | {100 * np.abs(e['error']).max():.2f} % |")
    return lines
