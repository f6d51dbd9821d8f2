#!/bin/bash
# set AQ, run once at main's loop (its verdicts as at 54ab45e: every kind cross-validated, the
# refit's signature check on; nothing in the loop changed since), one worker, nice 10
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.heldout.make_sets --set aq --out /work/runs/s59/sets_aq
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.loop_heldout --set aq --sets /work/runs/s59/sets_aq --workers 1 --out /work/runs/s59/out_aq --json /work/runs/s59/heldout_aq_main.json > /work/runs/s59/heldout_aq_main.out 2>&1
echo $? > /work/runs/s59/aq.rc
