"""Held-out set W: fourteen new cases the loop has never seen (DRAFT: sizes being costed)."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_W: list[Case] = [
    Case("hw_clean48", 32103, _mix(4, 0, 2), _mix(6, 0, 0), 48,
         notes="clean thorax, 48-count BRS; validated on R16 alone; SLED never run"),
    Case("hw_clean96", 32207, _mix(0, 4, 2), _mix(6, 0, 0), 96,
         notes="clean thorax, 96-count BRS; validated on R16 alone, never estimated there"),
    Case("hw_bumper_r16_sled", 32309, _mix(4, 0, 2), _mix(0, 6, 0), 48,
         (Effect("rib_bumper", 1.5e7, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="bumper"),
    Case("hw_squeeze_sled_full", 32411, _mix(3, 3, 0), _mix(1, 3, 2), 64,
         (Effect("rib_squeeze", 450.0, ("SLED", "FULL")),),
         (("chest_rate_damping", "SLED+FULL"),),
         notes="squeeze"),
    Case("hw_hysteresis_all", 32513, _mix(0, 3, 3), _mix(1, 0, 5), 128,
         (Effect("webbing_hysteresis", 0.57),), (("belt_unloading", "all"),),
         notes="hysteresis"),
    Case("hw_toe_r16_full", 32617, _mix(0, 2, 4), _mix(6, 0, 0), 96,
         (Effect("webbing_toe", 0.13, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="toe"),
    Case("hw_airbag_dual_full", 32719, _mix(3, 0, 3), _mix(0, 3, 3), 96,
         (Effect("airbag_dual", 0.3, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="dual"),
    Case("hw_lumbar_sled", 32823, _mix(3, 3, 0), _mix(0, 6, 0), 96,
         (Effect("lumbar_path", 0.4, ("SLED",)),), (("pelvis_coupling", "SLED"),),
         notes="lumbar"),
    Case("hw_eccentric_sled", 32927, _mix(2, 4, 0), _mix(0, 5, 1), 48,
         (Effect("brs_eccentric", 0.32, ("SLED",)),), (("input_gain", "SLED"),),
         notes="eccentric"),
    Case("hw_two_slack_sled_lumbar_full", 32031, _mix(0, 4, 2), _mix(0, 3, 3), 48,
         (Effect("webbing_slack", 1.0, ("SLED",)), Effect("lumbar_path", 0.38, ("FULL",))),
         (("belt_unloading", "SLED"), ("pelvis_coupling", "FULL")),
         notes="two"),
    Case("hw_pulse_late_1p10ms", 32137, _mix(0, 4, 2), _mix(4, 1, 1), 48,
         (Effect("pulse_late", 0.0011),), (("input_delay", "all"),),
         notes="pulse late"),
    Case("hw_brs_late_1p48ms", 32241, _mix(2, 4, 0), _mix(1, 0, 5), 128,
         (Effect("brs_late", 0.00148),), (("input_delay", "all"),),
         notes="brs late"),
    Case("hw_cd_sag", 32343, _mix(0, 0, 6), _mix(2, 2, 2), 48,
         (Effect("cd_sag", 0.2),), (), expect_note=UNEXPLAINED_CD,
         notes="cd sag"),
    Case("hw_broken_brs_reversed", 32447, _mix(4, 0, 2), _mix(1, 3, 2), 128,
         (Effect("brs_reversed", 1.0, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="brs reversed"),
]

BY_NAME_W = {c.name: c for c in SET_W}
ONE_PHYSICAL_W = ("hw_bumper_r16_sled", "hw_squeeze_sled_full", "hw_hysteresis_all",
                  "hw_toe_r16_full", "hw_airbag_dual_full", "hw_lumbar_sled", "hw_eccentric_sled")
