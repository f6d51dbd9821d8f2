"""Held-out set AP: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AO (``cases.py`` ... ``cases_ao.py``).

Set AO's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works, with no change: ``draw_ap.py`` (``numpy.random.default_rng(51000)``, set
W's ``drawn``, the pairings of A-AO taken, save where a case has none free for its rigs: it
then reuses one of A-AO's, ``reuse_all``, set AL's rule; ``python -m
benchmarks.heldout.draw_ap`` prints the draw). The cases follow the draw; only the sizes are
set, by costs, by the rule ``draw_ap.py`` wrote down before the first draw (``SIZING``; set
AO's, set AN's, set AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's, set AF's,
set AE's, its rule 4 as mended there). ``test_set_ap_follows_its_draw`` holds the draw and the
cases together.

Eleven cases run a pairing an earlier set ran (``draw_ap.py``'s docstring: none was free for
their rigs), each drawn uniformly among the pairings its rules allow that A-AO ran: the chest's
stiffening, est 0/2/4, val 2/1/3 (set V's ``hv_pulse_late_3p66ms``); the chest's rate damping,
est 0/3/3, val 2/2/2 (set K's ``hk_lumbar``); the belt's unloading, est 2/2/2, val 0/5/1 (set
U's ``hu_power_sled_full``); the belt's stiffening, est 3/3/0, val 2/0/4 (set AG's
``hag_airbag_sled_full``, set AL's ``hal_eccentric_sled_full``); the bag, est 0/4/2, val 0/2/4
(set C's ``hc_webbing_knee``); the pelvis as redrawn, est 2/0/4, val 5/1/0 (set AH's
``hah_fung_r16_sled``); the input gain, est 0/2/4, val 5/0/1 (set X's ``hx_spool_r16_sled``);
the two-effect case as redrawn, est 2/2/2, val 2/3/1 (set H's ``hh_clean48``); the late pulse,
est 3/3/0, val 3/2/1 (set S's ``hs_capstan_all``); the late BRS, est 2/4/0, val 0/5/1 (set W's
``hw_eccentric_sled``); clean96, est 4/2/0, val 1/0/5 (set AD's ``had_eccentric_all``). The
other three cases (the transducer error, the broken test, clean48) drew free pairings. No two
cases of AP share a pairing.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_hardening, R16+FULL, 48, est 0/2/4, val 2/1/3 (reused);
chest_rate_damping: rib_maxwell, SLED, 128, est 0/3/3, val 2/2/2 (reused); belt_unloading:
webbing_set, all three rigs, 48, est 2/2/2, val 0/5/1 (reused); belt_stiffening: webbing_toe,
R16, 96, est 3/3/0, val 2/0/4 (reused); airbag_contact: airbag_fabric, SLED, 48, est 0/4/2, val
0/2/4 (reused); pelvis_coupling: pelvis_knee, R16+SLED, 128, est 2/0/4, val 5/1/0 (reused;
redrawn three times, below); input_gain: brs_eccentric, R16+FULL, 48, est 0/2/4, val 5/0/1
(reused); the two-effect case airbag_contact (airbag_dual) on SLED beside belt_stiffening
(webbing_power) on R16+FULL, 64, est 2/2/2, val 2/3/1 (reused; redrawn twice, below); the late
pulse 3.56 ms, 96, est 3/3/0, val 3/2/1 (reused); the late BRS 4.76 ms, 64, est 2/4/0, val
0/5/1 (reused); the transducer error on CR, cr_creep, 48, est 0/0/6, val 5/0/1; the broken
test's channel CD, cd_dropout, 96, est 6/0/0, val 3/3/0, the test R16_007; clean48 est 6/0/0,
val 6/0/0; clean96 est 4/2/0, val 1/0/5 (reused).

Redrawn (``draw_ap.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken; the seed names the
generator that drew the rejected draw again). None at the draw (with a pairing always left to
draw, no draw is impossible for want of one); at the sizes, five, every one a run-away at its
first size. A run-away is judged by ``test_set_ap_has_no_run_aways``'s limits, each pay-out
against its rig's median over the set's other cases' tests at the first sizes (a rejected
draw's tests replaced by its redraw's); as set AG judged, a size that runs away makes the draw
impossible whatever its cost, and as set AM judged, a first size that runs away is costed for
the record. The order found: the two run-aways the run-away limits found at the first sizes,
before any cost, in this list's order (the order the test walks the cases: the pelvis before
the two-effect case); then the first sizes costed one at a time in this list's order (none
impossible); the redraws after the rest at their first sizes, checked in this list's order
(the pelvis's before the two-effect case's), then the steps:
- 51001, the pelvis: its first draw, pelvis_submarine on R16+SLED (96 counts, est 0/4/2, val
  5/1/0, reused, set AB's ``hab_knee_r16_sled``), at the rule's first size, the lap belt
  slipping past 6300 N (median 6050, half-way up: 6100; 6100-6200 taken), ran away: R16_002
  paid out 60.0 deg against the set's other cases' R16 median 285.0 (R16_006 93.8; SLED_002
  75.0 against SLED's 240.0): impossible. Costed for the record: 6.04 (92.85 -> 86.81; CR 5.33,
  CD 6.75).
- 51002, the two-effect case: its first draw, belt_unloading (webbing_hysteresis, 0.63: median
  0.52; 0.52-0.62 taken) on R16 beside pelvis_coupling (pelvis_submarine, 6300 N, the key's
  first size) on SLED+FULL (64 counts, est 2/2/2, val 4/1/1, reused, set E's ``he_clean48``),
  ran away: SLED_001 paid out 78.8 deg against the set's other cases' SLED median 240.0 (so
  too with the pelvis's rejected draw's tests replaced by its redraw's); its FULL tests 118-146
  against 270.0: impossible. Costed for the record: together 11.08 (91.94 -> 80.87; CR 7.20,
  CD 14.96), the hysteresis alone 6.44, the slip force alone 9.40 (ran away alone too).
- 51003, the pelvis again: 51001's draw, pelvis_submarine on all three rigs (48 counts, est
  2/0/4, val 1/4/1, reused, set S's ``hs_broken_brs_wrap``), 6300 N, ran away: FULL_003 paid
  out 82.5 deg against FULL's 270.0: impossible. Costed for the record: 5.66 (92.25 -> 86.59).
- 51004, the two-effect case again: 51002's draw, belt_stiffening (webbing_power, 1.8: median
  1.7, taken) on SLED beside belt_unloading (dring_capstan, 0.59: median 0.59, not taken) on
  R16+FULL (64 counts, est 2/2/2, val 3/3/0, reused, set O's ``ho_cr_damped``), ran away by the
  capstan: R16_003 paid out 16.9 deg against R16's 285.0 (R16_002 33.8, FULL_003 67.5):
  impossible. Costed for the record: together 1.51 (90.59 -> 89.07), the power alone 7.38, the
  capstan alone 0.04. Drawn again by 51004: airbag_dual on SLED beside webbing_power on
  R16+FULL, kept (below).
- 51005, the pelvis a third time: 51003's draw, pelvis_submarine on SLED+FULL (128 counts, est
  4/2/0, val 2/0/4, reused, set V's ``hv_eccentric_sled_full``), 6300 N, ran away: SLED_001
  paid out 36.6 deg against SLED's 240.0 (SLED_002 84.4): impossible. Costed for the record:
  7.95 (89.77 -> 81.81). Drawn again by 51005: pelvis_knee on R16+SLED, kept (below).

Sizes (the rule's; A-AO's values stepped off; the medians over every case of A-AO giving the
key; a median half-way rounded up): the ribs' hardening k3 1.6e8 N/m^3 (median 1.05e8,
half-way up: 1.1e8; 1.1e8-1.5e8 taken), the Maxwell branch 0.62 (median 0.62, not taken), the
webbing's set 0.69 (median 0.585, half-way up: 0.59; 0.59-0.68 taken), the webbing's toe 0.24
(median 0.23, taken), the fabric bag 0.82 (median 0.77; 0.77-0.81 taken), the encoder ring
0.49 (median 0.36; 0.36-0.48 taken), CR's creep 0.22 (median 0.205, half-way up: 0.21, set X's
one, taken), each at the rule's first size, in band; the knee bolster 0.057 (redrawn; median
0.155, half-way up: 0.16, taken, so 0.17, cost 11.86: CR 7.84, CD 15.89; then 0.17 x 3.5 /
11.86 = 0.050, clipped to a third, 0.0567, 0.057, not taken, cost 3.97, in band); the late
pulse 3.56 ms and the late BRS 4.76 ms as drawn, in the delay's band; the broken test's CD
dropout at 55 ms (rule 5: by rule 1 only; median 53 ms, set AN's one, taken; 54 ms taken; not
banded). The two-effect case (redrawn twice), the SLED rig's two-stage bag beside the webbing's
power on R16+FULL, at its first sizes 0.33 (median 0.325, half-way up: 0.33, not taken) and 1.8
(median 1.7, taken): the bag alone 5.76 (CR 5.78, CD 5.74), in band, the webbing's power alone
7.74 (CR 7.84, CD 7.64), above the band, the two together 5.60 (CR 7.13, CD 4.06). The power
by 1-2 alone: 1.8 x 3.5 / 7.74 = 0.814, 0.81 (not taken): alone 5.55 (CR 5.60, CD 5.51),
together 3.89 (CR 5.17, CD 2.62), the bag alone 5.76 as before: all three in band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD): hardening_r16_full 92.60 -> 86.68 (5.92; CR 2.98, CD 8.85);
maxwell_sled 90.91 -> 87.76 (3.15; CR 0.41, CD 5.89); set_all 91.39 -> 88.45 (2.94; CR 3.20, CD
2.68); toe_r16 90.97 -> 87.00 (3.97; CR 4.18, CD 3.75); fabric_sled 91.55 -> 87.02 (4.53; CR
4.45, CD 4.61); pelvis_knee_r16_sled 92.92 -> 88.95 (3.97; CR 0.22, CD 7.71); eccentric_r16_full
92.10 -> 86.32 (5.78; CR 6.22, CD 5.33); two_dual_sled_power_r16_full 91.61 -> 87.72 (3.89; CR
5.17, CD 2.62; the bag alone 5.76, the webbing's power alone 5.55); pulse_late_3p56ms 92.15 ->
88.31 (3.84; CR 5.24, CD 2.44); brs_late_4p76ms 90.12 -> 86.55 (3.58; CR 4.13, CD 3.03);
cr_creep 92.14 -> 86.16 (5.99; CR 9.10, CD 2.88); broken_cd_dropout 91.28 -> 90.43 (0.85; CR
0.84, CD 0.86; flagging the test is the verdict asked; not banded, by the rule). The clean
cases' fits (python -m benchmarks.heldout.costs --set ap --case hap_clean48 --case hap_clean96):
clean48 90.5 (CR 91.8, CD 89.3), clean96 92.1 (CR 92.8, CD 91.4). Each effect of the two-effect
case alone: the case's seed with the other effect's size 0 (kept in the case's list, so the
dummies and pulses draw as they do in the case), against the same twin. No kept size ran away
(``test_set_ap_has_no_run_aways``'s limits, each against its rig's median over the set's other
cases' tests at the first sizes, the rejected draws' tests left out for their redraws': R16
285.0, SLED 240.0, FULL 270.0 deg); the run-aways are the five rejected draws' above.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""


from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AP: list[Case] = [
    Case("hap_clean48", 51103, _mix(6, 0, 0), _mix(6, 0, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, validated there six "
               "times; SLED and FULL neither estimated nor validated"),
    Case("hap_clean96", 51207, _mix(4, 2, 0), _mix(1, 0, 5), 96,
         notes="clean thorax, 96-count BRS; R16 estimated four times, validated once; SLED "
               "estimated twice, never validated; FULL validated five times, never "
               "estimated; the pairing set AD's (reused, none free)"),
    Case("hap_hardening_r16_full", 51309, _mix(0, 2, 4), _mix(2, 1, 3), 48,
         (Effect("rib_hardening", 1.6e8, ("R16", "FULL")),), (("chest_stiffening", "R16+FULL"),),
         notes="the ribs harden from zero, F += k3 d^3 at k3 1.6e8 N/m^3, on R16 and FULL; R16 "
               "validated twice, never estimated; FULL estimated four times, validated three "
               "times; SLED clean, 2 estimation tests, validated once; the pairing set V's "
               "(reused, none free)"),
    Case("hap_maxwell_sled", 51411, _mix(0, 3, 3), _mix(2, 2, 2), 128,
         (Effect("rib_maxwell", 0.62, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="viscoelastic rib material, a Maxwell branch of 0.62 x the rib's stiffness "
               "relaxing in 10 ms, on SLED alone; SLED estimated three times, validated twice; "
               "FULL clean, 3 estimation tests, validated twice; R16 validated twice, never "
               "estimated; the pairing set K's (reused, none free)"),
    Case("hap_set_all", 51515, _mix(2, 2, 2), _mix(0, 5, 1), 48,
         (Effect("webbing_set", 0.69),), (("belt_unloading", "all"),),
         notes="the chest-side webbing unloads to a set of 0.69 x its peak stretch, on every "
               "rig; each estimated twice; SLED validated five times, FULL once, R16 never; "
               "the pairing set U's (reused, none free)"),
    Case("hap_toe_r16", 51617, _mix(3, 3, 0), _mix(2, 0, 4), 96,
         (Effect("webbing_toe", 0.24, ("R16",)),), (("belt_stiffening", "R16"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.24, on R16 "
               "alone; R16 estimated three times, validated twice; SLED clean, 3 estimation "
               "tests, never validated; FULL validated four times, never estimated; the "
               "pairing set AG's (reused, none free)"),
    Case("hap_fabric_sled", 51719, _mix(0, 4, 2), _mix(0, 2, 4), 48,
         (Effect("airbag_fabric", 0.82, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a ventless bag leaking through its fabric at fill 0.82, on SLED alone; SLED "
               "estimated four times, validated twice; FULL without a bag, 2 estimation "
               "tests, validated four times; R16 neither estimated nor validated; the pairing "
               "set C's (reused, none free)"),
    Case("hap_pelvis_knee_r16_sled", 51823, _mix(2, 0, 4), _mix(5, 1, 0), 128,
         (Effect("pelvis_knee", 0.057, ("R16", "SLED")),), (("pelvis_coupling", "R16+SLED"),),
         notes="the pelvis on lap belt and seat at 0.057 x set A's lumbar and lap stiffness, "
               "its knees meeting a knee bolster past a 45 mm gap, on R16 and SLED; R16 "
               "estimated twice, validated five times; SLED validated once, never estimated; "
               "FULL clean, 4 estimation tests, never validated; the pairing set AH's "
               "(reused, none free; redrawn three times)"),
    Case("hap_eccentric_r16_full", 51927, _mix(0, 2, 4), _mix(5, 0, 1), 48,
         (Effect("brs_eccentric", 0.49, ("R16", "FULL")),), (("input_gain", "R16+FULL"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.49 sin(th + phase), on "
               "R16 and FULL; R16 validated five times, never estimated; FULL estimated four "
               "times, validated once; SLED clean, 2 estimation tests, never validated; the "
               "pairing set X's (reused, none free)"),
    Case("hap_two_dual_sled_power_r16_full", 51031, _mix(2, 2, 2), _mix(2, 3, 1), 64,
         (Effect("airbag_dual", 0.33, ("SLED",)),
          Effect("webbing_power", 0.81, ("R16", "FULL"))),
         (("airbag_contact", "SLED"), ("belt_stiffening", "R16+FULL")),
         notes="two kinds on two rigs: the SLED rig's vented bag on a two-stage inflator at "
               "fill 0.33 (SLED); the webbing stiffening with its stretch, F += a k e "
               "(e/e_ref)^2, a = 0.81 (R16 and FULL); each rig estimated twice, R16 validated "
               "twice, SLED three times, FULL once; the pairing set H's (reused, none free; "
               "redrawn twice)"),
    Case("hap_pulse_late_3p56ms", 51137, _mix(3, 3, 0), _mix(3, 2, 1), 96,
         (Effect("pulse_late", 0.00356),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.56 ms after its record; R16 and SLED each "
               "estimated three times, R16 validated three times, SLED twice; FULL validated "
               "once, never estimated; the pairing set S's (reused, none free)"),
    Case("hap_brs_late_4p76ms", 51241, _mix(2, 4, 0), _mix(0, 5, 1), 64,
         (Effect("brs_late", 0.00476),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.76 ms after the BRS records it; R16 estimated "
               "twice, never validated; SLED estimated four times, validated five times; FULL "
               "validated once, never estimated; the pairing set W's (reused, none free)"),
    Case("hap_cr_creep", 51343, _mix(0, 0, 6), _mix(5, 0, 1), 48,
         (Effect("cr_creep", 0.22),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's gauges creep in their adhesive: under a sustained "
               "load CR reads up to 22 % more, with a 15 ms time constant, every test (set S's "
               "form); CD and the inputs untouched: a residual in cr only"),
    Case("hap_broken_cd_dropout", 51447, _mix(6, 0, 0), _mix(3, 3, 0), 96,
         (Effect("cd_dropout", 0.055, tests=("R16_007",)),), (), expect_broken=("R16_007",),
         notes="R16_007, an estimation test: its chest pot's wiper lifts off the track, the "
               "raw CD reads 0 mm from 55 to 65 ms, then recovers (CFC 600 after); its other "
               "channels and every other test clean"),
]

BY_NAME_AP = {c.name: c for c in SET_AP}
ONE_PHYSICAL_AP = ("hap_hardening_r16_full", "hap_maxwell_sled", "hap_set_all", "hap_toe_r16",
                   "hap_fabric_sled", "hap_pelvis_knee_r16_sled", "hap_eccentric_r16_full")
