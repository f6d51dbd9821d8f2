"""The one model description that passes between identification, the daemon and replay.

A model file is JSON (never pickle)::

    {"format": "chest-observer-model", "format_version": 1,
     "kind": "greybox" | "arx" | "n4sid", "name": "...", "software_version": "...",
     "tick_rate_hz": 1000.0, "input_transform": "velocity_brs_rate" | "raw",
     "inputs": [...], "outputs": [...],          # names, units, sign conventions
     "state_space": {"A": [[...]], "B": ..., "C": ..., "D": ...},   # discrete, at tick_rate_hz
     "parameters": {...},                        # kind-specific, with standard errors
     "effects": [...],                           # grey-box only: added physical effects
     "structure": {...},                         # kind-specific orders
     "fitted_on": {"tests": [...], "window_s": [0.01, 0.15], ...},
     "fits": {...}}                              # thesis fit (eq. 3.15-3.18) on its tests

A grey-box model's state space is its physical parameters discretised at ``tick_rate_hz``
(:mod:`.chest`: the thesis's 5 states, or 6 with effects, whose forces enter through
``structure.force_input_matrix_G``). The daemon steps an effects model from the parameters;
the loader checks that the stored matrices are those of the parameters, so what a reader of
the file sees is what runs.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from .. import __version__
from ..errors import ObserverError
from .effects import EFFECTS
from .kinds import MODEL_KINDS
from .nonlinear import NonlinearGreyBox, applies
from .observer import LinearObserver
from .schema import MAX_BYTES, validate

FORMAT = "chest-observer-model"
FORMAT_VERSION = 1
KINDS = tuple(MODEL_KINDS)  # the kinds registered in .kinds

INPUTS = [
    {"name": "pulse", "unit": "g",
     "sign": "vehicle deceleration positive (-SAE J211 X); accelerometer bias removed"},
    {"name": "brs", "unit": "rad",
     "sign": "spindle angle, + = webbing retracted; counts * 2*pi / counts_per_rev"},
]
OUTPUTS = [
    {"name": "cr", "unit": "g", "sign": "chest (spine) retardation positive (-SAE J211 X)"},
    {"name": "cd", "unit": "mm", "sign": "chest compression positive (-SAE J211 deflection)"},
]


class ModelFileError(ObserverError, ValueError):
    """A model file that cannot be used; the message names the file and key."""


@dataclass
class ModelFile:
    kind: str
    name: str
    tick_rate_hz: float
    input_transform: str
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    parameters: dict[str, Any] = field(default_factory=dict)
    structure: dict[str, Any] = field(default_factory=dict)
    fitted_on: dict[str, Any] = field(default_factory=dict)
    fits: dict[str, Any] = field(default_factory=dict)
    software_version: str = __version__
    effects: list[dict[str, Any]] = field(default_factory=list)
    # grey-box: "after_input" (the output of the state after the tick's inputs, this version)
    # or "state" (C x[k], files without the key); ARX and N4SID: their matrices say it all
    output_timing: str = "after_input"

    def physical(self) -> bool:
        """A physical grey-box (stepped from its parameters: may carry effects)."""
        kind = MODEL_KINDS.get(self.kind)
        return kind is not None and kind.physical

    def setups(self) -> list[str]:
        """The setups some effect is scoped to (empty: every effect acts on every setup)."""
        return sorted({s for e in self.effects for s in e.get("setups", ())})

    def for_setup(self, setup: str, where: str = "model") -> ModelFile:
        """The model a bench of ``setup`` runs: the effects that act there, unscoped. A model
        without scoped effects is returned as it is; ModelFileError when the model is scoped
        and ``setup`` is empty, or when ``setup`` is given and is not one the model knows
        (a typo would otherwise run silently)."""
        scoped = self.setups()
        known = sorted(set(scoped) | set(self.fitted_on.get("setups", [])))
        if not scoped:
            if setup and known and setup not in known:
                raise ModelFileError(f"{where}: setup {setup!r} is not one the model was "
                                     f"fitted on ({', '.join(known)}); no effect of it is "
                                     "scoped to a setup, so --setup can be left out")
            return self
        if not setup:
            raise ModelFileError(f"{where}: effects act on setups {', '.join(scoped)} only: say "
                                 f"which setup this bench is (--setup, one of {', '.join(known)})")
        if setup not in known:
            raise ModelFileError(f"{where}: setup {setup!r} is not one the model knows "
                                 f"({', '.join(known)})")
        effects = [{k: v for k, v in e.items() if k != "setups"} for e in self.effects
                   if applies(e, setup)]
        return replace(self, name=f"{self.name}@{setup}", effects=effects,
                       fitted_on={**self.fitted_on, "setup": setup})

    def observer(self, setup: str | list[str] | None = None
                 ) -> LinearObserver | NonlinearGreyBox:
        """The run-time observer: linear, or the grey-box with its added effects (those of
        ``setup`` when effects are scoped to setups, or each simulated test's setup, a list;
        raises ScopeError without it)."""
        if self.effects:
            base = {n: float(v["value"]) for n, v in self.parameters.items()}
            return NonlinearGreyBox(base, self.effects, self.tick_rate_hz, setup,
                                    after_input=self.output_timing == "after_input")
        return LinearObserver(self.A, self.B, self.C, self.D, self.input_transform,
                              self.tick_rate_hz)

    def to_dict(self) -> dict[str, Any]:
        return {
            "format": FORMAT, "format_version": FORMAT_VERSION, "kind": self.kind,
            "name": self.name, "software_version": self.software_version,
            "tick_rate_hz": self.tick_rate_hz, "input_transform": self.input_transform,
            "inputs": INPUTS, "outputs": OUTPUTS,
            "state_space": {k: np.asarray(v).tolist() for k, v in
                            (("A", self.A), ("B", self.B), ("C", self.C), ("D", self.D))},
            "parameters": self.parameters, "structure": self.structure,
            "fitted_on": self.fitted_on, "fits": self.fits,
            **({"effects": self.effects} if self.effects else {}),
            **({"output_timing": self.output_timing} if self.physical() else {}),
        }

    def dumps(self) -> str:
        return json.dumps(self.to_dict(), indent=1, sort_keys=False)

    def model_id(self) -> int:
        """16-bit id of this model (published in the status frame to tell models apart)."""
        digest = hashlib.sha256(self.dumps().encode()).digest()
        return int.from_bytes(digest[:2], "big")

    def save(self, path: str | Path) -> Path:
        """Write the model file at ``path`` whole or not at all (a full disk must not leave a
        truncated model for a daemon to refuse later): a temporary file beside it, renamed."""
        path = Path(path)
        if path.is_dir():
            raise ModelFileError(f"{path}: is a folder; give the model file's name "
                                 f"(e.g. {path / 'model.json'})")
        tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp.write_text(self.dumps() + "\n", encoding="utf-8")
            os.replace(tmp, path)
        except OSError as e:
            with contextlib.suppress(OSError):  # nothing half-written left behind
                tmp.unlink()
            raise ModelFileError(f"{path}: cannot write the model file: "
                                 f"{e.strerror or e}") from None
        return path

    @classmethod
    def from_dict(cls, d: Any, where: str = "<model>") -> ModelFile:
        """Build a model file from parsed JSON, refusing what a daemon must not run: a
        document the schema (:mod:`.schema`) rejects, or an unstable model."""
        if not isinstance(d, dict):
            raise ModelFileError(f"{where}: not a model file (a JSON {type(d).__name__}, "
                                 "expected an object)")
        if d.get("format") != FORMAT:
            raise ModelFileError(f"{where}: key 'format' must be {FORMAT!r}")
        if d.get("format_version") != FORMAT_VERSION:
            raise ModelFileError(f"{where}: key 'format_version' {d.get('format_version')!r} "
                                 f"is not supported (this software reads {FORMAT_VERSION})")
        said = validate(d, where)
        if said is not None:
            raise ModelFileError(said)
        try:
            ss = d["state_space"]
            mf = cls(
                kind=d["kind"], name=d.get("name", ""), tick_rate_hz=float(d["tick_rate_hz"]),
                input_transform=d["input_transform"],
                A=np.asarray(ss["A"], float), B=np.asarray(ss["B"], float),
                C=np.asarray(ss["C"], float), D=np.asarray(ss["D"], float),
                parameters=d.get("parameters", {}), structure=d.get("structure", {}),
                fitted_on=d.get("fitted_on", {}), fits=d.get("fits", {}),
                software_version=d.get("software_version", "?"),
                effects=list(d.get("effects", [])),
                output_timing=d.get("output_timing", "state"),
            )
        except KeyError as e:
            raise ModelFileError(f"{where}: missing key {e.args[0]!r}") from None
        except (TypeError, ValueError) as e:
            raise ModelFileError(f"{where}: key 'state_space': {e}") from None
        if mf.effects and not mf.physical():
            raise ModelFileError(f"{where}: key 'effects' is only for grey-box models")
        for i, effect in enumerate(mf.effects):
            if effect.get("kind") not in EFFECTS:
                raise ModelFileError(f"{where}: key 'effects[{i}].kind' {effect.get('kind')!r} "
                                     f"is not one of {sorted(EFFECTS)}")
        if mf.kind not in MODEL_KINDS:
            raise ModelFileError(f"{where}: key 'kind' {mf.kind!r} not one of "
                                 f"{tuple(MODEL_KINDS)}")
        for k, m in (("A", mf.A), ("B", mf.B), ("C", mf.C), ("D", mf.D)):
            if not np.all(np.isfinite(m)):
                raise ModelFileError(f"{where}: key 'state_space.{k}' has non-finite values")
        check = MODEL_KINDS[mf.kind].check
        said = check(mf) if check is not None else None
        if said is not None:
            raise ModelFileError(f"{where}: {said}")
        try:  # (a scoped model's matrices are the same for every setup)
            obs = mf.observer(mf.setups()[0] if mf.setups() else None)
        except (ValueError, KeyError) as e:
            key = "effects" if mf.effects else "state_space"
            raise ModelFileError(f"{where}: key '{key}': {e}") from None
        # Stable or marginally so (the grey-box's belt position integrates): a growing mode
        # would saturate the estimate within a crash.
        radius = float(np.max(np.abs(np.linalg.eigvals(obs.A))))
        if not radius <= 1.0 + 1e-9:
            key = "parameters" if mf.effects else "state_space.A"
            raise ModelFileError(f"{where}: key '{key}': the model is unstable (spectral radius "
                                 f"{radius:.6g} > 1)")
        return mf

    @classmethod
    def load(cls, path: str | Path) -> ModelFile:
        path = Path(path)
        try:
            with path.open("rb") as f:
                raw = f.read(MAX_BYTES + 1)
        except OSError as e:
            raise ModelFileError(f"{path}: cannot read: {e.strerror}") from None
        if len(raw) > MAX_BYTES:
            raise ModelFileError(f"{path}: larger than {MAX_BYTES >> 20} MiB: not a model file")
        try:
            text = raw.decode("utf-8-sig")
        except UnicodeDecodeError as e:
            line = raw[:e.start].count(b"\n") + 1
            raise ModelFileError(f"{path}:{line}: not UTF-8 text (byte {e.start})") from None

        def no_constant(name: str) -> None:
            raise ValueError(f"{name} is not a number a model may hold")

        try:
            d = json.loads(text, parse_constant=no_constant)
        except json.JSONDecodeError as e:
            raise ModelFileError(f"{path}:{e.lineno}: not valid JSON: {e.msg}") from None
        except ValueError as e:  # NaN or Infinity: JSON has no such number; say where
            at = re.search(r"-?\b(?:NaN|Infinity)\b", text)
            where = f"{path}:{text.count(chr(10), 0, at.start()) + 1}" if at else str(path)
            raise ModelFileError(f"{where}: {e}") from None
        except RecursionError:
            raise ModelFileError(f"{path}: nested too deeply to be a model file") from None
        return cls.from_dict(d, str(path))
