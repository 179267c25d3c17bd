#!/usr/bin/env python3
"""Checks of lmp_ellc (pair_style ellipsoid/bk) run by ctest.

  curve    the two-particle LAMMPS run reproduces `ellc curve` force-overlap points
  mpi      a dense run on 2 MPI ranks reproduces the 1-rank thermo output
  restart  a run split by write_restart/read_restart reproduces the same split without files
  contacts compute pair/local (Pair::single) and compute ellipsoid/bk/contacts report the same
           contacts, and their forces add up to the pair style's virial
  export   `ellc export-lammps` of a scenario: the data file brings `ellc dem` back to the same run
           ([packing] file), and lmp_ellc runs the exported protocol with the engine's columns
  engines  the exported scenario in LAMMPS (-np 1 and 2) agrees with `ellc dem` on the same packing
           within the spread of the built-in engine over packing seeds (measured in the test)
  wall     one ellipsoid pressed on a plane of fix wall/ellipsoid/bk gives `ellc geometry`'s wall
           force, for random orientations, both planes and wall materials
"""
import argparse
import csv
import math
import os
import random
import re
import subprocess
import sys
import tempfile


def mpi_launcher(args, np):
    """The command prefix that starts lmp_ellc on np ranks (--mpirun, its --mpirun-flag values)."""
    return [args.mpirun, *[flag for flag in args.mpirun_flag if flag], "-np", str(np)]


# Open MPI's runtime could not start its daemon: the process stopped inside MPI_Init, before any of
# our code ran. Seen once (2026-12-04) with ctest -j2 beside a two-thread DEM run on the 2-core
# machine; the same test passed when run again.
MPI_STARTUP_FAILURE = ("orte_init failed", "Unable to start a daemon on the local node")


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0 and any(sign in result.stdout for sign in MPI_STARTUP_FAILURE):
        print(f"MPI did not start (retrying once): {' '.join(command)}", file=sys.stderr)
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
        launcher = mpi_launcher(args, args.np) if args.mpirun else []
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
        one = run([*mpi_launcher(args, 1), args.lmp, *common], work)
        two = run([*mpi_launcher(args, 2), args.lmp, *common], work)
    if "2 by 1 by 1 MPI processor grid" not in two and "MPI processor grid" not in two:
        sys.exit("the 2-rank run did not report a processor grid")
    compare_thermo(one, two, args.digits, "np 2 vs np 1")


def check_restart(args):
    with tempfile.TemporaryDirectory() as work:
        common = ["-in", args.input, "-log", "none", "-var", "steps", args.steps]
        restart = ["-var", "restart", os.path.join(work, "split.restart")]
        common += ["-var", "dissipative", args.dissipative, "-var", "top", args.top]
        reference = run([args.lmp, *common, "-var", "mode", args.reference], work)
        first = run([args.lmp, *common, *restart, "-var", "mode", "first"], work)
        second = run([args.lmp, *common, *restart, "-var", "mode", "second"], work)
    what = "in-process split" if args.reference == "split" else "single run"
    compare_thermo(reference, first + second, args.digits, f"restart split vs {what}")


def read_dump(path):
    """Rows of the last snapshot of a LAMMPS text dump, as lists of floats."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    start = max(index for index, line in enumerate(lines) if line.startswith("ITEM: ENTRIES") or
                line.startswith("ITEM: ATOMS"))
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("ITEM:"):
            break
        rows.append([float(word) for word in line.split()])
    return rows


def check_contacts(args):
    launcher = mpi_launcher(args, args.np) if args.mpirun else []
    with tempfile.TemporaryDirectory() as work:
        output = run([*launcher, args.lmp, "-in", args.input, "-log", "none", "-var", "steps", args.steps,
                      "-var", "dir", work], work)
        pairs = read_dump(os.path.join(work, "pairs.dump"))
        contacts = read_dump(os.path.join(work, "contacts.dump"))
        atoms = {int(row[0]): row[1:4] for row in read_dump(os.path.join(work, "atoms.dump"))}
        # The same run with compute pair/local as the only reader of the per-contact records.
        run([*launcher, args.lmp, "-in", args.input, "-log", "none", "-var", "steps", args.steps,
             "-var", "dir", work, "-var", "readers", "pair_local"], work)
        pairs_alone = read_dump(os.path.join(work, "pairs.dump"))
    if pairs_alone != pairs:
        sys.exit("compute pair/local without compute ellipsoid/bk/contacts differs from the run with both "
                 f"({sum(row[3] > 0.0 for row in pairs_alone)} touching pairs against "
                 f"{sum(row[3] > 0.0 for row in pairs)})")
    names, rows = thermo_rows(output)
    last = rows[max(rows)]
    virial_pressure, volume = last[1], last[2]
    box = round(volume ** (1.0 / 3.0), 9)  # the cubic periodic box of the input
    # compute ellipsoid/bk/contacts: index, id_i, id_j, delta, delta_*, regime, c_c/r, Fn, |Ft|, F (3), point (3)
    by_pair = {}
    for row in contacts:
        key = (int(row[1]), int(row[2]))
        if key in by_pair or key[::-1] in by_pair:
            sys.exit(f"contact {key} appears twice in compute ellipsoid/bk/contacts")
        by_pair[key] = row[3:]
    if not by_pair:
        sys.exit("no contacts: the test packing should be dense")
    # compute pair/local with single(): index, id_i, id_j, p1..p12 (zero for pairs not touching)
    touching = [row for row in pairs if row[3] > 0.0]
    if len(touching) != len(by_pair):
        sys.exit(f"compute pair/local has {len(touching)} touching pairs, compute ellipsoid/bk/contacts {len(by_pair)}")
    for row in touching:
        key = (int(row[1]), int(row[2]))
        values = row[3:]
        if key not in by_pair:
            key = key[::-1]
            values = values[:6] + [-v for v in values[6:9]] + values[9:]  # the force on the other atom
        if key not in by_pair:
            sys.exit(f"pair {key} touches in compute pair/local but not in compute ellipsoid/bk/contacts")
        if any(abs(a - b) > 1e-12 * max(1.0, abs(a)) for a, b in zip(values, by_pair[key])):
            sys.exit(f"pair {key}: single() {values} vs compute {by_pair[key]}")
    # Each force splits into its normal and tangential parts; together they are the pair's virial.
    virial = 0.0
    for (a, b), values in by_pair.items():
        normal, tangential, force = values[4], values[5], values[6:9]
        magnitude = math.sqrt(sum(f * f for f in force))
        if abs(math.hypot(normal, tangential) - magnitude) > 1e-9 * max(magnitude, 1e-300):
            sys.exit(f"pair {(a, b)}: |F| = {magnitude} but hypot(F_n, F_t) = {math.hypot(normal, tangential)}")
        apart = [xa - xb - box * round((xa - xb) / box) for xa, xb in zip(atoms[a], atoms[b])]
        virial += sum(d * f for d, f in zip(apart, force))
    from_contacts = virial / (3.0 * volume)
    error = abs(from_contacts - virial_pressure) / abs(virial_pressure)
    if error > args.tolerance:
        sys.exit(f"sum over contacts of F.d / 3V = {from_contacts!r}, compute pressure virial {virial_pressure!r} "
                 f"(relative {error:.3g} > {args.tolerance:g})")
    print(f"{len(by_pair)} contacts: single() and compute ellipsoid/bk/contacts agree; their virial matches the "
          f"pair's to {error:.3g} (tolerance {args.tolerance:g})")


def check_proven_apart(args):
    """Skipping the pairs proven apart (pair_style ellipsoid/bk skip_proven_separated, the default)
    changes nothing: atoms, compute pair/local and compute ellipsoid/bk/contacts dumps equal byte
    for byte those of a run that evaluates every candidate pair. The input is run hot, so that
    pairs move in and out of reach (and turn) while lists are kept for many steps."""
    launcher = mpi_launcher(args, args.np) if args.mpirun else []
    dumps = {}
    with tempfile.TemporaryDirectory() as work:
        for skip in ("yes", "no"):
            directory = os.path.join(work, skip)
            os.mkdir(directory)
            run([*launcher, args.lmp, "-in", args.input, "-log", "none", "-var", "steps", args.steps,
                 "-var", "dir", directory, "-var", "temperature", args.temperature,
                 "-var", "settings", f"skip_proven_separated {skip}"], directory)
            dumps[skip] = {}
            for name in ("atoms.dump", "pairs.dump", "contacts.dump"):
                with open(os.path.join(directory, name), "rb") as handle:
                    dumps[skip][name] = handle.read()
    for name, content in dumps["no"].items():
        if dumps["yes"][name] != content:
            sys.exit(f"{name} differs between skip_proven_separated yes and no")
    print(f"skip_proven_separated yes and no: {', '.join(dumps['no'])} equal byte for byte")


WALL_INPUT = """units micro
atom_style ellipsoid
boundary p p f
read_data {data}
pair_style ellipsoid/bk
pair_coeff 1 1 1.42e8 0.25 7.9e6
fix wall all wall/ellipsoid/bk zplane {zlo} {zhi} {material}
thermo_style custom step f_wall[1] f_wall[2] f_wall[3] f_wall[4] f_wall[5] f_wall[6]
thermo_modify format float %.17g
run 0
"""


def random_quaternion(rng):
    """A uniformly random unit quaternion (w, x, y, z) (Shoemake)."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return (a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2), b * math.sin(2 * math.pi * u3),
            b * math.cos(2 * math.pi * u3))


def lowest_point(semi_axes, q):
    """Support of the posed ellipsoid along -z: centre z minus this is its lowest surface point."""
    w, x, y, z = q
    # Third row of the rotation matrix (body -> world): the body-frame components of world z.
    row = (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y))
    return math.sqrt(sum((a * r) ** 2 for a, r in zip(semi_axes, row)))


def geometry_force(output):
    for line in output.splitlines():
        if line.strip().startswith("force on J"):
            inside = line[line.index("(") + 1:line.index(")")]
            return [float(value) for value in inside.split(",")]
    sys.exit(f"no 'force on J' in the ellc geometry output:\n{output}")


def check_wall(args):
    rng = random.Random(args.seed)
    worst = 0.0
    with tempfile.TemporaryDirectory() as work:
        for case in range(args.cases):
            semi_axes = [rng.uniform(3.0, 6.0) for _ in range(3)]
            q = random_quaternion(rng)
            upper = case % 2 == 1
            wall_material = None if case % 3 == 0 else (rng.uniform(5e4, 3e5), rng.uniform(0.1, 0.4), 1e4)
            reach = lowest_point(semi_axes, q)
            overlap = rng.uniform(0.005, 0.06) * reach  # elastic to well into the plastic range
            wall_z = 0.0
            centre_z = wall_z - reach + overlap if upper else wall_z + reach - overlap
            poses = os.path.join(work, f"poses{case}.toml")
            with open(poses, "w") as handle:
                handle.write("[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n")
                handle.write(f"[body_I]\nsemi_axes = [{semi_axes[0]!r}, {semi_axes[1]!r}, {semi_axes[2]!r}]\n")
                handle.write(f"position = [0.0, 0.0, {centre_z!r}]\norientation = [{', '.join(repr(v) for v in q)}]\n")
                handle.write(f"[wall]\npoint = [0.0, 0.0, {wall_z!r}]\nnormal = [0.0, 0.0, {-1.0 if upper else 1.0}]\n")
                if wall_material:
                    handle.write("[wall.material]\nyoungs_modulus = {!r}\npoisson_ratio = {!r}\nyield_stress = {!r}\n"
                                 .format(*wall_material))
            expected = geometry_force(run([args.ellc, "geometry", poses], work))
            data = os.path.join(work, f"wall{case}.data")
            with open(data, "w") as handle:
                handle.write("wall test\n\n1 atoms\n1 atom types\n1 ellipsoids\n\n")
                handle.write("-50 50 xlo xhi\n-50 50 ylo yhi\n-50 50 zlo zhi\n\nAtoms # ellipsoid\n\n")
                handle.write(f"1 1 1 4.7 0.0 0.0 {centre_z!r}\n\nEllipsoids\n\n")
                handle.write(f"1 {' '.join(repr(2 * a) for a in semi_axes)} {' '.join(repr(v) for v in q)}\n")
            # LAMMPS units micro: pressure kPa (MPa x 1e3), force nN (uN x 1e3).
            material = "material particle" if wall_material is None else "material {!r} {!r} {!r}".format(
                wall_material[0] * 1e3, wall_material[1], wall_material[2] * 1e3)
            planes = ("NULL", repr(wall_z)) if upper else (repr(wall_z), "NULL")
            script = os.path.join(work, f"in.wall{case}")
            with open(script, "w") as handle:
                handle.write(WALL_INPUT.format(data=data, zlo=planes[0], zhi=planes[1], material=material))
            _, rows = thermo_rows(run([args.lmp, "-in", script, "-log", "none"], work))
            values = rows[0][1:]
            force = [1e-3 * v for v in (values[3:6] if upper else values[0:3])]
            other = values[0:3] if upper else values[3:6]
            if any(v != 0.0 for v in other):
                sys.exit(f"case {case}: the other plane (NULL) carries a force {other}")
            scale = math.sqrt(sum(v * v for v in expected))
            error = math.sqrt(sum((a - b) ** 2 for a, b in zip(force, expected))) / scale
            worst = max(worst, error)
            if error > args.tolerance:
                sys.exit(f"case {case} ({'upper' if upper else 'lower'} plane): ellc geometry {expected}, "
                         f"LAMMPS {force} (relative {error:.3g} > {args.tolerance:g})")
    print(f"{args.cases} random wall contacts agree with ellc geometry; worst relative difference {worst:.3g} "
          f"(tolerance {args.tolerance:g}; ellc geometry prints 10 digits)")


ENGINE_COLUMNS = ["step", "time", "phase", "plate_position", "thickness", "plate_pressure", "bottom_pressure",
                  "porosity", "coordination_number", "unbalanced_force_ratio"]


def read_series(path):
    with open(path) as handle:
        return list(csv.DictReader(handle))


def scenario_with(text, **packing):
    """The scenario text with its [packing] table replaced by the given keys."""
    lines, out, skipping = text.splitlines(), [], False
    for line in lines:
        if line.strip().startswith("["):
            skipping = line.strip() == "[packing]"
            if skipping:
                out.append("[packing]")
                out.extend(f"{key} = {value}" for key, value in packing.items())
                continue
        if not skipping:
            out.append(line)
    return "\n".join(out) + "\n"


def packing_value(text, key):
    inside = False
    for line in text.splitlines():
        if line.strip().startswith("["):
            inside = line.strip() == "[packing]"
        elif inside and line.split("=")[0].strip() == key:
            return line.split("=", 1)[1].split("#")[0].strip()
    sys.exit(f"no [packing] {key} in the scenario")


def run_lammps(args, directory, np, output=None):
    launcher = mpi_launcher(args, np) if np > 1 else []
    screen = run([*launcher, args.lmp, "-in", "in.scenario", "-log", "none"], directory)
    if output is not None:
        output.append(screen)
    return read_series(os.path.join(directory, "timeseries.csv"))


def scenario_value(text, table, key):
    inside = False
    for line in text.splitlines():
        if line.strip().startswith("["):
            inside = line.strip() == f"[{table}]"
        elif inside and line.split("=")[0].strip() == key:
            return line.split("=", 1)[1].split("#")[0].strip()
    return None


def with_calendering(text, **keys):
    """The scenario text with these [calendering] keys set (replaced or added)."""
    out, inside = [], False
    for line in text.splitlines():
        if line.strip().startswith("["):
            if inside:
                out.extend(f"{key} = {value}" for key, value in keys.items())
            inside = line.strip() == "[calendering]"
        elif inside and line.split("=")[0].strip() in keys:
            continue
        out.append(line)
    if inside:
        out.extend(f"{key} = {value}" for key, value in keys.items())
    return "\n".join(out) + "\n"


STAGE_END = re.compile(r"^ellc: (hold|relax) ended after (\S+) us, unbalanced-force ratio (\S+)$", re.M)


def stage_sequence(series):
    """The phases of a time series in order, each once; without the trailing "done" row that the
    last run's end writes only when it falls on a csv_every step."""
    phases = []
    for row in series:
        if not phases or phases[-1] != row["phase"]:
            phases.append(row["phase"])
    if phases and phases[-1] == "done":
        phases.pop()
    return phases


def check_equilibrium_ends(args, text, work):
    """The exported hold and relax end like the built-in engine's: past their minimum time, on the
    unbalanced-force ratio (below equilibrium_ratio), or stop with the engine's error at their limit;
    release = "servo" unloads to p_r and holds it."""
    hold_time = float(scenario_value(text, "calendering", "hold_time"))
    threshold = float(scenario_value(text, "calendering", "equilibrium_ratio"))
    # 1. The hold ends on the criterion: after hold_time, at the first step below the threshold
    #    (one the tiny bed reaches only some µs after hold_time).
    strict = 0.4 * threshold
    output = []
    directory = os.path.join(work, "criterion")
    path = os.path.join(work, "criterion.toml")
    with open(path, "w") as handle:
        handle.write(with_calendering(text, equilibrium_ratio=strict, max_hold_time=10 * hold_time))
    run([args.ellc, "export-lammps", path, "-o", directory], work)
    series = run_lammps(args, directory, 1, output)
    ends = STAGE_END.findall(output[0])
    if [stage for stage, _, _ in ends] != ["hold"]:
        sys.exit(f"expected one 'ellc: hold ended' line, got {ends}")
    held, ratio = float(ends[0][1]), float(ends[0][2])
    if not (held >= hold_time and ratio < strict):
        sys.exit(f"the hold ended after {held} µs at the ratio {ratio}: expected >= {hold_time} µs and < {strict}")
    hold = [row for row in series if row["phase"] == "hold"]
    late = [row for row in hold if float(row["time"]) - float(hold[0]["time"]) >= hold_time + 1e-9]
    if any(float(row["unbalanced_force_ratio"]) < strict for row in late[:-1]):
        sys.exit("the hold went on past a row below equilibrium_ratio after hold_time")
    print(f"hold: ended after {held:.4g} µs (hold_time {hold_time}) at the ratio {ratio:.3g} < {strict}; "
          f"{len(late)} rows past hold_time, all above it")
    # 2. A threshold it cannot reach: the hold runs to max_hold_time and stops with the engine's error.
    directory = os.path.join(work, "limit")
    path = os.path.join(work, "limit.toml")
    with open(path, "w") as handle:
        handle.write(with_calendering(text, equilibrium_ratio="1e-12", max_hold_time=1.5 * hold_time))
    run([args.ellc, "export-lammps", path, "-o", directory], work)
    result = subprocess.run([args.lmp, "-in", "in.scenario", "-log", "none"], cwd=directory, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    expected = "ERROR: ellc export-lammps: the loaded state did not reach equilibrium: after "
    if result.returncode == 0 or expected not in result.stdout:
        sys.exit(f"an unreachable equilibrium_ratio: exit {result.returncode}, expected the error '{expected}...'"
                 f"\n{result.stdout[-2000:]}")
    hold = [row for row in read_series(os.path.join(directory, "timeseries.csv")) if row["phase"] == "hold"]
    lasted = float(hold[-1]["time"]) - float(hold[0]["time"])
    if not 1.4 * hold_time <= lasted <= 1.5 * hold_time + 1e-9:
        sys.exit(f"the unreachable hold lasted {lasted} µs, expected max_hold_time = {1.5 * hold_time} µs")
    print(f"hold limit: stopped after {lasted:.4g} µs (max_hold_time {1.5 * hold_time}) with the engine's error")
    # 3. release = "servo": the plate servo-unloads to p_r and the relax ends at p_r in equilibrium.
    fraction = 0.2
    directory = os.path.join(work, "servo")
    path = os.path.join(work, "servo.toml")
    with open(path, "w") as handle:
        # 20 µs: in this 20-particle bed the layer keeps giving way under the plate, which the servo
        # (capped at the contacts' stiffness, engine/servo.hpp) follows in about 10 µs.
        handle.write(with_calendering(text, release='"servo"', release_pressure_fraction=fraction,
                                      relax_time=1.0, max_relax_time=20.0))
    run([args.ellc, "export-lammps", path, "-o", directory], work)
    output = []
    series = run_lammps(args, directory, 1, output)
    phases = stage_sequence(series)
    if phases != ["load", "hold", "unload", "relax"]:
        sys.exit(f"release = servo: phases {phases}, expected load, hold, unload, relax")
    ends = STAGE_END.findall(output[0])
    if [stage for stage, _, _ in ends] != ["hold", "relax"] or not float(ends[1][2]) < threshold:
        sys.exit(f"release = servo: stage ends {ends}")
    held = float([row for row in series if row["phase"] == "hold"][-1]["plate_pressure"])
    released = float(series[-1]["plate_pressure"])
    if abs(released - fraction * held) > 0.05 * fraction * held + 1e-9:
        sys.exit(f"release = servo: released at {released} MPa, expected p_r = {fraction} x {held} MPa within 5 %")
    print(f"release = servo: relaxed at {released:.4g} MPa = {released / held:.4g} x the held {held:.4g} MPa; "
          f"ratio {float(ends[1][2]):.3g}")


def check_export(args):
    with open(args.scenario) as handle:
        text = handle.read()
    with tempfile.TemporaryDirectory() as work:
        exported = os.path.join(work, "exported")
        run([args.ellc, "export-lammps", args.scenario, "-o", exported], work)
        # The data file brings `ellc dem` back to the generated packing, bit for bit.
        imported = os.path.join(work, "imported.toml")
        with open(imported, "w") as handle:
            handle.write(scenario_with(text, file='"exported/packing.data"', density=packing_value(text, "density")))
        run([args.ellc, "dem", args.scenario, "-o", os.path.join(work, "generated"), "--no-plot", "-q"], work)
        run([args.ellc, "dem", imported, "-o", os.path.join(work, "from_file"), "--no-plot", "-q"], work)
        # An imported packing's r̂ is its measured mean, not the generator's nominal one. Two things
        # use it: where the plate waits before the load (the settle row of a scenario without
        # settling) and the inertial number's length scale. Everything else must be identical.
        def physical(path):
            return [{key: value for key, value in row.items() if key != "inertial_number"}
                    for row in read_series(path) if row["phase"] != "settle"]
        generated = physical(os.path.join(work, "generated", "timeseries.csv"))
        from_file = physical(os.path.join(work, "from_file", "timeseries.csv"))
        if generated != from_file:
            first = next(k for k, (a, b) in enumerate(zip(generated, from_file)) if a != b) if len(generated) == len(
                from_file) else min(len(generated), len(from_file))
            sys.exit(f"ellc dem from the exported data file differs from the generated packing's run at row {first}")
        # The exported input runs in LAMMPS and writes the engine's columns through every phase.
        screen = []
        series = run_lammps(args, exported, 1, screen)
        if args.protocol_checks == "yes":
            check_equilibrium_ends(args, text, work)
    if list(series[0].keys()) != ENGINE_COLUMNS:
        sys.exit(f"timeseries.csv columns {list(series[0].keys())}, expected {ENGINE_COLUMNS}")
    engine_header = list(generated[0].keys())
    missing = [name for name in ENGINE_COLUMNS if name not in engine_header]
    if missing:
        sys.exit(f"the built-in engine's timeseries.csv has no column {missing}")
    phases = stage_sequence(series)
    if phases != ["load", "hold", "unload"]:
        sys.exit(f"phases {phases}, expected load, hold, unload (then done)")
    # The load stops at the step that meets the target, which the output rows (every few steps)
    # rarely hold: the input prints the pressure of that step.
    target = float(args.target)
    ended = re.search(r"ellc: load ended at (\S+) MPa", screen[0])
    if not ended:
        sys.exit("lmp_ellc did not print where the load ended ('ellc: load ended at ... MPa')")
    loaded = float(ended.group(1))
    if loaded < target:
        sys.exit(f"the load ended at {loaded} MPa, below the target {target} MPa")
    print(f"ellc dem from the exported packing repeats the generated run ({len(generated)} rows, identical); "
          f"lmp_ellc ran load, hold, unload ({len(series)} rows, the load ended at {loaded:.4g} MPa)")


def hold_start(series):
    """The first row of the hold: where the load reached its target."""
    return next(row for row in series if row["phase"] == "hold")


def hold_rows(series):
    """The rows where the load reached its target (first of the hold) and where the hold ended."""
    hold = [row for row in series if row["phase"] == "hold"]
    if not hold:
        sys.exit("the run has no hold phase")
    return {"end of load": hold[0], "end of hold": hold[-1]}


def check_engines(args):
    import statistics
    with open(args.scenario) as handle:
        text = handle.read()
    seed = int(packing_value(text, "seed"))
    quantities = ("porosity", "coordination_number")
    readings = [(when, name) for when in ("end of load", "end of hold") for name in quantities]
    with tempfile.TemporaryDirectory() as work:
        # The chaotic spread: the built-in engine over other packing seeds, the scenario otherwise the same.
        samples = {reading: [] for reading in readings}
        for other in range(seed + 1, seed + 1 + args.seeds):
            path = os.path.join(work, f"seed{other}.toml")
            with open(path, "w") as handle:
                handle.write(text.replace(f"seed = {seed}", f"seed = {other}"))
            run([args.ellc, "dem", path, "-o", os.path.join(work, f"dem{other}"), "--no-plot", "-q"], work)
            rows = hold_rows(read_series(os.path.join(work, f"dem{other}", "timeseries.csv")))
            for when, name in readings:
                samples[(when, name)].append(float(rows[when][name]))
        spread = {reading: statistics.stdev(values) for reading, values in samples.items()}
        run([args.ellc, "dem", args.scenario, "-o", os.path.join(work, "dem"), "--no-plot", "-q"], work)
        builtin = hold_rows(read_series(os.path.join(work, "dem", "timeseries.csv")))
        run([args.ellc, "export-lammps", args.scenario, "-o", os.path.join(work, "lammps")], work)
        worst = 0.0
        for np in (1, 2):
            lammps = hold_rows(run_lammps(args, os.path.join(work, "lammps"), np))
            for when, name in readings:
                a, b = float(builtin[when][name]), float(lammps[when][name])
                ratio = abs(a - b) / spread[(when, name)]
                worst = max(worst, ratio)
                print(f"np {np}: {name} at the {when}: ellc dem {a:.6g}, LAMMPS {b:.6g}; difference {abs(a - b):.3g}"
                      f" = {ratio:.3g} x the seed spread {spread[(when, name)]:.3g} (sd over {args.seeds} seeds)")
                if ratio > args.tolerance:
                    sys.exit(f"np {np}: {name} at the {when} differs by {ratio:.3g} seed spreads "
                             f"(tolerance {args.tolerance})")
    print(f"LAMMPS (np 1, 2) and ellc dem agree on the same packing; worst difference {worst:.3g} seed spreads "
          f"(tolerance {args.tolerance})")


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
            command.add_argument("--top", choices=["ramp", "servo"], default="ramp")
        if name == "mpi":
            command.add_argument("--mpirun", required=True)
            command.add_argument("--mpirun-flag", action="append", default=[])
    wall = sub.add_parser("wall")
    wall.add_argument("--ellc", required=True)
    wall.add_argument("--lmp", required=True)
    wall.add_argument("--cases", type=int, default=8)
    wall.add_argument("--seed", type=int, default=2026)
    wall.add_argument("--tolerance", type=float, default=1e-9)
    contacts = sub.add_parser("contacts")
    contacts.add_argument("--lmp", required=True)
    contacts.add_argument("--input", required=True)
    contacts.add_argument("--steps", default="100")
    contacts.add_argument("--tolerance", type=float, default=1e-10)
    contacts.add_argument("--mpirun", default="")
    contacts.add_argument("--mpirun-flag", action="append", default=[])
    contacts.add_argument("--np", type=int, default=1)
    apart = sub.add_parser("proven_apart")
    apart.add_argument("--lmp", required=True)
    apart.add_argument("--input", required=True)
    apart.add_argument("--steps", default="400")
    apart.add_argument("--temperature", default="2e14")
    apart.add_argument("--mpirun", default="")
    apart.add_argument("--mpirun-flag", action="append", default=[])
    apart.add_argument("--np", type=int, default=1)
    for name in ("export", "engines"):
        command = sub.add_parser(name)
        command.add_argument("--ellc", required=True)
        command.add_argument("--lmp", required=True)
        command.add_argument("--scenario", required=True)
        command.add_argument("--mpirun", default="")
        command.add_argument("--mpirun-flag", action="append", default=[])
        if name == "export":
            command.add_argument("--target", required=True, help="the scenario's target pressure, MPa")
            command.add_argument("--protocol-checks", choices=("yes", "no"), default="yes",
                                 help="also check how the exported hold and relax end (check_equilibrium_ends)")
        else:
            command.add_argument("--seeds", type=int, default=6)
            command.add_argument("--tolerance", type=float, default=2.0, help="in seed spreads (sd)")
    args = parser.parse_args()
    {"export": check_export, "engines": check_engines, "contacts": check_contacts, "proven_apart": check_proven_apart, "curve": check_curve, "mpi": check_mpi, "restart": check_restart, "wall": check_wall}[args.check](args)


if __name__ == "__main__":
    main()
