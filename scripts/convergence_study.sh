#!/usr/bin/env bash
# Rate (= mass-scaling) convergence of a calendering scenario over packing seeds.
#
#   scripts/convergence_study.sh SCENARIO.toml OUT_DIR "SPEEDS" "SEEDS"
#   e.g. scripts/convergence_study.sh examples/calendering_quick.toml out/convergence "0.05 0.025" "2026 2027 2028 2029 2030"
#
# Each speed replaces approach_speed, speed and lift_speed of [calendering] (the dynamics depend
# on v·sqrt(mass_scaling) alone, docs/engine.md), each seed [packing] seed. Every run's summary is
# kept in OUT_DIR/v<speed>_s<seed>/; OUT_DIR/convergence.md tabulates, for each speed against the
# one before it in SPEEDS (give them halving), the paired change over the seeds of the loaded
# thickness (%), the springback (points) and the held pressure (%): mean ± standard deviation,
# and the standard error of the mean, which says whether the change is resolved at all.
set -euo pipefail
cd "$(dirname "$0")/.."
scenario=$1 out=$2 speeds=$3 seeds=$4
ellc=${ELLC_BIN:-build/apps/ellc}
mkdir -p "$out"
for v in $speeds; do
  for s in $seeds; do
    dir="$out/v${v}_s${s}"
    [[ -f "$dir/summary.txt" ]] && continue
    mkdir -p "$dir"
    sed -e "s/^seed = .*/seed = $s/" -e "s/^approach_speed = [0-9.e-]*/approach_speed = $v/" \
        -e "s/^speed = [0-9.e-]*/speed = $v/" -e "s/^lift_speed = [0-9.e-]*/lift_speed = $v/" "$scenario" > "$dir/scenario.toml"
    echo "convergence: v = $v µm/µs, seed $s" >&2
    "$ellc" dem "$dir/scenario.toml" -o "$dir" --no-plot > "$dir/log.txt" 2>&1 || echo "convergence: v = $v, seed $s failed (see $dir/log.txt)" >&2
  done
done
/usr/bin/python3 - "$out" "$speeds" "$seeds" "$scenario" <<'PY'
import statistics, sys, pathlib
out, speeds, seeds, scenario = pathlib.Path(sys.argv[1]), sys.argv[2].split(), sys.argv[3].split(), sys.argv[4]
def summary(v, s):
    path = out / f"v{v}_s{s}" / "summary.txt"
    if not path.exists(): return None
    values = dict(line.split(" = ", 1) for line in path.read_text().splitlines() if " = " in line)
    return values if values.get("finished") == "true" else None
keys = [("loaded_thickness_um", "loaded thickness", "%", True), ("springback_percent", "springback", "points", False),
        ("held_pressure_MPa", "held pressure", "%", True)]
lines = [f"# Rate convergence of `{scenario}`", "",
         f"Seeds: {' '.join(seeds)}. Each row: the paired change from the previous speed to this one, "
         "mean ± sd over the seeds [standard error of the mean].", "",
         "| v (µm/µs) | from | runs | " + " | ".join(f"Δ {name} ({unit})" for _, name, unit, _ in keys) +
         " | unbalanced-force ratio at the reading (max) |",
         "|---" * (len(keys) + 4) + "|"]
for previous, v in zip(speeds, speeds[1:]):
    pairs = [(summary(previous, s), summary(v, s)) for s in seeds]
    pairs = [(a, b) for a, b in pairs if a and b]
    cells = []
    for key, _, unit, relative in keys:
        d = [(float(b[key]) - float(a[key])) * (100.0 / float(a[key]) if relative else 1.0) for a, b in pairs]
        sd = statistics.stdev(d) if len(d) > 1 else float("nan")
        cells.append(f"{statistics.mean(d):+.3f} ± {sd:.3f} [{sd / len(d) ** 0.5:.3f}]" if len(d) > 1 else "–")
    ratio = max((float(b["loaded_unbalanced_force_ratio"]) for _, b in pairs), default=float("nan"))
    lines.append(f"| {v} | {previous} | {len(pairs)} | " + " | ".join(cells) + f" | {ratio:.2g} |")
(out / "convergence.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
PY
