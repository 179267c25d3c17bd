"""The figures of the ellc tools, from arrays, and their command line.

Each figure the C++ tools draw is a function of numpy arrays (or lists) that returns the
matplotlib Figure, so the same figure can be made in Python from computed results:

* :func:`curve_figure`     ``ellc curve --plot``: F/F_pY against delta/delta_Y (Fig. 13, 15)
* :func:`fit_figures`      ``ellc fit --plot PREFIX``: lambda profiles (Fig. 11), radius fits (Fig. 12)
* :func:`dem_figure`       ``ellc dem``'s pressure_thickness.png: plate pressure against thickness
* :func:`pressure_figure`  pressure along a_c and b_c and the contact ellipses (Fig. 4, 9, 14)

The command line reads the CSV tables the tools write and calls these functions; the CLI runs it as
``python3 -m ellc.plots curve IN.csv OUT.png`` (subcommands ``curve``, ``fit PREFIX``,
``pressure CASE.toml OUT.png``, which needs the compiled module, ``dem IN.csv OUT.png``, and
``dem-ensemble OUT.png CSV...`` for the members of ``ellc dem --seeds N`` and
``dem-compare OUT.png CSV... --labels LAWS`` for ``ellc dem --compare``, both drawn by
:func:`plot_pressure_thickness_ensemble`, ``analysis DIR`` for the PNGs of ``ellc analyse`` and
``tortuosity-porosity OUT.png DIR...``, both drawn by :mod:`ellc.microstructure`).
The single panels live in ellc.figures.
"""

import argparse
import csv
import sys

import matplotlib.pyplot as plt
import numpy as np

from ellc import figures


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


def curve_figure(overlap_over_yield, force_over_yield, equal_volume_spheres=None, elastic_fully_plastic=None,
                 title=None):
    """F/F_pY against delta/delta_Y as ``ellc curve --plot`` draws it (paper Fig. 13 and 15).

    The arrays are the CSV columns of ``ellc curve`` of the same names: ``overlap_over_yield``,
    ``force_over_yield`` and, optionally, ``force_equal_volume_spheres_over_yield`` and
    ``force_elastic_fully_plastic_over_yield``, drawn dashed and dotted. Returns the Figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.8), dpi=120)
    x = np.asarray(overlap_over_yield, dtype=float)
    axes.plot(x, np.asarray(force_over_yield, dtype=float), color="tab:blue", lw=2,
              label="ellipsoids (Becker-Kamlah)")
    if equal_volume_spheres is not None:
        axes.plot(x, np.asarray(equal_volume_spheres, dtype=float), "--", color="tab:green",
                  label="equal-volume spheres")
    if elastic_fully_plastic is not None:
        axes.plot(x, np.asarray(elastic_fully_plastic, dtype=float), ":", color="tab:gray",
                  label="elastic-fully plastic (Thornton)")
    figures.style_normalized_force_axes(axes)
    if title:
        axes.set_title(title, fontsize=9)
    figure.tight_layout()
    return figure


def fit_figures(panels, radius_ratio, lambda_max, epsilon_max, curve_ratio, lambda_curve, epsilon_curve,
                prior_curves=None):
    """The two figures of ``ellc fit --plot``: ``(lambda_figure, radius_figure)``.

    ``panels`` is one dict per case as :func:`ellc.figures.plot_lambda_panels` takes (Fig. 11). The
    other arguments are those of :func:`ellc.figures.plot_radius_fits` (Fig. 12): lambda_max and
    epsilon_max per case against R_e/r^, and the eq. (52) curves on ``curve_ratio``.
    (:func:`ellc.figures.plot_calibration` makes both straight from an ``ellc.CalibrationResult``.)
    """
    lambda_figure = figures.plot_lambda_panels(panels)
    radius_figure, axes_pair = plt.subplots(1, 2, figsize=(10, 4.2), dpi=110)
    figures.plot_radius_fits(radius_ratio, lambda_max, epsilon_max, curve_ratio, lambda_curve, epsilon_curve,
                             axes_pair=axes_pair, prior_curves=prior_curves)
    radius_figure.tight_layout()
    return lambda_figure, radius_figure


# The energy-balance columns of timeseries.csv (ellc dem), drawn when all are given.
ENERGY_COLUMNS = ("work_bottom_plate", "work_top_plate", "gravity_work", "elastic_energy", "spring_energy",
                  "friction_dissipation", "damping_dissipation", "drag_dissipation", "energy_residual")


def dem_figure(thickness, plate_pressure, phase, time, kinetic_energy, plastic_dissipation, title=None,
               energies=None):
    """Calendering as ``ellc dem`` draws it (pressure_thickness.png); returns the Figure.

    Left: plate pressure [MPa] against layer thickness [um], one colour per ``phase`` (``"load"``,
    ``"hold"``, ``"unload"``), zoomed on where the pressure exceeds 1 % of its maximum. Right: the
    kinetic and the plastically dissipated energy [pJ] against ``time`` [us], and with
    ``energies`` (a dict of the ENERGY_COLUMNS) the whole energy balance. The arguments are the
    columns of ``timeseries.csv`` of the same names.
    """
    thickness = np.asarray(thickness, dtype=float)
    pressure = np.asarray(plate_pressure, dtype=float)
    phase = np.asarray(phase, dtype=str)
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4), dpi=110)
    colours = {"load": "tab:blue", "hold": "tab:orange", "unload": "tab:green"}
    for name, colour in colours.items():
        rows = phase == name
        if rows.any():
            left.plot(thickness[rows], pressure[rows], ".-", ms=2, lw=1.2, color=colour, label=name)
    # Zoom on the calendering proper: where the plate pressure exceeds 1 % of its maximum (the
    # compaction of the loose deposit before it is a long flat tail).
    peak = pressure.max() if pressure.size else 0.0
    pressed = thickness[pressure > 0.01 * peak]
    if pressed.size:
        low, high = pressed.min(), pressed.max()
        margin = 0.15 * (high - low) + 1e-9
        left.set_xlim(low - margin, high + margin)
    left.set_xlabel("layer thickness (plate gap) [um]")
    left.set_ylabel("plate pressure [MPa]")
    left.set_ylim(bottom=0)
    left.grid(alpha=0.3)
    left.legend(loc="upper right")
    right.plot(time, kinetic_energy, color="tab:red", label="kinetic")
    right.plot(time, plastic_dissipation, color="tab:purple", label="plastically dissipated")
    if energies is not None:
        e = {name: np.asarray(values, dtype=float) for name, values in energies.items()}
        right.plot(time, e["work_bottom_plate"] + e["work_top_plate"] + e["gravity_work"], color="black", lw=1.2,
                   label="work of plates and gravity")
        right.plot(time, e["elastic_energy"] + e["spring_energy"], color="tab:blue",
                   label="stored elastic (law and springs)")
        right.plot(time, e["friction_dissipation"], color="tab:olive", label="friction")
        right.plot(time, e["damping_dissipation"] + e["drag_dissipation"], color="tab:cyan", label="dashpots and drag")
        right.plot(time, e["energy_residual"], ":", color="tab:gray", label="residual of the balance")
    right.set_xlabel("time [us]")
    right.set_ylabel("energy [pJ]")
    right.set_yscale("symlog", linthresh=1.0)
    right.grid(alpha=0.3)
    right.legend(loc="upper left", fontsize=7)
    if title:
        figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    return figure


def pressure_figure(contact, path, title=None):
    """Pressure along a_c and b_c and the contact ellipses of an ``ellc.Contact`` along an overlap
    path (array), at the states of :func:`ellc.figures.contact_states`; returns the Figure."""
    patches, labels = figures.contact_states(contact, np.asarray(path, dtype=float))
    figure, axes = plt.subplots(1, 3, figsize=(14, 4.2), dpi=110)
    figures.plot_pressure_profiles(patches, labels, contact.constants.yield_stress, axes_pair=axes[:2])
    figures.plot_contact_ellipses(patches, labels, axes=axes[2])
    if title:
        figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    return figure


def _save(figure, path):
    figure.savefig(path)
    plt.close(figure)


def curve_command(args):
    columns = read_columns(args.csv)
    _save(curve_figure(columns["overlap_over_yield"], columns["force_over_yield"],
                       columns.get("force_equal_volume_spheres_over_yield"),
                       columns.get("force_elastic_fully_plastic_over_yield"), title=args.title), args.png)
    return 0


def fit_command(args):
    """PREFIX_lambda.png (Fig. 11, one panel per case) and PREFIX_radius.png (Fig. 12)."""
    samples = read_columns(args.prefix + "_lambda.csv")
    cases = read_columns(args.prefix + "_cases.csv")
    radius = read_columns(args.prefix + "_radius.csv")
    case_of_sample = np.array([str(name) for name in samples["case"]])
    panels = []
    for index, name in enumerate(str(name) for name in cases["case"]):
        chosen = case_of_sample == name
        panel = {key: np.asarray(samples[column], dtype=float)[chosen] for key, column in (
            ("overlap_over_yield", "overlap_over_yield"), ("lambda_data", "lambda_data"),
            ("lambda_fit", "lambda_shared_fit"), ("lambda_model", "lambda_model"))}
        panel.update(name=name, radius_ratio=float(cases["radius_ratio"][index]),
                     plateau_reached=float(cases["plateau_reached"][index]) > 0)
        panels.append(panel)
    lambda_figure, radius_figure = fit_figures(
        panels, cases["radius_ratio"], cases["lambda_max"], cases["epsilon_max"], radius["radius_ratio"],
        radius["lambda_max_fit"], radius["epsilon_max_fit"],
        prior_curves=(radius["lambda_max_prior"], radius["epsilon_max_prior"]))
    _save(lambda_figure, args.prefix + "_lambda.png")
    _save(radius_figure, args.prefix + "_radius.png")
    return 0


def pressure_command(args):
    """Pressure along a_c and b_c and the contact ellipses of a case's load/unload path."""
    import ellc

    case = ellc.read_curve_case(args.case)
    _save(pressure_figure(ellc.Contact.from_case(case), case.overlap_path(), title=args.title or args.case),
          args.png)
    return 0


def dem_command(args):
    """Calendering from `ellc dem` timeseries.csv: plate pressure against layer thickness during
    load, hold and unload, and the energies over time (with the energy balance's terms and its
    residual when the CSV has them)."""
    columns = read_columns(args.csv)
    energies = {name: columns[name] for name in ENERGY_COLUMNS if name in columns}
    _save(dem_figure(columns["thickness"], columns["plate_pressure"], columns["phase"], columns["time"],
                     columns["kinetic_energy"], columns["plastic_dissipation"], title=args.title,
                     energies=energies if len(energies) == len(ENERGY_COLUMNS) else None), args.png)
    return 0


def plot_pressure_thickness_ensemble(members, axes=None, title=None):
    """The pressure-thickness curves of an ensemble over packing seeds (``ellc dem --seeds N``)
    on one axes, one colour per member: load and hold solid, unload dashed.

    ``members``: a list of ``(label, columns)``, where ``columns`` maps ``"thickness"`` and
    ``"plate_pressure"`` (and optionally ``"phase"``) to equal-length sequences or arrays, as
    ``read_columns`` gives them for a member's timeseries.csv. Without ``"phase"`` every row is
    drawn as one solid line. Returns the axes.
    """
    import numpy as np

    if axes is None:
        _, axes = plt.subplots(figsize=(7.5, 5.0), dpi=110)
    colours = plt.get_cmap("viridis" if len(members) > 10 else "tab10")
    peak = 0.0
    for _, columns in members:
        pressure = np.asarray(columns["plate_pressure"], dtype=float)
        if pressure.size:
            peak = max(peak, float(np.nanmax(pressure)))
    pressed = []
    for index, (label, columns) in enumerate(members):
        colour = colours(index / max(len(members) - 1, 1)) if len(members) > 10 else colours(index % 10)
        thickness = np.asarray(columns["thickness"], dtype=float)
        pressure = np.asarray(columns["plate_pressure"], dtype=float)
        phases = np.asarray(columns["phase"], dtype=str) if "phase" in columns else None
        if phases is None:
            axes.plot(thickness, pressure, "-", lw=1.0, color=colour, label=label)
        else:
            loading = (phases == "load") | (phases == "hold")
            unloading = phases == "unload"
            axes.plot(thickness[loading], pressure[loading], "-", lw=1.0, color=colour, label=label)
            axes.plot(thickness[unloading], pressure[unloading], "--", lw=1.0, color=colour)
        pressed.extend(thickness[pressure > 0.05 * peak])
    # Zoom on the calendering proper: where the plate pressure exceeds 5 % of the ensemble's
    # largest (1 %, as for one run, would keep the few-MPa ripples of the loose deposit's
    # compaction, which reach 1 % in some member or other).
    if pressed:
        low, high = min(pressed), max(pressed)
        margin = 0.15 * (high - low) + 1e-9
        axes.set_xlim(low - margin, high + margin)
    axes.set_xlabel("layer thickness (plate gap) [um]")
    axes.set_ylabel("plate pressure [MPa]")
    axes.set_ylim(bottom=0)
    axes.grid(alpha=0.3)
    if members:
        if len(members) <= 10:
            axes.legend(loc="upper right", fontsize=8, title="load solid, unload dashed", title_fontsize=8)
        else:
            axes.text(0.98, 0.97, f"{len(members)} packing seeds; load solid, unload dashed",
                      transform=axes.transAxes, ha="right", va="top", fontsize=8)
    if title:
        axes.set_title(title, fontsize=9)
    return axes


def _pressure_thickness_curves(args, what):
    """One pressure-thickness plot of the CSVs in args.csv, each labelled by --labels or by its
    folder; the title says ``what`` they are (packing seeds, laws)."""
    import pathlib

    labels = args.labels.split(",") if args.labels else [pathlib.Path(path).parent.name for path in args.csv]
    if len(labels) != len(args.csv):
        raise SystemExit(f"--labels has {len(labels)} names for {len(args.csv)} CSV files")
    members = [(label, read_columns(path)) for label, path in zip(labels, args.csv)]
    figure, axes = plt.subplots(figsize=(7.5, 5.0), dpi=110)
    title = f"{args.title}: {what}" if args.title else what
    plot_pressure_thickness_ensemble(members, axes, title)
    figure.tight_layout()
    figure.savefig(args.png)
    plt.close(figure)
    return 0


def dem_ensemble_command(args):
    """The members' pressure-thickness curves of `ellc dem --seeds N` in one plot; a member is
    labelled by the folder of its CSV (seed_<seed>) unless --labels is given."""
    return _pressure_thickness_curves(args, f"{len(args.csv)} packing seeds")


def dem_compare_command(args):
    """One packing under several laws (`ellc dem --compare`), labelled by --labels (the laws)."""
    return _pressure_thickness_curves(args, f"one packing, {len(args.csv)} laws")


def analysis_command(args):
    """profile.png, pore_size_distribution.png, normal_force_pdf.png of an `ellc analyse` folder."""
    from ellc import microstructure

    microstructure.draw_analysis(args.directory, title=args.title)
    return 0


def tortuosity_porosity_command(args):
    """tau_z against porosity for analysed states (folders of `ellc analyse`), with Bruggeman."""
    import pathlib

    from ellc import microstructure

    states = [(pathlib.Path(folder).name.replace("analysis_", ""), microstructure.read_summary(folder))
              for folder in args.directories]
    _save(microstructure.tortuosity_porosity_figure(states, title=args.title), args.png)
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m ellc.plots")
    sub = parser.add_subparsers(dest="command", required=True)
    curve = sub.add_parser("curve", help="force-overlap curve from `ellc curve -o` CSV")
    curve.add_argument("csv")
    curve.add_argument("png")
    curve.add_argument("--title")
    curve.set_defaults(run=curve_command)
    fit = sub.add_parser("fit", help="calibration plots from `ellc fit --plot PREFIX` tables (Fig. 11, 12)")
    fit.add_argument("prefix")
    fit.set_defaults(run=fit_command)
    pressure = sub.add_parser("pressure", help="contact pressure along a_c, b_c and ellipses of a case file")
    pressure.add_argument("case")
    pressure.add_argument("png")
    pressure.add_argument("--title")
    pressure.set_defaults(run=pressure_command)
    dem = sub.add_parser("dem", help="pressure against thickness from `ellc dem` timeseries.csv")
    dem.add_argument("csv")
    dem.add_argument("png")
    dem.add_argument("--title")
    dem.set_defaults(run=dem_command)
    ensemble = sub.add_parser("dem-ensemble", help="pressure against thickness of the members of `ellc dem --seeds N`")
    ensemble.add_argument("png")
    ensemble.add_argument("csv", nargs="+", help="the members' timeseries.csv")
    ensemble.add_argument("--labels", help="comma-separated member names (default: each CSV's folder)")
    ensemble.add_argument("--title")
    ensemble.set_defaults(run=dem_ensemble_command)
    compare = sub.add_parser("dem-compare", help="pressure against thickness of one packing under several laws "
                             "(`ellc dem --compare`)")
    compare.add_argument("png")
    compare.add_argument("csv", nargs="+", help="each law's timeseries.csv")
    compare.add_argument("--labels", help="comma-separated law names (default: each CSV's folder)")
    compare.add_argument("--title")
    compare.set_defaults(run=dem_compare_command)
    analysis = sub.add_parser("analysis", help="profiles, pore sizes and force PDF of an `ellc analyse` folder")
    analysis.add_argument("directory")
    analysis.add_argument("--title")
    analysis.set_defaults(run=analysis_command)
    tortuosity = sub.add_parser("tortuosity-porosity", help="tau_z against porosity of `ellc analyse` folders")
    tortuosity.add_argument("png")
    tortuosity.add_argument("directories", nargs="+")
    tortuosity.add_argument("--title")
    tortuosity.set_defaults(run=tortuosity_porosity_command)
    args = parser.parse_args(argv)
    if argv is None:  # run as a program (the CLI): no display, write files only
        plt.switch_backend("Agg")
    return args.run(args)


if __name__ == "__main__":
    sys.exit(main())
