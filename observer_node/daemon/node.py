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
from dataclasses import asdict
from typing import BinaryIO

from observer_node.dbc import DBC_PATH, Codec

from .. import __version__
from ..criteria import chest_criteria
from ..errors import ObserverError, RecordingLostError
from ..model.modelfile import ModelFile
from ..recording import format as fmt
from ..recording.format import FrameFlag, RunMeta, TickRow, tick_values
from ..recording.writer import Recorder, RecorderError
from .config import NodeConfig
from .core import ACCEL_TIMEOUT, BRS_TIMEOUT, BUS_ERROR, OUT_OF_RANGE, RUNNING, ObserverCore
from .inputs import Counters, Inputs
from .outputs import Outputs
from .ports import FLAG_ERROR, FLAG_REMOTE, Port, PortError, open_port
from .realtime import hold_cpu_latency, restore_scheduling, set_rt_priority

FLAG_TX = FrameFlag.TX.value  # a plain int per frame


class ObserverNode:
    def __init__(self, cfg: NodeConfig, model: ModelFile, codec: Codec | None = None,
                 port_factory: Callable[[list[int]], Port] | None = None):
        self.cfg = cfg
        self.model = model
        self.codec = codec or Codec(DBC_PATH)
        self.core = ObserverCore(model.observer(), cfg.core)
        self.counters = Counters()
        self.stop_event = threading.Event()
        self.inputs = Inputs(self.codec, self.core, self.counters, cfg.core.counts_per_rev,
                             self._publish)
        self.outputs = Outputs(self.codec, model.model_id())
        self.input_ids = self.inputs.ids
        self._port_factory = port_factory or (
            lambda ids: open_port(cfg.interface, cfg.channel, ids, cfg.fd, cfg.raw_socketcan))
        self.log: Callable[[str], None] = lambda line: print(
            f"observer-node: {line}", file=sys.stderr, flush=True)
        self.period_s = 1.0 / model.tick_rate_hz
        self.accel_timeout_s = cfg.accel_timeout_s or 2 * self.period_s
        self.burst_timeout_s = cfg.accel_timeout_s or 2 * self.inputs.burst_n * self.period_s
        self.model_id = self.outputs.model_id
        self.recorder: Recorder | None = None
        self._row = TickRow()  # the tick recorded, refilled each tick
        self.port: Port | None = None
        self._pm_qos: BinaryIO | None = None
        self._last_reconnect = -math.inf
        self.cpu_latency = ""  # what hold_cpu_latency said
        self._old_sched: tuple[int, int] | None = None
        self.scheduling = ""  # what set_rt_priority said
        self.step_errors = 0  # loop passes that raised: counted, flagged invalid, survived
        self._step_error_seen: set[str] = set()  # each kind of failure is logged once

    # ------------------------------------------------------------------ lifecycle
    def metadata(self) -> dict[str, str]:
        cfg = asdict(self.cfg)
        meta = {RunMeta.SOFTWARE_VERSION: __version__, RunMeta.MODEL_NAME: self.model.name,
                RunMeta.MODEL_KIND: self.model.kind, RunMeta.MODEL_ID: str(self.model_id),
                RunMeta.TICK_RATE_HZ: str(self.model.tick_rate_hz),
                RunMeta.DBC_SHA256: self.codec.sha256(), RunMeta.CONFIG: json.dumps(cfg),
                RunMeta.CPU_LATENCY: self.cpu_latency, RunMeta.SCHEDULING: self.scheduling,
                RunMeta.STARTED_UTC: time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
        return {k.value: v for k, v in meta.items()}

    def open(self) -> None:
        """PM QoS, the recorder (its file created, its header written) and the bus port. On
        any failure what was opened is closed again (the caller sees the error)."""
        try:
            self._pm_qos, self.cpu_latency = hold_cpu_latency(self.cfg.cpu_latency_us)
            # this thread runs the ticks; the recorder started below runs at normal priority
            self._old_sched, self.scheduling = set_rt_priority(self.cfg.rt_priority)
            if self.cfg.record:
                atts = [(fmt.ATT_MODEL, fmt.MEDIA[fmt.ATT_MODEL], self.model.dumps().encode()),
                        (fmt.ATT_DBC, fmt.MEDIA[fmt.ATT_DBC], self.codec.path.read_bytes())]
                self.recorder = Recorder(self.cfg.record, self.metadata(), atts,
                                         self.codec.path, rows_per_s=self.model.tick_rate_hz,
                                         live=self.cfg.live)
                self.recorder.wait_ready(self.cfg.recorder_start_timeout_s)
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
        restore_scheduling(self._old_sched)
        self._old_sched = None

    def install_signal_handlers(self) -> None:
        def stop(_signum: int, _frame: object) -> None:
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
            self._tick_until_stopped(max_seconds, idle_exit_s)
        finally:
            self.close()
        return self.counters

    @property
    def recording_lost(self) -> bool:
        """The recording is not the whole run (a writer failed, or ticks were lost)."""
        return self.recorder is not None and self.recorder.degraded

    def _tick_until_stopped(self, max_seconds: float | None, idle_exit_s: float | None) -> None:
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
        inputs = self.inputs
        inputs.reset()
        acc_id, brs_id, ref_id, burst_id = inputs.ids[0], inputs.ids[2], inputs.ids[3], \
            inputs.ids[1]
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
                        inputs.accel(t, data)
                        last_accel = t
                        next_watchdog = t + self.accel_timeout_s
                        cnt.kernel_dropped = self.port.dropped  # type: ignore[union-attr]
                    elif cid == brs_id:
                        inputs.brs_frame(data)
                        last_brs = t
                    elif cid == burst_id:
                        inputs.burst_frame(t, data)
                        last_accel = last_brs = t
                        next_watchdog = t + self.burst_timeout_s
                        cnt.kernel_dropped = self.port.dropped  # type: ignore[union-attr]
                    elif cid == ref_id:
                        inputs.reference(data)
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
                        self._publish(now, math.nan, True, 1, watchdog=True)
                        next_watchdog = now + period
                    else:
                        next_watchdog = math.inf
                if last_brs is not None and now - last_brs > self.cfg.brs_timeout_s and \
                        last_accel is not None and now - last_accel < self.cfg.idle_after_s:
                    if not core.cause & BRS_TIMEOUT:
                        cnt.brs_timeouts += 1
                    core.fault(BRS_TIMEOUT)
                if core.finished is not None:  # an event ended: its criteria, once
                    self._send_criteria(now)
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
            except Exception as e:  # nothing raises out of the tick loop (docs/daemon.md, Faults)
                self._step_failed(e)

    def _step_failed(self, e: Exception) -> None:
        """A loop pass raised (a bug, a criterion on data it cannot handle): counted, the
        estimate flagged invalid (OutOfRange: no value can be trusted) and the first of
        each kind logged with where it happened; the loop goes on with the next frame."""
        self.step_errors += 1
        self.core.fault(OUT_OF_RANGE)
        tb = e.__traceback__
        while tb is not None and tb.tb_next is not None:
            tb = tb.tb_next
        where = f"{tb.tb_frame.f_code.co_filename}:{tb.tb_lineno}" if tb else "?"
        key = f"{type(e).__name__} at {where}"
        if key not in self._step_error_seen:
            self._step_error_seen.add(key)
            self.log(f"error in the tick loop, survived and counted (step_errors): "
                     f"{key}: {e}")

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

    def _publish(self, t: float, accel_g: float, send: bool, frame_ticks: int,
                 watchdog: bool = False) -> None:
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
        data = self.outputs.estimate(core, cr, cd, valid, running) if send else b""
        rec = self.recorder
        bus_gone = None
        if send:
            try:
                if not self.port.send(self.outputs.est_id, data):  # type: ignore[union-attr]
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
                rec.put_frame(done, self.outputs.est_id, data, FLAG_TX)
            row = self._row  # one row, its fields set by name: nothing built per tick
            row.t, row.tick = t, -1 if watchdog else core.tick_index
            row.accel_x_g, row.decel_g, row.bias_g = accel_g, -accel_g, core.bias_g
            row.brs_count, row.brs_ref = core.brs_count, core.brs_ref
            row.rad_per_count, row.cr_g, row.cd_mm = core.rad_per_count, cr, cd
            row.valid, row.running, row.state = valid, running, core.state
            row.cause, row.event, row.onset_tick = core.invalid_cause, core.event, core.onset_tick
            row.ref_cr_g, row.ref_cd_mm = self.inputs.ref_cr, self.inputs.ref_cd
            row.proc_us = (done - t) * 1e6
            rec.put_tick(tick_values(row))
        if bus_gone is not None:
            raise bus_gone

    def _send_criteria(self, now: float) -> None:
        """The ChestCriteria frame of the event that just ended (~0.1 ms, once per event, in
        the first loop pass after it, when the observer is holding), sent and recorded."""
        core = self.core
        assert core.finished is not None
        event = core.finished[0]
        cr, cd = core.finished_estimates()
        core.finished = None  # first: a failure below must not repeat every pass
        frame_id, data = self.outputs.criteria_frame(event, chest_criteria(cr, cd, core.fs_hz),
                                                     core.finished_valid)
        if self.port.send(frame_id, data):  # type: ignore[union-attr]
            if self.recorder is not None:
                self.recorder.put_frame(time.perf_counter(), frame_id, data, FLAG_TX)
        else:
            self.counters.tx_dropped += 1

    def _send_status(self, now: float, counter: int) -> None:
        for frame_id, data in self.outputs.status_frames(self.core, self.counters,
                                                         self.recorder, counter):
            try:
                ok = self.port.send(frame_id, data)  # type: ignore[union-attr]
            except PortError:  # the interface went down: the loop reconnects
                self.counters.tx_dropped += 1
                raise
            if not ok:
                self.counters.tx_dropped += 1
            elif self.recorder is not None:
                self.recorder.put_frame(now, frame_id, data, FLAG_TX)


def run_daemon(cfg: NodeConfig, quiet: bool = False) -> int:
    """The ``observer-node run`` command: 0 after a clean stop; an :class:`ObserverError` when
    it cannot start, a :class:`RecordingLostError` when the recording is not the whole run."""
    # a model scoped to setups runs the effects of this bench's setup only
    model = ModelFile.load(cfg.model).for_setup(cfg.setup, cfg.model)
    node = ObserverNode(cfg, model)
    node.install_signal_handlers()
    def ready() -> None:
        if not quiet:
            print(f"observer-node: {model.kind} model {model.name!r} (id {node.model_id:#06x}) "
                  f"at {model.tick_rate_hz:g} Hz listening on {cfg.interface}:{cfg.channel}"
                  + (f", recording to {node.recorder.path}" if node.recorder else "")
                  + f"; {node.cpu_latency}; {node.scheduling}", file=sys.stderr, flush=True)

    try:
        cnt = node.run(on_ready=ready)
    except (PortError, RecorderError) as e:
        raise ObserverError(e.strerror or str(e)) from None
    if not quiet:
        print("observer-node: stopped; " + ", ".join(f"{k} {v}" for k, v in asdict(cnt).items())
              + f", step_errors {node.step_errors}", file=sys.stderr)
    rec = node.recorder
    if rec is not None and rec.degraded:
        raise RecordingLostError(
            f"the recording is not the whole run: parts {', '.join(map(str, rec.parts))}; "
            f"{rec.lost_ticks} ticks and {rec.lost_frames} frames lost; " + "; ".join(rec.errors))
    return 0
