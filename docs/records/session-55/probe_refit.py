"""Probe (session 55): why ham_knee_all's belt_stiffening refit leaves more for its signature.
Wraps the refit's optimiser in the main process and prints each 120-evaluation refit's stop."""
import sys
import types

import scipy.optimize as so

import observer_node.loop.refit as rf

calls = []


def ls(fun, x0, **kw):
    r = so.least_squares(fun, x0, **kw)
    if kw.get("max_nfev") == int(sys.argv[2]):
        print(f"refit n={len(x0)} max_nfev={kw['max_nfev']} nfev={r.nfev} status={r.status} "
              f"cost={2 * r.cost:.6g} opt={r.optimality:.3g} ({r.message})", flush=True)
    return r


rf.optimize = types.SimpleNamespace(least_squares=ls)

from pathlib import Path  # noqa: E402

from benchmarks.heldout import sets as hs  # noqa: E402
from benchmarks.loop_heldout import run_case  # noqa: E402

if __name__ == "__main__":
    case = hs.select([sys.argv[1]], "am")[0]
    out = run_case(case, Path("/work/runs/s55/sets_am"), Path("/work/runs/s55/probe/out"), None)
    print({k: out[k] for k in ("named",) if k in out})
