"""Held-out set M: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-L (``cases.py`` ... ``cases_l.py``), which the loop's engineers
have looked at.

What set M judges is scope: on which rigs (R16, SLED, FULL) an effect is named when the
estimation tests hold a rig thinly or not at all. Every expected verdict names the rigs the
effect truly acts on ("all" for all three), whatever the estimation tests hold of them; how a
rig with too few estimation tests counts is the scoring's business, not the truth's.

Against sets A-L: other seeds (22xxx), other sizes of each effect, and (estimation,
validation) pairings of (R16, SLED, FULL) counts no case of A-L ran. The scope cases: an effect
on one rig only, holding 2 of the 6 estimation tests (the car's own webbing stiffening, FULL;
A-L's few-tests cases: rib damping on R16, a bag on SLED) and one holding 3 (the R16 lab's
dummy's rib cage stiffening, R16); an effect on two rigs beside a third with no estimation test
and 2 validation tests (the sled labs' webbing taking a set, R16+SLED; FULL clean) and one
beside a third with exactly one estimation test (a bag, SLED+FULL; R16 clean); an effect on all
three rigs with one rig estimated by none (viscoelastic ribs, no R16 estimation test, 2 R16
validation tests) and one with one rig estimated by a single test (the pelvis path, 1 SLED
estimation test); two effects of different kinds on different rigs (rib damping on R16, an
unvented bag on FULL, SLED clean); and the capstan below on FULL only (4 of 6 estimation tests).

Two physical forms no earlier set used, written from the physics (``physics.EFFECTS``):
viscoelastic rib material (``rib_maxwell``): beside each rib's spring and damper a Maxwell
branch, a spring of 1.5 x the rib's stiffness in series with a dashpot relaxing in 10 ms (a
standard linear solid: stiff to a fast load, a damper to a slow one; A-L's rate damping was
memoryless: power laws, a valve, a squeeze film); and D-ring friction as a capstan
(``dring_capstan``): the shoulder webbing wraps the car's D-ring, the chest side carrying the
retractor side's tension x exp(mu theta) while the chest draws webbing out, x exp(-mu theta)
while the retractor takes it back, mu theta = 0.5, in place of the nominal small linear
friction (A-L: the nominal D-ring friction only). The capstan is a friction hysteresis of the
belt's load path between loading and unloading, named as set B's webbing hysteresis is
(belt_unloading). On all three rigs at 0.5 it cost the grey-box nothing (-0.0, also with a
stick speed of 0.03 m/s instead of 0.15): on every rig alike its loading gain is taken up in
the belt's parameters; so it acts on FULL only (the car's own steel D-ring; the sleds' lab
D-rings are low-friction rollers). Above mu theta 0.6 the lumped belt mass's damping, scaled by
exp(mu theta), leaves the 20 kHz RK4's stability (0.8 diverged): 0.5 is the largest size.

The broken test fails no channel check: SLED_003, an estimation test, ran with the lab's small
female dummy (a Hybrid III 5th percentile, length scale 0.86 of the 50th male: masses x 0.64,
stiffnesses x 0.86, dampings x 0.74 by geometric similitude) while its file, made from the
campaign's template, names the 50th male; its channels are whole and clean, its chest answers
as a smaller chest does (A-L: every broken test a recording fault; none a physical test of
another dummy). The transducer error is on CR: the recorder's multiplexed digitiser samples CR
right after CD and its sample-and-hold has too little time to settle, so CR keeps a share of
CD's signal, 0.15 g per mm of CD (about 4-5 g at peak deflection), every test; CD and the
inputs read right (A-L on CR: a gain, a soft clip, an over-read, a charge leak, a zero shift, a
loose mount; none a crosstalk from another channel).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set m``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26, 2 busy cores, one cost job at a time, the committed
seeds and mixes): clean48 91.5, clean96 92.1; webbing_power_full 86.7 -> 91.0 (4.3),
rib_fung_r16 89.6 -> 92.7 (3.2), webbing_set_sleds 88.8 -> 91.5 (2.8), rib_maxwell 90.4 ->
93.5 (3.1), airbag_one_r16 84.8 -> 90.4 (5.6), lumbar_one_sled 89.4 -> 91.3 (1.9),
two_effects_apart 86.3 -> 92.0 (5.7; the damping alone 2.6, the bag alone 2.4), broken_dummy
83.0 -> 89.8 (6.8; flagging the test is the verdict asked; left in, it moves the fit),
cr_crosstalk 86.4 -> 89.7 (3.3), pulse_late_4p6ms 89.8 -> 93.2 (3.4), brs_late_1p5ms 90.6 ->
91.1 (0.5: below the 1-point bar, see below), dring_capstan 90.1 -> 91.8 (1.7). ("Alone": the
other effect's size set to 0, every draw the same.)

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes unless said): webbing_power_full was 10 on FULL, cost 9.6 (3.5: 7.4, 1.5: 5.2),
so 1.0; rib_fung_r16 was 0.4, cost 7.1, so 0.2; rib_maxwell was 0.6, cost 0.9 (2.5: 5.0), so
1.5; two_effects_apart was rib damping 3500 on R16 with an unvented bag of fill 0.5 on FULL,
cost 18.8, then 1200 and 0.35, cost 10.0 (alone 5.6 and 3.8), so 600 and 0.25; broken_dummy
was a larger dummy (a 95th percentile male, length scale 1.08), cost -0.8 (the fit a little
better with it than without), so the small female (0.86); the transducer error was first CR
filtered at CFC 60 where its file states CFC 180 (a zero-phase low-pass), cost -0.1, taken out
of the simulator; the crosstalk at 0.10 g/mm cost 1.7, at 0.20 4.9, so 0.15. The BRS delay was
1.3 ms on estimation 0-2-4 / validation 2-2-2, cost 0.2; 1.5 ms on the same mixes cost 0.4, on
estimation 4-2-0 (R16-heavy, same validation) 0.1, on estimation 2-2-2 / validation 1-5-0
0.5: no mix tried brought a BRS delay within the brief's 1.0-1.5 ms to the 1-point bar, and
the case keeps the brief's range (1.5 ms, the last mix) rather than the bar; a loop that does
not name it here has not missed a visible effect. dring_capstan was on all three rigs at 0.5
(estimation 1-1-4, validation 4-2-0), cost 0.0 (-0.0 with a stick speed of 0.03 m/s; 0.8
diverged, see above), so on FULL only, validated 0-2-4 (0.5: 1.7, 0.3: 0.9). airbag_one_r16,
lumbar_one_sled, webbing_set_sleds and pulse_late_4p6ms are as first written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_M: list[Case] = [
    Case("hm_clean48", 22103, _mix(2, 4, 0), _mix(1, 2, 3), 48,
         notes="clean thorax, 48-count BRS, no FULL estimation test and 3 FULL validation "
               "tests"),
    Case("hm_clean96", 22207, _mix(3, 1, 2), _mix(2, 4, 0), 96,
         notes="clean thorax, 96-count BRS, estimated on every rig, validated without FULL"),
    Case("hm_webbing_power_full", 22311, _mix(1, 3, 2), _mix(0, 2, 4), 64,
         (Effect("webbing_power", 1.0, ("FULL",)),), (("belt_stiffening", "FULL"),),
         notes="the car's own belt (FULL) only: its webbing stiffens with stretch, F += a k e "
               "(e/e_ref)^2 (e_ref 15 mm chest side, 25 mm up to the retractor), a = 1.0 (A-L: "
               "5 on R16+SLED, 6, 8, 11, 15 on all); the sleds run the lab's belt. FULL holds "
               "2 of the 6 estimation tests (beside 1 R16 and 3 SLED) and 4 of the 6 "
               "validation tests (beside 2 SLED)"),
    Case("hm_rib_fung_r16", 22419, _mix(3, 2, 1), _mix(4, 0, 2), 96,
         (Effect("rib_fung", 0.2, ("R16",)),), (("chest_stiffening", "R16"),),
         notes="the R16 certification lab's own dummy only: its rib cage stiffens "
               "exponentially (Fung's law, set J's form), amount 0.2 (J: 0.25 on all); the "
               "sled and full-scale labs' dummies are clean. R16 holds 3 of the 6 estimation "
               "tests (beside 2 SLED and 1 FULL) and 4 of the 6 validation tests (beside 2 "
               "FULL)"),
    Case("hm_webbing_set_sleds", 22523, _mix(3, 3, 0), _mix(2, 2, 2), 64,
         (Effect("webbing_set", 0.48, ("R16", "SLED")),), (("belt_unloading", "R16+SLED"),),
         notes="the sled labs' webbing stock (R16 and SLED) takes a permanent set, unloading "
               "to 0.48 of its peak stretch (A-L: 0.35-0.65, none 0.48); the car's own belt "
               "(FULL) is clean, and FULL has no estimation test: 2 FULL validation tests "
               "beside 6 R16+SLED estimation and 4 validation tests"),
    Case("hm_rib_maxwell", 22627, _mix(0, 4, 2), _mix(2, 2, 2), 128,
         (Effect("rib_maxwell", 1.5),), (("chest_rate_damping", "all"),),
         notes="viscoelastic rib material, every rig: each rib carries a Maxwell branch, a "
               "spring of 1.5 x the rib's stiffness in series with a dashpot relaxing in 10 "
               "ms (a new form: see the module's docstring). R16 has no estimation test "
               "(2 R16 validation tests); the verdict is every rig, where the effect is"),
    Case("hm_airbag_one_r16", 22729, _mix(1, 3, 2), _mix(2, 0, 4), 96,
         (Effect("airbag", 0.5, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="a vented driver bag (set A's form) at fill 0.5 of set A's (A: 1.0, F: 0.6, "
               "L: 0.42 on SLED+FULL, H: 0.4 on FULL, L: 0.9 on SLED) on the rigs with an "
               "interior; R16 has none and exactly one estimation test (beside 3 SLED and 2 "
               "FULL), and 2 validation tests (beside 4 FULL)"),
    Case("hm_lumbar_one_sled", 22831, _mix(2, 1, 3), _mix(0, 3, 3), 48,
         (Effect("lumbar_path", 0.85),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine, at 0.85 "
               "of set A's stiffness (A-L: 0.45-1.5, none 0.85), every rig; SLED holds "
               "exactly one estimation test (beside 2 R16 and 3 FULL) and 3 validation tests; "
               "the verdict is every rig, where the effect is"),
    Case("hm_two_effects_apart", 22937, _mix(2, 2, 2), _mix(4, 0, 2), 64,
         (Effect("rib_fluid", 600.0, ("R16",)), Effect("airbag_sealed", 0.25, ("FULL",))),
         (("chest_rate_damping", "R16"), ("airbag_contact", "FULL")),
         notes="two kinds on two rigs: the R16 lab's dummy's rib damping material stiffens "
               "with rate, F += c |d'|^2.2 sign(d'), c = 600 (A-L: 1000-8000), and the car's "
               "own bag (FULL) is unvented, fill 0.25 of the vented one's (A-L: 0.3-0.7); SLED "
               "clean of both (2 estimation tests, no validation test)"),
    Case("hm_broken_dummy", 22041, _mix(2, 3, 1), _mix(0, 4, 2), 96,
         (Effect("dummy_scale", 0.86, tests=("SLED_003",)),), (), expect_broken=("SLED_003",),
         notes="SLED_003, an estimation test, ran with the lab's small female dummy (a "
               "Hybrid III 5th percentile, length scale 0.86 of the 50th male: masses x 0.64, "
               "stiffnesses x 0.86, dampings x 0.74) while its file names the 50th male as "
               "every other test's does; whole, clean channels (no channel check sees it), "
               "only the chest's answer to its pulse and belt differs; the physics of every "
               "other test clean"),
    Case("hm_cr_crosstalk", 22143, _mix(4, 1, 1), _mix(0, 2, 4), 64,
         (Effect("cr_crosstalk", 0.15),), (), expect_note=UNEXPLAINED_CR,
         notes="the recorder's multiplexed digitiser samples CR right after CD with too little "
               "settling time: CR keeps 0.15 g per mm of CD (4-5 g at peak deflection), every "
               "test; CD and the inputs untouched: a residual in cr only, shaped as CD, not a "
               "static function of cr (A-L on CR: a gain, a soft clip, an over-read, a charge "
               "leak, a zero shift)"),
    Case("hm_pulse_late_4p6ms", 22247, _mix(1, 4, 1), _mix(0, 3, 3), 96,
         (Effect("pulse_late", 0.0046),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.6 ms after its record (A-L: 1.5 ... 4.25 ms, "
               "none above)"),
    Case("hm_brs_late_1p5ms", 22349, _mix(2, 2, 2), _mix(1, 5, 0), 128,
         (Effect("brs_late", 0.0015),), (("input_delay", "all"),),
         notes="the chest feels the belt 1.5 ms after the BRS records it (A-L: BRS 1, 2.2, "
               "2.5 ... 5 ms, none between 1 and 2.2); below the 1-point bar (see the "
               "module's docstring), kept at the brief's 1.0-1.5 ms"),
    Case("hm_dring_capstan", 22451, _mix(1, 1, 4), _mix(0, 2, 4), 48,
         (Effect("dring_capstan", 0.5, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the car's own D-ring (FULL): the shoulder webbing wraps it as a capstan, the "
               "chest side carrying the retractor side's tension x exp(0.5) while the chest "
               "draws webbing out, x exp(-0.5) while the retractor takes it back (a new form: "
               "see the module's docstring); the sleds' lab D-rings (R16, SLED) keep the "
               "nominal small friction. FULL holds 4 of the 6 estimation tests and 4 of the 6 "
               "validation tests"),
]

BY_NAME_M = {c.name: c for c in SET_M}
