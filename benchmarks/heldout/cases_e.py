"""Held-out set E: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A, B, C and D (``cases.py`` ... ``cases_d.py``), which the loop's
engineers have looked at.

Against sets A-D: other seeds (14047-14941), other sizes of each effect, and other setup mixes.
A-D between them used every split of six tests over the three setups in some part, so what is
new here is the pairing: no case of A-D ran its estimation and validation parts on the same
(R16, SLED, FULL) counts as any case here. Every effect that acts on some setups only rests on
at least 2 estimation and 2 validation tests of those setups, beside at least one test of a
setup it does not act on. The broken tests fail ways a lab records and a reviewer sees on the
plot (a CR cable parting mid-crash, a CR channel at the wrong polarity), and the transducer
error is another (CR over-reading progressively at high levels, CD untouched). The issue's list
makes 13 cases; the 14th is the second broken test. No new physical form: the physics cases
use forms of A-D at sizes none used; set E's new forms are lab-side (recorded channels only).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set e``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-25, 2 busy cores): clean48 88.7, clean96 92.5; rib_bilinear
89.1 -> 92.8, rib_visco 89.7 -> 91.6, webbing_set 88.4 -> 92.0, webbing_knee 87.6 -> 91.8,
airbag_sealed 91.9 -> 93.9, pelvis 88.0 -> 92.2, two_effects 89.4 -> 93.3 (each alone: the R16
ribs 2.7, the FULL bag 2.4), broken_cr_cable 68.5 -> 93.3 and broken_cr_reversed 86.6 -> 92.0
(flagging the test is the verdict asked; left in, each wrecks the fit), cr_progressive 89.1 ->
91.4, pulse_late_3p25ms 90.3 -> 92.5, brs_late_4p75ms 85.9 -> 89.9. Changed after a first look
at these costs, before any commit or loop run (same seeds): rib_bilinear 2.4 cost 6.0, 2.0 cost
5.3; two_effects was rib_hardening 2.2e8 on R16 with airbag_relief 0.7 on FULL, cost 11.7
(alone 8.9 and 7.6), then 1.2e8 with 0.5, cost 7.4 (alone 5.3 and 5.0); hardening 6e7 alone
cost 2.2, 8e7 3.3, relief 0.35 alone 3.0; the BRS delay was 4 ms (cost 2.8), a delay set A
used on the pulse, so 4.75 ms, a delay no set used on either input.
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: pairings no case of A-D used
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M411 = ("R16", "R16", "R16", "R16", "SLED", "FULL")  # 4-1-1
M330 = ("R16", "R16", "R16", "SLED", "SLED", "SLED")  # 3-3-0
M123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3
M321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M420 = ("R16", "R16", "R16", "R16", "SLED", "SLED")  # 4-2-0
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
M240 = ("R16", "R16", "SLED", "SLED", "SLED", "SLED")  # 2-4-0
M033 = ("SLED", "SLED", "SLED", "FULL", "FULL", "FULL")  # 0-3-3

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_E: list[Case] = [
    Case("he_clean48", 14101, M222, M411, 48,
         notes="clean thorax, coarse 48-count BRS, even estimation, R16-heavy validation"),
    Case("he_clean96", 14203, M330, M330, 96,
         notes="clean thorax, 96-count BRS, R16 and SLED only"),
    Case("he_rib_bilinear", 14311, M123, M321, 96,
         (Effect("rib_bilinear", 1.3),), (("chest_stiffening", "all"),),
         notes="ribs take up a second load path beyond 16 mm deflection, each rib's stiffness "
               "grows by 1.3 x its own beyond it (C: 1.6; A: power 2.5 past 12 mm; B, D: "
               "cubic from zero)"),
    Case("he_rib_visco", 14419, M231, M231, 64,
         (Effect("rib_visco", 3800.0),), (("chest_rate_damping", "all"),),
         notes="rib damping material with a power-1.5 rate law, F += c |d'|^1.5 sign(d') on "
               "each rib, at 1.5 x set B's c (A: |d'|^2.2; C, D: one-way d'^2)"),
    Case("he_webbing_set", 14521, M321, M321, 128,
         (Effect("webbing_set", 0.65),), (("belt_unloading", "all"),),
         notes="chest-side webbing takes a permanent set: past its peak stretch it unloads on "
               "a straight line to 65 % of that peak, no force below (C: 50 %; A: slack; "
               "B, D: a softer unloading path)"),
    Case("he_webbing_knee", 14627, M141, M141, 96,
         (Effect("webbing_knee", 7.0),), (("belt_stiffening", "all"),),
         notes="bilinear webbing, 8 x stiffer beyond 22 mm stretch chest side and 16 mm up to "
               "the retractor (C: 4 x, 3.0; A: exponential toe; B, D: cubic)"),
    Case("he_airbag_sealed", 14733, M222, M312, 96,
         (Effect("airbag_sealed", 0.45, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="unvented driver bag (the gas only compresses), fill 0.45 of set A's, on both "
               "rigs with an interior (C: 0.7 on FULL only); the R16 rig has none"),
    Case("he_pelvis", 14839, M420, M420, 64,
         (Effect("lumbar_path", 0.7),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine, 0.7 x "
               "set A's lumbar and lap stiffness (A 1.0, B 0.6, C 1.5 and 0.8, D 0.45)"),
    Case("he_two_effects", 14941, M213, M213, 96,
         (Effect("rib_hardening", 7e7, ("R16",)), Effect("airbag_relief", 0.3, ("FULL",))),
         (("chest_stiffening", "R16"), ("airbag_contact", "FULL")),
         notes="R16: the certification rig's dummy, its ribs hardening from zero, F += k3 d^3 "
               "(7e7, B: 1e8, D: 1.5e8, everywhere); FULL: the car's driver bag with a "
               "pressure-relief vent, fill 0.3 (B: 0.8 on SLED+FULL, D: 0.5 on SLED); 2 R16 "
               "and 3 FULL tests in each part, the one SLED test clean of both. Each alone "
               "costs 2.7 (R16) and 2.4 (FULL), together 3.9"),
    Case("he_broken_cr_cable", 14047, M132, M213, 96,
         (Effect("cr_cable_break", 0.046, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="SLED_003's spine accelerometer cable parts at 46 ms, near the chest's peak: "
               "the raw CR reads 0 g (the open bridge) from then to the end (CFC 180 after); "
               "physics clean"),
    Case("he_broken_cr_reversed", 14157, M114, M114, 128,
         (Effect("cr_reversed", 1.0, tests=("FULL_005",)),), (),
         expect_broken=("FULL_005",),
         notes="FULL_005's spine accelerometer recorded at the wrong polarity (its sign "
               "entered wrong in the recorder): the chest's retardation reads as an "
               "acceleration of -20 to -40 g, every sample its right size; physics clean"),
    Case("he_cr_progressive", 14263, M240, M240, 64,
         (Effect("cr_progressive", 0.10),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer over-reads progressively: CR reads "
               "cr (1 + 0.10 (cr / 25 g)^2), 1 % high at 8 g, 10 % at 25 g, 14 % at 30 g "
               "(B: a CR gain; D: CR compressing; A, B: CD non-linear), CD and the inputs "
               "untouched: a residual in cr only, a static function of cr"),
    Case("he_pulse_late_3p25ms", 14369, M033, M033, 128,
         (Effect("pulse_late", 0.00325),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.25 ms after it is recorded (A-D: pulse 1.5, 2, "
               "2.75, 3.5, 4, 4.25 ms; BRS 1, 2.5, 3, 3.75, 4.5, 5 ms)"),
    Case("he_brs_late_4p75ms", 14477, M411, M114, 48,
         (Effect("brs_late", 0.00475),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.75 ms after the BRS records it (A-D: BRS 1, 2.5, "
               "3, 3.75, 4.5, 5 ms; no delay of either input used before)"),
]

BY_NAME_E = {c.name: c for c in SET_E}
