"""The observer's per-tick logic, free of any I/O: arming, bias, trigger, stepping, validity.

States (published in ObserverStatus.ObserverState):

ARMED    the pulse is quiet; the accelerometer bias is the mean of the last ``bias_window_s``
         of pulse; the last ``pretrigger_s`` of inputs are kept in a ring.
RUNNING  from the trigger: bias-corrected deceleration >= ``trigger_g`` for ``trigger_ticks``
         ticks in a row. The observer starts from rest at the *onset* (the last tick before
         the trigger whose bias-corrected pulse was below ``onset_g``, at most
         ``pretrigger_s`` back), steps through the buffered ticks at once, then one step per
         tick, for ``event_s``. The BRS count at the onset is the angle reference.
HOLD     after the event: outputs 0 until the pulse has been quiet (|pulse| < ``quiet_g``)
         for ``rearm_s``; then ARMED again.

Validity: any fault (input timeout, bad CRC/counter, lost frame, value out of range, sensor
fault, bus error) marks the estimate invalid for the next ``recover_ticks`` ticks. Lost
accelerometer frames (alive-counter gaps) are bridged by stepping with the held pulse so the
observer keeps time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model.observer import LinearObserver

ARMED, RUNNING, HOLD, FAULT = 1, 2, 3, 4

# InvalidCause / ObserverFault bits (see the DBC)
ACCEL_TIMEOUT, BRS_TIMEOUT, BAD_E2E, LOST_FRAME, OUT_OF_RANGE, BUS_ERROR, SENSOR_FAULT = (
    1 << i for i in range(7))


@dataclass
class CoreConfig:
    trigger_g: float = 3.0
    trigger_ticks: int = 3
    onset_g: float = 0.5
    pretrigger_s: float = 0.02
    bias_window_s: float = 0.1
    event_s: float = 0.2
    quiet_g: float = 1.0
    rearm_s: float = 0.1
    recover_ticks: int = 5
    max_bridge_ticks: int = 10
    counts_per_rev: int = 96


class ObserverCore:
    """One instance per daemon. ``tick`` is called once per accelerometer sample."""

    def __init__(self, observer: LinearObserver, cfg: CoreConfig | None = None):
        self.obs = observer
        self.cfg = cfg or CoreConfig()
        fs = observer.fs_hz
        self.fs_hz = fs
        self.n_bias = max(1, round(self.cfg.bias_window_s * fs))
        self.n_pre = max(2, round(self.cfg.pretrigger_s * fs) + self.cfg.trigger_ticks + 1)
        self.n_event = round(self.cfg.event_s * fs)
        self.n_rearm = round(self.cfg.rearm_s * fs)
        # Preallocated rings: bias window and pre-trigger inputs.
        self._bias_ring = np.zeros(self.n_bias)
        self._pre_pulse = np.zeros(self.n_pre)  # raw deceleration, bias not removed
        self._pre_brs = np.zeros(self.n_pre)
        self.rad_per_count = 2 * math.pi / self.cfg.counts_per_rev
        self.reset()

    def reset(self) -> None:
        self.state = ARMED
        self.tick_index = -1
        self._bias_sum = 0.0
        self._bias_n = 0
        self._bias_i = 0
        self.bias_g = 0.0
        self._pre_i = 0
        self._pre_n = 0
        self._above = 0
        self._quiet = 0
        self.brs_count = 0.0
        self.brs_ref = 0.0
        self.event = -1
        self.events = 0
        self.onset_tick = -1
        self.run_ticks = 0
        self.cr_g = 0.0
        self.cd_mm = 0.0
        self.invalid_until = 0
        self.cause = 0  # causes active now (cleared when recovered)
        self.faults = 0  # latched since start
        self._last_pulse = 0.0
        self.obs.reset()

    # ------------------------------------------------------------------ inputs
    def set_brs(self, count: float, counts_per_rev: int) -> None:
        self.brs_count = count
        if counts_per_rev > 0:
            self.rad_per_count = 2 * math.pi / counts_per_rev

    def fault(self, cause: int) -> None:
        """An input fault: the estimate is invalid until ``recover_ticks`` good ticks."""
        self.cause |= cause
        self.faults |= cause
        self.invalid_until = self.tick_index + 1 + self.cfg.recover_ticks

    @property
    def valid(self) -> bool:
        return self.tick_index >= self.invalid_until

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
                self.state = HOLD
                self._quiet = 0
                self.event = -1
        else:  # HOLD
            self.cr_g = self.cd_mm = 0.0
            self._quiet = self._quiet + 1 if abs(decel_g - self.bias_g) < self.cfg.quiet_g else 0
            if self._quiet >= self.n_rearm:
                self.state = ARMED
                self._bias_n = self._bias_i = 0
                self._bias_sum = 0.0
                self._pre_n = 0

    def _step(self, decel_g: float) -> None:
        y = self.obs.step(decel_g - self.bias_g, (self.brs_count - self.brs_ref) *
                          self.rad_per_count)
        self.cr_g = y[0]
        self.cd_mm = y[1]

    def _armed(self, decel_g: float) -> None:
        self.cr_g = self.cd_mm = 0.0
        # Pre-trigger ring
        i = self._pre_i
        self._pre_pulse[i] = decel_g
        self._pre_brs[i] = self.brs_count
        self._pre_i = (i + 1) % self.n_pre
        if self._pre_n < self.n_pre:
            self._pre_n += 1
        # Trigger on the bias of the quiet window *before* this sample
        if self._bias_n and decel_g - self.bias_g >= self.cfg.trigger_g:
            self._above += 1
            if self._above >= self.cfg.trigger_ticks:
                self._start()
                return
        else:
            self._above = 0
            # Bias: running mean over the quiet window (a crash does not enter it)
            j = self._bias_i
            if self._bias_n == self.n_bias:
                self._bias_sum -= self._bias_ring[j]
            else:
                self._bias_n += 1
            self._bias_ring[j] = decel_g
            self._bias_sum += decel_g
            self._bias_i = (j + 1) % self.n_bias
            self.bias_g = self._bias_sum / self._bias_n

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
