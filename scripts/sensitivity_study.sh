#!/usr/bin/env bash
# Sensitivity of a calendering scenario to the dashpot ratio ζ and the friction coefficient μ,
# over packing seeds (issue 13, item 5).
#
#   scripts/sensitivity_study.sh SCENARIO.toml OUT_DIR "VARIANTS" "SEEDS"
#   e.g. nice -n 10 scripts/sensitivity_study.sh examples/calendering_quick.toml out/sensitivity \
#          "0.05:0.3 0.01:0.3 0.3:0.3 0.05:0.1 0.05:0.6" "2026 2027 2028"
#
# Each variant ζ:μ sets [contact] damping_ratio = ζ, and [contact] friction and [walls] friction
# = μ; the first variant is the reference. Every run is kept in OUT_DIR/z<ζ>_m<μ>_s<seed>/; the
# study is resumable as scripts/convergence_study.sh is (scripts/study/run_variant.sh).
# OUT_DIR/sensitivity.md tabulates, per variant, the loaded thickness, springback and held
# pressure (mean ± sd over the seeds), their paired change from the reference, and the shares of
# the plate work taken by plastic flow, friction, the dashpots and the background drag
# (scripts/study/tables.py). STUDY_TABLE_ONLY=1 only tabulates what has finished.
set -euo pipefail
cd "$(dirname "$0")/.."
scenario=$1 out=$2 variants=$3 seeds=$4
source scripts/study/run_variant.sh
mkdir -p "$out"
labels=()
for variant in $variants; do
  zeta=${variant%%:*} mu=${variant##*:}
  labels+=("z${zeta}_m${mu}")
  [[ -n "${STUDY_TABLE_ONLY:-}" ]] && continue
  for s in $seeds; do
    study_run "$out/z${zeta}_m${mu}_s${s}" "$scenario" "packing.seed=$s" "contact.damping_ratio=$zeta" \
      "contact.friction=$mu" "walls.friction=$mu" "output.vtk_every=0"
  done
done
/usr/bin/python3 scripts/study/tables.py sensitivity "$out" "${labels[*]}" "$seeds" "$scenario"
