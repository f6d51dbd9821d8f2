"""Held-out set G: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-F (``cases.py`` ... ``cases_f.py``), which the loop's engineers
have looked at.

Against sets A-F: other seeds (16xxx), other sizes of each effect, and (estimation,
validation) pairings of (R16, SLED, FULL) counts no case of A-F ran. Every effect that acts on
some setups only rests on at least 2 estimation and 2 validation tests of those setups, beside
at least one test of a setup it does not act on. The broken tests fail ways a lab records and
a reviewer sees on the plot (a CD conditioner saturating: a flat top; a pulse channel whose
recorder triggered on its own, its pulse starting 10 ms before time zero), and the transducer
error is another (a dead band in the chest pot's linkage, CR untouched). The issue's list
makes 13 cases; the 14th is the second broken test. No new physical form: the physics cases
use forms of A-F at sizes none used; set G's new forms are lab-side (recorded channels only).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set g``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-25, 2 busy cores): clean48 91.8, clean96 92.0; rib_hardening 88.8
-> 92.8, rib_visco 89.9 -> 92.1, webbing_hysteresis 85.2 -> 90.7, webbing_knee 86.7 -> 91.0,
airbag_sealed 87.9 -> 91.9, pelvis 89.0 -> 92.1, two_effects 85.9 -> 91.3 (each alone: the SLED
damping 1.8, the FULL knee 3.4), broken_cd_rail 92.1 -> 91.7 (flagging the test is the verdict
asked; one clipped top among six estimation tests barely moves the fit) and broken_pulse_sync
85.2 -> 91.5 (left in, it wrecks the fit), cd_dead_band 88.9 -> 92.4, pulse_late_3p9ms 87.5 ->
92.1, brs_late_3p4ms 88.5 -> 89.9. Changed after a first look at these costs, before the
verdicts' commit and any loop run (same seeds): airbag_sealed 0.6 cost 7.3, 0.5 5.6;
two_effects was rib_fluid 9500 on SLED with webbing_power 9 on FULL, cost 25.4 (alone 18.5 and
13.7; webbing_power on FULL alone cost 6.2 at 0.5 and 11.2 at 3: a power law on one setup's
webbing is steep), rib_fluid 3000 alone 7.5; with a 2.0 knee the pair cost 6.0 (the knee alone
4.1).
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: pairings no case of A-F used
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1
M114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M411 = ("R16", "R16", "R16", "R16", "SLED", "FULL")  # 4-1-1
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
M123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_G: list[Case] = [
    Case("hg_clean48", 16103, M222, M141, 48,
         notes="clean thorax, coarse 48-count BRS, even estimation, SLED-heavy validation"),
    Case("hg_clean96", 16207, M312, M231, 96,
         notes="clean thorax, 96-count BRS"),
    Case("hg_rib_hardening", 16311, M114, M312, 64,
         (Effect("rib_hardening", 1.2e8),), (("chest_stiffening", "all"),),
         notes="ribs harden from zero, F += k3 d^3 on each rib, k3 = 1.2e8 N/m^3 on every "
               "setup (B: 1e8, D: 1.5e8, E: 7e7 on R16; A, F: power 2.5 past 12 mm; C, E: a "
               "kink at 16 mm)"),
    Case("hg_rib_visco", 16417, M132, M411, 96,
         (Effect("rib_visco", 5500.0),), (("chest_rate_damping", "all"),),
         notes="rib damping material with a power-1.5 rate law, F += c |d'|^1.5 sign(d') on "
               "each rib, c = 5500 (B: 2500, E: 3800; A, F: |d'|^2.2; C, D, F: one-way)"),
    Case("hg_webbing_hysteresis", 16523, M213, M321, 128,
         (Effect("webbing_hysteresis", 0.7),), (("belt_unloading", "all"),),
         notes="the webbing unloads on a path 70 % softer than it loads (both segments, "
               "smooth in the rate) on every setup (B: 45 %, D: 60 % and 40 %, F: 50 %; A: "
               "slack; C, E, F: a permanent set)"),
    Case("hg_webbing_knee", 16627, M141, M114, 96,
         (Effect("webbing_knee", 5.0),), (("belt_stiffening", "all"),),
         notes="bilinear webbing, 6 x stiffer beyond 22 mm stretch chest side and 16 mm up to "
               "the retractor (C: 3.0 and 1.2 on FULL, E: 7.0; A: exponential toe; B, D, F: "
               "cubic)"),
    Case("hg_airbag_sealed", 16733, M321, M132, 64,
         (Effect("airbag_sealed", 0.4, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="unvented driver bag (the gas only compresses), fill 0.4 of set A's vented "
               "one, on both rigs with an interior (C: 0.7 on FULL, E: 0.45; A, F: vented; B, "
               "D, E: a relief vent); the R16 rig has none (3 R16 estimation tests, 1 "
               "validation)"),
    Case("hg_pelvis", 16839, M231, M411, 48,
         (Effect("lumbar_path", 0.9),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine, 0.9 x "
               "set A's lumbar and lap stiffness (A 1.0, B 0.6, C 1.5 and 0.8, D 0.45, E 0.7, "
               "F 0.55)"),
    Case("hg_two_effects", 16941, M123, M222, 96,
         (Effect("rib_fluid", 1000.0, ("SLED",)), Effect("webbing_knee", 1.5, ("FULL",))),
         (("chest_rate_damping", "SLED"), ("belt_stiffening", "FULL")),
         notes="SLED: the sled lab's dummy, its rib damping material rate-stiffening, "
               "F += c |d'|^2.2 sign(d') (1000; A: 8000 everywhere, 5000 on R16, F: 6500); "
               "FULL: the production car's own webbing, bilinear, 2.5 x stiffer beyond 22 mm "
               "stretch chest side and 16 mm up to the retractor (C: 1.2 on FULL, 3.0; E: "
               "7.0); 2 SLED and 2-3 FULL tests in each part, the R16 tests clean of both. "
               "Each alone costs 1.8 (SLED) and 3.4 (FULL), together 5.4"),
    Case("hg_broken_cd_rail", 16049, M123, M411, 96,
         (Effect("cd_rail", 22.0, tests=("FULL_003",)),), (),
         expect_broken=("FULL_003",),
         notes="FULL_003's chest-pot conditioner was set up for a smaller transducer: the raw "
               "CD saturates at 22 mm, a flat top over the chest's peak (CFC 600 after); the "
               "other channels and the physics clean"),
    Case("hg_broken_pulse_sync", 16153, M312, M114, 96,
         (Effect("pulse_sync", 0.010, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="R16_003's sled accelerometer went to a second recorder that triggered on its "
               "own contact: its time base is 10 ms early, the pulse rising 10 ms before time "
               "zero, on the pre-crash line the other tests keep flat; physics clean"),
    Case("hg_cd_dead_band", 16263, M231, M213, 64,
         (Effect("cd_dead_band", 3.0),), (), expect_note=UNEXPLAINED_CD,
         notes="slack in the chest pot's linkage, held one way by its return spring: CD reads "
               "nothing over the first 3 mm of deflection and 3 mm low beyond (A: CD "
               "over-reading, B: a CD knee, F: CD compressing; D: a CD gain cost nothing), CR "
               "and the inputs untouched: a residual in cd only, a static function of cd, "
               "zero at rest (not a zero offset)"),
    Case("hg_pulse_late_3p9ms", 16369, M141, M222, 128,
         (Effect("pulse_late", 0.0039),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.9 ms after it is recorded (A-F: pulse 1.5, 2, "
               "2.25, 2.75, 3.25, 3.5, 4, 4.25 ms; BRS 1, 2.5, 3, 3.75, 4.4, 4.5, 4.75, 5 ms)"),
    Case("hg_brs_late_3p4ms", 16477, M114, M132, 48,
         (Effect("brs_late", 0.0034),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.4 ms after the BRS records it (no delay of A-F on "
               "either input)"),
]

BY_NAME_G = {c.name: c for c in SET_G}
