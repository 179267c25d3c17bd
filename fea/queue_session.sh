#!/bin/bash
# The run queue of the first FE session (2026-11-22), one CalculiX job at a time on one core.
# Rerunnable: cases whose CSV is already in data/fea are skipped.
cd "$(dirname "$0")/.." || exit 1
export OMP_NUM_THREADS=1
G=fea/run_grid
E="fea/cases/elastic/e_sphere.toml fea/cases/elastic/e_case2.toml fea/cases/elastic/e_case1.toml"
nice -n 10 $G $E --elastic --mesh coarse --suffix _elastic_coarse
nice -n 10 $G $E --elastic --mesh medium --suffix _elastic_medium
nice -n 10 $G fea/cases/elastic/e_sphere.toml --elastic --mesh fine --suffix _elastic_fine
nice -n 10 $G fea/cases/grid/g01_sphere.toml --mesh medium
nice -n 10 $G fea/cases/paper_case2.toml --mesh medium --points 10
nice -n 10 $G fea/cases/grid/g0[2-9]*.toml fea/cases/grid/g1[0-2]*.toml --mesh medium
nice -n 10 $G fea/cases/paper_case1.toml --mesh medium --points 10
nice -n 10 $G fea/cases/elastic/e_case2.toml fea/cases/elastic/e_case1.toml --elastic --mesh fine --suffix _elastic_fine
nice -n 10 $G fea/cases/grid/g1[3-6]*.toml --mesh medium
echo "queue done $(date -u +%H:%M:%S)"
