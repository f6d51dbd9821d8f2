#!/bin/bash
# paired timing of one held-out case: every-kind (wt-k, 4c5ea24) vs the session's start (wt-base, db57a72)
case=$1
OPENBLAS_NUM_THREADS=1 farm-bench -n 3 --warmup 0 --timeout 3000 \
  --vs "sh -c 'cd /work/wt-base && PYTHONPATH=/work/wt-base exec /work/main/.venv/bin/python -m benchmarks.loop_heldout --set al --sets /work/runs/s55/sets_al --cases $case --out /tmp/tB_$case >>/tmp/tB_$case.log 2>&1'" \
  -- sh -c "cd /work/wt-k && PYTHONPATH=/work/wt-k exec /work/main/.venv/bin/python -m benchmarks.loop_heldout --set al --sets /work/runs/s55/sets_al --cases $case --out /tmp/tA_$case >>/tmp/tA_$case.log 2>&1"
