"""Held-out set AJ: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AI (``cases.py`` ... ``cases_ai.py``).

Set AI's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_aj.py`` (``numpy.random.default_rng(45000)``, set W's ``drawn``,
the pairings of A-AI taken, save the two-effect case's: with none free, it reuses one of
A-AI's, ``reuse_two``; ``python -m benchmarks.heldout.draw_aj`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_aj.py`` wrote down before
the first draw (``SIZING``; set AI's, set AH's, set AG's, set AF's, set AE's, its rule 4 as
mended there). ``test_set_aj_follows_its_draw`` holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 3/2/1, is set F's (``hf_clean48``; set AH's
two-effect case ran it too): the one pairing of this set an earlier set ran (``draw_aj.py``'s
docstring: none was free for its rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bumper, SLED+FULL, 96, est 4/0/2, val 0/1/5; chest_rate_damping:
rib_squeeze, FULL, 128, est 0/4/2, val 0/0/6; belt_unloading: webbing_set, R16+SLED, 48, est
0/3/3, val 2/3/1; belt_stiffening: webbing_knee, R16+SLED, 64, est 0/2/4, val 4/0/2;
airbag_contact: airbag_sealed, SLED, 96, est 4/2/0, val 1/5/0; pelvis_coupling: pelvis_knee,
FULL, 48, est 2/0/4, val 1/0/5 (redrawn by 45001, below); input_gain: brs_eccentric, R16, 128,
est 2/4/0, val 3/0/3; the two-effect case airbag_contact (airbag_relief) on SLED beside
pelvis_coupling (lumbar_path) on R16+FULL, 64, est 2/2/2, val 3/2/1 (an earlier set's pairing,
reused); the late pulse 4.74 ms, 128, est 0/6/0, val 2/3/1; the late BRS 2.37 ms, 128, est
4/2/0, val 3/0/3 (redrawn by 45004, below); the transducer error on CR, cr_zero_shift, 96, est
0/6/0, val 0/2/4; the broken test's channel the pulse, pulse_zero_shift, 48, est 2/4/0, val
6/0/0, the test SLED_007; clean48 est 4/0/2, val 1/0/5; clean96 est 3/3/0, val 5/0/1.

Redrawn (``draw_aj.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken; each item below names the
seed that drew the rejected draw again). A run-away is judged by
``test_set_aj_has_no_run_aways``'s limits, and, as set AG judged, a size that runs away makes
the draw impossible whatever its cost; a delay is its own size (rule 3): out of the delay's
band, 1-6 points, the draw is impossible:
- 45001, the pelvis coupling: its first draw, pelvis_submarine on SLED (48 counts, est 0/2/4,
  val 2/4/0), at the rule's first size, a slip force of 6100 N (median 6000, set AI's, taken),
  ran away (found by the test at the first sizes, before any cost): SLED_002 paid out 75.0 deg
  of the spool, not above a third of the set's SLED median, 225.0 (232.5 over the set's other
  cases' tests), its twin 135.0; its SLED tests 75-202.5 deg against their twin's 135-322.5:
  impossible. Costed for the record: 7.50 (89.23 -> 81.73; CR 4.14, CD 10.86), above the band
  as well.
- 45002, the late BRS: its first draw, 1.72 ms (128 counts, est 6/0/0, val 3/1/2), cost 0.80
  (92.26 -> 91.47; CR 1.02, CD 0.58), below the delay's band: impossible.
- 45003, the late BRS again: 45002's draw, 2.12 ms (48 counts, est 0/6/0, val 2/1/3), cost
  0.37 (89.34 -> 88.97; CR 0.50, CD 0.24): impossible.
- 45004, the late BRS again: 45003's draw, 1.16 ms (128 counts, est 0/0/6, val 1/5/0), cost
  0.06 (92.79 -> 92.73; CR -0.05, CD 0.17): impossible; drawn again by 45004: 2.37 ms, 128
  counts, est 4/2/0, val 3/0/3.

Sizes (the rule's; A-AI's values stepped off; the medians over every case of A-AI giving the
key; a median half-way rounded up): the rubber stop 2.5e7 N/m^1.5 (median 2.2e7; 2.2e7-2.4e7
taken), the webbing set 0.66 (median 0.57; 0.57-0.65 taken), the webbing knee 2.5 (median
2.25, half-way up: 2.3; 2.3, 2.4 taken), the sealed bag 0.42 (median 0.39; 0.39-0.41 taken),
the knee bolster's pelvis path 0.24 (redrawn; median 0.21; 0.21-0.23 taken), the encoder ring
0.43 (median 0.325, half-way up: 0.33; 0.33-0.42 taken), the CR zero shift 2.2 g (median
2.05, half-way up: 2.1, set AA's, taken), each at the rule's first size, in band; the squeeze
film 200 N s/m (median 430; 430-450 taken, so 460, cost 8.07: CR 4.97, CD 11.18; then 460 x
3.5 / 8.07 = 199.5, 200, not taken, cost 3.08, in band); the late pulse 4.74 ms and the late
BRS 2.37 ms as drawn, in the delay's band; the pulse channel's zero shift 4.1 g (median 4.0,
set C's one, taken; not banded). The two-effect case, the relief-vented bag on SLED beside
the lumbar path on R16+FULL, at the first sizes, 0.42 (median 0.415, half-way up: 0.42, not
taken) and 0.54 (median 0.53, set AH's, taken): the bag alone 1.69 (CR 1.96, CD 1.42), the
lumbar path alone 5.94 (CR 2.19, CD 9.70), the two together 4.59 (CR 2.09, CD 7.08): all
three in band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; 2 cores shared with other work): bumper_sled_full 92.30 -> 87.79
(4.51; CR 2.61, CD 6.42); squeeze_full 92.39 -> 89.31 (3.08; CR 1.90, CD 4.26); set_r16_sled
90.95 -> 87.89 (3.06; CR 3.75, CD 2.37); knee_r16_sled 91.62 -> 87.20 (4.42; CR 5.34, CD 3.49);
sealed_sled 91.71 -> 88.32 (3.40; CR 3.80, CD 2.99); pelvis_knee_full 86.28 -> 84.02 (2.26; CR
2.47, CD 2.05); eccentric_r16 91.04 -> 86.75 (4.29; CR 5.21, CD 3.37);
two_relief_sled_lumbar_r16_full 91.42 -> 86.83 (4.59; CR 2.09, CD 7.08; the relief-vented bag
alone 1.69: CR 1.96, CD 1.42; the lumbar path alone 5.94: CR 2.19, CD 9.70); pulse_late_4p74ms
89.01 -> 84.92 (4.10; CR 6.65, CD 1.54); brs_late_2p37ms 91.62 -> 90.16 (1.47; CR 1.95, CD
0.98); cr_zero_shift 92.15 -> 89.33 (2.83; CR 4.31, CD 1.35); broken_pulse_zero_shift 92.29 ->
91.55 (0.73; CR 0.69, CD 0.78; flagging the test is the verdict asked; not banded, by the
rule). The clean cases' fits (python -m benchmarks.heldout.costs --set aj --case haj_clean48
--case haj_clean96): clean48 92.8, clean96 93.7. Each effect of the two-effect case alone: the
case's seed with the other effect's size 0 (kept in the case's list, so the dummies and pulses
draw as they do in the case), against the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AJ: list[Case] = [
    Case("haj_clean48", 45103, _mix(4, 0, 2), _mix(1, 0, 5), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 and FULL; FULL validated five "
               "times, R16 once; SLED neither estimated nor validated"),
    Case("haj_clean96", 45207, _mix(3, 3, 0), _mix(5, 0, 1), 96,
         notes="clean thorax, 96-count BRS; estimated on R16 and SLED; R16 validated five "
               "times; FULL validated once, never estimated"),
    Case("haj_bumper_sled_full", 45309, _mix(4, 0, 2), _mix(0, 1, 5), 96,
         (Effect("rib_bumper", 2.5e7, ("SLED", "FULL")),),
         (("chest_stiffening", "SLED+FULL"),),
         notes="the lower sternum meeting the spine box's rubber stop, Hertz, K = 2.5e7 "
               "N/m^1.5, on SLED and FULL; SLED validated once, never estimated; FULL "
               "estimated twice, validated five times; R16 clean, 4 estimation tests, never "
               "validated"),
    Case("haj_squeeze_full", 45411, _mix(0, 4, 2), _mix(0, 0, 6), 128,
         (Effect("rib_squeeze", 200.0, ("FULL",)),), (("chest_rate_damping", "FULL"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 200 N s/m at "
               "rest, on FULL alone; FULL estimated twice, validated six times; SLED clean, 4 "
               "estimation tests, never validated; R16 neither estimated nor validated"),
    Case("haj_set_r16_sled", 45515, _mix(0, 3, 3), _mix(2, 3, 1), 48,
         (Effect("webbing_set", 0.66, ("R16", "SLED")),), (("belt_unloading", "R16+SLED"),),
         notes="the chest-side webbing unloads to a set of 0.66 x its peak stretch, on R16 "
               "and SLED; R16 validated twice, never estimated; SLED estimated three times, "
               "validated three times; FULL clean, 3 estimation tests, validated once"),
    Case("haj_knee_r16_sled", 45617, _mix(0, 2, 4), _mix(4, 0, 2), 64,
         (Effect("webbing_knee", 2.5, ("R16", "SLED")),), (("belt_stiffening", "R16+SLED"),),
         notes="the webbing's stiffness grows by 2.5 x k past its knee stretch, on R16 and "
               "SLED; R16 validated four times, never estimated; SLED estimated twice, never "
               "validated; FULL clean, 4 estimation tests, validated twice"),
    Case("haj_sealed_sled", 45719, _mix(4, 2, 0), _mix(1, 5, 0), 96,
         (Effect("airbag_sealed", 0.42, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="an unvented gas bag at fill 0.42 of the vented one's, on SLED alone; SLED "
               "estimated twice, validated five times; R16 without a bag, 4 estimation tests, "
               "validated once; FULL neither estimated nor validated"),
    Case("haj_pelvis_knee_full", 45823, _mix(2, 0, 4), _mix(1, 0, 5), 48,
         (Effect("pelvis_knee", 0.24, ("FULL",)),), (("pelvis_coupling", "FULL"),),
         notes="the pelvis on lap belt and seat at 0.24 x set A's lumbar and lap stiffness, "
               "its knees meeting a knee bolster past a 45 mm gap, on FULL alone; FULL "
               "estimated four times, validated five times; R16 clean, 2 estimation tests, "
               "validated once; SLED neither estimated nor validated (redrawn once)"),
    Case("haj_eccentric_r16", 45927, _mix(2, 4, 0), _mix(3, 0, 3), 128,
         (Effect("brs_eccentric", 0.43, ("R16",)),), (("input_gain", "R16"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.43 sin(th + phase), on "
               "R16 alone; R16 estimated twice, validated three times; SLED clean, 4 "
               "estimation tests, never validated; FULL validated three times, never "
               "estimated"),
    Case("haj_two_relief_sled_lumbar_r16_full", 45031, _mix(2, 2, 2), _mix(3, 2, 1), 64,
         (Effect("airbag_relief", 0.42, ("SLED",)),
          Effect("lumbar_path", 0.54, ("R16", "FULL"))),
         (("airbag_contact", "SLED"), ("pelvis_coupling", "R16+FULL")),
         notes="two kinds on two rigs: the SLED rig's bag (its interior) with a "
               "pressure-relief vent at fill 0.42; the pelvis on lap belt and seat, its "
               "lumbar spine to the thoracic spine, at scale 0.54 (R16 and FULL); each rig "
               "estimated twice; the pairing set F's (reused, no pairing left)"),
    Case("haj_pulse_late_4p74ms", 45137, _mix(0, 6, 0), _mix(2, 3, 1), 128,
         (Effect("pulse_late", 0.00474),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.74 ms after its record; estimated on SLED alone, "
               "validated there three times; R16 and FULL validated (twice, once), never "
               "estimated"),
    Case("haj_brs_late_2p37ms", 45241, _mix(4, 2, 0), _mix(3, 0, 3), 128,
         (Effect("brs_late", 0.00237),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.37 ms after the BRS records it; R16 estimated four "
               "times, validated three times; SLED estimated twice, never validated; FULL "
               "validated three times, never estimated (redrawn three times)"),
    Case("haj_cr_zero_shift", 45343, _mix(0, 6, 0), _mix(0, 2, 4), 96,
         (Effect("cr_zero_shift", 2.2),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's zero shifts under the shock: once its reading first "
               "passes 20 g it moves by +2.2 g over 4 ms and stays there, every test; CD and "
               "the inputs untouched: a residual in cr only, a step at a level"),
    Case("haj_broken_pulse_zero_shift", 45447, _mix(2, 4, 0), _mix(6, 0, 0), 48,
         (Effect("pulse_zero_shift", 4.1, tests=("SLED_007",)),), (),
         expect_broken=("SLED_007",),
         notes="SLED_007, an estimation test: its tunnel accelerometer shifts its zero by "
               "4.1 g at 11 ms, in the crash-box spike (a piezoresistive sensor's zero shift "
               "after a shock): the channel reads 4.1 g too much from then on, still 4.1 g "
               "after the sled is at rest; its other channels and every other test clean"),
]

BY_NAME_AJ = {c.name: c for c in SET_AJ}
ONE_PHYSICAL_AJ = ("haj_bumper_sled_full", "haj_squeeze_full", "haj_set_r16_sled",
                   "haj_knee_r16_sled", "haj_sealed_sled", "haj_pelvis_knee_full",
                   "haj_eccentric_r16")
