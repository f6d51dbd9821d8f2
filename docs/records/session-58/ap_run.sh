#!/bin/bash
# set AP, run once at main's loop (its verdicts as at 54ab45e: every kind cross-validated, the
# refit's signature check on), one worker, nice 10 beside fixes and their tests
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.heldout.make_sets --set ap --out /work/runs/s58/sets_ap
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.loop_heldout --set ap --sets /work/runs/s58/sets_ap --workers 1 --out /work/runs/s58/out_ap --json /work/runs/s58/heldout_ap_main.json > /work/runs/s58/heldout_ap_main.out 2>&1
