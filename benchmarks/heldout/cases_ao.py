"""Held-out set AO: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AN (``cases.py`` ... ``cases_an.py``).

Set AN's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works, with no change: ``draw_ao.py`` (``numpy.random.default_rng(50000)``, set
W's ``drawn``, the pairings of A-AN taken, save where a case has none free for its rigs: it
then reuses one of A-AN's, ``reuse_all``, set AL's rule; ``python -m
benchmarks.heldout.draw_ao`` prints the draw). The cases follow the draw; only the sizes are
set, by costs, by the rule ``draw_ao.py`` wrote down before the first draw (``SIZING``; set
AN's, set AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's, set AF's, set
AE's, its rule 4 as mended there). ``test_set_ao_follows_its_draw`` holds the draw and the
cases together.

Ten cases run a pairing an earlier set ran (``draw_ao.py``'s docstring: none was free for their
rigs), each drawn uniformly among the pairings its rules allow that A-AN ran: the chest's
stiffening, est 0/2/4, val 1/4/1 (set AA's ``haa_fabric_sled``); the chest's rate damping, est
4/2/0, val 1/4/1 (set AA's ``haa_clean96``); the belt's unloading, est 3/0/3, val 1/2/3 (set
S's ``hs_webbing_power_full``); the belt's stiffening, est 0/3/3, val 1/1/4 (set V's
``hv_fung_r16_full``); the bag, est 2/0/4, val 1/3/2 (set T's ``ht_bumper_sled_full``); the
pelvis as redrawn, est 3/0/3, val 3/1/2 (set S's ``hs_two_set_r16_hardening_full``, set AL's
``hal_squeeze_sled_full``); the input gain as redrawn, est 0/4/2, val 1/2/3 (set S's
``hs_rib_fung_sled``); the two-effect case, est 2/2/2, val 1/1/4 (set I's
``hi_pelvis_submarine``, set AM's ``ham_valve_r16_sled``); the late pulse, est 3/0/3, val 0/1/5
(set AA's ``haa_clean48``); the late BRS as redrawn, est 0/0/6, val 4/1/1 (set AL's
``hal_toe_all``). The other four cases drew free pairings. No two cases of AO share a pairing.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bilinear, R16+SLED, 48, est 0/2/4, val 1/4/1 (reused);
chest_rate_damping: rib_friction, SLED+FULL, 96, est 4/2/0, val 1/4/1 (reused);
belt_unloading: webbing_hysteresis, FULL, 64, est 3/0/3, val 1/2/3 (reused); belt_stiffening:
webbing_toe, R16+FULL, 48, est 0/3/3, val 1/1/4 (reused); airbag_contact: airbag_fabric, FULL,
48, est 2/0/4, val 1/3/2 (reused); pelvis_coupling: pelvis_knee, FULL, 64, est 3/0/3, val
3/1/2 (reused; redrawn once, below); input_gain: brs_eccentric, SLED, 96, est 0/4/2, val 1/2/3
(reused; redrawn once, below); the two-effect case chest_stiffening (rib_bilinear) on R16+SLED
beside belt_stiffening (webbing_power) on FULL, 96, est 2/2/2, val 1/1/4 (reused); the late
pulse 2.21 ms, 128, est 3/0/3, val 0/1/5 (reused); the late BRS 4.68 ms, 128, est 0/0/6, val
4/1/1 (reused; redrawn twice, below); the transducer error on CR, cr_late, 48, est 0/6/0, val
0/4/2; the broken test's channel CR, cr_hum, 64, est 0/0/6, val 0/3/3, the test FULL_007;
clean48 est 6/0/0, val 3/0/3; clean96 est 0/0/6, val 1/0/5.

Redrawn (``draw_ao.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken; the seed names the
generator that drew the rejected draw again). None at the draw (with a pairing always left to
draw, no draw is impossible for want of one); at the sizes, four. A run-away is judged by
``test_set_ao_has_no_run_aways``'s limits, each pay-out against its rig's median over the
set's other cases' tests at the first sizes, and the spool's radius below zero within 7 rad of
pay-out; as set AG judged, a size that runs away makes the draw impossible whatever its cost.
The order found: the slip force's run-away found by the test at the first sizes, before any
cost; then the first sizes costed one at a time in this list's order (the spool's before the
late BRS's), the redraws after the rest, then the steps:
- 50001, the pelvis: its first draw, pelvis_submarine on SLED+FULL (96 counts, est 4/0/2, val
  0/2/4, reused, set Y's ``hy_sealed_sled_full``), at the rule's first size, the lap belt
  slipping past 6300 N (median 6050, half-way up: 6100; 6100-6200 taken), ran away (found by
  the test at the first sizes): FULL_002 paid out 82.5 deg against the set's other cases' FULL
  median 270.0 (its other FULL tests 105-195, SLED_004 101.3 against SLED's 240): impossible.
  Costed for the record: 12.93 (92.49 -> 79.55; CR 8.39, CD 17.48).
- 50002, the input gain: its first draw, spool_buildup on R16 (48 counts, est 3/0/3, val
  3/2/1, reused, set T's ``ht_maxwell_r16_sled``), cost 0.45 at the rule's first size, 13 mm
  of radius per wrap (90.21 -> 89.77; CR 0.76, CD 0.14; median 0.012, set X's one, taken),
  below the band; the rule's next, 0.013 x 3.5 / 0.45 = 0.101, clipped to three times, 39 mm
  per wrap, would leave the spool's 17 mm radius below zero within 7 rad of pay-out (zero past
  15.3 mm per wrap): a run-away, impossible without costing it (as set AI judged). Drawn again
  by 50002: brs_eccentric on SLED, kept (below).
- 50003, the late BRS: its first draw, 1.23 ms (64 counts, est 4/2/0, val 2/1/3, reused, set
  T's ``ht_clean48``), cost -0.12 (90.52 -> 90.64; CR -0.38, CD 0.13), below the delay's band
  (a delay has nothing to set, rule 3): impossible.
- 50004, the late BRS again: 50003's draw, 2.65 ms (48 counts, est 3/0/3, val 2/4/0, reused,
  set W's ``hw_brs_late_4p17ms``), cost 0.93 (92.02 -> 91.09; CR 1.22, CD 0.65), below the
  delay's band: impossible. Drawn again by 50004: 4.68 ms, kept (below).

Sizes (the rule's; A-AN's values stepped off; the medians over every case of A-AN giving the
key; a median half-way rounded up): the webbing's hysteresis 0.61 (median 0.515, half-way up:
0.52; 0.52-0.60 taken), the webbing's toe 0.23 (median 0.225, half-way up: 0.23, not taken),
the fabric bag 0.81 (median 0.765, half-way up: 0.77; 0.77-0.80 taken), the knee bolster 0.16
(redrawn; median 0.15, taken), the encoder ring 0.48 (redrawn; median 0.355, half-way up:
0.36; 0.36-0.47 taken), CR written 5.1 ms late (median 5.0 ms, set Q's one, taken), each at
the rule's first size, in band; the bilinear ribs 0.98 (median 1.4; 1.4-1.6 taken, so 1.7,
cost 6.08: CR 4.27, CD 7.88; then 1.7 x 3.5 / 6.08 = 0.979, 0.98, not taken, cost 3.23, in
band); the rib cage's friction 200 N (median 410; 410-430 taken, so 440, cost 7.82: CR 2.63,
CD 13.01; then 440 x 3.5 / 7.82 = 197, 200, not taken, cost 2.10, in band); the late pulse
2.21 ms and the late BRS 4.68 ms (redrawn twice) as drawn, in the delay's band; the broken
test's CR hum 6.2 g (rule 5: by rule 1 only; median 6.05 g, half-way up: 6.1; 6.1 taken; not
banded). The two-effect case, the bilinear ribs on R16+SLED beside the webbing's power on
FULL, at its first sizes 1.7 (the key's first, as the single's) and 1.9 (median 1.85, half-way
up: 1.9, not taken): the bilinear ribs alone 7.95 (CR 2.25, CD 13.66), above the band, the
webbing's power alone 5.56 (CR 7.73, CD 3.40), the two together 9.93 (CR 6.11, CD 13.74). The
bilinear ribs by 1-2 alone: 1.7 x 3.5 / 7.95 = 0.748, 0.75 (not taken): alone 4.63 (CR 1.23,
CD 8.02), together 7.29 (CR 6.02, CD 8.56), above the band. Each alone in band, the two
together not: the higher alone, the webbing's power (5.56 against 4.63), stepped, the bilinear
ribs kept at 0.75, 1.9 the first of its four: 1.9 x 3.75 / 7.29 = 0.977, 0.98 (not taken):
together 6.02 (CR 3.95, CD 8.09), above the band, the power alone 3.68 (CR 5.52, CD 1.84);
then 0.98 x 3.75 / 6.02 = 0.610, 0.61 (not taken; no two sizes yet bracketing the band):
together 5.18 (CR 2.53, CD 7.84), the power alone 2.36 (CR 3.94, CD 0.78), the bilinear ribs
alone 4.63 as before: all three in band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD): bilinear_r16_sled 91.66 -> 88.42 (3.23; CR 2.92, CD 3.55);
friction_sled_full 93.90 -> 91.80 (2.10; CR 0.96, CD 3.24); hysteresis_full 90.38 -> 85.98
(4.41; CR 5.74, CD 3.07); toe_r16_full 90.48 -> 85.81 (4.67; CR 5.66, CD 3.69); fabric_full
91.03 -> 89.35 (1.68; CR 1.52, CD 1.85); pelvis_knee_full 90.10 -> 87.41 (2.69; CR 2.35, CD
3.03); eccentric_sled 92.59 -> 88.16 (4.42; CR 5.21, CD 3.64); two_bilinear_r16_sled_power_full
91.77 -> 86.59 (5.18; CR 2.53, CD 7.84; the bilinear ribs alone 4.63, the webbing's power alone
2.36); pulse_late_2p21ms 93.51 -> 92.01 (1.51; CR 2.00, CD 1.01); brs_late_4p68ms 94.40 -> 88.80
(5.60; CR 7.04, CD 4.15); cr_late 91.95 -> 90.08 (1.87; CR 2.82, CD 0.92); broken_cr_hum 92.48
-> 92.49 (-0.01; CR 0.04, CD -0.05; flagging the test is the verdict asked; not banded, by the
rule). The clean cases' fits (python -m benchmarks.heldout.costs --set ao --case hao_clean48
--case hao_clean96): clean48 88.1 (CR 90.5, CD 85.6), clean96 90.5 (CR 92.7, CD 88.4). Each
effect of the two-effect case alone: the case's seed with the other effect's size 0 (kept in the
case's list, so the dummies and pulses draw as they do in the case), against the same twin. No
kept size ran away (``test_set_ao_has_no_run_aways``'s limits, each against its rig's median
over the set's other cases' tests at the first sizes, the rejected draws' tests left out for
their redraws': R16 270.0, SLED 240.0, FULL 270.0 deg); the run-away is the rejected slip
force's above.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AO: list[Case] = [
    Case("hao_clean48", 50103, _mix(6, 0, 0), _mix(3, 0, 3), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, validated there three "
               "times; FULL validated three times, never estimated; SLED neither estimated "
               "nor validated"),
    Case("hao_clean96", 50207, _mix(0, 0, 6), _mix(1, 0, 5), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone, validated there five "
               "times; R16 validated once, never estimated; SLED neither estimated nor "
               "validated"),
    Case("hao_bilinear_r16_sled", 50309, _mix(0, 2, 4), _mix(1, 4, 1), 48,
         (Effect("rib_bilinear", 0.98, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the ribs' second load path past 16 mm, their stiffness growing by 0.98 x k_r "
               "beyond it, on R16 and SLED; R16 validated once, never estimated; SLED "
               "estimated twice, validated four times; FULL clean, 4 estimation tests, "
               "validated once; the pairing set AA's (reused, none free)"),
    Case("hao_friction_sled_full", 50411, _mix(4, 2, 0), _mix(1, 4, 1), 96,
         (Effect("rib_friction", 200.0, ("SLED", "FULL")),),
         (("chest_rate_damping", "SLED+FULL"),),
         notes="dry (Coulomb) friction in the rib cage, 200 N against the chest's rate, on "
               "SLED and FULL; SLED estimated twice, validated four times; FULL validated "
               "once, never estimated; R16 clean, 4 estimation tests, validated once; the "
               "pairing set AA's (reused, none free)"),
    Case("hao_hysteresis_full", 50515, _mix(3, 0, 3), _mix(1, 2, 3), 64,
         (Effect("webbing_hysteresis", 0.61, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the webbing's elastic force 61 % lower while it shortens (set B's form), on "
               "FULL alone; FULL estimated three times, validated three times; R16 clean, 3 "
               "estimation tests, validated once; SLED validated twice, never estimated; the "
               "pairing set S's (reused, none free)"),
    Case("hao_toe_r16_full", 50617, _mix(0, 3, 3), _mix(1, 1, 4), 48,
         (Effect("webbing_toe", 0.23, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.23, on R16 "
               "and FULL; R16 validated once, never estimated; FULL estimated three times, "
               "validated four times; SLED clean, 3 estimation tests, validated once; the "
               "pairing set V's (reused, none free)"),
    Case("hao_fabric_full", 50719, _mix(2, 0, 4), _mix(1, 3, 2), 48,
         (Effect("airbag_fabric", 0.81, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="a ventless bag leaking through its fabric at fill 0.81, on FULL alone; FULL "
               "estimated four times, validated twice; R16 without a bag, 2 estimation tests, "
               "validated once; SLED clean, validated three times, never estimated; the "
               "pairing set T's (reused, none free)"),
    Case("hao_pelvis_knee_full", 50823, _mix(3, 0, 3), _mix(3, 1, 2), 64,
         (Effect("pelvis_knee", 0.16, ("FULL",)),), (("pelvis_coupling", "FULL"),),
         notes="the pelvis on lap belt and seat at 0.16 x set A's lumbar and lap stiffness, "
               "its knees meeting a knee bolster past a 45 mm gap, on FULL alone; FULL "
               "estimated three times, validated twice; R16 clean, 3 estimation tests, "
               "validated three times; SLED validated once, never estimated; the pairing set "
               "S's (reused, none free; redrawn once)"),
    Case("hao_eccentric_sled", 50927, _mix(0, 4, 2), _mix(1, 2, 3), 96,
         (Effect("brs_eccentric", 0.48, ("SLED",)),), (("input_gain", "SLED"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.48 sin(th + phase), on "
               "SLED alone; SLED estimated four times, validated twice; FULL clean, 2 "
               "estimation tests, validated three times; R16 validated once, never estimated; "
               "the pairing set S's (reused, none free; redrawn once)"),
    Case("hao_two_bilinear_r16_sled_power_full", 50031, _mix(2, 2, 2), _mix(1, 1, 4), 96,
         (Effect("rib_bilinear", 0.75, ("R16", "SLED")),
          Effect("webbing_power", 0.61, ("FULL",))),
         (("chest_stiffening", "R16+SLED"), ("belt_stiffening", "FULL")),
         notes="two kinds on two rigs: the ribs' second load path past 16 mm, their stiffness "
               "growing by 0.75 x k_r beyond it (R16 and SLED); the webbing stiffening with "
               "its stretch, F += a k e (e/e_ref)^2, a = 0.61 (FULL); each rig estimated "
               "twice, R16 and SLED validated once each, FULL four times; the pairing set I's "
               "(reused, none free)"),
    Case("hao_pulse_late_2p21ms", 50137, _mix(3, 0, 3), _mix(0, 1, 5), 128,
         (Effect("pulse_late", 0.00221),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.21 ms after its record; R16 and FULL each "
               "estimated three times, FULL validated five times, SLED once, R16 never; the "
               "pairing set AA's (reused, none free)"),
    Case("hao_brs_late_4p68ms", 50241, _mix(0, 0, 6), _mix(4, 1, 1), 128,
         (Effect("brs_late", 0.00468),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.68 ms after the BRS records it; estimated on FULL "
               "alone, validated there once; R16 and SLED validated (four times, once), never "
               "estimated; the pairing set AL's (reused, none free; redrawn twice)"),
    Case("hao_cr_late", 50343, _mix(0, 6, 0), _mix(0, 4, 2), 48,
         (Effect("cr_late", 0.0051),), (), expect_note=UNEXPLAINED_CR,
         notes="the CR channel's digitiser module writes its samples 5.1 ms late (a pipeline "
               "delay left in its time stamps, set Q's form), every test: CR late, its values "
               "right; CD and the inputs on time: a residual in cr only, no input late"),
    Case("hao_broken_cr_hum", 50447, _mix(0, 0, 6), _mix(0, 3, 3), 64,
         (Effect("cr_hum", 6.2, tests=("FULL_007",)),), (), expect_broken=("FULL_007",),
         notes="FULL_007, an estimation test: its spine accelerometer picks up 50 Hz mains hum "
               "through a ground loop, 6.2 g amplitude, from before the crash to the end (CFC "
               "180 passes it): a sine on the flat pre-crash line; its other channels and "
               "every other test clean"),
]

BY_NAME_AO = {c.name: c for c in SET_AO}
ONE_PHYSICAL_AO = ("hao_bilinear_r16_sled", "hao_friction_sled_full", "hao_hysteresis_full",
                   "hao_toe_r16_full", "hao_fabric_full", "hao_pelvis_knee_full",
                   "hao_eccentric_sled")
