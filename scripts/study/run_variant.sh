#!/usr/bin/env bash
# One run of a scenario study (sourced by scripts/convergence_study.sh and sensitivity_study.sh).
#
#   study_run DIR SCENARIO.toml [KEY=VALUE ...]
#
# Copies SCENARIO.toml to DIR/scenario.toml, writes the overrides to DIR/set.txt (one per line)
# and runs `ellc dem DIR/scenario.toml --set KEY=VALUE ...` into DIR (the summary's header lists
# the overrides). Resumable: a run whose DIR/summary.txt says `finished = true` is skipped, and a run
# that was interrupted continues from DIR/checkpoint.bin when it has one (written every
# [output] checkpoint_every steps) rather than from the start; a run another study process is
# running (DIR/.lock) is skipped. ELLC_BIN (default build/apps/ellc)
# and ELLC_THREADS (default 1: the studies are run niced beside other work) choose the binary.

study_finished() { [[ -f "$1/summary.txt" ]] && grep -q '^finished = true' "$1/summary.txt"; }

study_run() {
  local dir=$1 scenario=$2
  shift 2
  study_finished "$dir" && return 0
  mkdir -p "$dir"
  # Another study process may be running this very run (studies split over processes): skip it
  # then; a lock left by a process that has died is taken over.
  if ! mkdir "$dir/.lock" 2> /dev/null; then
    if kill -0 "$(cat "$dir/.lock/pid" 2> /dev/null)" 2> /dev/null; then
      echo "study: $dir is being run by process $(cat "$dir/.lock/pid"); skipped" >&2
      return 0
    fi
  fi
  echo $$ > "$dir/.lock/pid"
  study_run_locked "$dir" "$scenario" "$@"
  rm -rf "$dir/.lock"
}

study_run_locked() {
  local dir=$1 scenario=$2
  shift 2
  local ellc=${ELLC_BIN:-build/apps/ellc} threads=${ELLC_THREADS:-1}
  local sets=()
  for entry in "$@"; do sets+=(--set "$entry"); done
  cp "$scenario" "$dir/scenario.toml.new"
  printf '%s\n' "$@" > "$dir/set.txt.new"
  # A checkpoint only continues the scenario that wrote it: restart only if file and overrides are unchanged.
  if [[ -f "$dir/checkpoint.bin" ]] && cmp -s "$dir/scenario.toml.new" "$dir/scenario.toml" &&
    cmp -s "$dir/set.txt.new" "$dir/set.txt"; then
    echo "study: continuing $dir from its checkpoint" >&2
    if "$ellc" dem "$dir/scenario.toml" "${sets[@]}" -o "$dir" --no-plot -q -j "$threads" \
        --restart "$dir/checkpoint.bin" >> "$dir/log.txt" 2>&1; then
      rm -f "$dir/scenario.toml.new" "$dir/set.txt.new"
      return 0
    fi
    echo "study: the restart of $dir failed (see $dir/log.txt); running it again from the start" >&2
  fi
  mv "$dir/scenario.toml.new" "$dir/scenario.toml"
  mv "$dir/set.txt.new" "$dir/set.txt"
  rm -f "$dir/checkpoint.bin" "$dir/summary.txt" "$dir/timeseries.csv"
  echo "study: running $dir" >&2
  "$ellc" dem "$dir/scenario.toml" "${sets[@]}" -o "$dir" --no-plot -q -j "$threads" > "$dir/log.txt" 2>&1 ||
    echo "study: $dir failed (see $dir/log.txt)" >&2
}
