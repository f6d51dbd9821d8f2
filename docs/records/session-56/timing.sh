# the loop's time on campaign-a (12+12): HEAD (A) paired against session 30's f357ce1 (B) at
# two workers idle, A B A B; then A at one worker idle, and A at 1 and 2 workers with both
# cores busy. The set-AO helper's processes run beside it at nice 19 (renice.sh).
export OPENBLAS_NUM_THREADS=1
A=/work/main; B=/work/wt-s30; PY=/work/main/.venv/bin/python
run() { # label dir args
  local l=$1 d=$2; shift 2
  echo "== $l $(date +%T) load $(cut -d' ' -f1-3 /proc/loadavg)"
  ( cd $d && PYTHONPATH=$d /usr/bin/time -f "wall %e s cpu %U+%S" $PY benchmarks/loop_time.py "$@" 2>&1 )
}
run A-idle-2 $A --workers 2 --no-load
run B-idle-2 $B --workers 2 --no-load
run A-idle-2 $A --workers 2 --no-load
run B-idle-2 $B --workers 2 --no-load
run A-idle-1 $A --workers 1 --no-load
run A-loaded-1-2 $A --workers 1 2 --loaded-only
touch /work/runs/s56/timing.done
