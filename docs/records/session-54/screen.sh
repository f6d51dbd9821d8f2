#!/bin/bash
# ./screen.sh knee.lane (or bag.lane): each line a set, a case and the kind judged against
lane=$(realpath "$1")
cd "$(dirname "$0")/../../.."  # the checkout this lives in
PY=.venv/bin/python
while read -r s c a; do
  $PY -m benchmarks.heldout.make_sets --out ${SETS:-/tmp/sets}/$s --set $s --case $c > /dev/null 2>&1
  if [ -n "$a" ]; then
    $PY -m benchmarks.form_screen --form belt_knee --set $s --case $c --sets ${SETS:-/tmp/sets}/$s --against $a 2>&1
  else
    $PY -m benchmarks.form_screen --form belt_knee --set $s --case $c --sets ${SETS:-/tmp/sets}/$s 2>&1
  fi
done < "$lane"
