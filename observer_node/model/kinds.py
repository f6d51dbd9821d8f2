"""Model kinds: one definition each, registered once.

A :class:`ModelKind` says what a model file of that kind must agree with when it is loaded, and
what is reported of it beside its fits. The model file's schema and loader, the evaluation's
tables and the command line read :data:`MODEL_KINDS`. How a kind is identified is the
identification's business, registered beside it in :mod:`observer_node.ident.kinds`: the model
file, and so the daemon, never reach fitting code.

What a model runs as does not depend on its kind: every model file becomes a linear observer
(:class:`.observer.LinearObserver`), a grey-box with effects the non-linear one
(:class:`.nonlinear.NonlinearGreyBox`); both expose ``A``, ``reset``, ``step`` and
``simulate``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from . import chest

if TYPE_CHECKING:
    from .modelfile import ModelFile


@dataclass(frozen=True)
class ModelKind:
    name: str
    description: str
    # a physical grey-box: stepped from its parameters, it may carry effects and says its
    # output timing
    physical: bool = False
    # on load: None, or why the file's parts disagree (one line naming the key)
    check: Callable[[ModelFile], str | None] | None = None
    # what the evaluation reports beside the fits, and the lines `identify` prints
    summary: Callable[[ModelFile], dict[str, Any]] = lambda mf: {}
    describe: Callable[[ModelFile], list[str]] = lambda mf: []


_REGISTRY: dict[str, ModelKind] = {}
MODEL_KINDS: Mapping[str, ModelKind] = MappingProxyType(_REGISTRY)


def register_kind(kind: ModelKind) -> ModelKind:
    if kind.name in _REGISTRY:
        raise ValueError(f"model kind {kind.name!r} is registered already")
    _REGISTRY[kind.name] = kind
    return kind


@contextmanager
def registered_kind(kind: ModelKind) -> Iterator[ModelKind]:
    """``kind`` registered for the duration of the block (tests, experiments)."""
    register_kind(kind)
    try:
        yield kind
    finally:
        del _REGISTRY[kind.name]


# ---------------------------------------------------------------------------- grey-box
def _greybox_disagrees(mf: ModelFile) -> str | None:
    """None unless the matrices are not the parameters' (rel. 1e-9)."""
    try:
        p = {n: float(mf.parameters[n]["value"]) for n in chest.PARAM_NAMES}
    except (KeyError, TypeError, ValueError):
        if mf.effects:
            return "key 'parameters': a grey-box with effects needs k1 c1 k2 c2 m1 m2 R values"
        return None  # a grey-box given by its matrices alone: they are the model
    if not all(np.isfinite(v) and v >= 0.0 for v in p.values()) or p["m1"] <= 0 or p["m2"] <= 0:
        return "key 'parameters': grey-box values must be finite, masses positive, others >= 0"
    Ad, Bd, C, D = chest.model_matrices(p, mf.tick_rate_hz, bool(mf.effects),
                                        mf.output_timing == "after_input")
    for key, stored, expected in (("A", mf.A, Ad), ("B", mf.B, Bd), ("C", mf.C, C), ("D", mf.D, D)):
        if stored.shape != expected.shape:
            return (f"key 'state_space.{key}': shape {stored.shape} is not the grey-box's "
                    f"{expected.shape}")
        tol = 1e-9 * max(float(np.max(np.abs(expected))), 1.0)
        worst = float(np.max(np.abs(stored - expected)))
        if worst > tol:
            return (f"key 'state_space.{key}' disagrees with 'parameters' discretised at "
                    f"{mf.tick_rate_hz:g} Hz (largest difference {worst:.3g})")
    return None


def _greybox_lines(mf: ModelFile) -> list[str]:
    out = ["parameters (value ± standard error):"]
    for n, p in mf.parameters.items():
        fixed = "  (fixed: mass scale)" if p["fixed"] else ""
        out.append(f"  {n:<3} {p['value']:12.5g} ± {p['std_err']:<10.2g} {p['unit']}{fixed}")
    return out


register_kind(ModelKind(
    "greybox", "the thesis's two-mass chest (eq. 3.1-3.8) from its physical parameters; may "
    "carry added effects", physical=True, check=_greybox_disagrees,
    summary=lambda mf: {"parameters": mf.parameters}, describe=_greybox_lines))


# ---------------------------------------------------------------------------- ARX
register_kind(ModelKind(
    "arx", "iterated ARX (thesis section 3.4), its orders searched up to --nmax",
    summary=lambda mf: {"orders": {k: mf.structure[k] for k in ("NA", "NB", "NK")}},
    describe=lambda mf: [f"orders: NA={mf.structure['NA']} NB={mf.structure['NB']} "
                         f"NK={mf.structure['NK']}"]))


# ---------------------------------------------------------------------------- N4SID
register_kind(ModelKind("n4sid", "a subspace (N4SID) state space of order --order"))
