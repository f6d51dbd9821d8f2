"""Held-out set F: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-E (``cases.py`` ... ``cases_e.py``), which the loop's engineers
have looked at.

Against sets A-E: other seeds (15xxx), other sizes of each effect, and (estimation,
validation) pairings of (R16, SLED, FULL) counts no case of A-E ran. Every effect that acts on
some setups only rests on at least 2 estimation and 2 validation tests of those setups, beside
at least one test of a setup it does not act on. The broken tests fail ways a lab records and
a reviewer sees on the plot (a BRS counter resetting to zero mid-crash; mains hum on the CR
channel from a ground loop), and the transducer error is another (CD compressing smoothly at
large deflection, CR untouched). The issue's list makes 13 cases; the 14th is the second broken
test. No new physical form: the physics cases use forms of A-E at sizes none used; set F's new
forms are lab-side (recorded channels only).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set f``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-25, 2 busy cores): clean48 92.1, clean96 93.2; rib_bottoming
87.5 -> 89.3, rib_fluid 88.1 -> 90.9, webbing_hysteresis 91.4 -> 94.0, webbing_power 88.3 ->
93.8, airbag_vented 88.2 -> 90.6, pelvis 89.0 -> 93.6, two_effects 87.7 -> 92.8 (each alone:
the R16 valve 3.7, the SLED set 1.8), broken_brs_reset 89.6 -> 92.0 and broken_cr_hum 91.8 ->
91.8 (flagging the test is the verdict asked; the hum is zero-mean and costs the fit nothing),
cd_compress 86.9 -> 88.8, pulse_late_2p25ms 90.8 -> 92.5, brs_late_4p4ms 87.5 -> 91.7.
Changed after a first look at these costs, after the verdicts' commit and before any loop run
(same seeds, verdicts unchanged): two_effects was rib_valve 3000 on R16 with webbing_set 0.55
on SLED, cost 7.1; cd_compress was 50 mm, cost 0.2 (30 mm 1.1); the BRS reset was at 40 ms,
where the spool had paid in only 6 counts (cost -0.1, a reviewer could miss it), now at 70 ms
in the load limiter's pay-out.
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: pairings no case of A-E used
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M411 = ("R16", "R16", "R16", "R16", "SLED", "FULL")  # 4-1-1
M114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_F: list[Case] = [
    Case("hf_clean48", 15107, M222, M321, 48,
         notes="clean thorax, coarse 48-count BRS, even estimation, R16-heavy validation"),
    Case("hf_clean96", 15211, M132, M141, 96,
         notes="clean thorax, 96-count BRS, SLED-heavy"),
    Case("hf_rib_bottoming", 15313, M312, M123, 64,
         (Effect("rib_bottoming", 7.0e7),), (("chest_stiffening", "all"),),
         notes="ribs stiffen beyond 12 mm deflection, F += k (|d| - 12 mm)^2.5, k = 7e7 on "
               "every setup (A: 9e7 everywhere; D: 6e7 on FULL; B, D, E: cubic from zero; "
               "C, E: a kink at 16 mm)"),
    Case("hf_rib_fluid", 15419, M213, M141, 96,
         (Effect("rib_fluid", 6500.0),), (("chest_rate_damping", "all"),),
         notes="rate-stiffening rib damping material, F += c |d'|^2.2 sign(d') on each rib, "
               "c = 6500 (A: 8000 everywhere, 5000 on R16; B, E: |d'|^1.5; C, D: one-way)"),
    Case("hf_webbing_hysteresis", 15521, M123, M312, 128,
         (Effect("webbing_hysteresis", 0.5),), (("belt_unloading", "all"),),
         notes="the webbing unloads on a path 50 % softer than it loads (both segments, "
               "smooth in the rate) on every setup (B: 45 %; D: 60 % on FULL, 40 % on SLED; "
               "A: slack; C, E: a permanent set)"),
    Case("hf_webbing_power", 15627, M411, M222, 96,
         (Effect("webbing_power", 15.0),), (("belt_stiffening", "all"),),
         notes="webbing stiffens with the square of its stretch, F += a k e (e/e_ref)^2 at "
               "a = 15 (B: 6, 5; D: 11; A: exponential toe; C, E: a knee)"),
    Case("hf_airbag_vented", 15733, M222, M123, 64,
         (Effect("airbag", 0.6, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="vented driver bag beyond an 85 mm gap, fill 0.6 of set A's (A: 1.0; B, D, E: "
               "a relief vent; C, E: sealed), on both rigs with an interior; the R16 rig has "
               "none (1 R16 test per part)"),
    Case("hf_pelvis", 15839, M114, M231, 48,
         (Effect("lumbar_path", 0.55),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine, 0.55 x "
               "set A's lumbar and lap stiffness (A 1.0, B 0.6, C 1.5 and 0.8, D 0.45, E 0.7)"),
    Case("hf_two_effects", 15941, M231, M222, 96,
         (Effect("rib_valve", 2000.0, ("R16",)), Effect("webbing_set", 0.4, ("SLED",))),
         (("chest_rate_damping", "R16"), ("belt_unloading", "SLED")),
         notes="R16: the certification rig's dummy, its rib damping resisting compression "
               "only, F += c d'^2 while compressing (2000; C: 4000, D: 2200, everywhere); "
               "SLED: the rig's much-used webbing takes a permanent set, unloading to 40 % "
               "of its peak stretch (C: 50 %, E: 65 %, everywhere); 2 R16 and 2-3 SLED tests "
               "in each part, the FULL tests clean of both. Each alone costs 3.7 (R16) and "
               "1.8 (SLED), together 5.1"),
    Case("hf_broken_brs_reset", 15049, M321, M213, 96,
         (Effect("brs_reset", 0.070, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="SLED_003's BRS counter resets to zero at 70 ms (a supply glitch) and counts "
               "on from there: the spindle angle jumps back by the load limiter's pay-out so "
               "far (some 30 counts), every later count at its right size; physics clean"),
    Case("hf_broken_cr_hum", 15157, M411, M411, 96,
         (Effect("cr_hum", 6.0, tests=("R16_005",)),), (),
         expect_broken=("R16_005",),
         notes="R16_005's spine accelerometer picks up 50 Hz mains hum through a ground loop, "
               "6 g amplitude, from before the crash to the end (CFC 180 passes it): a sine "
               "on the flat pre-crash line; physics clean"),
    Case("hf_cd_compress", 15263, M123, M123, 96,
         (Effect("cd_compress", 25.0),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's signal conditioner works near its output range and "
               "compresses: CD reads 25 mm tanh(cd / 25 mm), 5 % low at 10 mm, 17 % at "
               "20 mm, 30 % at 30 mm (A: CD over-reading, B: a CD knee, D: CR compressing), "
               "CR and the inputs untouched: a residual in cd only, a static function of cd. "
               "At 50 mm (10 % low at 30 mm) it cost 0.2, at 30 mm 1.1: the plain structure "
               "absorbs a mild one"),
    Case("hf_pulse_late_2p25ms", 15369, M213, M114, 128,
         (Effect("pulse_late", 0.00225),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.25 ms after it is recorded (A-E: pulse 1.5, 2, "
               "2.75, 3.25, 3.5, 4, 4.25 ms; BRS 1, 2.5, 3, 3.75, 4.5, 4.75, 5 ms)"),
    Case("hf_brs_late_4p4ms", 15477, M321, M231, 48,
         (Effect("brs_late", 0.0044),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.4 ms after the BRS records it (no delay of A-E on "
               "either input)"),
]

BY_NAME_F = {c.name: c for c in SET_F}
