#!/bin/bash
# usage: sensor_run.sh WT TAG  -- runs every transducer case at worktree WT
WT=$1; TAG=$2; OUT=/work/runs/s50/sensor_$TAG; mkdir -p $OUT
cd $WT
start=$(date +%s)
while read s c; do
  [ -d /work/runs/s50/sets/$s/$c ] || PYTHONPATH=$WT /work/main/.venv/bin/python -m benchmarks.heldout.make_sets --set $s --case $c --out /work/runs/s50/sets/$s >/dev/null 2>&1
  PYTHONPATH=$WT /work/main/.venv/bin/python -m benchmarks.loop_heldout --set $s --cases $c --sets /work/runs/s50/sets/$s --out $OUT/$s --json $OUT/$c.json > $OUT/$c.out 2>&1
  grep -A1 "^$c" $OUT/$c.out
done < /work/runs/s50/sensor_cases.txt > $OUT/all.out
echo "secs=$(( $(date +%s) - start ))" >> $OUT/all.out
