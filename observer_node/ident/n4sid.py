"""N4SID subspace identification of state-space models (thesis section 3.4.2), over many
experiments at once.

1. Block Hankel matrices of past/future inputs and outputs, ``i`` block rows, built per test
   and joined column-wise (every column lies inside one test).
2. The oblique projection of the future outputs along the future inputs onto the past
   (Van Overschee & De Moor's N4SID, unit weights), by least squares.
3. Its SVD gives the extended observability matrix for order n; A from its shift invariance,
   C from its first block row.
4. B and D by linear least squares on the *simulated* output from rest (every test starts at
   rest at t = 0), which is what the fit of eq. 3.15 scores.
Unstable poles of A are mirrored into the unit circle (reported), so the observer never runs
away on a bench.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..data.crashtest import CrashDataError
from ..model.modelfile import ModelFile
from ..model.observer import simulate_ss
from .dataset import Dataset
from .metrics import FitTable, fit_table
from .progress import Progress

TRANSFORM = "raw"


@dataclass
class StateSpaceModel:
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    singular_values: np.ndarray
    mirrored_poles: int = 0
    fits: FitTable | None = None  # on the data it was estimated on

    def simulate(self, data: Dataset) -> np.ndarray:
        with np.errstate(all="ignore"):
            return simulate_ss(self.A, self.B, self.C, self.D, _inputs(data))


def _inputs(data: Dataset) -> np.ndarray:
    return np.stack([data.pulse_g, data.brs_rad], axis=-1)


def _hankel(x: np.ndarray, rows: int, start: int, cols: int) -> np.ndarray:
    """Block Hankel of x (n, m): block row r holds x[start + r + c] for c < cols."""
    m = x.shape[1]
    H = np.empty((rows * m, cols))
    for r in range(rows):
        H[r * m:(r + 1) * m] = x[start + r:start + r + cols].T
    return H


def _subspace(data: Dataset, i: int) -> tuple[np.ndarray, np.ndarray]:
    """Left singular vectors and singular values of the oblique projection."""
    u = _inputs(data)
    blocks: dict[str, list[np.ndarray]] = {"Up": [], "Uf": [], "Yp": [], "Yf": []}
    n = data.y.shape[1]
    cols = n - 2 * i + 1
    if cols < 4 * i:  # fewer columns than rows: the projection is not determined
        raise CrashDataError(
            f"N4SID ({i} block rows) needs at least {6 * i - 1} ticks per test from time zero "
            f"to the window's end; {data.window_s[1]:g} s at {data.fs_hz:g} Hz gives {n}: a "
            "later --window end or a higher --rate")
    for k in range(data.n_tests):
        blocks["Up"].append(_hankel(u[k], i, 0, cols))
        blocks["Uf"].append(_hankel(u[k], i, i, cols))
        blocks["Yp"].append(_hankel(data.y[k], i, 0, cols))
        blocks["Yf"].append(_hankel(data.y[k], i, i, cols))
    Up, Uf, Yp, Yf = (np.hstack(blocks[k]) for k in ("Up", "Uf", "Yp", "Yf"))
    Wp = np.vstack([Up, Yp])
    # Yf = Lw Wp + Lu Uf + noise; the oblique projection is Lw Wp.
    L = np.linalg.lstsq(np.vstack([Wp, Uf]).T, Yf.T, rcond=None)[0].T
    oblique = L[:, :Wp.shape[0]] @ Wp
    U, s, _ = np.linalg.svd(oblique, full_matrices=False)
    return U, s


def _stabilise(A: np.ndarray) -> tuple[np.ndarray, int]:
    lam, V = np.linalg.eig(A)
    bad = np.abs(lam) > 0.9999
    if not bad.any():
        return A, 0
    lam = np.where(bad, 0.9999 * lam / np.abs(lam) ** 2, lam)
    return np.real(V @ np.diag(lam) @ np.linalg.inv(V)), int(bad.sum())


def _estimate_bd(A: np.ndarray, C: np.ndarray, data: Dataset) -> tuple[np.ndarray, np.ndarray]:
    """B, D minimising the simulation error on the window (linear in B and D)."""
    nx, nu, ny = A.shape[0], 2, 2
    u = _inputs(data)
    cols = []
    for a in range(nx):
        for b in range(nu):
            B = np.zeros((nx, nu))
            B[a, b] = 1.0
            cols.append(simulate_ss(A, B, C, np.zeros((ny, nu)), u)[:, data.win])
    for a in range(ny):
        for b in range(nu):
            D = np.zeros((ny, nu))
            D[a, b] = 1.0
            cols.append(np.broadcast_to(u[:, data.win] @ D.T, cols[0].shape))
    y = data.y[:, data.win]
    # Weight outputs by their spread so CR (g) and CD (mm) count alike, as the fit does.
    w = 1.0 / y.reshape(-1, ny).std(axis=0)
    Phi = np.stack([(c * w).ravel() for c in cols], axis=1)
    theta = np.linalg.lstsq(Phi, (y * w).ravel(), rcond=None)[0]
    return theta[:nx * nu].reshape(nx, nu), theta[nx * nu:].reshape(ny, nu)


def n4sid(data: Dataset, order: int, block_rows: int | None = None,
          svd: tuple[np.ndarray, np.ndarray] | None = None) -> StateSpaceModel:
    """Identify a state-space model of ``order`` (``svd`` may be reused across orders)."""
    i = block_rows or max(order + 4, 20)
    U, s = svd if svd is not None else _subspace(data, i)
    ny = 2
    gamma = U[:, :order] * np.sqrt(s[:order])
    A = np.linalg.lstsq(gamma[:-ny], gamma[ny:], rcond=None)[0]
    A, mirrored = _stabilise(A)
    C = gamma[:ny]
    B, D = _estimate_bd(A, C, data)
    m = StateSpaceModel(A, B, C, D, s, mirrored)
    m.fits = fit_table(data.names, data.y[:, data.win], m.simulate(data)[:, data.win])
    return m


def order_scan(est: Dataset, val: Dataset | None, orders: range, block_rows: int = 24,
               progress: Progress | None = None) -> list[dict]:
    """fit_TOT against model order (thesis Figure 3.7), on estimation and validation tests."""
    svd = _subspace(est, block_rows)
    rows = []
    for n in orders:
        m = n4sid(est, n, block_rows, svd)
        row = {"order": n, "estimation_fit": m.fits.fit.total if m.fits else float("nan")}
        if val is not None:
            y_hat = m.simulate(val)[:, val.win]
            row["validation_fit"] = fit_table(val.names, val.y[:, val.win], y_hat).fit.total
        rows.append(row)
        if progress:
            progress.update(f"order {n}: estimation fit {row['estimation_fit']:.1f} %")
    return rows


def to_model_file(m: StateSpaceModel, data: Dataset, name: str, block_rows: int) -> ModelFile:
    return ModelFile(
        kind="n4sid", name=name, tick_rate_hz=data.fs_hz, input_transform=TRANSFORM,
        A=m.A, B=m.B, C=m.C, D=m.D,
        parameters={"singular_values": m.singular_values[:30].tolist()},
        structure={"order": m.A.shape[0], "block_rows": block_rows,
                   "weighting": "N4SID (unit weights)", "B_D": "least squares on simulation",
                   "mirrored_unstable_poles": m.mirrored_poles},
        fitted_on={"tests": data.names, "setups": sorted(set(data.setups)),
                   "rate_hz": data.fs_hz, "window_s": list(data.window_s),
                   "simulation_start_s": 0.0},
        fits=m.fits.as_dict() if m.fits else {},
    )
