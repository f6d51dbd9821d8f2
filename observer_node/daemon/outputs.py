"""The daemon's outputs: the ChestEstimate frame every tick and the three status frames.

What each bit and value means on the bus comes from the DBC, by signal name: the estimate's
counter and flags are packed where the codec says, the observer's states are sent as the
DBC's value table names them, and each invalid cause or latched fault of the core goes to
the one-bit signal of that name (``Invalid_<Name>``, ``Fault_<Name>``).
"""

from __future__ import annotations

import math

from observer_node.dbc import Codec
from observer_node.dbc.meanings import CAUSE_SIGNALS, InvalidCause, RecorderState

from ..criteria import ChestCriteria
from ..recording.writer import Recorder
from .core import ObserverCore
from .inputs import Counters

# The core's cause bits (plain ints) and the names of their Invalid_/Fault_ signals
CAUSES = {bit.value: name for bit, name in CAUSE_SIGNALS.items()}
_NOT_ARMED = InvalidCause.NOT_ARMED.value


def wrap16(v: int) -> int:
    """Counters on the bus are free-running and wrap modulo 65536 (the DBC says so): a
    receiver takes differences modulo 65536 and never sees a counter stick."""
    return v & 0xFFFF


class Outputs:
    def __init__(self, codec: Codec, model_id: int):
        est = codec["ChestEstimate"]
        self.est_id, self.est_struct = est.frame_id, est.struct
        self.est_crc = est.locate("ChestEstimate_CRC")[0]
        self.est_cnt = est.locate("ChestEstimate_Counter")
        self.est_valid = est.locate("ChestEstimate_Valid")[:2]
        self.est_running = est.locate("ChestEstimate_Running")[:2]
        self.est_cr = est.locate("ChestAccelCR")[0]
        self.est_cd = est.locate("ChestDeflCD")[0]
        self.est_scale_cr = est.scale("ChestAccelCR")
        self.est_scale_cd = est.scale("ChestDeflCD")
        self.est_lo, self.est_hi = est.raw_range("ChestAccelCR")
        self.est_protect = est.e2e_protect
        self.est_modulus = est.counter_modulus
        self._est_counter = -1  # one step per frame built, and a frame is built to be sent
        self._slots = [0] * est.slots
        self._buf = bytearray(est.length)
        self.status, self.counters, self.health = (codec["ObserverStatus"],
                                                   codec["ObserverCounters"],
                                                   codec["ObserverHealth"])
        self.model_id = model_id
        self.criteria = codec["ChestCriteria"]
        self._criteria_counter = 0
        self._criteria_events = self.criteria.raw_range("CriteriaEvent")[1] + 1

    def estimate(self, core: ObserverCore, cr: float, cd: float, valid: bool,
                 running: bool) -> bytes:
        """The ChestEstimate frame to send now (CR and CD saturated to the signal). Its
        alive counter steps once per call: build a frame only to send it (a burst's earlier
        ticks and the watchdog's publishes are not ticks of a frame of their own), so that
        an E2E receiver rates every frame OK, none repeated or out of sequence."""
        lo, hi = self.est_lo, self.est_hi
        s = self._slots
        cs, csh, _ = self.est_cnt
        vs, vsh = self.est_valid
        rs, rsh = self.est_running
        s[cs] = s[vs] = s[rs] = s[self.est_crc] = 0
        n = self._est_counter + 1
        if n == self.est_modulus:
            n = 0
        self._est_counter = n
        s[cs] |= n << csh
        s[vs] |= valid << vsh
        s[rs] |= running << rsh
        s[self.est_cr] = min(max(round(cr / self.est_scale_cr), lo), hi)
        s[self.est_cd] = min(max(round(cd / self.est_scale_cd), lo), hi)
        buf = self._buf
        self.est_struct.pack_into(buf, 0, *s)
        self.est_protect(buf)
        return bytes(buf)

    def status_frames(self, core: ObserverCore, cnt: Counters, rec: Recorder | None,
                      counter: int) -> list[tuple[int, bytes]]:
        """ObserverStatus, ObserverCounters and ObserverHealth, E2E-protected (at the
        status period, off the per-tick path)."""
        lost = rec is not None and rec.degraded
        cause, faults = core.invalid_cause, core.faults
        status = {"ObserverState": int(core.state), "ModelId": self.model_id,
                  "TickOverruns": wrap16(cnt.overruns), "Fault_RecordingLost": int(lost)}
        for bit, name in CAUSES.items():
            status[f"Invalid_{name}"] = int(bool(cause & bit))
            if bit != _NOT_ARMED:  # a state, not a fault: never latched
                status[f"Fault_{name}"] = int(bool(faults & bit))
        counters = {"LostFrames": wrap16(cnt.lost + cnt.kernel_dropped),
                    "RejectedFrames": wrap16(cnt.rejected + cnt.unknown_id),
                    "BadE2EFrames": wrap16(cnt.bad_e2e)}
        health = {"RecorderState": int(RecorderState.OFF if rec is None else rec.state),
                  "ErrorFrames": wrap16(cnt.error_frames),
                  "RecorderLostTicks": wrap16(0 if rec is None else rec.lost_ticks),
                  "SensorFaults": wrap16(core.hold_timeouts + core.bias_faults
                                         + core.brs_jumps)}
        return [(fc.frame_id, fc.encode(values, counter)) for fc, values in
                ((self.status, status), (self.counters, counters), (self.health, health))]

    def criteria_frame(self, event: int, crit: ChestCriteria,
                       valid: bool = True) -> tuple[int, bytes]:
        """ChestCriteria of a finished event (E2E-protected, values saturated to the
        signals' ranges). ``ChestCriteria_Valid`` is 0 when the event's estimates were
        degraded (``valid`` false: see ObserverCore.finished_valid) or a criterion is not a
        finite number (sent as 0)."""
        fc = self.criteria
        values = {"ChestDeflMax": crit.cd_max_mm, "ChestAccel3ms": crit.cr_3ms_g,
                  "ViscousCritMax": crit.vc_max_m_s}
        for name, v in values.items():
            lo, hi = (r * fc.scale(name) for r in fc.raw_range(name))
            valid = valid and math.isfinite(v)
            values[name] = min(max(v, lo), hi) if math.isfinite(v) else 0.0
        values["CriteriaEvent"] = event % self._criteria_events
        values["ChestCriteria_Valid"] = int(valid)
        self._criteria_counter += 1
        return fc.frame_id, fc.encode(values, self._criteria_counter)
