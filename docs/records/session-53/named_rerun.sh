#!/bin/bash
# rerun the named physical cases of sets AD-AK (latest outputs), one at a time, reports kept
cd "$(git -C "$(dirname "$0")" rev-parse --show-toplevel)"  # the checkout whose loop is rerun
PY=/work/main/.venv/bin/python
S=${1:-/work/runs/s53/named}  # where the sets and outputs go
while read set case; do
  [ -d $S/sets/$case ] || PYTHONPATH=. $PY -m benchmarks.heldout.make_sets --out $S/sets --set $set --case $case > /dev/null 2>&1
  [ -f $S/$case/report.json ] && continue
  /work/main/.venv/bin/observer-node loop --estimate $S/sets/$case/est --validate $S/sets/$case/val --out $S/$case --quiet > $S/$case.log 2>&1
  echo "$case $?" >> $S/done.txt
done <<LIST
ad had_toe_all
ad had_submarine_all
ae hae_bottoming_r16
af haf_hysteresis_r16_full
af haf_toe_r16_full
ah hah_power_all
ah hah_lumbar_full
ah hah_two_maxwell_r16_full_dual_sled
ai hai_power_sled_full
aj haj_bumper_sled_full
aj haj_sealed_sled
ak hak_fluid_r16
LIST
echo ALLDONE >> $S/done.txt
