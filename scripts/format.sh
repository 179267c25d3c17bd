#!/usr/bin/env bash
# Formats every tracked C++ file under src apps bench integrations tests in place with
# clang-format-15 and the repository's .clang-format. scripts/check_format.sh is the CI check.
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=${CLANG_FORMAT:-clang-format-15}
mapfile -t files < <(git ls-files -- src apps bench integrations tests | grep -E '\.(cpp|hpp|h)$')
"$clang_format" -i --style=file "${files[@]}"
echo "format: ${#files[@]} files formatted with $("$clang_format" --version | head -1)"
