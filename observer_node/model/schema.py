"""The model file's JSON schema, checked with ``jsonschema`` before anything is built from it.

The schema bounds what a daemon may be handed: the model kinds (:mod:`.kinds`); the tick rate
(finite, and one the DBC provides for: 100 Hz to 10 kHz, the top rates as InputBurst frames);
matrix shapes (at most ``MAX_STATES`` states, two inputs, two outputs); every effect with the
parameters its definition (:mod:`.effects`) requires; finite numbers only (NaN and Infinity
are refused by the reader before the schema sees them). Stability is checked after, on the
matrices themselves (:meth:`observer_node.model.modelfile.ModelFile.from_dict`)."""

from __future__ import annotations

import reprlib
from typing import Any

from .effects import EFFECTS, Effect, registry_version
from .kinds import MODEL_KINDS

MAX_STATES = 64
MAX_BYTES = 4 << 20  # a model file is kilobytes; more is not a model

_NUMBER = {"type": "number"}
_ROW = {"type": "array", "items": _NUMBER, "maxItems": MAX_STATES}


def _matrix(rows: int | None, cols: int | None) -> dict[str, Any]:
    row = dict(_ROW)
    if cols is not None:
        row |= {"minItems": cols, "maxItems": cols}
    m: dict[str, Any] = {"type": "array", "items": row, "minItems": 1, "maxItems": MAX_STATES}
    if rows is not None:
        m |= {"minItems": rows, "maxItems": rows}
    return m


def _effect(e: Effect) -> dict[str, Any]:
    """The ``if kind then parameters`` clause of one effect, from its definition."""
    params: dict[str, Any] = dict(e.parameters_schema or {"type": "object"})
    required = [p.name for p in e.params if p.required]
    if e.parameters_schema is None:
        params["properties"] = {
            p.name: _NUMBER if p.bounds is None else
            {"type": "number", "minimum": p.bounds[0], "maximum": p.bounds[1]}
            for p in e.params}
        params["required"] = required
    return {"if": {"properties": {"kind": {"const": e.kind}}},
            "then": {"properties": {"parameters": params},
                     **({"required": ["parameters"]} if required else {})}}


_GREYBOX = ("k1", "c1", "k2", "c2", "m1", "m2", "R")


def _signals(*name_unit: tuple[str, str]) -> dict[str, Any]:
    """The inputs or outputs list: these signals, in this order, in these units (the daemon
    feeds and publishes exactly these; a file that says m/s^2 describes another model)."""
    return {"type": "array", "minItems": len(name_unit), "maxItems": len(name_unit),
            "prefixItems": [{"type": "object", "required": ["name", "unit"],
                             "properties": {"name": {"const": n}, "unit": {"const": u}}}
                            for n, u in name_unit]}
_PARAMETER = {"type": "object", "required": ["value"],
              "properties": {"value": _NUMBER, "std_err": {"type": ["number", "null"]}}}


def schema() -> dict[str, Any]:
    """The schema of the effects and model kinds registered now (built again when they
    change)."""
    version = (registry_version(), tuple(MODEL_KINDS))
    if _cache[0] != version:
        _cache[:] = [version, _schema()]
    return _cache[1]


_cache: list[Any] = [None, None]


def _one_of(values: list[str]) -> dict[str, Any]:
    return {"const": values[0]} if len(values) == 1 else {"enum": values}


def _schema() -> dict[str, Any]:
    physical = [k for k, m in MODEL_KINDS.items() if m.physical]
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "chest-observer model file",
        "type": "object",
        "required": ["format", "format_version", "kind", "tick_rate_hz", "input_transform",
                     "state_space"],
        "properties": {
            "format": {"const": "chest-observer-model"},
            "format_version": {"const": 1},
            "kind": {"enum": list(MODEL_KINDS)},
            "name": {"type": "string", "maxLength": 200},
            "tick_rate_hz": {"type": "number", "minimum": 100, "maximum": 10_000},
            "input_transform": {"enum": ["velocity_brs_rate", "raw"]},
            "output_timing": {"enum": ["after_input", "state"]},
            "state_space": {
                "type": "object", "required": ["A", "B", "C", "D"],
                "properties": {"A": _matrix(None, None), "B": _matrix(None, 2),
                               "C": _matrix(2, None), "D": _matrix(2, 2)}},
            "inputs": _signals(("pulse", "g"), ("brs", "rad")),
            "outputs": _signals(("cr", "g"), ("cd", "mm")),
            # kind-specific: the grey-box's, where given, numbers (all seven with effects)
            "parameters": {"type": "object"},
            # what the model was fitted on: read by run --setup (setups) and evaluate
            # (window_s); the rest is for the reader
            "fitted_on": {"type": "object", "properties": {
                "setups": {"type": "array", "items": {"type": "string", "minLength": 1}},
                "window_s": {"type": "array", "minItems": 2, "maxItems": 2,
                             "items": _NUMBER}}},
            "effects": {
                "type": "array", "maxItems": 32,
                "items": {"type": "object", "required": ["kind"],
                          "properties": {
                              "kind": {"enum": sorted(EFFECTS)},
                              # scope: the setups the effect acts on (absent: all)
                              # note: why it is there when it is no finding (the loop's
                              # carried side of a tie)
                              "note": {"type": "string", "maxLength": 300},
                              "setups": {"type": "array", "minItems": 1, "uniqueItems": True,
                                         "items": {"type": "string", "minLength": 1}}},
                          "allOf": [_effect(e) for e in EFFECTS.values()]}},
        },
        "allOf": [
            # A grey-box with effects is stepped from its physical parameters, not its
            # matrices.
            {"if": {"required": ["effects"], "properties": {"effects": {"minItems": 1}}},
             "then": {"properties": {"kind": _one_of(physical),
                                     "parameters": {"required": list(_GREYBOX)}},
                      "required": ["parameters"]}},
            {"if": {"properties": {"kind": _one_of(physical)}},
             "then": {"properties": {"parameters": {
                 "properties": dict.fromkeys(_GREYBOX, _PARAMETER)}}}},
        ],
    }


def validate(d: Any, where: str) -> str | None:
    """None when ``d`` is a valid model file, else one line naming the key at fault."""
    import jsonschema

    v = jsonschema.Draft202012Validator(schema())
    err = jsonschema.exceptions.best_match(v.iter_errors(d))
    if err is None:
        return None
    key = ".".join(f"[{p}]" if isinstance(p, int) else str(p) for p in err.absolute_path)
    key = key.replace(".[", "[")
    if err.validator == "required" and isinstance(err.instance, dict):
        missing = next(k for k in err.validator_value if k not in err.instance)
        return f"{where}: missing key '{key + '.' if key else ''}{missing}'"
    # the message quotes the value at fault: a matrix of 100 rows would hide what is wrong
    msg = err.message.replace(repr(err.instance), reprlib.repr(err.instance))
    msg = msg if len(msg) < 160 else msg[:157] + "..."
    return f"{where}: " + (f"key '{key}': " if key else "") + msg
