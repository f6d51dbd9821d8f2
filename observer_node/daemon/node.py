"""observer-node run: the daemon's loop.

One thread, one loop: receive a frame (kernel-filtered to the input IDs), validate it (DLC,
E2E CRC, alive counter, range), hand it to :class:`ObserverCore`, publish the estimate,
record both frames and the tick to the shared-memory rings. An InputBurst frame (CAN FD,
for 10 kHz) is eight such ticks with their own BRS counts and one estimate frame, the last
tick's. Status frames go out every ``status_period_s``. Receive timeouts drive the
watchdog: with no accelerometer frame for two tick periods (two burst periods for bursts) an
invalid estimate is published each tick period (for up to ``idle_after_s``);
with no BRS frame for ``brs_timeout_s`` the estimate is flagged invalid. Bus errors and a
downed interface are counted and survived: the port is reopened until the bus is back.

Everything per frame is a handful of integer and float operations on values prepared at
start-up; nothing is logged and nothing looked up by name per frame.
"""

from __future__ import annotations

import contextlib
import gc
import json
import math
import signal
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass
from typing import BinaryIO

from dbc import DBC_PATH, Codec, e2e_crc

from .. import __version__
from ..model.modelfile import ModelFile
from ..recording.format import FLAG_TX, TickRow
from ..recording.writer import OFF, Recorder, RecorderError
from .config import NodeConfig
from .core import (
    ACCEL_TIMEOUT,
    BAD_E2E,
    BRS_TIMEOUT,
    BUS_ERROR,
    LATCHED_MASK,
    OUT_OF_RANGE,
    RUNNING,
    SENSOR_FAULT,
    ObserverCore,
)
from .ports import FLAG_ERROR, FLAG_REMOTE, Port, PortError, open_port
from .realtime import hold_cpu_latency

RECORDING_LOST = 0x80  # ObserverFault bit 7 (see the DBC)
EXIT_RECORDING_LOST = 3  # run's exit code when the recording is not the whole run


@dataclass
class Counters:
    """Every received frame is counted once as accepted, rejected, bad_e2e, unknown_id or
    error_frames (rx is their sum); the others count events."""

    rx: int = 0
    accepted: int = 0
    ticks: int = 0
    lost: int = 0
    rejected: int = 0
    bad_e2e: int = 0
    unknown_id: int = 0
    error_frames: int = 0
    overruns: int = 0
    tx_dropped: int = 0
    reconnects: int = 0
    accel_timeouts: int = 0
    brs_timeouts: int = 0
    kernel_dropped: int = 0


def _wrap16(v: int) -> int:
    """Counters on the bus are free-running and wrap modulo 65536 (the DBC says so): a
    receiver takes differences modulo 65536 and never sees a counter stick."""
    return v & 0xFFFF


class ObserverNode:
    def __init__(self, cfg: NodeConfig, model: ModelFile, codec: Codec | None = None,
                 port_factory: Callable[[list[int]], Port] | None = None):
        self.cfg = cfg
        self.model = model
        self.codec = codec or Codec(DBC_PATH)
        self.core = ObserverCore(model.observer(), cfg.core)
        self.counters = Counters()
        self.stop_event = threading.Event()
        c = self.codec
        acc, brs, est, ref = (c["TunnelAccel"], c["BeltSpindle"], c["ChestEstimate"],
                              c["ReferenceChest"])
        burst = c["InputBurst"]
        self.input_ids = [acc.frame_id, burst.frame_id, brs.frame_id, ref.frame_id]
        self._port_factory = port_factory or (
            lambda ids: open_port(cfg.interface, cfg.channel, ids, cfg.fd, cfg.raw_socketcan))
        # Everything the hot path needs, resolved once.
        self.acc_id, self.acc_len, self.acc_struct = acc.frame_id, acc.length, acc.struct
        self.acc_scale = acc.scale("TunnelAccelX")
        self.acc_lo, self.acc_hi = acc.raw_range("TunnelAccelX")
        self.brs_id, self.brs_len, self.brs_struct = brs.frame_id, brs.length, brs.struct
        self.burst_id, self.burst_len, self.burst_struct = (burst.frame_id, burst.length,
                                                            burst.struct)
        self.burst_n = sum(1 for n in burst.signal_names if n.startswith("BurstAccelX"))
        self.ref_id, self.ref_len, self.ref_struct = ref.frame_id, ref.length, ref.struct
        self.ref_scale_cr = ref.scale("RefChestAccelCR")
        self.ref_scale_cd = ref.scale("RefChestDeflCD")
        self.est_id, self.est_struct = est.frame_id, est.struct
        self.est_valid_bit = 1 << est.bit_shift("ChestEstimate_Valid")
        self.est_running_bit = 1 << est.bit_shift("ChestEstimate_Running")
        self.est_scale_cr = est.scale("ChestAccelCR")
        self.est_scale_cd = est.scale("ChestDeflCD")
        self.est_lo, self.est_hi = est.raw_range("ChestAccelCR")
        self._est_buf = bytearray(est.length)
        self.status_codec, self.counters_codec = c["ObserverStatus"], c["ObserverCounters"]
        self.health_codec = c["ObserverHealth"]
        self.log: Callable[[str], None] = lambda line: print(
            f"observer-node: {line}", file=sys.stderr, flush=True)
        self.period_s = 1.0 / model.tick_rate_hz
        self.accel_timeout_s = cfg.accel_timeout_s or 2 * self.period_s
        self.burst_timeout_s = cfg.accel_timeout_s or 2 * self.burst_n * self.period_s
        self.model_id = model.model_id()
        self.recorder: Recorder | None = None
        self.port: Port | None = None
        self._pm_qos: BinaryIO | None = None
        self._last_reconnect = -math.inf
        self.cpu_latency = ""  # what hold_cpu_latency said

    # ------------------------------------------------------------------ lifecycle
    def metadata(self) -> dict[str, str]:
        cfg = asdict(self.cfg)
        return {"software_version": __version__, "model_name": self.model.name,
                "model_kind": self.model.kind, "model_id": str(self.model_id),
                "tick_rate_hz": str(self.model.tick_rate_hz), "dbc_sha256": self.codec.sha256(),
                "config": json.dumps(cfg), "cpu_latency": self.cpu_latency,
                "started_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}

    def open(self) -> None:
        """PM QoS, the recorder (its file created, its header written) and the bus port. On
        any failure what was opened is closed again (the caller sees the error)."""
        try:
            self._pm_qos, self.cpu_latency = hold_cpu_latency(self.cfg.cpu_latency_us)
            if self.cfg.record:
                atts = [("model.json", "application/json", self.model.dumps().encode()),
                        ("chest_observer.dbc", "text/plain", self.codec.path.read_bytes())]
                self.recorder = Recorder(self.cfg.record, self.metadata(), atts,
                                         self.codec.path, rows_per_s=self.model.tick_rate_hz)
                self.recorder.wait_ready()
            self.port = self._port_factory(self.input_ids)
        except BaseException:
            if self.recorder is not None:
                self.recorder.close(discard=True)  # nothing was recorded: leave no file
            self.close()
            raise

    def close(self) -> None:
        if self.port is not None:
            with contextlib.suppress(OSError):
                self.port.close()
            self.port = None
        if self.recorder is not None:
            said = self.recorder.close()  # kept: its parts, errors and losses are the record
            if said is not None:
                self.log(said)
        if self._pm_qos is not None:
            self._pm_qos.close()
            self._pm_qos = None

    def install_signal_handlers(self) -> None:
        def stop(_signum, _frame):
            self.stop_event.set()
        signal.signal(signal.SIGINT, stop)
        signal.signal(signal.SIGTERM, stop)

    # ------------------------------------------------------------------ loop
    def run(self, max_seconds: float | None = None, idle_exit_s: float | None = None,
            on_ready: Callable[[], None] | None = None) -> Counters:
        """Run until stopped (signal, ``stop_event``), ``max_seconds`` or, with
        ``idle_exit_s``, that long without any input frame after the first one.
        ``on_ready`` is called once the bus is open and the recorder is writing."""
        # Everything alive now (model, codec, numpy) lives for the whole run: move it out of
        # the collector's sight, so that a full collection cannot pause a tick for tens of
        # milliseconds scanning it. Before the bus opens: nobody is waiting for us yet.
        gc.collect()
        gc.freeze()
        self.open()
        try:
            if on_ready is not None:
                on_ready()
            self._loop(max_seconds, idle_exit_s)
        finally:
            self.close()
        return self.counters

    @property
    def recording_lost(self) -> bool:
        """The recording is not the whole run (a writer failed, or ticks were lost)."""
        return self.recorder is not None and self.recorder.degraded

    def _loop(self, max_seconds: float | None, idle_exit_s: float | None) -> None:
        cnt, core = self.counters, self.core
        rec_frame = self.recorder.put_frame if self.recorder else None
        keep_up = self.recorder.keep_up if self.recorder else None
        next_keep_up = 0.0
        period = self.period_s
        t_start = time.perf_counter()
        last_accel = last_brs = last_any = None
        next_status = t_start
        next_watchdog = math.inf
        status_counter = 0
        acc_id, brs_id, ref_id, burst_id = self.acc_id, self.brs_id, self.ref_id, self.burst_id
        acc_counter = brs_counter = burst_counter = -1
        self.ref_cr = self.ref_cd = math.nan
        stop = self.stop_event
        while not stop.is_set():
            now = time.perf_counter()
            if max_seconds is not None and now - t_start > max_seconds:
                break
            if idle_exit_s is not None and last_any is not None and now - last_any > idle_exit_s:
                break
            timeout = min(next_status, next_watchdog) - now
            # A PortError anywhere (receive, or sending an estimate or status on an
            # interface that went down) means the bus is gone: reconnect.
            try:
                r = self.port.recv(min(max(timeout, 1e-4), 0.05))  # type: ignore[union-attr]
                now = time.perf_counter()
                if r is not None:
                    t, cid, data, flags = r
                    cnt.rx += 1
                    last_any = t
                    if rec_frame:
                        rec_frame(t, cid, data, flags)
                    if flags & FLAG_ERROR:
                        cnt.error_frames += 1
                        core.fault(BUS_ERROR)
                    elif flags & FLAG_REMOTE:
                        cnt.rejected += 1  # a request for data is never data
                    elif cid == acc_id:
                        acc_counter = self._on_accel(t, data, acc_counter)
                        last_accel = t
                        next_watchdog = t + self.accel_timeout_s
                    elif cid == brs_id:
                        brs_counter = self._on_brs(data, brs_counter)
                        last_brs = t
                    elif cid == burst_id:
                        burst_counter = self._on_burst(t, data, burst_counter)
                        last_accel = last_brs = t
                        next_watchdog = t + self.burst_timeout_s
                    elif cid == ref_id:
                        self._on_reference(data)
                    else:
                        cnt.unknown_id += 1
                # Watchdog: accelerometer silent for two tick periods -> invalid estimate per tick
                if now >= next_watchdog:
                    if last_accel is not None and now - last_accel < self.cfg.idle_after_s:
                        if not core.cause & ACCEL_TIMEOUT:
                            cnt.accel_timeouts += 1  # outages, not ticks
                        core.fault(ACCEL_TIMEOUT)
                        if core.state == RUNNING and now - last_accel > self.cfg.core.event_s:
                            core.end_event()  # a silence, then another test: not this event
                        self._publish(now, watchdog=True)
                        next_watchdog = now + period
                    else:
                        next_watchdog = math.inf
                if last_brs is not None and now - last_brs > self.cfg.brs_timeout_s and \
                        last_accel is not None and now - last_accel < self.cfg.idle_after_s:
                    if not core.cause & BRS_TIMEOUT:
                        cnt.brs_timeouts += 1
                    core.fault(BRS_TIMEOUT)
                if keep_up is not None and now >= next_keep_up:
                    keep_up()  # the MCAP writer's priority: idle unless it lags
                    next_keep_up = now + 0.01
                if now >= next_status:
                    if self.recorder is not None:
                        said = self.recorder.poll()
                        if said is not None:
                            self.log(said)
                    self._send_status(now, status_counter)
                    status_counter += 1
                    next_status += self.cfg.status_period_s
                    if next_status < now:
                        next_status = now + self.cfg.status_period_s
            except PortError:
                core.fault(BUS_ERROR)
                self._reconnect()

    def _reconnect(self) -> None:
        """Reopen the port. A socket bound to a downed interface opens fine and fails on
        first use, so reopenings are spaced ``reconnect_s`` apart, not spun."""
        cnt = self.counters
        try:
            if self.port is not None:
                self.port.close()
        except OSError:
            pass
        self.port = None
        if time.monotonic() - self._last_reconnect < self.cfg.reconnect_s:
            self.stop_event.wait(self.cfg.reconnect_s)
        self._last_reconnect = time.monotonic()
        while not self.stop_event.is_set():
            cnt.reconnects += 1
            try:
                self.port = self._port_factory(self.input_ids)
                return
            except PortError:
                self.stop_event.wait(self.cfg.reconnect_s)

    # ------------------------------------------------------------------ frames
    def _on_accel(self, t: float, data: bytes, last_counter: int) -> int:
        cnt, core = self.counters, self.core
        if len(data) != self.acc_len:
            cnt.rejected += 1
            core.fault(OUT_OF_RANGE)
            return last_counter
        crc, b1, raw = self.acc_struct.unpack_from(data)
        gap = self._admit(self.acc_id, data, crc, b1, last_counter)
        if gap < 0:
            return last_counter
        if gap:
            core.bridge(gap)
        if b1 >> 4 & 1:
            core.fault(SENSOR_FAULT)
        if raw <= self.acc_lo or raw >= self.acc_hi:
            core.fault(OUT_OF_RANGE)  # saturated sensor: used, but flagged
        accel_g = raw * self.acc_scale
        core.tick(-accel_g)  # J211 X acceleration -> deceleration positive
        cnt.ticks += 1
        self._publish(t, accel_g)
        cnt.kernel_dropped = self.port.dropped  # type: ignore[union-attr]
        return b1 & 0xF

    def _on_burst(self, t: float, data: bytes, last_counter: int) -> int:
        """An InputBurst frame: ``burst_n`` ticks, each with its own BRS count; one estimate
        frame (the last tick's) goes out, every tick is recorded."""
        cnt, core, n = self.counters, self.core, self.burst_n
        if len(data) != self.burst_len:
            cnt.rejected += 1
            core.fault(OUT_OF_RANGE)
            return last_counter
        v = self.burst_struct.unpack_from(data)  # crc, b1, counts/rev, (accel, count) x n
        gap = self._admit(self.burst_id, data, v[0], v[1], last_counter)
        if gap < 0:
            return last_counter
        if gap:
            core.bridge(gap * n)
        if v[1] >> 4 & 0b101:
            core.fault(SENSOR_FAULT)
        per_rev = v[2] or self.cfg.core.counts_per_rev
        lo, hi, scale = self.acc_lo, self.acc_hi, self.acc_scale
        for j in range(n):
            raw = v[3 + 2 * j]
            if raw <= lo or raw >= hi:
                core.fault(OUT_OF_RANGE)
            core.set_brs(float(v[4 + 2 * j]), per_rev)
            accel_g = raw * scale
            core.tick(-accel_g)
            cnt.ticks += 1
            self._publish(t, accel_g, send=j == n - 1, frame_ticks=n)
        cnt.kernel_dropped = self.port.dropped  # type: ignore[union-attr]
        return v[1] & 0xF

    def _on_brs(self, data: bytes, last_counter: int) -> int:
        cnt = self.counters
        if len(data) != self.brs_len:
            cnt.rejected += 1
            self.core.fault(OUT_OF_RANGE)
            return last_counter
        crc, b1, count, per_rev = self.brs_struct.unpack_from(data)
        if self._admit(self.brs_id, data, crc, b1, last_counter) < 0:
            return last_counter
        if b1 >> 4 & 1:
            self.core.fault(SENSOR_FAULT)
        self.core.set_brs(float(count), per_rev or self.cfg.core.counts_per_rev)
        return b1 & 0xF

    def _admit(self, frame_id: int, data: bytes, crc: int, b1: int, last_counter: int) -> int:
        """E2E check of an unpacked input frame: how many frames were lost before it (alive
        counter gap, counted), or -1 for a bad CRC or repeated counter (counted, flagged)."""
        counter = b1 & 0xF
        if crc != e2e_crc(frame_id, data) or counter == last_counter:
            self.counters.bad_e2e += 1
            self.core.fault(BAD_E2E)
            return -1
        self.counters.accepted += 1
        if last_counter < 0:
            return 0
        gap = (counter - last_counter - 1) & 0xF
        self.counters.lost += gap
        return gap

    def _on_reference(self, data: bytes) -> None:
        if len(data) != self.ref_len or data[0] != e2e_crc(self.ref_id, data):
            self.counters.rejected += 1
            return
        self.counters.accepted += 1
        _, _, cr, cd = self.ref_struct.unpack_from(data)
        self.ref_cr = cr * self.ref_scale_cr
        self.ref_cd = cd * self.ref_scale_cd

    def _publish(self, t: float, accel_g: float = math.nan, watchdog: bool = False,
                 send: bool = True, frame_ticks: int = 1) -> None:
        """Send the estimate frame for this tick (unless ``send`` is false: a burst's earlier
        ticks) and record the tick (watchdog publishes, between ticks, with tick -1). A frame
        carrying ``frame_ticks`` samples overruns when it took longer than as many periods."""
        core = self.core
        cr, cd = core.cr_g, core.cd_mm
        running = core.state == RUNNING
        valid = core.valid
        if not (math.isfinite(cr) and math.isfinite(cd)):
            core.fault(OUT_OF_RANGE)
            cr = cd = 0.0
            valid = False
        lo, hi = self.est_lo, self.est_hi
        cr_raw = min(max(round(cr / self.est_scale_cr), lo), hi)
        cd_raw = min(max(round(cd / self.est_scale_cd), lo), hi)
        b1 = (core.tick_index & 0xF) | (self.est_valid_bit if valid else 0) | \
            (self.est_running_bit if running else 0)
        buf = self._est_buf
        self.est_struct.pack_into(buf, 0, 0, b1, cr_raw, cd_raw)
        buf[0] = e2e_crc(self.est_id, buf)
        data = bytes(buf)
        rec = self.recorder
        bus_gone = None
        if send:
            try:
                if not self.port.send(self.est_id, data):  # type: ignore[union-attr]
                    self.counters.tx_dropped += 1
                    send = False
            except PortError as e:  # the interface went down: record the tick, then reconnect
                self.counters.tx_dropped += 1
                send, bus_gone = False, e
        done = time.perf_counter()
        if send and done - t > self.period_s * frame_ticks:
            self.counters.overruns += 1
        if rec is not None:
            if send:
                rec.put_frame(done, self.est_id, data, FLAG_TX)
            rec.put_tick(TickRow(t, -1 if watchdog else core.tick_index, accel_g, -accel_g,
                                 core.bias_g, core.brs_count, core.brs_ref,
                                 core.rad_per_count, cr, cd, valid, running, core.state,
                                 core.invalid_cause, core.event, core.onset_tick, self.ref_cr,
                                 self.ref_cd, (done - t) * 1e6))
        if bus_gone is not None:
            raise bus_gone

    def _send_status(self, now: float, counter: int) -> None:
        cnt, core, rec = self.counters, self.core, self.recorder
        lost = rec is not None and rec.degraded
        frames = (
            (self.status_codec, {"ObserverState": core.state, "ModelId": self.model_id,
                                 "TickOverruns": _wrap16(cnt.overruns),
                                 "InvalidCause": core.invalid_cause,
                                 "ObserverFault": (core.faults & LATCHED_MASK)
                                 | (RECORDING_LOST if lost else 0)}),
            (self.counters_codec, {"LostFrames": _wrap16(cnt.lost + cnt.kernel_dropped),
                                   "RejectedFrames": _wrap16(cnt.rejected + cnt.unknown_id),
                                   "BadE2EFrames": _wrap16(cnt.bad_e2e)}),
            (self.health_codec, {"RecorderState": OFF if rec is None else rec.state,
                                 "ErrorFrames": _wrap16(cnt.error_frames),
                                 "RecorderLostTicks": _wrap16(0 if rec is None
                                                              else rec.lost_ticks),
                                 "SensorFaults": _wrap16(core.hold_timeouts + core.bias_faults
                                                         + core.brs_jumps)}),
        )
        for fc, values in frames:
            data = fc.encode(values, counter)
            try:
                ok = self.port.send(fc.frame_id, data)  # type: ignore[union-attr]
            except PortError:  # the interface went down: the loop reconnects
                cnt.tx_dropped += 1
                raise
            if not ok:
                cnt.tx_dropped += 1
            elif self.recorder is not None:
                self.recorder.put_frame(now, fc.frame_id, data, FLAG_TX)


def run_daemon(cfg: NodeConfig, quiet: bool = False) -> int:
    """The ``observer-node run`` command."""
    model = ModelFile.load(cfg.model)
    node = ObserverNode(cfg, model)
    node.install_signal_handlers()
    def ready() -> None:
        if not quiet:
            print(f"observer-node: {model.kind} model {model.name!r} (id {node.model_id:#06x}) "
                  f"at {model.tick_rate_hz:g} Hz listening on {cfg.interface}:{cfg.channel}"
                  + (f", recording to {node.recorder.path}" if node.recorder else "")
                  + f"; {node.cpu_latency}", file=sys.stderr, flush=True)

    try:
        cnt = node.run(on_ready=ready)
    except (PortError, RecorderError) as e:
        print(f"observer-node: error: {e.strerror or e}", file=sys.stderr)
        return 2
    if not quiet:
        print("observer-node: stopped; " + ", ".join(f"{k} {v}" for k, v in asdict(cnt).items()),
              file=sys.stderr)
    rec = node.recorder
    if rec is not None and rec.degraded:
        print(f"observer-node: error: the recording is not the whole run: parts "
              f"{', '.join(map(str, rec.parts))}; {rec.lost_ticks} ticks and {rec.lost_frames} "
              f"frames lost; " + "; ".join(rec.errors), file=sys.stderr)
        return EXIT_RECORDING_LOST
    return 0
