"""How each model kind is identified: one function per kind of :data:`..model.kinds.MODEL_KINDS`,
registered once here, on the identification's side of the model file (the daemon loads model
files and never reaches this). :func:`observer_node.evaluation.identify` reads
:data:`IDENTIFY`."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from types import MappingProxyType

from ..model.kinds import MODEL_KINDS
from ..model.modelfile import ModelFile
from . import arx, greybox, n4sid
from .dataset import Dataset
from .metrics import fit_table
from .progress import Progress

N4SID_BLOCK_ROWS = 24


@dataclass(frozen=True)
class IdentifyOptions:
    """What identification may be told; each kind reads its own."""

    nmax: int = 6  # ARX: the largest order searched
    order: int = 7  # N4SID: the model order
    orders: arx.ArxOrders | None = None  # ARX: these orders, no search
    m1_kg: float = greybox.DEFAULT_M1_KG  # grey-box: the fixed spine mass, the mass scale
    progress: Progress | None = None
    name: str | None = None  # the model's name (default: from the kind and its options)


Identify = Callable[[Dataset, IdentifyOptions], ModelFile]
_REGISTRY: dict[str, Identify] = {}
IDENTIFY: Mapping[str, Identify] = MappingProxyType(_REGISTRY)


def register_identify(kind: str, fn: Identify) -> Identify:
    """``fn`` identifies models of ``kind``, a kind the model file knows."""
    if kind not in MODEL_KINDS:
        raise ValueError(f"model kind {kind!r} is not registered in observer_node.model.kinds")
    if kind in _REGISTRY:
        raise ValueError(f"model kind {kind!r} has an identification already")
    _REGISTRY[kind] = fn
    return fn


@contextmanager
def registered_identify(kind: str, fn: Identify) -> Iterator[Identify]:
    """``fn`` registered for the duration of the block (tests, experiments)."""
    register_identify(kind, fn)
    try:
        yield fn
    finally:
        del _REGISTRY[kind]


def _greybox(data: Dataset, o: IdentifyOptions) -> ModelFile:
    fit = greybox.fit_greybox(data, m1_kg=o.m1_kg, progress=o.progress)
    return greybox.to_model_file(fit, data, o.name or "greybox")


def _arx(data: Dataset, o: IdentifyOptions) -> ModelFile:
    orders = o.orders
    history: list[dict] = []
    if orders is None:
        orders, history = arx.search_orders(data, o.nmax, progress=o.progress)
    m = arx.estimate_arx(data, orders)
    m.fits = fit_table(data.names, data.y[:, data.win], m.simulate(data)[:, data.win])
    return arx.to_model_file(m, data, o.name or f"arx-nmax{o.nmax}", o.nmax, history)


def _n4sid(data: Dataset, o: IdentifyOptions) -> ModelFile:
    ss = n4sid.n4sid(data, o.order, N4SID_BLOCK_ROWS)
    return n4sid.to_model_file(ss, data, o.name or f"n4sid-{o.order}", N4SID_BLOCK_ROWS)


register_identify("greybox", _greybox)
register_identify("arx", _arx)
register_identify("n4sid", _n4sid)
