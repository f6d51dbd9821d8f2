"""Fuzz benchmark: a million fuzzed frames into a recording daemon on python-can's virtual bus
(random IDs, DLCs and payloads, valid-CRC frames with wild values, bad alive counters, error
and remote frames; see observer_node/daemon/fuzz.py), then R16_002 replayed. Prints the
counters, whether every frame was counted once, the process's memory along the way, and
whether the crash afterwards was detected and stepped as the offline simulation steps it.

    python benchmarks/fuzz.py [--frames 1000000] [--seed 1]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from dataclasses import asdict, replace
from pathlib import Path

import numpy as np

from observer_node.daemon.fuzz import rss_mb, run_fuzz
from observer_node.daemon.harness import Harness, r16_schedule
from observer_node.data import bundled_campaign, load_tests
from observer_node.evaluation import identify
from observer_node.ident.dataset import make_dataset
from observer_node.recording import offline_estimates, read_recording


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--frames", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    tests = [t for t in load_tests([bundled_campaign()])
             if t.name in ("R16_001", "R16_003", "R16_005")]
    model = identify("greybox", make_dataset(tests, 1000.0))
    with tempfile.TemporaryDirectory() as tmp:
        rec_path = Path(tmp) / "run.mcap"
        t0 = time.monotonic()
        rss: list[tuple[int, float]] = []
        step = max(a.frames // 10, 200)

        def progress(sent: int) -> None:
            if sent % step < 200:
                rss.append((sent, rss_mb()))
                print(f"  {sent:>9,} frames sent, RSS {rss[-1][1]:.1f} MB", flush=True)

        with Harness(model, "fuzz-bench", record=rec_path) as h:
            passed = run_fuzz(h, a.frames, a.seed, on_batch=progress)
            c = replace(h.node.counters)  # as the fuzz left them, before the crash
            alive = h.thread.is_alive()
            events = h.node.core.events
            h.play(r16_schedule(pre_s=0.6))
            time.sleep(0.1)
        elapsed = time.monotonic() - t0
        rec = read_recording(rec_path, frames=False)
        last = int(rec.ticks["event"].max())
        ticks, y_off = offline_estimates(rec, last)
        rows = np.searchsorted(rec.ticks["tick"], ticks)
        run = rec.ticks["running"][rows] > 0
        diff = max(float(np.max(np.abs(rec.ticks["cr_g"][rows][run] - y_off[run, 0]))),
                   float(np.max(np.abs(rec.ticks["cd_mm"][rows][run] - y_off[run, 1]))))
    total = c.accepted + c.rejected + c.bad_e2e + c.unknown_id + c.error_frames
    print(f"{a.frames:,} fuzzed frames in {elapsed:.0f} s; {passed:,} passed the port's ID "
          f"filter and reached the daemon; daemon alive after: {alive}")
    print("counters: " + ", ".join(f"{k} {v:,}" for k, v in asdict(c).items()))
    print(f"every received frame counted once: {c.rx == total == passed} "
          f"(rx {c.rx:,}, accepted+rejected+bad_e2e+unknown_id+error_frames {total:,})")
    print(f"RSS from {rss[0][1]:.1f} MB (after {rss[0][0]:,} frames) to {rss[-1][1]:.1f} MB "
          f"(after {rss[-1][0]:,})")
    print(f"crash replayed after the fuzz: detected {h.node.core.events == events + 1}, "
          f"{int(run.sum())} ticks stepped, largest difference from offline {diff:.2g}")


if __name__ == "__main__":
    main()
