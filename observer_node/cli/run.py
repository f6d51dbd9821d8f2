"""``observer-node run``: the real-time observer daemon on a CAN bus.

Its options set keys of the daemon's config (:mod:`observer_node.daemon.config`) by an
explicit table; an option not given keeps the ``--config`` file's value, else the config's
default, which its help shows.
"""

from __future__ import annotations

import argparse
import dataclasses
from typing import Any

from observer_node.dbc.bus import add_bus_arguments

from ..daemon.config import NodeConfig
from ..daemon.core import CoreConfig
from ..errors import ObserverError, RecordingLostError, UsageError

# option (its argparse dest) -> config key: a NodeConfig field, or core.FIELD of CoreConfig
CONFIG_KEYS = {
    "interface": "interface", "channel": "channel", "fd": "fd",
    "raw_socketcan": "raw_socketcan", "model": "model", "setup": "setup", "record": "record",
    "live": "live", "cpu_latency_us": "cpu_latency_us", "rt_priority": "rt_priority",
    "trigger_g": "core.trigger_g", "event_s": "core.event_s",
    "counts_per_rev": "core.counts_per_rev",
}
_NODE, _CORE = NodeConfig(), CoreConfig()


def add_subparser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    s = subparsers.add_parser(
        "run", help="run the real-time observer daemon on a CAN bus",
        description="Read TunnelAccel and BeltSpindle frames, step the model once per "
        "accelerometer frame, publish ChestEstimate every tick and the status at 10 Hz, and "
        "record the run to MCAP. Stops cleanly on SIGINT/SIGTERM.",
        epilog="A recording never overwrites a file: if --record names one that exists, the "
        "run goes to NAME.1.mcap, NAME.2.mcap, ... If the MCAP writer fails, the daemon "
        "keeps estimating, says so on the bus (ObserverHealth) and in the log, and records "
        f"on in NAME.part2.mcap. Exit codes: 0 a clean stop; {ObserverError.exit_code} it "
        "could not start (bad model file or config, a port or record path that cannot be "
        f"opened); {RecordingLostError.exit_code} it ran, but the recording is not the whole "
        "run.")
    add_bus_arguments(s, interface=_NODE.interface, channel=_NODE.channel, unset=True)
    s.add_argument("--model", help="model file (JSON) from identify, evaluate or loop")
    s.add_argument("--setup", metavar="NAME",
                   help="this bench's setup (R16, SLED, ...): needed for a model whose effects "
                   "act on some setups only (loop's model.json says which); the daemon runs "
                   "that setup's effects. A setup the model was not fitted on is refused")
    s.add_argument("--record", help="MCAP file to record the run to")
    s.add_argument("--live", nargs="?", const="127.0.0.1:8765", metavar="HOST:PORT",
                   help="serve the run live to the Foxglove app (its WebSocket protocol; "
                   "default %(const)s; needs --record: the recorder process serves it, "
                   "so a slow viewer never delays a tick): the recording's topics and "
                   "schemas, per-tick topics at about 100 Hz; layout in docker/foxglove/")
    s.add_argument("--config", help="TOML file with an [observer] table of these options")
    s.add_argument("--print-config", action="store_true",
                   help="print every config key with its default and range, and exit")
    s.add_argument("--python-can-socketcan", dest="raw_socketcan", action="store_false",
                   default=None,
                   help="use python-can's socketcan backend instead of the raw socket port")
    s.add_argument("--cpu-latency-us", type=int, metavar="US",
                   help="hold every CPU's wake-up latency at most US microseconds while running "
                   f"(Linux PM QoS, needs root; default {_NODE.cpu_latency_us}, as cyclictest "
                   "does; -1: leave power management alone)")
    s.add_argument("--rt-priority", type=int, metavar="N",
                   help="run the tick loop under SCHED_FIFO at priority N (1-99), so a viewer "
                   "or any other process on the bench PC never delays a tick (needs root, "
                   "CAP_SYS_NICE or RLIMIT_RTPRIO; said at start-up when refused; default "
                   f"{_NODE.rt_priority}: normal scheduling)")
    s.add_argument("--trigger-g", type=float,
                   help=f"crash trigger threshold in g (default {_CORE.trigger_g:g})")
    s.add_argument("--event-s", type=float,
                   help=f"observer run time after trigger in s (default {_CORE.event_s:g})")
    s.add_argument("--counts-per-rev", type=int,
                   help="BRS counts/rev if the BRS frame does not say "
                   f"(default {_CORE.counts_per_rev})")
    s.add_argument("--quiet", action="store_true", help="log warnings and errors only")
    s.set_defaults(func=_do_run)


def config_from_args(a: argparse.Namespace) -> NodeConfig:
    """The ``--config`` file's config (else the defaults) with every option given on the
    command line set, checked whole; ConfigError or UsageError naming the key."""
    cfg = NodeConfig.from_toml(a.config) if a.config else NodeConfig()
    node: dict[str, Any] = {}
    core: dict[str, Any] = {}
    for dest, key in CONFIG_KEYS.items():
        value = getattr(a, dest)
        if value is not None:
            table, _, name = key.rpartition(".")
            (core if table == "core" else node)[name] = value
    cfg = dataclasses.replace(cfg, **node, core=dataclasses.replace(cfg.core, **core))
    if not cfg.model:
        raise UsageError("run needs --model (or model in the config file)")
    cfg.check("command line" if not a.config else f"{a.config} with the command line")
    return cfg


def _do_run(a: argparse.Namespace) -> int:
    from ..daemon.config import example_toml
    from ..daemon.node import run_daemon

    if a.print_config:
        print(example_toml())
        return 0
    return run_daemon(config_from_args(a), quiet=a.quiet)

