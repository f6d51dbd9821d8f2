"""The daemon's configuration: defaults, the TOML file, and the ranges every value must lie in.

A config is checked whole, after the file and the command line are merged, before the bus
opens: a syntax error, an unknown key, a wrong type, a value that is not finite or out of its
range is one line naming the file (or the command line) and the key. The ranges are checked
with a JSON schema (``jsonschema``), the same library that checks model files.
"""

from __future__ import annotations

import ipaddress
import math
import socket
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import Any

from observer_node.dbc.bus import DEFAULT_CHANNEL, DEFAULT_INTERFACE

from ..errors import ObserverError
from .core import CoreConfig


class ConfigError(ObserverError, ValueError):
    """A configuration the daemon must not run with; the message names where and the key."""


@dataclass
class NodeConfig:
    interface: str = DEFAULT_INTERFACE
    channel: str = DEFAULT_CHANNEL
    fd: bool = False
    raw_socketcan: bool = True
    model: str = ""
    setup: str = ""  # the bench's setup, for a model with effects scoped to setups
    record: str = ""
    live: str = ""  # HOST:PORT of the Foxglove live view (served by the recorder process)
    status_period_s: float = 0.1
    accel_timeout_s: float = 0.0  # 0: two tick periods
    brs_timeout_s: float = 0.03
    idle_after_s: float = 1.0
    reconnect_s: float = 0.5
    cpu_latency_us: int = 0  # PM QoS while running; -1: leave power management alone
    rt_priority: int = 0  # SCHED_FIFO priority of the tick loop (1-99); 0: normal scheduling
    # how long the recorder may take to write the file's header before the run is refused
    # (its start-up imports take seconds on a busy PC, minutes under CPU emulation)
    recorder_start_timeout_s: float = 120.0
    core: CoreConfig = field(default_factory=CoreConfig)

    @classmethod
    def from_toml(cls, path: str | Path) -> NodeConfig:
        """Keys of the ``[observer]`` table are NodeConfig fields; ``[observer.core]`` holds
        CoreConfig fields. Anything else, or a value of the wrong type, is a ConfigError."""
        import tomllib

        p = Path(path)
        try:
            d = tomllib.loads(p.read_text(encoding="utf-8"))
        except tomllib.TOMLDecodeError as e:
            raise ConfigError(f"{p}: {e}") from None
        except UnicodeDecodeError as e:
            raise ConfigError(f"{p}: not UTF-8 text (byte {e.start})") from None
        except OSError as e:
            raise ConfigError(f"{p}: cannot read: {e.strerror}") from None
        extra = sorted(set(d) - {"observer"})
        if extra:
            raise ConfigError(f"{p}: unknown table or key {extra[0]!r} (the daemon reads "
                              "[observer] and [observer.core])")
        obs = d.get("observer", {})
        if not isinstance(obs, dict):  # `observer = 3`, `[[observer]]`: not one table
            raise ConfigError(f"{p}: observer: must be a table [observer], not "
                              f"{_toml_kind(obs)}")
        obs = dict(obs)
        core = obs.pop("core", {})
        if not isinstance(core, dict):
            raise ConfigError(f"{p}: [observer] core: must be a table [observer.core], not "
                              f"{_toml_kind(core)}")
        check({**obs, "core": core}, str(p))
        return cls(**obs, core=CoreConfig(**core))

    def check(self, where: str = "command line") -> None:
        check(asdict(self), where)
        if self.live and not self.record:
            raise ConfigError(f"{where}: live {self.live!r} needs record: the live view is "
                              "served by the recorder process (give --record FILE)")
        if self.live:
            _check_live(self.live, where)


def _check_live(live: str, where: str) -> None:
    """HOST:PORT the live view can listen on, checked before the run: the recorder process
    opens it after the daemon has started, where a bad one could only be warned about."""
    host, _, port = live.rpartition(":")
    if not host or any(c.isspace() or c == ":" for c in host):
        raise ConfigError(f"{where}: live {live!r}: expected HOST:PORT, e.g. 127.0.0.1:8765")
    if not port.isdigit() or not 1 <= int(port) <= 65535:
        raise ConfigError(f"{where}: live {live!r}: the port must be 1-65535")
    if host.replace(".", "").isdigit():  # an IPv4 address: each of its four parts 0-255
        try:
            ipaddress.IPv4Address(host)
        except ValueError:
            raise ConfigError(f"{where}: live {live!r}: {host} is not an IPv4 address"
                              ) from None
    try:
        socket.getaddrinfo(host, int(port), type=socket.SOCK_STREAM)
    except (socket.gaierror, UnicodeError) as e:
        raise ConfigError(f"{where}: live {live!r}: cannot resolve {host}: {e}") from None


def _toml_kind(v: object) -> str:
    """What a TOML value is, in TOML's words (for an error message)."""
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, list):
        return "an array of tables" if v and all(isinstance(x, dict) for x in v) \
            else "an array"
    return {int: "an integer", float: "a float", str: "a string"}.get(type(v), "a date/time")


def _num(lo: float, hi: float, integer: bool = False) -> dict[str, Any]:
    return {"type": "integer" if integer else "number", "minimum": lo, "maximum": hi}


_STR = {"type": "string", "maxLength": 4096}
_Schema = dict[str, dict[str, Any]]
_NODE: _Schema = {
    "interface": {**_STR, "minLength": 1}, "channel": _STR, "fd": {"type": "boolean"},
    "raw_socketcan": {"type": "boolean"}, "model": _STR, "setup": _STR, "record": _STR,
    "live": {"type": "string", "maxLength": 300},  # HOST:PORT, checked by _check_live
    "status_period_s": _num(0.01, 10), "accel_timeout_s": _num(0, 60),
    "brs_timeout_s": _num(0.001, 10), "idle_after_s": _num(0.01, 3600),
    "reconnect_s": _num(0.01, 60), "cpu_latency_us": _num(-1, 100_000, True),
    "rt_priority": _num(0, 99, True), "recorder_start_timeout_s": _num(1, 3600)}
_CORE: _Schema = {
    "trigger_g": _num(0.5, 100), "trigger_ticks": _num(1, 100, True),
    "onset_g": _num(0, 100), "pretrigger_s": _num(0, 1), "bias_window_s": _num(0.002, 10),
    "event_s": _num(0.01, 10), "quiet_g": _num(0.001, 100), "rearm_s": _num(0, 10),
    "hold_max_s": _num(0.01, 3600), "bias_max_g": _num(0.1, 300),
    "brs_max_rate_rad_s": _num(1, 1e6), "recover_ticks": _num(0, 100_000, True),
    "max_bridge_ticks": _num(0, 10_000, True), "counts_per_rev": _num(1, 255, True)}
assert set(_NODE) | {"core"} == {f.name for f in fields(NodeConfig)}
assert set(_CORE) == {f.name for f in fields(CoreConfig)}

SCHEMA = {"type": "object", "additionalProperties": False,
          "properties": {**_NODE, "core": {"type": "object", "additionalProperties": False,
                                           "properties": _CORE}}}


def check(d: dict[str, Any], where: str) -> None:
    """Raise ConfigError for the first key of ``d`` (NodeConfig fields, ``core`` a dict of
    CoreConfig fields) that is unknown, of the wrong type, not finite or out of range."""
    import jsonschema

    for table, values in (("[observer]", d), ("[observer.core]", d.get("core", {}))):
        for k, v in values.items():
            if isinstance(v, float) and not math.isfinite(v):
                raise ConfigError(f"{where}: {table} {k}: {v} is not a finite number")
    err = jsonschema.exceptions.best_match(
        jsonschema.Draft202012Validator(SCHEMA).iter_errors(d))
    if err is not None:
        path = list(err.absolute_path)
        table = "[observer.core]" if path[:1] == ["core"] else "[observer]"
        key = str(path[-1]) if path and path != ["core"] else ""
        if err.validator == "additionalProperties":
            known = sorted(_CORE if table == "[observer.core]" else _NODE)
            unknown = sorted(set(err.instance) - set(known) - {"core"})
            raise ConfigError(f"{where}: {table} unknown key {unknown[0]!r} "
                              f"(known: {', '.join(known)})")
        raise ConfigError(f"{where}: {table} {key}: {err.message}")
    core = d.get("core", {})
    trig, onset = core.get("trigger_g", 3.0), core.get("onset_g", 0.5)
    if onset >= trig:
        raise ConfigError(f"{where}: [observer.core] onset_g: {onset} must be below "
                          f"trigger_g {trig}")


def example_toml() -> str:
    """Every key with its default and allowed range, as a config file would hold them."""
    node, core = NodeConfig(), CoreConfig()
    out = ["# observer-node run --config FILE: every key, its default and its range"]
    tables: tuple[tuple[str, object, dict[str, dict[str, Any]]], ...] = (
        ("[observer]", node, _NODE), ("[observer.core]", core, _CORE))
    for table, obj, schema in tables:
        out.append(f"\n{table}")
        for k, sch in schema.items():
            v = getattr(obj, k)
            val = f'"{v}"' if isinstance(v, str) else str(v).lower() if isinstance(v, bool) \
                else repr(v)
            rng = f"  # {sch['minimum']:g} .. {sch['maximum']:g}" if "minimum" in sch else ""
            out.append(f"{k} = {val}{rng}")
    return "\n".join(out)
