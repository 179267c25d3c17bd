"""Elastic check: FE force against exact elliptical Hertz, three mesh levels."""
from __future__ import annotations

import numpy as np

from .data import complete_runs
from .plotting import figure, save
from .tables import markdown_table, pct

PAIRS = {"e_sphere": "spheres 10/10 um", "e_case2": "case-2 pair (1:1:0.8 / 1:1.25:1.25)",
         "e_case1": "case-1 pair (1:1.25:1.5 / 1:0.5:0.8)", "e_oblate": "oblate pair 1:2:2 (grid g03)"}
LEVELS = ("coarse", "medium", "fine")


def elastic_errors() -> dict:
    """{pair: {level: {"overlap", "error" (force, relative to exact Hertz), "nodes", "seconds",
    "contact_error" (equivalent contact radius at the last increment)}}}"""
    out: dict = {}
    for run in complete_runs("e_"):
        pair, level = run.name.split("_elastic_")
        contact = run.contact(exact=True)
        err = run.force / contact.hertz(run.overlap) - 1.0
        c_fe = np.sqrt(run.table["contact_semi_y"][-1] * run.table["contact_semi_z"][-1])
        out.setdefault(pair, {})[level] = {"overlap": run.overlap, "error": err,
                                           "nodes": run.record["nodes"],
                                           "seconds": run.record["ccx_seconds"],
                                           "contact_error": float(c_fe / np.sqrt(contact.c2(run.overlap[-1])) - 1.0)}
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
    body = [[label, level, str(e["nodes"]), f"{e['seconds']:.0f}", pct(e["error"][-1], sign=True),
             pct(float(np.abs(e["error"]).max())), pct(e["contact_error"], 1, sign=True)]
            for pair, label in PAIRS.items() for level in LEVELS
            if (e := errors.get(pair, {}).get(level))]
    return markdown_table(["pair", "mesh", "nodes", "ccx time (s)", "force error at δ_end",
                           "max abs force error", "c_c = √(a_c b_c) error at δ_end"], "llrrrrr", body)
