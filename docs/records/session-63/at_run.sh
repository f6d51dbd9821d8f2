#!/bin/bash
# set AT, run once at main's loop as it stands (463efca; verdicts as at 54ab45e), from the
# set-at worktree (branched from 463efca, adding only benchmarks/heldout and its tests), so
# that later commits cannot reach the run; one worker, nice 10
cd /work/wt-at && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set at --out /work/runs/s63/sets_at
cd /work/wt-at && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set at --sets /work/runs/s63/sets_at --workers 1 --out /work/runs/s63/out_at --json /work/runs/s63/heldout_at_main.json > /work/runs/s63/heldout_at_main.out 2>&1
echo $? > /work/runs/s63/at.rc
