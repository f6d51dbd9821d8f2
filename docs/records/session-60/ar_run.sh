#!/bin/bash
# set AR, run once at main's loop as merged (64b0995), from its own worktree so that later
# commits cannot reach the run; its verdicts as at 54ab45e (the session's changes touch the
# Dask runner's waiting, progress lines, plots and the dataset's dead-channel check, no
# verdict); one worker, nice 10
cd /work/wt-run && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set ar --out /work/runs/s60/sets_ar
cd /work/wt-run && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set ar --sets /work/runs/s60/sets_ar --workers 1 --out /work/runs/s60/out_ar --json /work/runs/s60/heldout_ar_main.json > /work/runs/s60/heldout_ar_main.out 2>&1
echo $? > /work/runs/s60/ar.rc
