#!/bin/bash
# The FE queue for the aluminium data in data/fea/aluminium/ (issue 14), on one core.
# Cases already done (their CSV exists) are skipped, so rerunning resumes where it stopped:
#   OMP_NUM_THREADS=1 nohup nice -n 10 fea/queue_aluminium.sh > out/queue_aluminium.log 2>&1 &
# Order (fea/ellc_fea/grid.py, ALUMINIUM_GRID): the elastic Hertz check; the held-out pairs
# g04 and g05 (the fit already has g01); the plastic mesh check of g01 one level coarser; the
# remaining grid (the two geometries that stalled, g02 and g03, last); the fine mesh check.
cd "$(dirname "$0")/.." || exit 1
export OMP_NUM_THREADS=1
G="fea/run_grid --out data/fea/aluminium --manifest data/fea/aluminium/manifest.json --work out/fea/work_aluminium"
C=fea/cases/grid_aluminium
nice -n 10 $G fea/cases/elastic/e_sphere_aluminium.toml --elastic --mesh ductile --suffix _elastic
nice -n 10 $G $C/g04_sphere_2_10.toml $C/g05_paper_fig10.toml --mesh ductile
nice -n 10 $G $C/g01_sphere.toml --mesh ductile_coarse --suffix _coarse
CASES=$(/usr/bin/python3 -c "import sys; sys.path.insert(0, 'fea'); from ellc_fea.grid import ALUMINIUM_GRID; print(' '.join(ALUMINIUM_GRID))")
for name in $CASES; do nice -n 10 $G $C/$name.toml --mesh ductile; done
nice -n 10 $G $C/g01_sphere.toml --mesh ductile_fine --suffix _fine
echo "aluminium queue done $(date -u +%H:%M:%S)"
