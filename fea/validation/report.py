"""fea/make_validation: recompute every number and figure of docs/validation.md from data/fea.

Tables go between <!-- BEGIN:key --> and <!-- END:key --> markers in the document, so the
prose stays hand-written while the numbers always match the committed data.
"""
from __future__ import annotations

import json
import os
import re
import sys

from . import aluminium_report as alu
from . import calibration_report as cal
from .elastic_report import elastic_errors, elastic_table, plot_elastic
from .ellc_fit import ellc_fit
from .plotting import REPO
from .tables import markdown_table, pct
from .protocol_report import plot_protocols, protocol_results, protocol_table

DOC = os.path.join(REPO, "docs", "validation.md")
SUMMARY = os.path.join(REPO, "data", "fea", "validation_summary.json")


def _replace(text: str, key: str, lines: list[str]) -> str:
    pattern = re.compile(rf"(<!-- BEGIN:{key} -->\n).*?(<!-- END:{key} -->)", re.S)
    if not pattern.search(text):
        print(f"make_validation: no markers for {key} in docs/validation.md", file=sys.stderr)
        return text
    return pattern.sub(lambda m: m.group(1) + "\n".join(lines) + "\n" + m.group(2), text)


def _summary_entries(cases: dict) -> dict:
    """Per-case results for the JSON summary: without the Run objects and the law's force arrays."""
    return {n: {k: ({q: v for q, v in e.items() if q != "force"} if isinstance(e, dict) else e)
                for k, e in c.items() if k != "run"} for n, c in cases.items()}


def _constants_table(fits: dict[str, dict], n_best: float) -> list[str]:
    keys = ("m", "o", "p", "s", "t", "u")
    body = [[label, *(f"{f[k]:.2f}" for k in keys), f"{f['n']:.2f}", f"{f['lam_rms']:.3f}", f"{f['eps_rms']:.2f}"]
             for label, f in fits.items()]
    body.append(["best common n (summed rms force error)", *[""] * 6, f"{n_best:.1f}", "", ""])
    return markdown_table(["constants", *keys, "n", "rms λ_max", "rms ε_max"], "lrrrrrrrrr", body)


def _case_table(rows: list[dict]) -> list[str]:
    body = [[r["run"].name, f"{r['x']:.3f}", pct(r["pre_yield"], 1, sign=True), f"{r['max_over_yield']:.1f}",
             f"{r['fixed'].lam_max:.2f}",
             f"{r['fixed'].eps_max:.2f}", "yes" if r["fixed"].plateau else "no", pct(r["fixed"].rms),
             f"{r['free'].lam_max:.2f}, {r['free'].eps_max:.2f}, {r['free'].n:.2f}"] for r in rows]
    return markdown_table(["case", "R_e/r̂", "F_FE/F_Hertz − 1 below δ_Y", "δ_end/δ_Y", "λ_max", "ε_max",
                           "plateau", "rms force error", "n free: λ_max, ε_max, n"], "lrrrrrlrl", body)


def _effect_table(effect: list[dict]) -> list[str]:
    body = [[e["name"], f"{pct(e['paper']['mean_rel'])} / {pct(e['paper']['max_rel'])}",
             f"{pct(e['ours']['mean_rel'])} / {pct(e['ours']['max_rel'])}", pct(e["max_change"])]
            for e in effect]
    return markdown_table(["case", "law vs FE, paper constants: mean / max", "ours: mean / max",
                           "largest change of the force"], "lrrr", body)


def main() -> int:
    with open(DOC) as fh:
        text = fh.read()
    summary: dict = {}
    errors = elastic_errors()
    plot_elastic(errors)
    text = _replace(text, "elastic", elastic_table(errors))
    summary["elastic"] = {p: {lv: {"final_error": float(e["error"][-1]), "nodes": e["nodes"]}
                              for lv, e in d.items()} for p, d in errors.items()}
    text = _replace(text, "plastic_mesh", cal.plastic_mesh_table())
    rows = cal.per_case_fits()
    if len(rows) >= 4:
        fits = {}
        for label, sel in cal.subsets(rows).items():
            if len(sel) < 3:
                continue
            fits[f"{label}: paper (eq. 53)"] = cal.paper_rms(sel)
            if len(sel) >= 8:  # fewer cases leave the decay rates undetermined
                fits[f"{label}: ours, o and t fitted"] = cal.constants_fit(sel)
            fits[f"{label}: ours, o and t kept at the paper's"] = cal.constants_fit(sel, paper_rates=True)
        ours = cal.recommended_constants(rows)
        # All cases at once, for comparison: its own n leaves g03_oblate at 11.6 % RMS, above the
        # 10 % that `ellc fit` accepts by default, so the report asks for the model anyway.
        cxx = ellc_fit([r["run"] for r in rows], ("--accept-poor-fit",))
        if cxx:
            label = f"`ellc fit --accept-poor-fit` (C++), all {len(rows)} cases, its own n"
            fits[label] = {**cxx, "lam_rms": float("nan"), "eps_rms": float("nan")}
        n_best, _ = cal.common_n(rows)
        effect = cal.force_effect(rows, ours)
        cal.plot_lambda_profiles(rows)
        cal.plot_constants(rows, ours)
        text = _replace(text, "constants", _constants_table(fits, n_best))
        text = _replace(text, "cases", _case_table(rows))
        text = _replace(text, "effect", _effect_table(effect))
        summary["constants"] = fits
        summary["common_n"] = n_best
        summary["force_effect"] = effect
    results = protocol_results()
    if results:
        plot_protocols(results)
        text = _replace(text, "protocols", protocol_table(results))
        summary["protocols"] = {n: {m: {k: v for k, v in e[m].items() if k != "force"}
                                    for m in ("hale", "exact")} for n, e in results.items()}
        if len(rows) >= 4:
            mine = protocol_results(constants=ours)
            plot_protocols(mine, suffix="_our_constants", constants=ours)
            text = _replace(text, "protocols_ours", protocol_table(mine))
    aluminium = alu.results()
    if aluminium["models"]:
        text = _replace(text, "aluminium_constants", alu.constants_table(aluminium))
        text = _replace(text, "aluminium_holdout", alu.holdout_table(aluminium))
        text = _replace(text, "aluminium_partial", alu.partial_table(aluminium))
        text = _replace(text, "aluminium_nmc", alu.nmc_check(aluminium))
        alu.plot_holdout(aluminium)
        summary["aluminium"] = {
            "fit_cases": aluminium["fit_cases"], "held_out": aluminium["held_out"],
            "nmc_fit_cases": aluminium.get("nmc_fit_cases", []), "models": aluminium["models"],
            "cases": _summary_entries(aluminium["cases"]), "partial": _summary_entries(aluminium.get("partial", {}))}
    with open(DOC, "w") as fh:
        fh.write(text)
    with open(SUMMARY, "w") as fh:
        json.dump(summary, fh, indent=1, default=float)
        fh.write("\n")
    print(f"make_validation: updated {os.path.relpath(DOC, REPO)} and {os.path.relpath(SUMMARY, REPO)}")
    return 0
