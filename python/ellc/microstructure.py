"""The microstructure of a packing of ellipsoids (docs/microstructure.md).

The compiled part (``ellc._ellc.microstructure``, when the module is built) analyses a packing::

    import numpy as np
    from ellc import microstructure as ms
    packing = ms.Packing(centres, semi_axes, quaternions, box_lower, box_upper, periodic=(True, True, False))
    solid = ms.voxelise(packing, voxels_per_semi_axis=5)      # numpy uint8 array [iz, iy, ix]
    tau = ms.tortuosity(packing, axis=2)                      # dict: tortuosity, porosity, ...
    report = ms.analyse(packing, "out_dir")                   # everything `ellc analyse` writes

Definitions: the tortuosity factor is tau = porosity * D_bulk / D_eff from a steady diffusion solve
on the voxels; the pore-size distribution is the continuous PSD of Muench & Holzer (2008).

The figures below need only numpy and matplotlib and read the CSV tables of an analysis folder;
``python3 -m ellc.plots analysis DIR`` draws them for the CLI.
"""

import csv
import math
import os
import tomllib

try:
    from ellc._ellc import microstructure as _core

    # A pybind11 submodule is an attribute, not an importable module: copy its names.
    globals().update({name: getattr(_core, name) for name in dir(_core) if not name.startswith("_")})
    HAVE_CORE = True
except ImportError:  # figures only
    _core = None
    HAVE_CORE = False


def _read_table(path):
    """CSV with '#' comment lines and a header -> dict of column -> list (floats where possible)."""
    with open(path, newline="") as handle:
        rows = [line for line in handle if not line.startswith("#")]
    records = list(csv.DictReader(rows))
    columns = {}
    for name in records[0].keys() if records else []:
        values = [record[name] for record in records]
        try:
            columns[name] = [float(value) for value in values]
        except ValueError:
            columns[name] = values
    return columns


def read_summary(directory):
    """analysis.txt of an analysis folder (a TOML document) as a dict: numbers, the grids as
    [nx, ny, nz], notes as strings."""
    with open(os.path.join(directory, "analysis.txt"), "rb") as handle:
        return tomllib.load(handle)


def profile_figure(profile, title=None):
    """Porosity (analytic and voxel) and contacts / mean normal force against height; returns the Figure.

    ``profile`` maps the columns of profile.csv: z_mid, porosity_analytic, porosity_voxels
    (optional), contacts, mean_normal_force.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    z = np.asarray(profile["z_mid"], dtype=float)
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4.4), dpi=110, sharey=True)
    left.plot(profile["porosity_analytic"], z, "-", color="tab:blue", label="analytic (ellipsoid-slab volumes)")
    if "porosity_voxels" in profile:
        left.plot(profile["porosity_voxels"], z, "--", color="tab:orange", label="voxels")
    left.set_xlabel("porosity")
    left.set_ylabel("height z [um]")
    left.grid(alpha=0.3)
    left.legend(loc="best", fontsize=8)
    right.barh(z, profile["contacts"], height=(z[1] - z[0]) if z.size > 1 else 1.0, color="tab:gray", alpha=0.5,
               label="contacts")
    right.set_xlabel("contacts per slab")
    force_axes = right.twiny()
    force_axes.plot(profile["mean_normal_force"], z, ".-", color="tab:red", label="mean normal force")
    force_axes.set_xlabel("mean normal force [uN]", color="tab:red")
    right.grid(alpha=0.3)
    if title:
        figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    return figure


def pore_size_figure(psd, title=None):
    """The continuous pore-size distribution (Muench & Holzer 2008): V(r) and -dV/dr; returns the Figure."""
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(6.4, 4.4), dpi=110)
    axes.plot(psd["radius"], psd["cumulative_fraction"], "o-", ms=3, color="tab:blue",
              label="V(r): pore fraction coverable by spheres of radius r")
    axes.set_xlabel("pore radius r [um]")
    axes.set_ylabel("cumulative pore fraction")
    axes.set_ylim(0, 1.05)
    axes.grid(alpha=0.3)
    density_axes = axes.twinx()
    density_axes.step(psd["radius"], psd["density"], where="pre", color="tab:green", label="-dV/dr")
    density_axes.set_ylabel("-dV/dr [1/um]", color="tab:green")
    axes.legend(loc="upper right", fontsize=8)
    if title:
        axes.set_title(title, fontsize=9)
    figure.tight_layout()
    return figure


def force_pdf_figure(pdf, title=None):
    """The PDF of the normal contact forces normalised by their mean, on a log scale; returns the Figure."""
    import matplotlib.pyplot as plt
    import numpy as np

    low = np.asarray(pdf["f_over_mean_low"], dtype=float)
    high = np.asarray(pdf["f_over_mean_high"], dtype=float)
    density = np.asarray(pdf["pdf"], dtype=float)
    figure, axes = plt.subplots(figsize=(6.4, 4.4), dpi=110)
    shown = density > 0
    axes.semilogy(0.5 * (low + high)[shown], density[shown], "o", ms=4, color="tab:blue", label="contacts")
    x = np.linspace(0, max(high.max() if high.size else 1.0, 1.0), 200)
    axes.semilogy(x, np.exp(-x), ":", color="tab:gray", label="exp(-f/<f>)")
    axes.set_xlabel("f / <f>")
    axes.set_ylabel("probability density")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8)
    if title:
        axes.set_title(title, fontsize=9)
    figure.tight_layout()
    return figure


def tortuosity_porosity_figure(states, title=None, axes=None):
    """Through-plane tortuosity factor against porosity for analysed states, with Bruggeman's tau = eps^-0.5.

    ``states``: a list of ``(label, summary)`` where ``summary`` is :func:`read_summary` of an
    analysis folder (porosity_voxels, tortuosity_z, tortuosity_z_coarse, tortuosity_z_extrapolated,
    voxel sizes). The value at the coarser resolution is drawn hollow, the first-order extrapolation
    of the two to zero voxel size as a triangle (the lower end of their bracket). Returns the Figure.
    """
    import matplotlib.pyplot as plt
    import numpy as np

    if axes is None:
        figure, axes = plt.subplots(figsize=(6.4, 4.6), dpi=110)
    else:
        figure = axes.figure
    porosity = [s["porosity_voxels"] for _, s in states]
    low = min(porosity + [0.25]) - 0.05
    high = max(porosity + [0.5]) + 0.05
    eps = np.linspace(max(low, 0.01), min(high, 1.0), 100)
    axes.plot(eps, eps ** -0.5, "-", color="tab:gray", label="Bruggeman tau = eps^-0.5")
    colours = plt.get_cmap("tab10")
    for index, (label, summary) in enumerate(states):
        tau = summary.get("tortuosity_z")
        if isinstance(tau, float) and math.isfinite(tau):
            axes.plot(summary["porosity_voxels"], tau, "o", color=colours(index), ms=7,
                      label=f"{label}: {summary['voxel_size_um']:.3g} um voxels")
        coarse = summary.get("tortuosity_z_coarse")
        if isinstance(coarse, float) and math.isfinite(coarse):
            axes.plot(summary["porosity_voxels"], coarse, "o", mfc="none", color=colours(index), ms=7,
                      label=f"{label}: {summary['coarse_voxel_size_um']:.3g} um voxels")
        estimate = summary.get("tortuosity_z_extrapolated")
        if isinstance(estimate, float) and math.isfinite(estimate):
            axes.plot(summary["porosity_voxels"], estimate, "v", color=colours(index), ms=7,
                      label=f"{label}: first-order extrapolation to 0 um voxels")
    axes.set_xlabel("porosity eps")
    axes.set_ylabel("through-plane tortuosity factor tau_z")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8)
    if title:
        axes.set_title(title, fontsize=9)
    figure.tight_layout()
    return figure


def draw_analysis(directory, title=None):
    """Writes profile.png, pore_size_distribution.png and normal_force_pdf.png of an analysis folder."""
    import matplotlib.pyplot as plt

    def save(figure, name):
        figure.savefig(os.path.join(directory, name))
        plt.close(figure)

    save(profile_figure(_read_table(os.path.join(directory, "profile.csv")), title), "profile.png")
    save(pore_size_figure(_read_table(os.path.join(directory, "pore_size_distribution.csv")), title),
         "pore_size_distribution.png")
    pdf = _read_table(os.path.join(directory, "normal_force_pdf.csv"))
    if pdf.get("pdf"):
        save(force_pdf_figure(pdf, title), "normal_force_pdf.png")


def analyse(packing, directory=None, **options):
    """Runs the whole analysis (as ``ellc analyse``) on a :class:`Packing`; writes the files into
    ``directory`` when given. Options: voxels_per_semi_axis, spacing, memory_limit_gib,
    coarse_factor. Returns the summary as a dict (the keys of analysis.txt)."""
    if _core is None:
        raise ImportError("ellc.microstructure.analyse needs the compiled module ellc._ellc")
    return tomllib.loads(_core.analyse(packing, directory or "", **options))
