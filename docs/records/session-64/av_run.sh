#!/bin/bash
# set AV, run once at main's loop as it stands when the draw is merged (the rate-limit check
# of 6d80a9a added, no physical verdict changed since 54ab45e), from a worktree of that merge
# (/work/wt-avrun), so that later commits cannot reach the run; one worker, nice 10
cd /work/wt-avrun && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set av --out /work/runs/s64/sets_av
cd /work/wt-avrun && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set av --sets /work/runs/s64/sets_av --workers 1 --out /work/runs/s64/out_av --json /work/runs/s64/heldout_av_main.json > /work/runs/s64/heldout_av_main.out 2>&1
echo $? > /work/runs/s64/av.rc
