"""Identification benchmark: our grey-box, ARX and N4SID beside the Python peers.

Peers: SIPPY (PyPI ``sippy-unipi``: ARX and N4SID) and ``nfoursid`` (N4SID). No Python package
offers a grey-box fit like MATLAB's greyest, so ours stands alone there.

Same data for everyone: the bundled campaign's R16 tests (odd estimate, even validate, or
``--setup``), resampled as the bus carries them (``--rate``, default 1000 Hz), window
0.01..0.15 s. The peers take one record, so their estimation tests are concatenated; every
model is then simulated from rest on each validation test and scored with eq. 3.15-3.18.
Times are the median of ``--repeat`` runs of the fit alone, on this machine, in one run.

    pip install -e '.[bench]' && python benchmarks/identification.py [--rate 1000]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import statistics
import time
import warnings

import numpy as np
from scipy import signal

from observer_node.data import bundled_campaign, load_tests
from observer_node.evaluation import split_halves
from observer_node.ident import arx, greybox, n4sid
from observer_node.ident.dataset import Dataset, make_dataset
from observer_node.ident.metrics import fit_table
from observer_node.model import simulate_ss


def timed(fn, repeat: int):
    times, result = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = fn()
        times.append(time.perf_counter() - t0)
    return result, statistics.median(times)


def concatenated(d: Dataset) -> tuple[np.ndarray, np.ndarray]:
    u = np.concatenate([np.stack([d.pulse_g[k], d.brs_rad[k]]) for k in range(d.n_tests)], 1)
    y = np.concatenate([d.y[k].T for k in range(d.n_tests)], axis=1)
    return u, y


def score(val: Dataset, y_hat: np.ndarray) -> dict:
    with np.errstate(all="ignore"):
        return fit_table(val.names, val.y[:, val.win], y_hat[:, val.win]).fit.as_dict()


def ss_sim(val: Dataset, A, B, C, D) -> np.ndarray:
    with np.errstate(all="ignore"):
        return simulate_ss(np.asarray(A), np.asarray(B), np.asarray(C), np.asarray(D),
                           np.stack([val.pulse_g, val.brs_rad], -1))


def sippy_arx_sim(model, val: Dataset) -> np.ndarray:
    """Simulate SIPPY's MIMO ARX transfer functions from rest on each test."""
    out = np.zeros_like(val.y)
    u = [val.pulse_g, val.brs_rad]
    for i in range(2):
        for j in range(2):
            num = np.atleast_1d(np.asarray(model.NUMERATOR[i][j], float))
            den = np.atleast_1d(np.asarray(model.DENOMINATOR[i][j], float))
            b = np.concatenate([np.zeros(len(den) - len(num)), num])
            out[:, :, i] += signal.lfilter(b, den, u[j], axis=1)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rate", type=float, default=1000.0, help="sampling rate in Hz")
    ap.add_argument("--setup", default="R16")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--block-rows", type=int, default=24, help="subspace block rows (all)")
    a = ap.parse_args()

    import pandas as pd
    from nfoursid.nfoursid import NFourSID
    from sippy_unipi import system_identification

    tests = [t for t in load_tests([bundled_campaign()]) if t.setup == a.setup]
    est_t, val_t = split_halves(tests)
    est, val = make_dataset(est_t, a.rate), make_dataset(val_t, a.rate)
    u, y = concatenated(est)
    ts = 1.0 / a.rate
    rows: list[tuple[str, str, str, float, dict]] = []
    br = a.block_rows
    print(f"{a.setup}: estimate on {', '.join(est.names)}; validate on {', '.join(val.names)}")
    print(f"rate {a.rate:g} Hz, window 0.01..0.15 s, {u.shape[1]} estimation samples, "
          f"median of {a.repeat} runs\n")

    fit, t = timed(lambda: greybox.fit_greybox(est), a.repeat)
    rows.append(("grey-box", "ours", "least_squares, 3 starts", t,
                 score(val, greybox.simulate(fit.params, val))))

    # ARX at one fixed structure for all: na = 4 (own output), nb = 4, nk = 1.
    orders = arx.ArxOrders(np.array([[4, 0], [0, 4]]), np.full((2, 2), 4), np.ones((2, 2), int))
    m, t = timed(lambda: arx.estimate_arx(est, orders), a.repeat)
    rows.append(("ARX na4 nb4 nk1", "ours", "least squares, all tests", t,
                 score(val, m.simulate(val))))
    sm, t = timed(lambda: system_identification(
        y, u, "ARX", ARX_orders=[[4, 4], [[4, 4], [4, 4]], [[1, 1], [1, 1]]], tsample=ts),
        a.repeat)
    rows.append(("ARX na4 nb4 nk1", "SIPPY", "ARX_mod=LLS, concatenated", t,
                 score(val, sippy_arx_sim(sm, val))))
    # ARX with the thesis's order search (no peer has it)
    (o6, _), t = timed(lambda: arx.search_orders(est, 6), a.repeat)
    rows.append(("ARX Nmax=6 search", "ours", f"NA={o6.na.tolist()} NB={o6.nb.tolist()}", t,
                 score(val, arx.estimate_arx(est, o6).simulate(val))))

    df = pd.DataFrame(np.vstack([u, y]).T, columns=["pulse", "brs", "cr", "cd"])
    for order in (7, 16):
        mm, t = timed(lambda order=order: n4sid.n4sid(est, order, br), a.repeat)
        rows.append((f"N4SID n={order}", "ours", f"{br} block rows, B/D by simulation", t,
                     score(val, mm.simulate(val))))
        ps, t = timed(lambda order=order: system_identification(
            y, u, "N4SID", SS_fixed_order=order, SS_f=br, SS_p=br, tsample=ts), a.repeat)
        rows.append((f"N4SID n={order}", "SIPPY", f"SS_f=SS_p={br}", t,
                     score(val, ss_sim(val, ps.A, ps.B, ps.C, ps.D))))
        for nbr in (br, 2):
            def nf(order=order, nbr=nbr):
                n = NFourSID(df, output_columns=["cr", "cd"], input_columns=["pulse", "brs"],
                             num_block_rows=nbr)
                n.subspace_identification()
                return n.system_identification(rank=min(order, 2 * nbr))[0]
            try:
                ns, t = timed(nf, a.repeat)
                label = f"num_block_rows={nbr}" + (" (default)" if nbr == 2 else "")
                if order > 2 * nbr:
                    label += f", order capped at {2 * nbr}"
                rows.append((f"N4SID n={order}", "nfoursid", label, t,
                             score(val, ss_sim(val, ns.a, ns.b, ns.c, ns.d))))
            except Exception as e:  # a peer failing is a result too
                rows.append((f"N4SID n={order}", "nfoursid", f"failed: {e}"[:50], float("nan"),
                             {"cr": float("nan"), "cd": float("nan"), "total": float("nan")}))

    print(f"{'model':<20}{'tool':<10}{'settings':<44}{'time [s]':>10}{'val CR':>8}"
          f"{'val CD':>8}{'val TOT':>9}")
    for model, tool, settings, t, f in rows:
        print(f"{model:<20}{tool:<10}{settings:<44}{t:>10.4f}{f['cr']:>8.1f}{f['cd']:>8.1f}"
              f"{f['total']:>9.1f}")


if __name__ == "__main__":
    main()
