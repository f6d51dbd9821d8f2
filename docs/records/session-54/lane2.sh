#!/bin/bash
# As run in session 54: a worktree of branch every-kind (69afb11, every_kind.diff) at /work/wt-k, outputs under /work/runs/s54
cd /work/wt-k
PY=/work/main/.venv/bin/python
export PYTHONPATH=/work/wt-k
for s in ak al; do
  $PY -m benchmarks.heldout.make_sets --out /work/sets2/$s --set $s > /dev/null 2>&1
  /usr/bin/time -f "%e s" $PY -m benchmarks.loop_heldout --set $s --sets /work/sets2/$s --out /work/runs/s54/k_set_$s --json /work/runs/s54/k_set_$s.json 2>&1
done
echo LANE2 DONE
