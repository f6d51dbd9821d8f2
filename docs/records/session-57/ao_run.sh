#!/bin/bash
# set AO, run once at main's loop (its verdicts as at 54ab45e: every kind cross-validated, the
# refit's signature check on), one worker, nice 10 beside a hostile-user helper
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.heldout.make_sets --set ao --out /work/runs/s57/sets_ao
cd /work/main && OPENBLAS_NUM_THREADS=1 nice -n 10 .venv/bin/python -m benchmarks.loop_heldout --set ao --sets /work/runs/s57/sets_ao --workers 1 --out /work/runs/s57/out_ao --json /work/runs/s57/heldout_ao_main.json > /work/runs/s57/heldout_ao_main.out 2>&1
