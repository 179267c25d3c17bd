#!/usr/bin/env bash
# Fails (exit 1) if any tracked C++ file under src apps bench integrations tests differs from
# what clang-format-15 makes of it, and lists those files. Fix with: bash scripts/format.sh
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=${CLANG_FORMAT:-clang-format-15}
mapfile -t files < <(git ls-files -- src apps bench integrations tests | grep -E '\.(cpp|hpp|h)$')
# One run over all files; each difference is reported as "FILE:LINE:COL: error: code should be
# clang-formatted [-Wclang-format-violations]".
status=0
report=$("$clang_format" --style=file --dry-run -Werror "${files[@]}" 2>&1) || status=$?
if ((status != 0)); then
  mapfile -t unformatted < <(grep -oE '^[^:]+:[0-9]+:[0-9]+: error: code should be clang-formatted' <<<"$report" |
                             cut -d: -f1 | sort -u)
  if ((${#unformatted[@]} == 0)); then  # clang-format itself failed
    echo "$report" >&2
    exit "$status"
  fi
  echo "check_format: ${#unformatted[@]} of ${#files[@]} files are not formatted (fix: bash scripts/format.sh):"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "check_format: all ${#files[@]} files formatted ($("$clang_format" --version | head -1))"
