#!/usr/bin/env bash
# One large calendering run, timed as a whole process (issue 16 item 5): examples/calendering.toml
# with COUNT particles in a box whose area grows with the count, so the layer height, the plate's
# travel and hence the number of steps stay those of the 2000-particle example. Records wall time,
# CPU time, peak RSS, steps and particle-steps/s as JSON next to the run's own outputs.
#
#   nice -n 10 bench/calendering_large.sh [COUNT] [THREADS] [SPEED] [OUT_DIR]
#   defaults: 100000 particles, 2 threads, the example's 0.05 µm/µs, out/calendering_<COUNT>
#
# SPEED replaces the approach, calendering and lift speeds (v·√(mass scaling) is what sets the
# dynamics, docs/engine.md). A run at another speed than the example's is a measurement of cost,
# not a converged result. ELLC_BIN chooses the binary (default build/apps/ellc).
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-100000} threads=${2:-2} speed=${3:-0.05}
out=${4:-out/calendering_${count}}
ellc=${ELLC_BIN:-build/apps/ellc}
mkdir -p "$out"
# The example's 2000 particles stand on 100 × 100 µm²: keep that area per particle.
side=$(/usr/bin/python3 -c "print(f'{100.0 * ($count / 2000.0) ** 0.5:.6g}')")
overrides=("packing.count=$count" "box.size=[$side, $side]" "calendering.approach_speed=$speed"
  "calendering.speed=$speed" "calendering.lift_speed=$speed" "output.vtk_every=0" "output.checkpoint_every=20000")
sets=()
for entry in "${overrides[@]}"; do sets+=(--set "$entry"); done
# What ran: the example and its overrides (a --restart from the checkpoint needs the same --set list).
cp examples/calendering.toml "$out/scenario.toml"
printf '%s\n' "${overrides[@]}" > "$out/set.txt"
load_before=$(cut -d' ' -f1 /proc/loadavg)
if ! /usr/bin/time -o "$out/time.txt" -f "%e %U %S %M" \
  "$ellc" dem "$out/scenario.toml" "${sets[@]}" -o "$out" --no-plot -j "$threads" > "$out/log.txt" 2>&1; then
  echo "calendering_large: the run failed ($out/log.txt):" >&2
  tail -3 "$out/log.txt" >&2
  exit 1
fi
load_after=$(cut -d' ' -f1 /proc/loadavg)
read -r wall user sys max_rss_kib < "$out/time.txt"
steps=$(sed -n 's/^steps = //p' "$out/summary.txt")
/usr/bin/python3 - "$out" "$count" "$threads" "$speed" "$wall" "$user" "$sys" "$max_rss_kib" "$steps" \
  "$load_before" "$load_after" "$(git rev-parse --short HEAD)" << 'EOF'
import json, sys, datetime
out, count, threads, speed, wall, user, sys_, rss_kib, steps, load0, load1, commit = sys.argv[1:]
count, steps, wall = int(count), int(steps), float(wall)
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(f"{out}/summary.txt") if " = " in line and not line.startswith("#"))
result = {
    "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="minutes"), "commit": commit,
    "particles": count, "threads": int(threads), "speed_um_per_us": float(speed), "steps": steps,
    "simulated_time_us": float(summary["time_us"]), "wall_s": wall, "cpu_s": float(user) + float(sys_),
    "peak_rss_bytes": int(rss_kib) * 1024, "peak_rss_bytes_per_particle": int(rss_kib) * 1024 / count,
    "particle_steps_per_s": count * steps / wall, "load_before": float(load0), "load_after": float(load1),
    "finished": summary.get("finished") == "true", "loaded_thickness_um": float(summary["loaded_thickness_um"]),
    "springback_percent": float(summary["springback_percent"]),
    "energy_residual_fraction": float(summary["energy_residual_fraction"]),
}
json.dump(result, open(f"{out}/large_run.json", "w"), indent=1)
print(json.dumps(result, indent=1))
EOF
