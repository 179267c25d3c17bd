#!/usr/bin/env bash
# Rate (= mass-scaling) convergence of a calendering scenario over packing seeds.
#
#   scripts/convergence_study.sh SCENARIO.toml OUT_DIR "SPEEDS" "SEEDS"
#   e.g. nice -n 10 scripts/convergence_study.sh examples/calendering.toml out/convergence "0.05 0.025" "2026 2027 2028 2029 2030"
#
# Each speed replaces approach_speed, speed and lift_speed of [calendering] (the dynamics depend
# on v·sqrt(mass_scaling) alone, docs/engine.md), each seed [packing] seed; no VTK frames but the
# first and last. Every run is kept in OUT_DIR/v<speed>_s<seed>/. The study is resumable: run the
# same command again and it skips finished runs and continues interrupted ones from their
# checkpoint (scripts/study/run_variant.sh). OUT_DIR/convergence.md tabulates, for each speed
# against the one before it in SPEEDS (give them halving), the paired change over the seeds of
# the loaded thickness (%), the springback (points) and the held pressure (%): mean ± standard
# deviation, and the standard error of the mean, which says whether the change is resolved at
# all; and the means of each speed over its finished runs (scripts/study/tables.py).
# STUDY_TABLE_ONLY=1 only tabulates what has finished.
set -euo pipefail
cd "$(dirname "$0")/.."
scenario=$1 out=$2 speeds=$3 seeds=$4
source scripts/study/run_variant.sh
mkdir -p "$out"
if [[ -z "${STUDY_TABLE_ONLY:-}" ]]; then
  for v in $speeds; do
    for s in $seeds; do
      study_run "$out/v${v}_s${s}" "$scenario" "packing.seed=$s" "calendering.approach_speed=$v" \
        "calendering.speed=$v" "calendering.lift_speed=$v" "output.vtk_every=0"
    done
  done
fi
/usr/bin/python3 scripts/study/tables.py convergence "$out" "$speeds" "$seeds" "$scenario"
