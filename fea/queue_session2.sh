#!/bin/bash
# Second queue of the first FE session: starts when the first (PID $1) has ended.
# Elastic check of the oblate pair, plastic mesh-convergence check on the sphere grid case, then grid cases g17-g25.
while kill -0 "$1" 2>/dev/null; do sleep 20; done
cd "$(dirname "$0")/.." || exit 1
export OMP_NUM_THREADS=1
G=fea/run_grid
nice -n 10 $G fea/cases/elastic/e_oblate.toml --elastic --mesh medium --suffix _elastic_medium
nice -n 10 $G fea/cases/grid/g01_sphere.toml --mesh coarse --suffix _coarse
nice -n 10 $G fea/cases/grid/g01_sphere.toml --mesh fine --suffix _fine
nice -n 10 $G fea/cases/grid/g1[7-9]*.toml fea/cases/grid/g2*.toml --mesh medium
echo "queue 2 done $(date -u +%H:%M:%S)"
