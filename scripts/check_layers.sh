#!/usr/bin/env bash
# The layer rules of src/CMakeLists.txt and docs/architecture.md: each layer of src/ellc includes
# only the layers listed for it. Prints every include that breaks a rule; exit 1 if any does.
set -uo pipefail
cd "$(dirname "$0")/../src/ellc"
rules=(
  "io:"
  "material:"
  "hertz:material"
  "law:hertz,material"
  "geometry:hertz,material"
  "contact:geometry,law,hertz,material"
  "engine:contact,geometry,law,hertz,material"
  "cases:io,geometry,law,hertz,material"
  "scenario:engine,cases,io,contact,geometry,law,hertz,material,microstructure"
  "calibration:cases,geometry,law,io,hertz,material"
  "microstructure:io,geometry,hertz,material"
)
bad=0
for rule in "${rules[@]}"; do
  layer=${rule%%:*} allowed=${rule#*:}
  [[ -d $layer ]] || { echo "check_layers: no folder src/ellc/$layer"; bad=1; continue; }
  pattern="\"ellc/($layer${allowed:+|${allowed//,/|}})/"
  # ellc/assert.hpp (ELLC_ASSERT) sits below every layer.
  if grep -rnE '#include *"ellc/' "$layer" | grep -v '"ellc/assert.hpp"' | grep -vE "$pattern"; then bad=1; fi
done
for folder in */; do
  folder=${folder%/}
  printf '%s\n' "${rules[@]}" | grep -q "^$folder:" || { echo "check_layers: src/ellc/$folder has no rule"; bad=1; }
done
if ((bad)); then echo "check_layers: layer rules broken"; exit 1; fi
echo "layer rules hold"
