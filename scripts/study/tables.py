"""Tables of the scenario studies (scripts/convergence_study.sh, scripts/sensitivity_study.sh).

    tables.py convergence OUT_DIR "SPEEDS" "SEEDS" SCENARIO
    tables.py sensitivity OUT_DIR "VARIANTS" "SEEDS" SCENARIO

Each run lives in OUT_DIR/<variant>_s<seed>/ with its summary.txt and timeseries.csv; only
finished runs count. The table goes to stdout and OUT_DIR/<study>.md.
"""
import csv
import pathlib
import statistics
import sys
import tomllib

# The summary figures the studies compare: key, name, unit of a change, relative change?
FIGURES = [("loaded_thickness_um", "loaded thickness", "%", True),
           ("springback_percent", "springback", "points", False),
           ("held_pressure_MPa", "held pressure", "%", True)]
# Issue 13's convergence criterion: halving v·√s changes each figure's mean by less than this.
CRITERION = {"loaded_thickness_um": 0.2, "springback_percent": 0.1, "held_pressure_MPa": 1.0}


def verdict(changes, limit):
    """The paired changes against a limit on |mean change|, with the mean's 2-standard-error band:
    met (the whole band inside), not met (the whole band outside) or undecided (which side the
    mean is on)."""
    if len(changes) < 2:
        return "–"
    mean = statistics.mean(changes)
    band = 2.0 * statistics.stdev(changes) / len(changes) ** 0.5
    if abs(mean) + band < limit:
        return f"met (abs Δ + 2 SE = {abs(mean) + band:.3f} < {limit:g})"
    if abs(mean) - band > limit:
        return f"not met (abs Δ − 2 SE = {abs(mean) - band:.3f} > {limit:g})"
    side = "<" if abs(mean) < limit else "≥"
    return f"undecided (abs Δ = {abs(mean):.3f} {side} {limit:g}, ± {band:.3f})"


def summary(run_dir):
    """The run's summary.txt as a dict, or None when it is missing or the run did not finish."""
    path = run_dir / "summary.txt"
    if not path.exists():
        return None
    with path.open("rb") as handle:
        values = tomllib.load(handle)  # summary.txt is a TOML document (docs/engine.md)
    return values if values.get("finished") is True else None


def last_row(run_dir):
    """The last row of the run's timeseries.csv (the energies at the end), or None."""
    path = run_dir / "timeseries.csv"
    if not path.exists():
        return None
    row = None
    with path.open() as f:
        for row in csv.DictReader(f):
            pass
    return row


def mean_sd(values, digits=3, sign=""):
    if not values:
        return "–"
    if len(values) == 1:
        return f"{values[0]:{sign}.{digits}f}"
    return f"{statistics.mean(values):{sign}.{digits}f} ± {statistics.stdev(values):.{digits}f}"


def paired_change(pairs, key, relative):
    return [(float(b[key]) - float(a[key])) * (100.0 / float(a[key]) if relative else 1.0) for a, b in pairs]


def reading_limits(runs):
    """The largest unbalanced-force ratio and inertial number at the loaded and released readings."""
    keys = ["loaded_unbalanced_force_ratio", "released_unbalanced_force_ratio", "loaded_inertial_number",
            "released_inertial_number"]
    if not runs:
        return "–", "–"
    worst = [max(float(r[k]) for r in runs) for k in keys]
    return f"{max(worst[:2]):.2e}", f"{max(worst[2:]):.2e}"


def convergence(out, speeds, seeds, scenario):
    lines = [f"# Rate convergence of `{scenario}`", "",
             f"Seeds: {' '.join(seeds)}. Each row: the paired change from the previous speed to this one, "
             "mean ± sd over the seeds [standard error of the mean]. The last two columns: the largest "
             "unbalanced-force ratio and inertial number at the loaded and released readings of the row's runs.", "",
             "| v (µm/µs) | from | runs | " + " | ".join(f"Δ {name} ({unit})" for _, name, unit, _ in FIGURES) +
             " | ratio at the readings (max) | I at the readings (max) |",
             "|---" * (len(FIGURES) + 5) + "|"]
    verdicts = []
    for previous, v in zip(speeds, speeds[1:]):
        pairs = [(summary(out / f"v{previous}_s{s}"), summary(out / f"v{v}_s{s}")) for s in seeds]
        pairs = [(a, b) for a, b in pairs if a and b]
        cells, judged = [], []
        for key, _, _, relative in FIGURES:
            d = paired_change(pairs, key, relative)
            if len(d) > 1:
                sd = statistics.stdev(d)
                cells.append(f"{statistics.mean(d):+.3f} ± {sd:.3f} [{sd / len(d) ** 0.5:.3f}]")
            else:
                cells.append("–")
            judged.append(verdict(d, CRITERION[key]))
        ratio, inertial = reading_limits([b for _, b in pairs] + [a for a, _ in pairs])
        lines.append(f"| {v} | {previous} | {len(pairs)} | " + " | ".join(cells) + f" | {ratio} | {inertial} |")
        verdicts.append(f"| {previous} → {v} | {len(pairs)} | " + " | ".join(judged) + " |")
    lines += ["", "Against the criterion (issue 13: halving v·√s moves the mean by less than "
              "0.2 % in loaded thickness, 0.1 point in springback, 1 % in held pressure), with the "
              "mean's band of ± 2 standard errors:", "",
              "| halving | pairs | " + " | ".join(name for _, name, _, _ in FIGURES) + " |",
              "|---" * (len(FIGURES) + 2) + "|", *verdicts]
    lines += ["", "Means over the finished runs of each speed:", "",
              "| v (µm/µs) | runs | " + " | ".join(f"{name}" for _, name, _, _ in FIGURES) + " |",
              "|---" * (len(FIGURES) + 2) + "|"]
    for v in speeds:
        runs = [r for r in (summary(out / f"v{v}_s{s}") for s in seeds) if r]
        lines.append(f"| {v} | {len(runs)} | " +
                     " | ".join(mean_sd([float(r[key]) for r in runs]) for key, _, _, _ in FIGURES) + " |")
    lines += ["", "Finished runs, one line each (the plate work and the friction dissipation over the whole run):", "",
              "| run | loaded thickness (µm) | released thickness (µm) | springback (%) | held pressure (MPa) | "
              "unbalanced-force ratio loaded / released | plate work (pJ) | friction dissipation (pJ) | steps |",
              "|---" * 9 + "|"]
    for v in speeds:
        for s in seeds:
            r = summary(out / f"v{v}_s{s}")
            if not r:
                continue
            end = last_row(out / f"v{v}_s{s}") or {}
            friction = f"{float(end['friction_dissipation']):.4g}" if "friction_dissipation" in end else "–"
            plate = f"{float(r['plate_work_pJ']):.4g}" if "plate_work_pJ" in r else "–"
            lines.append(f"| v{v}_s{s} | {float(r['loaded_thickness_um']):.3f} | {float(r['final_thickness_um']):.3f} | "
                         f"{float(r['springback_percent']):.3f} | {float(r['held_pressure_MPa']):.2f} | "
                         f"{float(r['loaded_unbalanced_force_ratio']):.1e} / "
                         f"{float(r['released_unbalanced_force_ratio']):.1e} | "
                         f"{plate} | {friction} | "
                         f"{r['steps']} |")
    return "convergence.md", lines


# Where the plate work went, as shares of the net plate work of the cycle (the work of both plates).
SHARES = [("plastic_dissipation", "plastic"), ("friction_dissipation", "friction"),
          ("damping_dissipation", "dashpots"), ("drag_dissipation", "drag")]


def sensitivity(out, variants, seeds, scenario):
    """VARIANTS: labels z<ζ>_m<μ>; the first is the reference the changes are paired against."""
    lines = [f"# Sensitivity of `{scenario}` to the dashpot ratio ζ and the friction coefficient μ", "",
             f"Seeds: {' '.join(seeds)}. ζ is `[contact] damping_ratio` (both dashpots); μ is `[contact] friction` "
             "and `[walls] friction` together. Figures: mean ± sd over the seeds; Δ: the paired change "
             f"from the reference ({variants[0]}) over the same seeds, mean ± sd. Energy shares: the "
             "dissipation of each kind over the whole run, over the plate work (both plates).", "",
             "| ζ | μ | runs | loaded thickness (µm) | Δ (%) | springback (%) | Δ (points) | held pressure (MPa) | "
             + " | ".join(f"{name} share" for _, name in SHARES) + " | ratio at the readings (max) |",
             "|---" * (8 + len(SHARES) + 1) + "|"]
    reference = {s: summary(out / f"{variants[0]}_s{s}") for s in seeds}
    for variant in variants:
        zeta, mu = variant[1:].split("_m")
        runs = {s: summary(out / f"{variant}_s{s}") for s in seeds}
        done = [s for s in seeds if runs[s]]
        pairs = [(reference[s], runs[s]) for s in done if reference[s]]
        figure = lambda key: mean_sd([float(runs[s][key]) for s in done])
        shares = []
        for column, _ in SHARES:
            values = []
            for s in done:
                row = last_row(out / f"{variant}_s{s}")
                work = float(runs[s]["plate_work_pJ"])
                if row and work > 0:
                    values.append(100.0 * float(row[column]) / work)
            shares.append(mean_sd(values, 1) + " %" if values else "–")
        ratio, _ = reading_limits([runs[s] for s in done])
        same = variant == variants[0]
        lines.append(f"| {zeta} | {mu} | {len(done)} | {figure('loaded_thickness_um')} | " +
                     ("–" if same else mean_sd(paired_change(pairs, "loaded_thickness_um", True), 3, "+")) +
                     f" | {figure('springback_percent')} | " +
                     ("–" if same else mean_sd(paired_change(pairs, "springback_percent", False), 3, "+")) +
                     f" | {figure('held_pressure_MPa')} | " + " | ".join(shares) + f" | {ratio} |")
    return "sensitivity.md", lines


if __name__ == "__main__":
    study, out, variants, seeds, scenario = sys.argv[1:6]
    name, lines = {"convergence": convergence, "sensitivity": sensitivity}[study](
        pathlib.Path(out), variants.split(), seeds.split(), scenario)
    (pathlib.Path(out) / name).write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
