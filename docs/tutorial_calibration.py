#!/usr/bin/python3
"""Tutorial: from FEA force-overlap points to a calibrated [model] table and a DEM run with it.

Run from the repository root after building (docs/python.md):

    cmake --build build-py --target ellc_cli ellc_python
    PYTHONPATH=build-py/python /usr/bin/python3 docs/tutorial_calibration.py

Options: --out DIR (default out/tutorial_calibration), --cli PATH (default build-py/apps/ellc),
--data DIR (default data/fea). Every step prints what it does; the files it writes are listed
at the end. docs/calibration.md explains the method and the data format.

Steps
  1. Collect the FE runs: CSV files `overlap,force,...` (µm, µN) and the case file of each run
     (its geometry and material), here from data/fea/manifest.json.
  2. Calibrate from Python (ellc.calibrate), read the warnings, drop runs the law cannot
     describe, and calibrate with the CLI (`ellc fit`): the same [model] table. Plots like the
     paper's Fig. 11 (lambda profiles) and Fig. 12 (eq. 52 fits).
  3. An elastic FE run is rejected with a clear message.
  4. `ellc curve` with the calibrated table against the FE curve of the paper's case 2.
  5. `ellc dem` (calendering of 100 ellipsoids) with the paper's constants and with the
     calibrated ones.
"""

import argparse
import json
import pathlib
import re
import subprocess
import sys

import numpy as np

import ellc

ROOT = pathlib.Path(__file__).resolve().parents[1]


def say(text):
    print(f"\n== {text}", flush=True)


def run(command, **options):
    """Runs an ellc command, echoing it; raises with its stderr when it fails."""
    print("   $", " ".join(str(word) for word in command), flush=True)
    completed = subprocess.run([str(word) for word in command], capture_output=True, text=True, **options)
    if completed.returncode != 0:
        raise SystemExit(f"failed ({completed.returncode}):\n{completed.stderr}")
    return completed


def fe_runs(data_dir):
    """(name, csv, case toml, elastic) of every complete FE run in the manifest."""
    manifest = json.loads((data_dir / "manifest.json").read_text())
    runs = []
    for name, record in sorted(manifest.items()):
        if record.get("status") != "complete":
            continue
        # The case file is the argument of fea/run_case in the recorded command (paths from the root).
        case = record.get("case") or record["command"].split()[1]
        runs.append((name, data_dir / record["csv"], ROOT / case, bool(record.get("elastic_only"))))
    return runs


def replace_model_table(toml_text, model_table):
    """The scenario/case text with its [model] table (if any) replaced by `model_table`."""
    without = re.sub(r"(?ms)^\[model\]\n.*?(?=^\[|\Z)", "", toml_text)
    return without.rstrip() + "\n\n" + model_table


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=str(ROOT / "out" / "tutorial_calibration"))
    parser.add_argument("--cli", default=str(ROOT / "build-py" / "apps" / "ellc"))
    parser.add_argument("--data", default=str(ROOT / "data" / "fea"))
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    cli = args.cli

    say("1. FE runs: force against overlap, with the case file of each run")
    runs = fe_runs(pathlib.Path(args.data))
    plastic = [(name, csv, case) for name, csv, case, elastic in runs if not elastic]
    elastic = [(name, csv, case) for name, csv, case, is_elastic in runs if is_elastic]
    for name, csv, case in plastic:
        print(f"   {name:24s} {csv.relative_to(ROOT)}  geometry: {case.relative_to(ROOT)}")
    if not plastic:
        raise SystemExit("no complete elastic-plastic FE run in the manifest")
    data = [f"{csv}:{case}" for _, csv, case in plastic]  # DATA.csv:CASE.toml pairs (docs/calibration.md)

    say("2a. Calibrate from Python: ellc.calibrate_files(...)")
    result = ellc.calibrate_files(data)
    print(f"   {'case':24s} {'R_e/r^':>7s} {'lambda_max':>10s} {'epsilon_max':>11s} {'plateau':>8s} {'rms':>7s}")
    for case in result.cases:
        print(f"   {case.name:24s} {case.radius_ratio:7.4f} {case.shared.lambda_max:10.4f} "
              f"{case.shared.epsilon_max:11.4f} {'yes' if case.plateau_reached else 'no':>8s} "
              f"{100 * case.model_rms:6.2f}%")
    fit = result.fit
    print(f"   m, o, p = {fit.m:.4g}, {fit.o:.4g}, {fit.p:.4g}   s, t, u = {fit.s:.4g}, {fit.t:.4g}, {fit.u:.4g}"
          f"   n = {fit.n:.4g}")
    for warning in result.warnings:
        print("   warning:", warning)

    say("2b. Read the warnings: drop the runs the law cannot describe, and fit again")
    # A run whose lambda_FEM never rises from 1.6 (epsilon_max ends on its lower bound 1) has a force
    # far off Hertz already at delta_Y: its FE model or its geometry does not suit the law, and it
    # would pull eq. (52) off for every other case. Look at out/fit_lambda.png before dropping runs.
    dropped = {case.name for case in result.cases if not case.transition_found}
    if dropped:
        print("   dropped:", ", ".join(sorted(dropped)))
        data = [item for item, (name, _, _) in zip(data, plastic) if name not in dropped]
        plastic = [run_ for run_ in plastic if run_[0] not in dropped]
        result = ellc.calibrate_files(data)
        fit = result.fit
        print(f"   m, o, p = {fit.m:.4g}, {fit.o:.4g}, {fit.p:.4g}   s, t, u = {fit.s:.4g}, {fit.t:.4g}, "
              f"{fit.u:.4g}   n = {fit.n:.4g}")
        for warning in result.warnings:
            print("   warning:", warning)
    else:
        print("   nothing to drop")

    say("2c. The same with the CLI: ellc fit DATA... -o model.toml --plot PREFIX")
    model_path = out / "model.toml"
    run([cli, "fit", *data, "-o", model_path, "--plot", out / "fit"])
    model_table = model_path.read_text()
    import tomllib

    from_cli = tomllib.loads(model_table)["model"]
    assert all(from_cli[key] == value for key, value in fit.as_dict().items()), "CLI and Python differ"
    print(f"   {model_path}: identical constants to the Python result")
    print(f"   plots: {out / 'fit_lambda.png'} (Fig. 11), {out / 'fit_radius.png'} (Fig. 12)")

    say("3. Elastic data is rejected: the law's transition cannot be fitted from it")
    if elastic:
        name, csv, case = elastic[-1]
        completed = subprocess.run([cli, "fit", f"{csv}:{case}"], capture_output=True, text=True)
        print(f"   ellc fit {csv.name}: exit {completed.returncode}")
        print("  ", completed.stderr.strip())
        assert completed.returncode == 2
    else:
        print("   (no elastic FE run in the manifest)")

    say("4. ellc curve with the calibrated [model] against the FE curve")
    chosen = next(((n, c, k) for n, c, k in plastic if n == "paper_case2"), plastic[0])
    name, csv, case = chosen
    calibrated_case = out / f"{name}_calibrated.toml"
    calibrated_case.write_text(replace_model_table(case.read_text(), model_table))
    run([cli, "curve", calibrated_case, "-o", out / f"{name}_calibrated.csv"])
    curve = np.genfromtxt(out / f"{name}_calibrated.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    measured = np.genfromtxt(csv, delimiter=",", names=True)
    contact = ellc.Contact.from_case(ellc.read_curve_case(str(calibrated_case)))
    paper = ellc.Contact.from_case(ellc.read_curve_case(str(case)))  # the case file's own [model]: eq. (53)
    model_force = contact.force(measured["overlap"])
    paper_force = paper.force(measured["overlap"])
    # Loading envelope beyond delta_Y (what the calibration fits) and the whole protocol.
    envelope = (measured["overlap"] >= np.maximum.accumulate(measured["overlap"])) & (
        measured["overlap"] > contact.constants.yield_overlap)
    loaded = measured["force"] > 0.05 * measured["force"].max()
    for label, force in (("calibrated", model_force), ("paper eq. 53", paper_force)):
        def rms(chosen):
            return 100 * np.sqrt(np.mean((force[chosen] / measured["force"][chosen] - 1.0) ** 2))
        print(f"   {label:13s}: RMS relative force error against the FE points: loading {rms(envelope):.2f} %, "
              f"whole protocol (F > 5 % of max) {rms(loaded):.2f} %")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ellc import figures

    constants = contact.constants
    figure, axes = plt.subplots(figsize=(6.4, 4.8), dpi=110)
    path = np.asarray(curve["overlap"])
    figures.plot_normalized_force(path, curve["force"], constants.yield_overlap, constants.yield_force, axes=axes,
                                  label="calibrated law", data=(measured["overlap"], measured["force"]))
    figures.plot_normalized_force(path, paper.force(path), constants.yield_overlap, constants.yield_force, axes=axes,
                                  label="paper constants (eq. 53)", ls="--", lw=1)
    axes.set_title(f"{name}: FE points and the law", fontsize=9)
    figure.tight_layout()
    figure.savefig(out / f"{name}_force.png")
    print(f"   plot: {out / (name + '_force.png')} (Fig. 13/15 style)")

    say("5. DEM: calendering with the paper's constants and with the calibrated ones")
    scenario = (ROOT / "examples" / "calendering_quick.toml").read_text()
    summaries = {}
    for label, text in (("paper", scenario), ("calibrated", replace_model_table(scenario, model_table))):
        scenario_path = out / f"calendering_{label}.toml"
        scenario_path.write_text(text)
        run([cli, "dem", scenario_path, "-o", out / f"dem_{label}", "-q", "--no-plot"], cwd=out)
        summaries[label] = (out / f"dem_{label}" / "summary.txt").read_text()
    for label, summary in summaries.items():
        wanted = [line.strip() for line in summary.splitlines()
                  if line.split(" =")[0] in ("max_pressure_MPa", "loaded_thickness_um", "final_thickness_um",
                                              "springback_percent", "plastic_dissipation_pJ")]
        print(f"   {label}:")
        for line in wanted:
            print("     ", line)

    say("Files")
    for path in sorted(out.iterdir()):
        print("  ", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
