"""The paper's case 1 and case 2 protocols: FE against the law (Hale and exact)."""
from __future__ import annotations

import numpy as np

from .curves import law_forces
from .data import load_run
from .errors import force_errors
from .fit import loading_points
from .plotting import figure, save
from .tables import markdown_table, pct

CASES = {"paper_case1": "case 1 (paper: mean error 1.01 %)", "paper_case2": "case 2 (paper: mean error 0.59 %)"}


def protocol_results(constants: dict | None = None) -> dict:
    out = {}
    for name in CASES:
        run = load_run(name)
        if run is None:
            continue
        entry = {"run": run}
        for mode in ("hale", "exact"):
            law, source = law_forces(run.case, run.overlap, mode, constants=constants)
            _, fe_f = loading_points(run.overlap, run.force)
            _, law_f = loading_points(run.overlap, law)  # same mask: it depends on overlap only
            loading = force_errors(law_f, fe_f)
            entry[mode] = {"force": law, "source": source, **force_errors(law, run.force),
                           "loading_mean": loading["mean_rel"], "loading_max": loading["max_rel"]}
        out[name] = entry
    return out


def dense_path(waypoints, points: int) -> np.ndarray:
    """The protocol sampled finely (for drawing the law as a line)."""
    segs = [np.linspace(a, b, points + 1)[1:] for a, b in zip(waypoints, waypoints[1:])]
    return np.concatenate(segs)


def plot_protocols(results: dict, suffix: str = "", constants: dict | None = None) -> str:
    fig, axes = figure(max(1, len(results)), width=5.0)
    for ax, (name, entry) in zip(axes, results.items()):
        run = entry["run"]
        contact = run.contact()
        x = run.overlap / contact.delta_y
        ax.plot(x, run.force / contact.f_py, "o", ms=3, color="tab:blue", alpha=0.6, label="FE (CalculiX)")
        dense = dense_path(run.case.waypoints, 60)
        for mode, style in (("hale", "-"), ("exact", "--")):
            e = entry[mode]
            law, _ = law_forces(run.case, dense, mode, constants=constants)
            ax.plot(dense / contact.delta_y, law / contact.f_py, style, lw=1,
                    label=f"law, {mode} ({e['source']}): mean {100 * e['mean_rel']:.2f} %, "
                          f"max {100 * e['max_rel']:.1f} %")
        ax.set(title=f"{name}: {CASES[name]}", xlabel="δ / δ_Y", ylabel="F / F_pY")
        ax.legend(fontsize=7)
    return save(fig, f"paper_cases{suffix}.png")


def protocol_table(results: dict) -> list[str]:
    body = [[name, mode, e["source"], pct(e["mean_rel"]), pct(e["max_rel"]), pct(e["mean_of_peak"]),
             pct(e["max_of_peak"]), f"{pct(e['loading_mean'])} / {pct(e['loading_max'])}"]
            for name, entry in results.items() for mode in ("hale", "exact") if (e := entry[mode])]
    return markdown_table(["case", "Hertz", "source", "mean rel. error", "max rel. error",
                           "mean of F_max", "max of F_max", "virgin loading only: mean / max rel."],
                          "lllrrrrr", body)
