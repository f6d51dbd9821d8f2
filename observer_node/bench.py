"""observer-node bench: the whole bench in one command.

1. a model: ``--model``, or the grey-box identified on the bundled campaign's odd R16 tests;
2. the daemon on vcan0 if this machine has it (SocketCAN), else on an in-process python-can
   virtual bus, recording to MCAP;
3. crash-replay's schedule of bundled validation tests (even numbers), with reference frames;
4. the recording read back and analysed, beside the offline evaluation of the same model on
   the same tests.

The daemon runs in a thread of this process so the virtual bus can be shared; on a bench PC
run ``observer-node run`` and ``crash-replay`` as separate processes instead.
"""

from __future__ import annotations

import sys
import threading
import time
from pathlib import Path

from .data import bundled_campaign, read_isomme
from .evaluation import evaluate_model, identify, split_halves
from .ident.dataset import make_dataset
from .model.modelfile import ModelFile
from .recording import analyze, read_recording

DEFAULT_TESTS = ("R16_002", "SLED_002", "FULL_002")


def run_bench(out: Path, model_path: str | None = None, interface: str = "auto",
              channel: str = "vcan0", tests: tuple[str, ...] = DEFAULT_TESTS,
              rate: float = 1.0) -> dict:
    import can

    from observer_node.dbc import Codec
    from observer_node.replay.player import bus_sender, play
    from observer_node.replay.schedule import concat, crash_test_schedule, restamp_counters

    from .daemon.config import NodeConfig
    from .daemon.node import ObserverNode
    from .daemon.ports import PythonCanPort

    out.mkdir(parents=True, exist_ok=True)
    codec = Codec()
    if model_path:
        model = ModelFile.load(model_path)
    else:
        est, _ = split_halves([read_isomme(p) for p in sorted(bundled_campaign().glob("R16_*"))])
        print(f"bench: identifying the grey-box model on {', '.join(t.name for t in est)}")
        model = identify("greybox", make_dataset(est, 1000.0), name="bench-r16-greybox")
    model.save(out / "model.json")

    if interface == "auto":
        interface = "socketcan" if Path(f"/sys/class/net/{channel}").exists() else "virtual"
    if interface == "virtual":
        channel = "bench"
    record = out / "run.mcap"
    cfg = NodeConfig(interface=interface, channel=channel, record=str(record))
    factory = (lambda ids: PythonCanPort("virtual", channel, ids)) if interface == "virtual" \
        else None
    node = ObserverNode(cfg, model, codec, port_factory=factory)
    ready = threading.Event()
    thread = threading.Thread(target=node.run, kwargs={"on_ready": ready.set})
    thread.start()
    if not ready.wait(60):
        node.stop_event.set()
        thread.join()
        raise RuntimeError("the daemon did not start")
    print(f"bench: daemon listening on {interface}:{channel}, recording to {record}; "
          f"{node.cpu_latency}")

    crash = [read_isomme(bundled_campaign() / f"{name}.zip") for name in tests]
    sched = restamp_counters(concat([
        crash_test_schedule(t, codec, model.tick_rate_hz, reference=True, pre_s=0.2)
        for t in crash], gap_s=0.3), codec)
    bus = can.Bus(interface=interface, channel=channel)
    send = bus_sender(bus, sched)
    print(f"bench: replaying {', '.join(tests)} ({len(sched)} frames, "
          f"{sched.t_s[-1] / rate:.1f} s)")
    report = play(sched, send, rate=rate)
    time.sleep(0.3)
    node.stop_event.set()
    thread.join()
    bus.shutdown()
    print(f"bench: replay {report.summary()}")
    c = node.counters
    core = node.core
    print(f"bench: daemon ticks {c.ticks}, lost {c.lost}, rejected {c.rejected}, bad E2E "
          f"{c.bad_e2e}, overruns {c.overruns}, sensor faults {core.brs_jumps} BRS jumps "
          f"{core.bias_faults} bias {core.hold_timeouts} hold timeouts")

    rec = read_recording(record)
    result = analyze(rec, out_dir=out, ratings=False)  # ISO 18571: observer-node analyze
    offline = {t.name: evaluate_model(model, [t], ratings=False)["tests"][t.name] for t in crash}
    rows = []
    for test, ev in zip(tests, result["events"], strict=False):
        live = ev.get("fit_vs_reference", {})
        off = offline[test]
        rows.append((test, live.get("cr", float("nan")), live.get("cd", float("nan")),
                     off["cr"], off["cd"], max(ev["max_abs_diff_offline"].values())))
    print("\n  test        daemon on the bus      offline (evaluate)   max |daemon - offline"
          " re-run|")
    print("              fit CR   fit CD         fit CR   fit CD")
    for name, lcr, lcd, ocr, ocd, diff in rows:
        print(f"  {name:<10}{lcr:9.1f}{lcd:9.1f}      {ocr:9.1f}{ocd:9.1f}      {diff:.1e}")
    print("\n  Fits are eq. 3.15 over 0.01..0.15 s; the daemon's window starts at its detected "
          "onset, the offline one at the lab's t = 0, hence small differences.")
    for (name, *_, diff), ev in zip(rows, result["events"], strict=False):
        if not diff < 1e-6:  # the daemon must step exactly what an offline run of its inputs does
            print(f"bench: WARNING: {name}: the daemon differs from the offline re-run of its own "
                  f"inputs by {diff:.3g} ({ev['invalid_ticks']} invalid ticks): see "
                  f"{out}/analysis.json", file=sys.stderr)
    print(f"bench: wrote {out}/model.json, run.mcap, analysis.json and event plots")
    result["offline"] = offline
    return result
