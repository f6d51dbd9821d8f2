"""Held-out set AI: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AH (``cases.py`` ... ``cases_ah.py``).

Set AH's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_ai.py`` (``numpy.random.default_rng(44000)``, set W's ``drawn``,
the pairings of A-AH taken, save the two-effect case's: with none free, it reuses one of
A-AH's, ``reuse_two``; ``python -m benchmarks.heldout.draw_ai`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_ai.py`` wrote down before
the first draw (``SIZING``; set AH's, set AG's, set AF's, set AE's, its rule 4 as mended
there). ``test_set_ai_follows_its_draw`` holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 0/2/4, is set K's (``hk_clean48``): the one
pairing of this set an earlier set ran (``draw_ai.py``'s docstring: none was free for its
rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_lock, R16+SLED, 48, est 0/4/2, val 4/0/2; chest_rate_damping: rib_foam,
R16+SLED, 96, est 0/2/4, val 5/1/0; belt_unloading: webbing_hysteresis, SLED+FULL, 128, est
4/2/0, val 0/1/5 (redrawn by 44006, below); belt_stiffening: webbing_power, SLED+FULL, 48, est
3/3/0, val 3/1/2; airbag_contact: airbag, SLED+FULL, 48, est 3/3/0, val 4/1/1;
pelvis_coupling: pelvis_submarine, SLED, 48, est 0/4/2, val 1/4/1; input_gain: brs_eccentric,
all three rigs, 64, est 0/6/0, val 1/2/3 (redrawn by 44004, below); the two-effect case
airbag_contact (airbag_relief) on FULL beside chest_stiffening (rib_bumper) on R16+SLED, 64,
est 2/2/2, val 0/2/4 (an earlier set's pairing, reused; redrawn by 44007, below); the late
pulse 3.69 ms, 64, est 6/0/0, val 0/3/3; the late BRS 3.26 ms, 48, est 6/0/0, val 1/1/4; the
transducer error on CD, cd_pot_nonlinear, 96, est 0/0/6, val 0/6/0; the broken test's channel
BRS, brs_quadrature, 128, est 0/4/2, val 2/0/4, the test FULL_001; clean48 est 0/6/0, val
0/1/5; clean96 est 0/0/6, val 0/4/2.

Redrawn (``draw_ai.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken; each item below names the
seed that drew the rejected draw again). A run-away is judged by
``test_set_ai_has_no_run_aways``'s limits and the spool's radius below zero within 7 rad of
pay-out, and, as set AG judged, a size that runs away makes the draw impossible whatever its
cost; a switch has nothing to set (rule 3):
- 44001, the belt unloading: its first draw, dring_capstan on SLED (96 counts, est 0/3/3, val
  2/3/1), at the rule's first size, mu theta 0.59 (median 0.59, not taken), cost 2.68 (91.63
  -> 88.95; CR 2.88, CD 2.48), in band, but ran away (found by the test at the first sizes):
  the capstan held the SLED rig's webbing, its SLED tests paid out 3.8-82.5 deg against their
  twin's 120-262.5 (SLED_001 37.5 against the set's SLED median 221.25; five of six below a
  third of it): impossible.
- 44002, the input gain: its first draw, spool_buildup on SLED+FULL (64 counts, est 2/4/0, val
  3/0/3), at the rule's first size, 13 mm per wrap (median 0.012, set X's one, taken), cost
  0.84 (88.83 -> 87.99; CR 1.39, CD 0.29), below the band; the rule's next, 0.013 x 3.5 / 0.84
  = 0.054, clipped to three times, 39 mm per wrap, leaves the spool's 17 mm radius below zero
  within 7 rad of pay-out (zero past 15 mm per wrap; set AD's run-away, as set AG found it):
  impossible.
- 44003, the belt unloading again: 44001's draw, webbing_slack on SLED (96 counts, est 0/2/4,
  val 2/4/0), a switch with nothing to set, cost 14.16 (92.18 -> 78.02; CR 15.39, CD 12.94),
  above the band: impossible.
- 44004, the input gain again: 44002's draw, spool_buildup on R16+SLED (48 counts, est 0/2/4,
  val 4/0/2), at 13 mm per wrap, cost 1.07 (92.72 -> 91.66; CR 1.02, CD 1.12), below the band;
  its next, 0.013 x 3.5 / 1.07 = 0.043, clipped to 39 mm per wrap, a run-away as above:
  impossible; drawn again by 44004: brs_eccentric on every rig, 64 counts, est 0/6/0, val
  1/2/3.
- 44005, the two-effect case: its first draw, airbag_relief on FULL beside rib_squeeze on SLED
  (96 counts, est 0/2/4, val 0/2/4, set O's pairing, ``ho_broken_brs_counts``), at the first
  sizes, fill 0.44 (median 0.43, taken) and 460 N s/m (median 430; 430-450 taken): together
  9.93 (91.40 -> 81.47; CR 7.15, CD 12.71), the relief-vented bag alone 5.19 (CR 5.39, CD
  5.00), the squeeze film alone 3.73 (CR 1.62, CD 5.84), each alone in band, the two together
  above it; by rule 4 the higher alone, the bag, stepped: 0.44 x 3.75 / 9.93 = 0.166, 0.17,
  not taken: together 5.81 (CR 3.12, CD 8.51), in band, the bag alone 1.30 (CR 1.19, CD 1.41),
  out of it, which ends the steps with no size at which all three are in band: impossible.
- 44006, the belt unloading again: 44003's draw, webbing_slack on R16 (64 counts, est 2/4/0,
  val 5/1/0), a switch, cost 16.64 (90.98 -> 74.34; CR 17.81, CD 15.47), above the band:
  impossible; drawn again by 44006: webbing_hysteresis on SLED+FULL, 128 counts, est 4/2/0,
  val 0/1/5.
- 44007, the two-effect case again: 44005's draw, webbing_toe on R16 beside rib_visco on SLED
  (96 counts, est 2/2/2, val 2/2/2, set A's pairing, ``h_clean48``), at the first sizes, 0.21
  (median 0.20, taken) and 2300 N/(m/s)^1.5 (median 2300, not taken): together 16.74 (92.21 ->
  75.47; CR 7.90, CD 25.59). Each alone by rules 1-2: the toe 0.21, 5.85 (CR 5.85, CD 5.84),
  in band; the rib damping 2300, 12.85 (CR 3.85, CD 21.86); 2300 x 3.5 / 12.85 = 626, clipped
  to a third, 767, 770, not taken, 4.22 (CR 1.47, CD 6.96), in band. Together at 0.21 and 770
  9.28 (CR 6.68, CD 11.88), above the band; by rule 4 the higher alone, the toe, stepped
  (the rib damping kept at 770): 0.21 x 3.75 / 9.28 = 0.085, together 7.88 (CR 5.11, CD
  10.66), the toe alone 4.18 (CR 4.05, CD 4.32); 0.085 x 3.75 / 7.88 = 0.040, together 6.88
  (CR 4.01, CD 9.76), alone 3.01 (CR 2.82, CD 3.20); 0.040 x 3.75 / 6.88 = 0.0218, 0.022,
  taken, so 0.023, together 6.25 (CR 3.34, CD 9.17), alone 2.26 (CR 2.06, CD 2.47): four sizes
  of the toe, the two together above the band at each: impossible; drawn again by 44007:
  airbag_relief on FULL beside rib_bumper on R16+SLED, 64 counts, est 2/2/2, val 0/2/4.

Sizes (the rule's; A-AH's values stepped off; the medians over every case of A-AH giving the
key; a median half-way rounded up): the rib lock 0.093 m (median 0.091, taken; 0.092 taken),
the vented bag 0.62 (median 0.605, half-way up: 0.61, taken), the lap belt's slip force 6000 N
(median 6000, not taken), each at the rule's first size, in band; the foam pad 1300 N s/m
(median 875, half-way up: 880, taken, so 890, cost 1.24: CR 1.09, CD 1.38; then 890 x 3.5 /
1.24 = 2512, 2500, taken, so 2600, cost 7.85: CR 5.12, CD 10.59; then log-linear between them
toward 3.5, 1284, 1300, not taken, cost 2.93, in band); the webbing's power law 0.49 (median
2.05, half-way up: 2.1, taken, so 2.2, cost 8.68: CR 9.86, CD 7.49; then 2.2 x 3.5 / 8.68 =
0.887, 0.89, not taken, cost 6.30: CR 7.26, CD 5.34; then 0.89 x 3.5 / 6.30 = 0.494, 0.49, not
taken, cost 4.71, in band); the webbing hysteresis 0.24 (redrawn; median 0.52; 0.52-0.58
taken, so 0.59, cost 8.44: CR 9.17, CD 7.72; then 0.59 x 3.5 / 8.44 = 0.245, 0.24, not taken,
cost 2.82, in band); the encoder ring 0.26 (redrawn; median 0.33; 0.33-0.42 taken, so 0.43,
cost 6.01: CR 6.47, CD 5.55, just above the band; then 0.43 x 3.5 / 6.01 = 0.250, 0.25, taken,
so 0.26, not taken, cost 3.88, in band); the CD pot's non-linearity 0.24 (median 0.225,
half-way up: 0.23, taken), at the rule's first size, in band; the late pulse 3.69 ms and the
late BRS 3.26 ms as drawn, in the delay's band; the BRS decoder's 6 edges a step (a whole
number; median 4.5, half-way up: 5, set AG's, taken, so 6; not banded). The two-effect case
(redrawn), the relief-vented bag on FULL beside the rubber stop on R16+SLED: at the first
sizes, 0.44 (median 0.43, taken) and 2.4e7 N/m^1.5 (median 2.15e7, half-way up: 2.2e7; 2.2e7,
2.3e7 taken), the bag alone 5.14 (CR 5.44, CD 4.84) and the stop alone 4.01 (CR 1.56, CD
6.47), each in band, the two together 7.05 (CR 6.55, CD 7.56), above it; by rule 4 the higher
alone, the bag, stepped: 0.44 x 3.75 / 7.05 = 0.234, 0.23, not taken: together 4.94 (CR 3.62,
CD 6.25), the bag alone 1.98 (CR 2.19, CD 1.77), the stop alone 4.01 as before: all three in
band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; 2 cores shared with other work): lock_r16_sled 91.47 -> 85.64
(5.83; CR 1.64, CD 10.02); foam_r16_sled 90.46 -> 87.53 (2.93; CR 2.28, CD 3.58);
hysteresis_sled_full 92.13 -> 89.31 (2.82; CR 3.06, CD 2.58); power_sled_full 90.47 -> 85.76
(4.71; CR 5.47, CD 3.95); airbag_sled_full 91.38 -> 88.90 (2.48; CR 2.71, CD 2.24);
submarine_sled 90.99 -> 85.89 (5.10; CR 2.02, CD 8.19); eccentric_all 93.63 -> 89.74 (3.88; CR
4.18, CD 3.59); two_relief_full_bumper_r16_sled 92.80 -> 87.86 (4.94; CR 3.62, CD 6.25; the
relief-vented bag alone 1.98: CR 2.19, CD 1.77; the rubber stop alone 4.01: CR 1.56, CD 6.47);
pulse_late_3p69ms 90.76 -> 88.11 (2.66; CR 3.74, CD 1.57); brs_late_3p26ms 90.02 -> 87.46
(2.55; CR 3.11, CD 2.00); cd_pot_nonlinear 91.23 -> 88.74 (2.49; CR 3.01, CD 1.98);
broken_brs_quadrature 94.22 -> 84.16 (10.06; CR 12.69, CD 7.42; flagging the test is the
verdict asked; not banded, by the rule). The clean cases' fits (python -m
benchmarks.heldout.costs --set ai --case hai_clean48 --case hai_clean96): clean48 91.2,
clean96 91.0. Each effect of the two-effect case alone: the case's seed with the other effect's
size 0 (kept in the case's list, so the dummies and pulses draw as they do in the case), against
the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AI: list[Case] = [
    Case("hai_clean48", 44103, _mix(0, 6, 0), _mix(0, 1, 5), 48,
         notes="clean thorax, 48-count BRS; estimated on SLED alone; FULL validated five "
               "times, never estimated; R16 neither estimated nor validated"),
    Case("hai_clean96", 44207, _mix(0, 0, 6), _mix(0, 4, 2), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone; SLED validated four "
               "times, never estimated; R16 neither estimated nor validated"),
    Case("hai_lock_r16_sled", 44309, _mix(0, 4, 2), _mix(4, 0, 2), 48,
         (Effect("rib_lock", 0.093, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the chest locking up near a 93 mm deflection, each rib's force gaining "
               "k d^2 / (d_l - d), on R16 and SLED; R16 validated four times, never estimated; "
               "SLED estimated four times, never validated; FULL clean, 2 estimation tests, "
               "validated twice"),
    Case("hai_foam_r16_sled", 44411, _mix(0, 2, 4), _mix(5, 1, 0), 96,
         (Effect("rib_foam", 1300.0, ("R16", "SLED")),), (("chest_rate_damping", "R16+SLED"),),
         notes="the sternum's damping pad engaging as the chest closes, c (d / 30 mm) d' in "
               "compression, c = 1300 N s/m, on R16 and SLED; R16 validated five times, never "
               "estimated; SLED estimated twice, validated once; FULL clean, 4 estimation "
               "tests, never validated"),
    Case("hai_hysteresis_sled_full", 44515, _mix(4, 2, 0), _mix(0, 1, 5), 128,
         (Effect("webbing_hysteresis", 0.24, ("SLED", "FULL")),),
         (("belt_unloading", "SLED+FULL"),),
         notes="the webbing's elastic force 24 % lower while it shortens (set B's form), on "
               "SLED and FULL; SLED estimated twice, validated once; FULL validated five "
               "times, never estimated; R16 clean, 4 estimation tests, never validated "
               "(redrawn three times)"),
    Case("hai_power_sled_full", 44617, _mix(3, 3, 0), _mix(3, 1, 2), 48,
         (Effect("webbing_power", 0.49, ("SLED", "FULL")),), (("belt_stiffening", "SLED+FULL"),),
         notes="the webbing stiffens with its stretch, F += a k e (e/e_ref)^2 (e_ref 15 mm "
               "chest side, 25 mm up to the retractor), a = 0.49, on SLED and FULL; SLED "
               "estimated three times, validated once; FULL validated twice, never estimated; "
               "R16 clean, 3 estimation tests, validated three times"),
    Case("hai_airbag_sled_full", 44719, _mix(3, 3, 0), _mix(4, 1, 1), 48,
         (Effect("airbag", 0.62, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="set A's vented driver bag at fill 0.62 on the rigs with an interior, SLED and "
               "FULL; SLED estimated three times, validated once; FULL validated once, never "
               "estimated; R16 without a bag, 3 estimation tests, validated four times"),
    Case("hai_submarine_sled", 44823, _mix(0, 4, 2), _mix(1, 4, 1), 48,
         (Effect("pelvis_submarine", 6000.0, ("SLED",)),), (("pelvis_coupling", "SLED"),),
         notes="the pelvis on lap belt and seat (set A's lumbar and lap stiffness), the lap "
               "belt slipping over the iliac wings past 6000 N (submarining), on SLED alone; "
               "SLED estimated four times, validated four times; FULL clean, 2 estimation "
               "tests, validated once; R16 validated once, never estimated"),
    Case("hai_eccentric_all", 44927, _mix(0, 6, 0), _mix(1, 2, 3), 64,
         (Effect("brs_eccentric", 0.26),), (("input_gain", "all"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.26 sin(th + phase), on "
               "every rig; estimated on SLED alone, validated there twice; R16 and FULL "
               "validated (once, three times), never estimated (redrawn twice)"),
    Case("hai_two_relief_full_bumper_r16_sled", 44031, _mix(2, 2, 2), _mix(0, 2, 4), 64,
         (Effect("airbag_relief", 0.23, ("FULL",)),
          Effect("rib_bumper", 2.4e7, ("R16", "SLED"))),
         (("airbag_contact", "FULL"), ("chest_stiffening", "R16+SLED")),
         notes="two kinds on two rigs: the car's (FULL) driver bag with a pressure-relief "
               "vent at fill 0.23; the lower sternum meeting the spine box's rubber stop, "
               "Hertz, K = 2.4e7 N/m^1.5 (R16 and SLED); each rig estimated twice; R16 never "
               "validated; the pairing set K's (reused, no pairing left; redrawn twice)"),
    Case("hai_pulse_late_3p69ms", 44137, _mix(6, 0, 0), _mix(0, 3, 3), 64,
         (Effect("pulse_late", 0.00369),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.69 ms after its record; estimated on R16 alone, "
               "never validated there; SLED and FULL validated three times each, never "
               "estimated"),
    Case("hai_brs_late_3p26ms", 44241, _mix(6, 0, 0), _mix(1, 1, 4), 48,
         (Effect("brs_late", 0.00326),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.26 ms after the BRS records it; estimated on R16 "
               "alone; SLED and FULL validated (once, four times), never estimated"),
    Case("hai_cd_pot_nonlinear", 44343, _mix(0, 0, 6), _mix(0, 6, 0), 96,
         (Effect("cd_pot_nonlinear", 0.24),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot over-reads at large deflection, CD = d (1 + 0.24 (d / 25 mm)^2) "
               "(a cubic static non-linearity, 24 % high at 25 mm), every test; CR and the "
               "inputs untouched: a residual in cd only, a static function of cd, zero at "
               "rest"),
    Case("hai_broken_brs_quadrature", 44447, _mix(0, 4, 2), _mix(2, 0, 4), 128,
         (Effect("brs_quadrature", 6.0, tests=("FULL_001",)),), (),
         expect_broken=("FULL_001",),
         notes="FULL_001, an estimation test: its BRS decoder counts six edges a step while "
               "the test's header keeps the spindle's 128 counts/rev: its belt reads six times "
               "the spool's angle, the pretensioner's pay-in and the load limiter's pay-out "
               "six times those of the other FULL tests; its other channels and every other "
               "test clean"),
]

BY_NAME_AI = {c.name: c for c in SET_AI}
ONE_PHYSICAL_AI = ("hai_lock_r16_sled", "hai_foam_r16_sled", "hai_hysteresis_sled_full",
                   "hai_power_sled_full", "hai_airbag_sled_full", "hai_submarine_sled",
                   "hai_eccentric_all")
