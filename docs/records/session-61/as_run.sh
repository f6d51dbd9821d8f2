#!/bin/bash
# set AS, run once at main's loop as merged, from its own worktree so that later commits
# cannot reach the run; its verdicts as at 54ab45e (the session's loop changes touch
# report.md's names and a not_read list, no verdict); the benchmark counts a sensor
# correction where no transducer is at fault as wrong (de74818); one worker, nice 10
cd /work/wt-run && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set as --out /work/runs/s61/sets_as
cd /work/wt-run && OPENBLAS_NUM_THREADS=1 nice -n 10 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set as --sets /work/runs/s61/sets_as --workers 1 --out /work/runs/s61/out_as --json /work/runs/s61/heldout_as_main.json > /work/runs/s61/heldout_as_main.out 2>&1
echo $? > /work/runs/s61/as.rc
