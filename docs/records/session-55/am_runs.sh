#!/bin/bash
# set AM, the loop at main (every kind) and at the session's start (top five), side by side
cd /work/main && OPENBLAS_NUM_THREADS=1 PYTHONPATH=/work/main /work/main/.venv/bin/python -m benchmarks.loop_heldout --set am --sets /work/runs/s55/sets_am --out /work/runs/s55/out_am_main --json /work/runs/s55/heldout_am_main.json > /work/runs/s55/heldout_am_main.out 2>&1 &
cd /work/wt-base-am && OPENBLAS_NUM_THREADS=1 PYTHONPATH=/work/wt-base-am /work/main/.venv/bin/python -m benchmarks.loop_heldout --set am --sets /work/runs/s55/sets_am --out /work/runs/s55/out_am_base --json /work/runs/s55/heldout_am_base.json > /work/runs/s55/heldout_am_base.out 2>&1 &
wait
