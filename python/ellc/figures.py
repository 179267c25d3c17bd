"""Figures of the paper from ellc results (matplotlib).

Every function draws into given ``axes`` (or a new figure when ``axes`` is None) and returns the
axes. Inputs are numpy arrays or ellc objects; nothing here computes the law itself: forces,
patches and fits come from the compiled core (``ellc.Contact``, ``ellc.calibrate``) or from CSV
tables written by ``ellc curve`` / ``ellc fit``.

* :func:`plot_normalized_force`  force-overlap, F/F_pY against delta/delta_Y (Fig. 13, 15)
* :func:`plot_lambda_profile`    lambda against delta/delta_Y with its fit (Fig. 11)
* :func:`plot_radius_fits`       lambda_max, epsilon_max against R_e/r^ with eq. (52) (Fig. 12)
* :func:`plot_lambda_panels`     one Fig. 11 panel per calibration case
* :func:`plot_calibration`       both calibration figures straight from ``ellc.calibrate``
* :func:`plot_pressure_profiles` contact pressure along a_c and b_c (Fig. 4, 9, 14)
* :func:`plot_contact_ellipses`  the contact ellipses of the same states
"""

import numpy as np


def _axes(axes, **figure_options):
    if axes is not None:
        return axes
    import matplotlib.pyplot as plt

    return plt.subplots(**figure_options)[1]


def style_normalized_force_axes(axes):
    """Labels, limits, grid and legend of an F/F_pY against delta/delta_Y plot (Fig. 13, 15)."""
    axes.set_xlabel(r"$\delta_n / \delta_Y$")
    axes.set_ylabel(r"$F_n / F_{pY}$")
    axes.set_xlim(left=0)
    axes.set_ylim(bottom=0)
    axes.grid(alpha=0.3)
    axes.legend(loc="upper left")
    return axes


def plot_normalized_force(overlap, force, yield_overlap, yield_force, axes=None, label="model", data=None,
                          **line_options):
    """F/F_pY against delta/delta_Y (paper Fig. 13 and 15).

    ``data`` is an optional ``(overlap, force)`` pair of measured points (e.g. FEA), drawn as dots.
    """
    axes = _axes(axes)
    overlap = np.asarray(overlap, dtype=float)
    axes.plot(overlap / yield_overlap, np.asarray(force, dtype=float) / yield_force, label=label,
              **({"lw": 2} | line_options))
    if data is not None:
        axes.plot(np.asarray(data[0]) / yield_overlap, np.asarray(data[1]) / yield_force, ".", color="tab:cyan",
                  label="data")
    return style_normalized_force_axes(axes)


def plot_lambda_profile(overlap_over_yield, lambda_data, lambda_fit=None, axes=None, label=None,
                        lambda_model=None, color=None):
    """lambda against delta/delta_Y (paper Fig. 11): eq. (51) points and the eq. (28) fit.

    ``lambda_model`` optionally adds the calibrated law (eq. 52 constants) as a dashed line.
    """
    axes = _axes(axes)
    x = np.asarray(overlap_over_yield, dtype=float)
    order = np.argsort(x)
    points = axes.plot(x, lambda_data, "o", ms=3.5, alpha=0.6, color=color,
                       label=f"{label}: eq. (51)" if label else "eq. (51) from data")
    color = points[0].get_color()
    if lambda_fit is not None:
        axes.plot(x[order], np.asarray(lambda_fit)[order], "-", color=color,
                  label=f"{label}: eq. (28) fit" if label else "eq. (28) fit")
    if lambda_model is not None:
        axes.plot(x[order], np.asarray(lambda_model)[order], "--", color=color, lw=1,
                  label=f"{label}: calibrated law" if label else "calibrated law (eq. 52)")
    axes.set_xlabel(r"$\delta_n / \delta_Y$")
    axes.set_ylabel(r"$\lambda$")
    axes.grid(alpha=0.3)
    return axes


def plot_radius_fits(radius_ratio, lambda_max, epsilon_max, curve_ratio, lambda_curve, epsilon_curve,
                     axes_pair=None, prior_curves=None):
    """lambda_max and epsilon_max of each case against R_e/r^ with the eq. (52) fits (paper Fig. 12).

    ``prior_curves`` optionally is ``(lambda_curve, epsilon_curve)`` of the prior (e.g. the paper's
    eq. 54) on the same ``curve_ratio``.
    """
    if axes_pair is None:
        import matplotlib.pyplot as plt

        axes_pair = plt.subplots(1, 2, figsize=(10, 4.2))[1]
    for axes, values, curve, prior, name in (
            (axes_pair[0], lambda_max, lambda_curve, None if prior_curves is None else prior_curves[0],
             r"$\lambda_{max}$"),
            (axes_pair[1], epsilon_max, epsilon_curve, None if prior_curves is None else prior_curves[1],
             r"$\epsilon_{max}$")):
        axes.plot(radius_ratio, values, "o", color="tab:blue", label="cases (eq. 28 fits)")
        axes.plot(curve_ratio, curve, "-", color="tab:red", label="eq. (52) fit")
        if prior is not None:
            axes.plot(curve_ratio, prior, ":", color="tab:gray", label="prior (paper eq. 54)")
        axes.set_xlabel(r"$R_e / \hat r^{I,J}$")
        axes.set_ylabel(name)
        axes.grid(alpha=0.3)
        axes.legend()
    return axes_pair


def plot_lambda_panels(panels, columns=3):
    """One lambda-profile panel per case (Fig. 11); returns the figure.

    Each panel is a dict with name, radius_ratio, plateau_reached and the arrays
    overlap_over_yield, lambda_data, lambda_fit and lambda_model.
    """
    import matplotlib.pyplot as plt

    columns = min(columns, max(1, len(panels)))
    rows = max(1, (len(panels) + columns - 1) // columns)
    figure, grid = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.4 * rows), dpi=110, squeeze=False)
    for index, panel in enumerate(panels):
        axes = grid[index // columns][index % columns]
        plot_lambda_profile(panel["overlap_over_yield"], panel["lambda_data"], panel["lambda_fit"], axes=axes,
                            lambda_model=panel["lambda_model"])
        plateau = "plateau reached" if panel["plateau_reached"] else "plateau NOT reached"
        axes.set_title(f"{panel['name']}: R_e/r^ = {panel['radius_ratio']:.3g}, {plateau}", fontsize=8)
        if index == 0:
            axes.legend(fontsize=7)
    for index in range(len(panels), rows * columns):
        grid[index // columns][index % columns].set_visible(False)
    figure.tight_layout()
    return figure


def plot_calibration(result, prior=None):
    """Fig. 11 and Fig. 12 of an ``ellc.CalibrationResult``; returns ``(lambda_figure, radius_figure)``.

    ``prior`` is the ``ellc.LawParameters`` to compare with (default: the paper's eq. 53).
    """
    import matplotlib.pyplot as plt

    import ellc

    prior = prior or ellc.LawParameters()
    law = result.law
    panels = []
    for case in result.cases:
        profile = case.profile
        ratio = profile["contact_radius_ratio"]
        model = ellc.TransitionPoint(float(law.fit.lambda_max(case.radius_ratio)),
                                     float(law.fit.epsilon_max(case.radius_ratio)), law.fit.n)
        panels.append(dict(
            name=case.name, radius_ratio=case.radius_ratio, plateau_reached=case.plateau_reached,
            overlap_over_yield=profile["overlap"] / case.yield_overlap, lambda_data=profile["lambda"],
            lambda_fit=ellc.profile_lambda(case.shared, ratio, law.yield_pressure_factor),
            lambda_model=ellc.profile_lambda(model, ratio, law.yield_pressure_factor)))
    lambda_figure = plot_lambda_panels(panels)
    ratios = np.array([case.radius_ratio for case in result.cases])
    curve = np.linspace(0.5 * ratios.min(), 1.25 * ratios.max(), 200)
    radius_figure, axes_pair = plt.subplots(1, 2, figsize=(10, 4.2), dpi=110)
    plot_radius_fits(ratios, [case.shared.lambda_max for case in result.cases],
                     [case.shared.epsilon_max for case in result.cases], curve, law.fit.lambda_max(curve),
                     law.fit.epsilon_max(curve), axes_pair=axes_pair,
                     prior_curves=(prior.fit.lambda_max(curve), prior.fit.epsilon_max(curve)))
    radius_figure.tight_layout()
    return lambda_figure, radius_figure


def pressure_along_axes(patch, samples=201):
    """Pressure along a_c (y = 0) and b_c (x = 0) of one contact patch.

    ``patch`` has semi_axis_major, semi_axis_minor, field_peak_pressure and pressure_cap (an
    ``ellc.ContactPatch`` or the entries of ``ellc.PatchArrays``). Returns ``(x, p_x, y, p_y)``:
    eq. (1) with the peak of the elliptic field, truncated at the cap (the plateau p_lambda) while
    loading plastically.
    """
    a_c, b_c = float(patch.semi_axis_major), float(patch.semi_axis_minor)
    p0, cap = float(patch.field_peak_pressure), float(patch.pressure_cap)
    x = np.linspace(-a_c, a_c, samples)
    y = np.linspace(-b_c, b_c, samples)
    p_x = p0 * np.sqrt(np.clip(1.0 - (x / a_c) ** 2, 0.0, None)) if a_c > 0 else np.zeros_like(x)
    p_y = p0 * np.sqrt(np.clip(1.0 - (y / b_c) ** 2, 0.0, None)) if b_c > 0 else np.zeros_like(y)
    return x, np.minimum(p_x, cap), y, np.minimum(p_y, cap)


def plot_pressure_profiles(patches, labels, yield_stress, axes_pair=None):
    """Contact pressure p/Y along a_c and along b_c for several states (paper Fig. 4, 9, 14).

    Elastic states show the Hertz ellipse profile, plastic loading the Hertz profile truncated at
    p_lambda = lambda Y, unloading the Hertz profile of R_e,pmax about delta_p.
    """
    if axes_pair is None:
        import matplotlib.pyplot as plt

        axes_pair = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)[1]
    for patch, label in zip(patches, labels):
        x, p_x, y, p_y = pressure_along_axes(patch)
        line = axes_pair[0].plot(x, p_x / yield_stress, label=label)
        axes_pair[1].plot(y, p_y / yield_stress, color=line[0].get_color(), label=label)
    axes_pair[0].set_xlabel(r"$x$ along $a_c$ (µm)")
    axes_pair[1].set_xlabel(r"$y$ along $b_c$ (µm)")
    axes_pair[0].set_ylabel(r"$p / Y$")
    for axes in axes_pair:
        axes.grid(alpha=0.3)
        axes.set_ylim(bottom=0)
    axes_pair[1].legend(fontsize=8)
    return axes_pair


def plot_contact_ellipses(patches, labels, axes=None):
    """The contact ellipses (a_c along x, b_c along y) of several states, to scale."""
    axes = _axes(axes)
    angle = np.linspace(0.0, 2.0 * np.pi, 181)
    for patch, label in zip(patches, labels):
        a_c, b_c = float(patch.semi_axis_major), float(patch.semi_axis_minor)
        axes.plot(a_c * np.cos(angle), b_c * np.sin(angle), label=f"{label}: {a_c:.3g} x {b_c:.3g} µm")
    axes.set_aspect("equal")
    axes.set_xlabel(r"$x$ (µm)")
    axes.set_ylabel(r"$y$ (µm)")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8)
    return axes


def contact_states(contact, path):
    """Representative states of a load/unload path for the pressure plots.

    Returns ``(patches, labels)`` for: the elastic limit, the middle of the transition (if reached),
    the largest overlap, and halfway down the following unloading. ``contact`` is an ``ellc.Contact``.
    """
    import ellc

    constants = contact.constants
    path = np.asarray(path, dtype=float)
    result = contact.evaluate_path(path)
    peak = int(np.argmax(path))
    states = [(constants.yield_overlap, 0.0, r"elastic limit $\delta_Y$")]
    middle = np.sqrt(constants.yield_overlap * min(constants.plastic_limit_overlap, path[peak]))
    if path[peak] > constants.yield_overlap * 1.05:
        states.append((middle, 0.0, r"transition $\delta$ = %.3g µm" % middle))
    states.append((path[peak], 0.0, r"loaded, $\delta_*$ = %.3g µm" % path[peak]))
    plastic = result.plastic_overlap[peak]
    if path[peak] > constants.yield_overlap:
        halfway = 0.5 * (path[peak] + plastic)
        states.append((halfway, path[peak], r"unloading, $\delta$ = %.3g µm" % halfway))
    patches = [ellc.contact_patch(constants, overlap, history) for overlap, history, _ in states]
    return patches, [label for _, _, label in states]
