#!/usr/bin/env python3
"""Checks of lmp_ellc (pair_style ellipsoid/bk) run by ctest.

  curve    the two-particle LAMMPS run reproduces `ellc curve` force-overlap points
  mpi      a dense run on 2 MPI ranks reproduces the 1-rank thermo output
  restart  a run split by write_restart/read_restart reproduces the same split without files
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        sys.exit(f"command failed ({result.returncode}): {' '.join(command)}\n{result.stdout[-4000:]}")
    return result.stdout


def thermo_rows(output):
    """Numeric thermo rows of every run in a LAMMPS screen output, keyed by step (later runs win)."""
    rows, header, names = {}, None, None
    for line in output.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header = names = words
            continue
        if header is None:
            continue
        if line.startswith("Loop time"):
            header = None
            continue
        try:
            values = [float(word) for word in words]
        except ValueError:
            header = None
            continue
        if len(values) == len(header):
            rows[int(values[0])] = values
    return names, rows


def compare_thermo(reference, candidate, digits, what):
    header, expected = thermo_rows(reference)
    _, actual = thermo_rows(candidate)
    if not expected or set(expected) != set(actual):
        sys.exit(f"{what}: thermo steps differ: {sorted(expected)[:5]}... vs {sorted(actual)[:5]}...")
    tolerance = 0.5 * 10.0 ** (1 - digits)  # agreement to `digits` significant digits
    # Values at roundoff level of their column (e.g. the shear stress of the symmetric start,
    # zero up to 1e-11) carry no significant digits: both below 1e-9 of the column's largest
    # magnitude counts as agreement.
    noise = [1e-9 * max(abs(row[k]) for row in expected.values()) for k in range(len(header))]
    worst = 0.0
    for step in sorted(expected):
        for name, a, b, small in zip(header, expected[step], actual[step], noise):
            scale = max(abs(a), abs(b))
            if scale <= small:
                continue
            error = abs(a - b) / scale if scale > 0 else 0.0
            worst = max(worst, error)
            if error > tolerance:
                sys.exit(f"{what}: step {step} {name}: {a!r} vs {b!r} (relative {error:.3g} > {tolerance:.1g})")
    print(f"{what}: {len(expected)} thermo rows x {len(header)} columns agree; worst relative difference "
          f"{worst:.3g} (tolerance {tolerance:.1g})")


def check_curve(args):
    with tempfile.TemporaryDirectory() as work:
        curve_csv = os.path.join(work, "curve.csv")
        lammps_csv = os.path.join(work, "lammps.csv")
        run([args.ellc, "curve", args.case, "-o", curve_csv], work)
        launcher = [args.mpirun, *[flag for flag in args.mpirun_flag if flag], "-np", str(args.np)] if args.mpirun else []
        output = run([*launcher, args.lmp, "-in", args.input, "-log", "none", "-var", "out", lammps_csv,
                      "-var", "w2", args.w2, "-var", "n", args.points], work)
        if args.np > 1 and f"{args.np} by 1 by 1 MPI processor grid" not in output:
            sys.exit(f"expected the two bodies on {args.np} ranks split along x")
        with open(curve_csv) as handle:
            reference = list(csv.DictReader(handle))
        with open(lammps_csv) as handle:
            actual = list(csv.DictReader(handle))
    if len(reference) != len(actual):
        sys.exit(f"ellc curve has {len(reference)} points, the LAMMPS run {len(actual)}")
    largest = max(abs(float(row["force"])) for row in reference)
    worst, worst_row = 0.0, None
    for index, (expected, got) in enumerate(zip(reference, actual)):
        overlap_ref, overlap = float(expected["overlap"]), float(got["overlap"])
        force_ref, force = float(expected["force"]), float(got["force"]) * args.force_scale
        if abs(overlap - overlap_ref) > 1e-12 * args.overlap_scale:
            sys.exit(f"point {index}: overlap {overlap!r} in LAMMPS, {overlap_ref!r} in ellc curve")
        # Relative to the force, floored at 1e-6 of the largest force where both pass through zero.
        error = abs(force - force_ref) / max(abs(force_ref), 1e-6 * largest)
        if error > worst:
            worst, worst_row = error, (index, overlap_ref, force_ref, force)
        if error > args.tolerance:
            sys.exit(f"point {index} (overlap {overlap_ref}): ellc curve {force_ref!r}, LAMMPS {force!r} "
                     f"(relative {error:.3g} > {args.tolerance:g})")
    print(f"{len(reference)} force-overlap points agree; worst relative difference {worst:.3g} at point "
          f"{worst_row[0]} (overlap {worst_row[1]:.6g}, force {worst_row[2]:.6g})")


def check_mpi(args):
    with tempfile.TemporaryDirectory() as work:
        common = ["-in", args.input, "-log", "none", "-var", "steps", args.steps]
        one = run([args.mpirun, *[flag for flag in args.mpirun_flag if flag], "-np", "1", args.lmp, *common], work)
        two = run([args.mpirun, *[flag for flag in args.mpirun_flag if flag], "-np", "2", args.lmp, *common], work)
    if "2 by 1 by 1 MPI processor grid" not in two and "MPI processor grid" not in two:
        sys.exit("the 2-rank run did not report a processor grid")
    compare_thermo(one, two, args.digits, "np 2 vs np 1")


def check_restart(args):
    with tempfile.TemporaryDirectory() as work:
        common = ["-in", args.input, "-log", "none", "-var", "steps", args.steps]
        restart = ["-var", "restart", os.path.join(work, "split.restart")]
        common += ["-var", "dissipative", args.dissipative]
        reference = run([args.lmp, *common, "-var", "mode", args.reference], work)
        first = run([args.lmp, *common, *restart, "-var", "mode", "first"], work)
        second = run([args.lmp, *common, *restart, "-var", "mode", "second"], work)
    what = "in-process split" if args.reference == "split" else "single run"
    compare_thermo(reference, first + second, args.digits, f"restart split vs {what}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="check", required=True)
    curve = sub.add_parser("curve")
    curve.add_argument("--ellc", required=True)
    curve.add_argument("--lmp", required=True)
    curve.add_argument("--case", required=True)
    curve.add_argument("--input", required=True)
    curve.add_argument("--w2", default="0.01")
    curve.add_argument("--points", default="200")
    curve.add_argument("--force-scale", type=float, default=1e-3, help="LAMMPS force unit in ellc units (nN -> uN)")
    curve.add_argument("--overlap-scale", type=float, default=20.0)
    curve.add_argument("--tolerance", type=float, default=1e-9)
    curve.add_argument("--mpirun", default="")
    curve.add_argument("--mpirun-flag", action="append", default=[])
    curve.add_argument("--np", type=int, default=1)
    for name in ("mpi", "restart"):
        command = sub.add_parser(name)
        command.add_argument("--lmp", required=True)
        command.add_argument("--input", required=True)
        command.add_argument("--steps", default="1000")
        command.add_argument("--digits", type=int, default=10)
        if name == "restart":
            command.add_argument("--reference", choices=["split", "full"], default="split")
            command.add_argument("--dissipative", choices=["yes", "no"], default="yes")
        if name == "mpi":
            command.add_argument("--mpirun", required=True)
            command.add_argument("--mpirun-flag", action="append", default=[])
    args = parser.parse_args()
    {"curve": check_curve, "mpi": check_mpi, "restart": check_restart}[args.check](args)


if __name__ == "__main__":
    main()
