"""The observer's per-tick logic, free of any I/O: arming, bias, trigger, stepping, validity.

It is designed as a restraint ECU's crash detection is: the accelerometer's zero is learned
whenever the pulse is quiet, so a zero shift left by one crash (a bent mount, a sensor that
took a shock) cannot blind it to the next one.

States (published in ObserverStatus.ObserverState):

ARMED    the bias is the mean of the last ``bias_window_s`` of pulse (samples at or above the
         trigger level are left out); the last ``pretrigger_s`` of inputs are kept in a ring.
RUNNING  from the trigger: bias-corrected deceleration >= ``trigger_g`` for ``trigger_ticks``
         ticks in a row. The observer starts from rest at the *onset* (the last tick before
         the trigger whose bias-corrected pulse was below ``onset_g``, at most
         ``pretrigger_s`` back), steps through the buffered ticks at once, then one step per
         tick, for ``event_s``. The BRS count at the onset is the angle reference.
HOLD     after the event: outputs 0. The pulse is *quiet* when its standard deviation over
         the last ``bias_window_s`` is below ``quiet_g``: its spread, not its distance to the
         old zero, because a crash may leave the sensor with a new zero. Once quiet, and at
         least ``rearm_s`` after the event, the bias is re-learned from that window and the
         observer is ARMED again. A pulse that is not quiet within ``hold_max_s`` is a sensor
         fault (counted in ``hold_timeouts``); the observer re-arms on the window's mean and
         stays flagged invalid until the pulse is quiet.

Validity: the estimate is valid only when the observer can see a crash or is stepping one:
ARMED with a learned, plausible bias, or RUNNING. HOLD is invalid (``NOT_ARMED``). Any
input fault (input timeout, bad CRC/counter, lost frame, value out of range, sensor fault,
bus error) marks the estimate invalid for the next ``recover_ticks`` ticks. A bias beyond
``bias_max_g`` is a sensor fault (``bias_faults`` counts the episodes). A BRS count that
moves faster than ``brs_max_rate_rad_s`` (no belt can) is a sensor fault, not an input: the
angle reference moves with it, so a counter reset between two tests is not a belt movement.
Lost accelerometer frames (alive-counter gaps) are bridged by stepping with the held pulse
so the observer keeps time. An accelerometer silent for longer than ``event_s`` ends a running
event (:meth:`end_event`, called by the daemon's watchdog): that is what separates two tests
replayed one after another (crash-replay's ``--gap``), and the next one re-arms on its own
quiet lead-in.

A finished event's criteria are valid (``finished_valid``) when every tick it stepped was
made of input samples received as sent: no input fault active at any of its ticks (from the
onset) other than a frame rejected by the E2E check (a bad CRC, repeated or stale counter
loses no sample by itself; a sample lost with it shows as a lost frame). Faults after its
last tick (the inputs falling silent at the end of a replayed test) do not count.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from observer_node.dbc.meanings import InvalidCause, ObserverState

if TYPE_CHECKING:  # the config is read before a model is: `observer-node` starts faster
    from ..model.nonlinear import NonlinearGreyBox
    from ..model.observer import LinearObserver

# The states as the DBC numbers them (IntEnum: compared at C speed)
ARMED, RUNNING, HOLD = ObserverState.ARMED, ObserverState.RUNNING, ObserverState.HOLD

# Causes of an invalid estimate (the DBC's Invalid_<Name> bits: dbc/meanings.py), as plain
# ints: the core ors them per tick, and an IntFlag's operators run Python code.
ACCEL_TIMEOUT, BRS_TIMEOUT, BAD_E2E, LOST_FRAME, OUT_OF_RANGE, BUS_ERROR, SENSOR_FAULT, \
    NOT_ARMED = (c.value for c in (
        InvalidCause.ACCEL_TIMEOUT, InvalidCause.BRS_TIMEOUT, InvalidCause.BAD_E2E,
        InvalidCause.LOST_FRAME, InvalidCause.OUT_OF_RANGE, InvalidCause.BUS_ERROR,
        InvalidCause.SENSOR_FAULT, InvalidCause.NOT_ARMED))
# Causes that mean an event's estimates were not made of every sample as sent
DEGRADING = ~(BAD_E2E | NOT_ARMED)


@dataclass
class CoreConfig:
    trigger_g: float = 3.0
    trigger_ticks: int = 3
    onset_g: float = 0.5
    pretrigger_s: float = 0.02
    bias_window_s: float = 0.1
    event_s: float = 0.2
    quiet_g: float = 1.0  # standard deviation of the pulse over the bias window
    rearm_s: float = 0.1  # shortest HOLD after an event
    hold_max_s: float = 2.0
    bias_max_g: float = 15.0  # beyond any zero a healthy sensor has, even after shocks
    # Real spindles reach ~2000 rad/s (campaign-a at 10 kHz: pretensioner and load-limiter
    # pay-out in FULL_002, R16_007); 5000 rad/s is 125 m/s of webbing on a 25 mm spool.
    brs_max_rate_rad_s: float = 5000.0
    recover_ticks: int = 5
    max_bridge_ticks: int = 10
    counts_per_rev: int = 96


class ObserverCore:
    """One instance per daemon. ``tick`` is called once per accelerometer sample."""

    def __init__(self, observer: LinearObserver | NonlinearGreyBox,
                 cfg: CoreConfig | None = None):
        self.obs = observer
        self.cfg = cfg or CoreConfig()
        fs = observer.fs_hz
        self.fs_hz = fs
        self.n_bias = max(2, round(self.cfg.bias_window_s * fs))
        self.n_pre = max(2, round(self.cfg.pretrigger_s * fs) + self.cfg.trigger_ticks + 1)
        self.n_event = round(self.cfg.event_s * fs)
        self.n_rearm = round(self.cfg.rearm_s * fs)
        self.n_hold_max = max(self.n_bias, self.n_rearm, round(self.cfg.hold_max_s * fs))
        self._quiet_var = self.cfg.quiet_g ** 2
        self._brs_max_step = self.cfg.brs_max_rate_rad_s / fs  # rad per tick
        # Preallocated rings: bias window and pre-trigger inputs.
        self._bias_ring = np.zeros(self.n_bias)
        self._pre_pulse = np.zeros(self.n_pre)  # raw deceleration, bias not removed
        self._pre_brs = np.zeros(self.n_pre)
        # The running event's estimates (for its injury criteria), and the last finished
        # event's: two buffers swapped at the event's end, so nothing is allocated.
        n_ev = self.n_event + self.n_pre
        self._ev = np.zeros((2, n_ev))
        self._done = np.zeros((2, n_ev))
        self._ev_n = 0
        self.finished: tuple[int, int] | None = None  # (event, ticks) not yet reported
        self.finished_valid = True  # the last finished event's criteria can be used
        self._ev_cause = 0  # input-fault causes since the running event started
        self.rad_per_count = 2 * math.pi / self.cfg.counts_per_rev
        self.hold_timeouts = 0
        self.bias_faults = 0
        self.brs_jumps = 0
        self.events_cut = 0
        self.reset()

    def reset(self) -> None:
        self.state: ObserverState = ARMED
        self.tick_index = -1
        self._clear_window()
        self.bias_g = 0.0
        self._pre_i = 0
        self._pre_n = 0
        self._above = 0
        self._hold = 0
        self._unsettled = False
        self._bias_bad = False
        self.brs_count = 0.0
        self._brs_tick = -1
        self._brs_seen = False
        self.brs_ref = 0.0
        self.event = -1
        self.events = 0
        self.onset_tick = -1
        self.run_ticks = 0
        self.cr_g = 0.0
        self.cd_mm = 0.0
        self.invalid_until = 0
        self.cause = 0  # input-fault causes active now (cleared when recovered)
        self.faults = 0  # latched since start
        self._last_pulse = 0.0
        self.obs.reset()

    # ------------------------------------------------------------------ inputs
    def set_brs(self, count: float, counts_per_rev: int) -> None:
        """A BRS count. A step no belt can make (a counter reset, a decoder glitch) is a
        sensor fault: the reference moves with it so the spindle angle stays continuous."""
        if counts_per_rev > 0:
            self.rad_per_count = 2 * math.pi / counts_per_rev
        if self._brs_seen:
            ticks = max(1, self.tick_index - self._brs_tick)
            step = count - self.brs_count
            if abs(step) * self.rad_per_count > self._brs_max_step * ticks:
                self.brs_jumps += 1
                self.brs_ref += step
                self.fault(SENSOR_FAULT)
        self._brs_seen = True
        self._brs_tick = self.tick_index
        self.brs_count = count

    def fault(self, cause: int) -> None:
        """An input fault: the estimate is invalid until ``recover_ticks`` good ticks."""
        self.cause |= cause
        self.faults |= cause
        self.invalid_until = self.tick_index + 1 + self.cfg.recover_ticks

    @property
    def armed(self) -> bool:
        """The observer can see a crash now or is stepping one."""
        if self.state == RUNNING:
            return True
        return self.state == ARMED and self._bias_n > 0 and not self._unsettled

    @property
    def valid(self) -> bool:
        return self.tick_index >= self.invalid_until and self.armed

    @property
    def invalid_cause(self) -> int:
        """The cause bits of an invalid estimate now (0 when valid)."""
        if self.valid:
            return 0
        return (self.cause if self.tick_index < self.invalid_until else 0) | \
            (0 if self.armed else NOT_ARMED)

    # ------------------------------------------------------------------ per tick
    def bridge(self, missing: int) -> None:
        """``missing`` accelerometer samples were lost: hold the last pulse for them."""
        self.fault(LOST_FRAME)
        for _ in range(min(missing, self.cfg.max_bridge_ticks)):
            self.tick(self._last_pulse, bridged=True)

    def tick(self, decel_g: float, bridged: bool = False) -> None:
        """One sample of deceleration (model convention, bias not removed). Updates
        ``cr_g``, ``cd_mm``, ``state``."""
        self.tick_index += 1
        if self.state == RUNNING:  # the faults since the last tick stand for this one
            self._ev_cause |= self.cause
        if not bridged:
            self._last_pulse = decel_g
            if self.tick_index >= self.invalid_until:
                self.cause = 0
        state = self.state
        if state == ARMED:
            self._armed(decel_g)
        elif state == RUNNING:
            self._step(decel_g)
            self.run_ticks += 1
            if self.run_ticks >= self.n_event:
                self._to_hold()
        else:
            self._holding(decel_g)

    def end_event(self) -> None:
        """The inputs stopped mid-event (the accelerometer silent for longer than an event):
        what follows is another test or another crash, not this one. Hold, and re-arm on
        the next quiet window."""
        if self.state == RUNNING:
            self.events_cut += 1
            self._to_hold()

    def _to_hold(self) -> None:
        """From RUNNING: the event is over; its estimates wait in ``finished_estimates``."""
        self._ev, self._done = self._done, self._ev
        self.finished = (self.event, self._ev_n)
        self.finished_valid = not self._ev_cause & DEGRADING
        self.state = HOLD
        self._hold = 0
        self.event = -1
        self._clear_window()

    def _clear_window(self) -> None:
        self._bias_n = self._bias_i = 0
        self._bias_sum = self._bias_sq = 0.0

    def _push(self, decel_g: float) -> None:
        """Add a sample to the bias window (running sum and sum of squares)."""
        j = self._bias_i
        if self._bias_n == self.n_bias:
            old = self._bias_ring[j]
            self._bias_sum -= old
            self._bias_sq -= old * old
        else:
            self._bias_n += 1
        self._bias_ring[j] = decel_g
        self._bias_sum += decel_g
        self._bias_sq += decel_g * decel_g
        j += 1
        if j == self.n_bias:
            j = 0
            # Once per window: recompute exactly, so rounding cannot accumulate over days.
            self._bias_sum = float(self._bias_ring.sum())
            self._bias_sq = float(self._bias_ring @ self._bias_ring)
        self._bias_i = j

    def _quiet(self) -> bool:
        n = self._bias_n
        if n < self.n_bias:
            return False
        mean = self._bias_sum / n
        return self._bias_sq / n - mean * mean < self._quiet_var

    def _learn_bias(self) -> None:
        self.bias_g = self._bias_sum / self._bias_n
        bad = abs(self.bias_g) > self.cfg.bias_max_g
        if bad:
            if not self._bias_bad:
                self.bias_faults += 1
            self.fault(SENSOR_FAULT)
        self._bias_bad = bad

    def _holding(self, decel_g: float) -> None:
        self.cr_g = self.cd_mm = 0.0
        self._hold += 1
        self._push(decel_g)
        quiet = self._quiet()
        if (quiet and self._hold >= self.n_rearm) or self._hold >= self.n_hold_max:
            if not quiet:  # never settled: re-arm all the same, a crash must not be missed
                self.hold_timeouts += 1
                self._unsettled = True
                self.fault(SENSOR_FAULT)
            self._learn_bias()
            self.state = ARMED
            self._pre_n = 0
            self._above = 0

    def _step(self, decel_g: float) -> None:
        y = self.obs.step(decel_g - self.bias_g, (self.brs_count - self.brs_ref) *
                          self.rad_per_count)
        self.cr_g = y[0]
        self.cd_mm = y[1]
        n = self._ev_n
        if n < self._ev.shape[1]:
            self._ev[0, n] = y[0]
            self._ev[1, n] = y[1]
            self._ev_n = n + 1

    def finished_estimates(self) -> tuple[np.ndarray, np.ndarray]:
        """CR [g] and CD [mm] of the last finished event, from its onset (views)."""
        n = self.finished[1] if self.finished else 0
        return self._done[0, :n], self._done[1, :n]

    def _armed(self, decel_g: float) -> None:
        self.cr_g = self.cd_mm = 0.0
        # Pre-trigger ring
        i = self._pre_i
        self._pre_pulse[i] = decel_g
        self._pre_brs[i] = self.brs_count
        self._pre_i = (i + 1) % self.n_pre
        if self._pre_n < self.n_pre:
            self._pre_n += 1
        # Trigger on the bias of the window *before* this sample
        if self._bias_n and decel_g - self.bias_g >= self.cfg.trigger_g:
            self._above += 1
            if self._above >= self.cfg.trigger_ticks:
                self._start()
            return
        self._above = 0
        # Bias: running mean over the window (a crash does not enter it)
        self._push(decel_g)
        self._learn_bias()
        if self._unsettled:
            if self._quiet():
                self._unsettled = False
            else:
                self.fault(SENSOR_FAULT)

    def _start(self) -> None:
        """Trigger: find the onset in the pre-trigger ring, start from rest there, catch up."""
        n = self._pre_n
        last = (self._pre_i - 1) % self.n_pre
        back = 0  # samples before the newest one
        while back + 1 < n:
            k = (last - back - 1) % self.n_pre
            if self._pre_pulse[k] - self.bias_g < self.cfg.onset_g:
                break
            back += 1
        start = (last - back) % self.n_pre
        self.onset_tick = self.tick_index - back
        self.brs_ref = self._pre_brs[start]
        self.obs.reset()
        self._ev_n = 0
        # faults still active stand for the buffered ticks stepped from the onset
        self._ev_cause = self.cause if self.tick_index < self.invalid_until else 0
        self.state = RUNNING
        self.event = self.events
        self.events += 1
        self.run_ticks = back + 1
        brs_now = self.brs_count
        for m in range(back + 1):
            k = (start + m) % self.n_pre
            self.brs_count = self._pre_brs[k]
            self._step(self._pre_pulse[k])
        self.brs_count = brs_now
