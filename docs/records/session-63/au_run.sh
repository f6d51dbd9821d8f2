#!/bin/bash
# set AU, run once at main's loop as it stands (4047938, the loop as at 463efca; verdicts as at 54ab45e), from the
# set-au worktree (branched from 4047938, adding only benchmarks/heldout and its tests), so
# that later commits cannot reach the run; one worker, nice 10
cd /work/wt-au && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set au --out /work/runs/s63/sets_au
cd /work/wt-au && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set au --sets /work/runs/s63/sets_au --workers 1 --out /work/runs/s63/out_au --json /work/runs/s63/heldout_au_main.json > /work/runs/s63/heldout_au_main.out 2>&1
echo $? > /work/runs/s63/au.rc
