#!/bin/bash
# As run in session 54: a worktree of branch every-kind (69afb11, every_kind.diff) at /work/wt-k, outputs under /work/runs/s54
cd /work/wt-k
PY=/work/main/.venv/bin/python
export PYTHONPATH=/work/wt-k
$PY -m benchmarks.heldout.make_sets --out /work/sets/ag --set ag --case hag_airbag_sled_full > /dev/null 2>&1
for sc in "al hal_toe_all" "ak hak_knee_r16_sled" "ag hag_airbag_sled_full"; do
  set -- $sc
  $PY -m benchmarks.loop_heldout --set $1 --sets /work/sets/$1 --out /work/runs/s54/k_$2 --cases $2 --json /work/runs/s54/k_$2.json 2>&1 | tail -25
done
for s in ad ae af ag ah ai aj; do
  for c in $(grep -o 'Case("h[a-z]*_clean[0-9]*"' benchmarks/heldout/cases_$s.py | sed 's/Case("//;s/"//'); do
    $PY -m benchmarks.heldout.make_sets --out /work/sets/$s --set $s --case $c > /dev/null 2>&1
    $PY -m benchmarks.loop_heldout --set $s --sets /work/sets/$s --out /work/runs/s54/k_$c --cases $c --json /work/runs/s54/k_$c.json 2>&1 | tail -4
  done
done
echo LANE1 DONE
