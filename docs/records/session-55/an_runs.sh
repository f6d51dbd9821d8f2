#!/bin/bash
# set AN, the loop at main (every kind; wt-an = set-an on d6624fd, the loop as main's) and
# with the signature check off (wt-an-ns), side by side, nice 19 beside the CI
cd /work/wt-an && OPENBLAS_NUM_THREADS=1 PYTHONPATH=/work/wt-an nice -n 19 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set an --sets /work/runs/s55/sets_an --workers 1 --out /work/runs/s55/out_an_main --json /work/runs/s55/heldout_an_main.json > /work/runs/s55/heldout_an_main.out 2>&1 &
cd /work/wt-an-ns && OPENBLAS_NUM_THREADS=1 PYTHONPATH=/work/wt-an-ns nice -n 19 /work/main/.venv/bin/python -m benchmarks.loop_heldout --set an --sets /work/runs/s55/sets_an --workers 1 --out /work/runs/s55/out_an_ns --json /work/runs/s55/heldout_an_ns.json > /work/runs/s55/heldout_an_ns.out 2>&1 &
wait
