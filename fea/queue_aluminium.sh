#!/bin/bash
# The FE queue for the aluminium data in data/fea/aluminium/ (issue 14), on one core.
# Elastic check first (Hertz), then the reduced grid at the contact-refined "ductile" mesh,
# then the plastic mesh check of g01 at "ductile_fine".  Cases already done are skipped.
cd "$(dirname "$0")/.." || exit 1
export OMP_NUM_THREADS=1
G="fea/run_grid --out data/fea/aluminium --manifest data/fea/aluminium/manifest.json --work out/fea/work_aluminium"
nice -n 10 $G fea/cases/elastic/e_sphere_aluminium.toml --elastic --mesh ductile --suffix _elastic
nice -n 10 $G fea/cases/grid_aluminium/*.toml --mesh ductile
nice -n 10 $G fea/cases/grid_aluminium/g01_sphere.toml --mesh ductile_fine --suffix _fine
echo "aluminium queue done $(date -u +%H:%M:%S)"
