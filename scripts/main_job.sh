#!/usr/bin/env bash
# The README's main job: installs what is missing, builds, and runs both paper cases (CSV, PNG,
# summaries) and the calendering example. Results go to ./out.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
for case in paper_case1 paper_case2; do
  echo "== ellc curve examples/${case}.toml"
  build/apps/ellc curve "examples/${case}.toml" -o "out/${case}.csv" --plot "out/${case}.png"
done
echo "== ellc dem examples/calendering.toml"
build/apps/ellc dem examples/calendering.toml --output-dir out/calendering
