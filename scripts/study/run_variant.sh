#!/usr/bin/env bash
# One run of a scenario study (sourced by scripts/convergence_study.sh and sensitivity_study.sh).
#
#   study_run DIR SCENARIO.toml [sed expression ...]
#
# Writes DIR/scenario.toml (SCENARIO.toml edited by the sed expressions) and runs `ellc dem` on it
# into DIR. Resumable: a run whose DIR/summary.txt says `finished = true` is skipped, and a run
# that was interrupted continues from DIR/checkpoint.bin when it has one (written every
# [output] checkpoint_every steps) rather than from the start. ELLC_BIN (default build/apps/ellc)
# and ELLC_THREADS (default 1: the studies are run niced beside other work) choose the binary.

study_finished() { [[ -f "$1/summary.txt" ]] && grep -q '^finished = true' "$1/summary.txt"; }

study_run() {
  local dir=$1 scenario=$2
  shift 2
  local ellc=${ELLC_BIN:-build/apps/ellc} threads=${ELLC_THREADS:-1}
  study_finished "$dir" && return 0
  mkdir -p "$dir"
  local expressions=()
  for expression in "$@"; do expressions+=(-e "$expression"); done
  sed "${expressions[@]}" "$scenario" > "$dir/scenario.toml.new"
  # A checkpoint only continues the scenario that wrote it: restart only if the file is unchanged.
  if [[ -f "$dir/checkpoint.bin" ]] && cmp -s "$dir/scenario.toml.new" "$dir/scenario.toml"; then
    echo "study: continuing $dir from its checkpoint" >&2
    if "$ellc" dem "$dir/scenario.toml" -o "$dir" --no-plot -q -j "$threads" --restart "$dir/checkpoint.bin" \
        >> "$dir/log.txt" 2>&1; then
      rm -f "$dir/scenario.toml.new"
      return 0
    fi
    echo "study: the restart of $dir failed (see $dir/log.txt); running it again from the start" >&2
  fi
  mv "$dir/scenario.toml.new" "$dir/scenario.toml"
  rm -f "$dir/checkpoint.bin" "$dir/summary.txt" "$dir/timeseries.csv"
  echo "study: running $dir" >&2
  "$ellc" dem "$dir/scenario.toml" -o "$dir" --no-plot -q -j "$threads" > "$dir/log.txt" 2>&1 ||
    echo "study: $dir failed (see $dir/log.txt)" >&2
}
