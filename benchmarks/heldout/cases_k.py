"""Held-out set K: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-J (``cases.py`` ... ``cases_j.py``), which the loop's engineers
have looked at.

Against sets A-J: other seeds (20xxx), other sizes of each effect, and (estimation, validation)
pairings of (R16, SLED, FULL) counts no case of A-J ran (every case's pairing is new, and no
two cases of K share one). Every effect that acts on some setups only rests on at least 2
estimation and 2 validation tests of those setups, beside tests of a setup it does not act on.
One physical class comes in a form no earlier set used, written from the physics
(``physics.EFFECTS``): a vented driver bag on a two-stage inflator, its second stage firing 30
ms after the first and adding 30 % of the first stage's gas over 8 ms just before the chest
reaches the bag (A-J: a vented bag, a pressure-relief vent, a sealed bag, a bag leaking through
its fabric, all on one charge). The other physical cases use forms of A-J at sizes none used.
Two effects share the same setups, one large (3.3 points alone) and one small (1.3 alone), of
two kinds that both stiffen the chest's load path (the ribs' second load path, the webbing's
knee). The broken test is the only estimation test of its setup and fails no channel check: its
sled carriage channel is another run's (the R16 and SLED sleds write the same channel code; the
export took the wrong run's file). The transducer error is on CR (A-J: mostly CD): the spine
accelerometer's zero shifts by 2 g under the loading's first hard rise, and stays shifted.

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set k``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-26, 2 busy cores; the cases changed after the first look measured
with the same make/identify/evaluate on the same seeds and mixes): clean48 90.5, clean96 92.4;
airbag_dual 86.3 -> 91.0, rib_bottoming 87.2 -> 89.6, webbing_power 88.6 -> 93.1, airbag_relief
90.2 -> 92.9, lumbar 86.6 -> 89.0, pulse_late_2p4ms 91.7 -> 93.5, brs_late_3p6ms 88.1 -> 90.4,
brs_eccentric 89.9 -> 92.1, two_effects_same 87.8 -> 92.2 (each alone: the ribs 3.3, the
webbing 1.3), broken_pulse_from 83.8 -> 93.0 (flagging the test is the verdict asked; left in,
it wrecks the fit), cr_zero_shift 90.4 -> 93.4, few_tests 87.8 -> 91.6. ("Each alone": the
other effect's size set to 0, every draw the same.)

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): airbag_relief was fill 0.65 on SLED, cost 8.9 (0.4 cost 5.1), so 0.25;
two_effects_same was the ribs' second path 1.8 with a webbing toe 2.0, both on R16+FULL, cost
17.4 (the ribs alone 5.6, the toe alone 10.3, a toe of 1.0 alone 9.0: an exponential toe on two
setups of three is steep), so the ribs at 1.0 (3.3 alone) and, as the small effect, a webbing
knee (1.0 alone cost 2.6), the knee at 0.5 (1.3 alone; the pair with a knee of 1.0 cost 5.6);
few_tests was rib valve damping 2600 on R16, cost 5.6, so 1700. The input_gain case was to be a
spool whose effective radius shrinks as the webbing pays out (``spool_buildup``, a thick or
doubled webbing on the spool of 17 mm radius: radius r0 + t th / 2 pi, the BRS's webbing per radian
changing by t / (2 pi r0) per radian): 2.4, 3.6 and 4.5 mm per wrap (0.022, 0.034 and 0.042 per
radian, the radius 7-30 % smaller at the 3-7 rad of pay-out) cost 0.0, 0.1 and 0.1 (the webbing
paid out, r0 th + t th^2 / 4 pi, is all but linear in the spool angle over one monotone
pay-out, most likely taken up in the belt's own parameters); not kept. In its place the encoder
ring off its spindle's centre (set A's form, the angle read with an error e sin(th)) at a size
A did not use, 0.2 rad (0.12 cost 0.9).
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: every (estimation, validation) pairing
# below is one no case of A-J ran
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M420 = ("R16", "R16", "R16", "R16", "SLED", "SLED")  # 4-2-0
M501 = ("R16", "R16", "R16", "R16", "R16", "FULL")  # 5-0-1
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1
M033 = ("SLED", "SLED", "SLED", "FULL", "FULL", "FULL")  # 0-3-3
M150 = ("R16", "SLED", "SLED", "SLED", "SLED", "SLED")  # 1-5-0
M024 = ("SLED", "SLED", "FULL", "FULL", "FULL", "FULL")  # 0-2-4
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M402 = ("R16", "R16", "R16", "R16", "FULL", "FULL")  # 4-0-2
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M330 = ("R16", "R16", "R16", "SLED", "SLED", "SLED")  # 3-3-0
M204 = ("R16", "R16", "FULL", "FULL", "FULL", "FULL")  # 2-0-4
V024 = M024
V042 = ("SLED", "SLED", "SLED", "SLED", "FULL", "FULL")  # 0-4-2
V033 = M033
V114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
V123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3
V240 = ("R16", "R16", "SLED", "SLED", "SLED", "SLED")  # 2-4-0
V222 = M222
V321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
V420 = M420
V402 = M402

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_K: list[Case] = [
    Case("hk_clean48", 20103, M222, V024, 48,
         notes="clean thorax, 48-count BRS, estimated on every rig, validated without R16"),
    Case("hk_clean96", 20207, M312, V042, 96,
         notes="clean thorax, 96-count BRS, R16-heavy estimation, validated without R16"),
    Case("hk_airbag_dual", 20311, M132, V033, 64,
         (Effect("airbag_dual", 0.45, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="both rigs with an interior carry a vented driver bag (set A's form, fill 0.45 "
               "of set A's) on a two-stage inflator: the second stage fires 30 ms after the "
               "first (46-50 ms here), just before the chest reaches the bag (51-62 ms), and "
               "adds 30 % of the first stage's gas over 8 ms while the vents go on venting: "
               "the chest meets a harder bag that vents faster (at fill 0.6, peak CR 5.3-5.7 "
               "g above a one-stage bag's). R16 has no interior and no bag (1 estimation "
               "test); 5 SLED+FULL estimation and 6 validation tests"),
    Case("hk_rib_bottoming", 20419, M420, V114, 96,
         (Effect("rib_bottoming", 1.0e8),), (("chest_stiffening", "all"),),
         notes="ribs stiffen beyond 12 mm deflection, F += k (|d| - 12 mm)^2.5, k = 1.0e8 "
               "N/m^2.5, every setup (A: 9e7, F: 7e7, H: 1.2e8, and 6e7 on FULL)"),
    Case("hk_webbing_power", 20521, M501, V123, 128,
         (Effect("webbing_power", 8.0),), (("belt_stiffening", "all"),),
         notes="webbing stiffens with stretch, F += a k e (e/e_ref)^2 (e_ref 15 mm chest "
               "side, 25 mm up to the retractor), a = 8, every setup (B: 6, D: 15, F: 11, "
               "5 on R16+SLED)"),
    Case("hk_airbag_relief", 20627, M231, V240, 96,
         (Effect("airbag_relief", 0.25, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a driver bag with a pressure-relief vent, fill 0.25 of set A's, on the sled "
               "with interior only (A-J: 0.3 on FULL, 0.5 on SLED, 0.55 and 0.8 on "
               "SLED+FULL); 3 SLED estimation and 4 validation tests beside 2 R16 and 1 FULL "
               "estimation and 2 R16 validation tests without a bag"),
    Case("hk_lumbar", 20729, M033, V222, 64,
         (Effect("lumbar_path", 0.65),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine, at 0.65 "
               "of set A's stiffness, every setup (A-J: 0.45, 0.55, 0.6, 0.7, 0.75, 0.8 on "
               "R16, 0.9, 1.0, 1.5); estimated without R16, validated on every rig"),
    Case("hk_pulse_late_2p4ms", 20833, M150, V114, 96,
         (Effect("pulse_late", 0.0024),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.4 ms after its record (A-J: 1.5, 2, 2.25, 2.6, "
               "2.75, 3 on FULL, 3.25, 3.5, 3.6, 3.9, 4, 4.25 ms); estimated without FULL"),
    Case("hk_brs_late_3p6ms", 20937, M024, V321, 48,
         (Effect("brs_late", 0.0036),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.6 ms after the BRS records it (A-J: BRS 1, 2.5, "
               "2.8, 3, 3.2, 3.4, 3.75, 4.1, 4.4, 4.5, 4.75, 5 ms); estimated without R16"),
    Case("hk_brs_eccentric", 20041, M213, V420, 128,
         (Effect("brs_eccentric", 0.2),), (("input_gain", "all"),),
         notes="the BRS's encoder ring sits off its spindle's centre: the angle is read with "
               "an error e sin(th + phase), e = 0.2 rad, so the BRS's gain (counts per radian "
               "of spool) drifts with the spool's angle, every setup (A: 0.3). (The spool's "
               "own radius shrinking with pay-out, spool_buildup, was tried first: see the "
               "module's docstring)"),
    Case("hk_two_effects_same", 20143, M402, V222, 96,
         (Effect("rib_bilinear", 1.0, ("R16", "FULL")),
          Effect("webbing_knee", 0.5, ("R16", "FULL"))),
         (("chest_stiffening", "R16+FULL"), ("belt_stiffening", "R16+FULL")),
         notes="R16 and FULL: the ribs' second load path adds 1.0 x their stiffness past "
               "16 mm (C: 1.3, E: 1.6, all setups), the large effect (3.3 alone); and the "
               "webbing's stiffness grows by 0.5 x its own past a knee (22 mm chest side, 16 "
               "mm up to the retractor; A-J: 1.2, 1.5 and 1.8 on some setups, 3-9 on all), the "
               "small one (1.3 alone): both stiffen the chest's load path as it loads; SLED "
               "clean of both (2 validation tests only). 6 R16+FULL estimation tests, 4 "
               "validation ones"),
    Case("hk_broken_pulse_from", 20247, M141, V402, 64,
         (Effect("pulse_from", 1.0, tests=("R16_001",)),), (), expect_broken=("R16_001",),
         notes="R16_001, the only R16 estimation test, carries SLED_001's sled carriage "
               "channel: both sleds write the channel S0SLED000000ACXP and the lab's export "
               "took the other run's file (one way: SLED_001 keeps its own). The channel is "
               "a whole, clean crash pulse (a car pulse, skewed, peak near 36 g at 38-48 ms "
               "and 14-15.6 m/s, where R16_001 ran a 13.6-14.4 m/s trapezoid): no channel "
               "check (frozen, saturated, dropout, spike) sees it, only the chest's response "
               "to it does; 4 R16 validation tests; the physics clean"),
    Case("hk_cr_zero_shift", 20353, M330, V123, 64,
         (Effect("cr_zero_shift", 2.0),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's zero shifts under the shock: once its reading "
               "first passes 20 g (the loading's hard rise, 25-44 ms) it moves by +2 g over 4 "
               "ms and stays there to the record's end (the chest's CR peaks at 27-32 g); CR "
               "reads 2 g high from then on, nothing before, every test; CD and the inputs "
               "untouched: a residual in cr only, a step at a level, not an offset from rest "
               "(A-J on CR: a gain, a soft clip, an over-read, a charge leak)"),
    Case("hk_few_tests", 20459, M204, M204, 48,
         (Effect("rib_valve", 1700.0, ("R16",)),), (("chest_rate_damping", "R16"),),
         notes="the certification lab's dummy only (R16): rib damping that resists "
               "compression only, F += c d'^2 while the chest closes, c = 1700 N/(m/s)^2 "
               "(A-J: 2000 on R16, 2200, 4000); 2 R16 estimation and 2 validation "
               "tests beside 4 and 4 clean FULL tests, no SLED"),
]

BY_NAME_K = {c.name: c for c in SET_K}
