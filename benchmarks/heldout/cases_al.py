"""Held-out set AL: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AK (``cases.py`` ... ``cases_ak.py``).

Set AK's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works, with one change: ``draw_al.py`` (``numpy.random.default_rng(47000)``, set
W's ``drawn``, the pairings of A-AK taken, save where a case has none free for its rigs: it
then reuses one of A-AK's, ``reuse_all``, set Z's reuse extended to every case; ``python -m
benchmarks.heldout.draw_al`` prints the draw). The cases follow the draw; only the sizes are
set, by costs, by the rule ``draw_al.py`` wrote down before the first draw (``SIZING``; set
AK's, set AJ's, set AI's, set AH's, set AG's, set AF's, set AE's, its rule 4 as mended there).
``test_set_al_follows_its_draw`` holds the draw and the cases together.

Six cases run a pairing an earlier set ran (``draw_al.py``'s docstring: none was free for their
rigs), each drawn uniformly among the pairings its rules allow that A-AK ran: the chest's
stiffening, est 0/3/3, val 6/0/0 (set AC's ``hac_maxwell_r16_sled``); the chest's rate
damping, est 3/0/3, val 3/1/2 (set S's ``hs_two_set_r16_hardening_full``); the bag, est
4/0/2, val 2/2/2 (set K's ``hk_two_effects_same``); the pelvis, est 2/2/2, val 3/1/2 (set E's
``he_airbag_sealed``); the input gain as redrawn, est 3/3/0, val 2/0/4 (set AG's
``hag_airbag_sled_full``; its first draw's, est 2/0/4, val 2/0/4, set K's ``hk_few_tests``,
reused as well); the two-effect case, est 0/3/3, val 1/3/2 (set V's ``hv_squeeze_full``). The
other eight cases drew free pairings. No two cases of AL share a pairing.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bumper, R16+SLED, 64, est 0/3/3, val 6/0/0 (reused); chest_rate_damping:
rib_squeeze, SLED+FULL, 48, est 3/0/3, val 3/1/2 (reused); belt_unloading: webbing_hysteresis,
R16, 96, est 3/3/0, val 6/0/0; belt_stiffening: webbing_toe, R16+SLED+FULL, 64, est 0/0/6, val
4/1/1; airbag_contact: airbag_fabric, SLED+FULL, 48, est 4/0/2, val 2/2/2 (reused);
pelvis_coupling: pelvis_submarine, SLED+FULL, 48, est 2/2/2, val 3/1/2 (reused); input_gain:
brs_eccentric, SLED+FULL, 48, est 3/3/0, val 2/0/4 (reused; redrawn by 47001, below); the
two-effect case belt_stiffening (webbing_knee) on SLED beside input_gain (brs_eccentric) on
FULL, 48, est 0/3/3, val 1/3/2 (reused); the late pulse 3.27 ms, 64, est 0/6/0, val 3/1/2; the
late BRS 4.64 ms, 128, est 0/0/6, val 1/5/0; the transducer error on CD, cd_sag, 64, est 0/6/0,
val 4/2/0; the broken test's channel CR, cr_hum, 48, est 0/6/0, val 1/5/0, the test SLED_005;
clean48 est 0/6/0, val 5/1/0; clean96 est 0/6/0, val 0/3/3.

Redrawn (``draw_al.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken; the seed names the
generator that drew the rejected draw again). None at the draw (with a pairing always left to
draw, no draw is impossible for want of one); at the sizes:
- 47001, the input gain: its first draw, spool_buildup on FULL (96 counts, est 2/0/4, val
  2/0/4, reused), cost the grey-box 0.99 at the rule's first size, 13 mm of radius per wrap
  (92.05 -> 91.07; CR 0.97, CD 1.00; median 0.012, set X's one, taken), below the band; the
  rule's next, 0.013 x 3.5 / 0.99 = 0.046, clipped to three times, 39 mm per wrap, would leave
  the spool's 17 mm radius below zero within 7 rad of pay-out (zero past 15.3 mm per wrap, 17
  mm x 2 pi / 7): a run-away, impossible without costing it (as set AI judged, set AC's and
  set AD's build-ups the same); drawn again by 47001: brs_eccentric on SLED+FULL, 48 counts,
  est 3/3/0, val 2/0/4 (none free for SLED+FULL: reused, set AG's).

Sizes (the rule's; A-AK's values stepped off; the medians over every case of A-AK giving the
key; a median half-way rounded up): the bumper 2.6e7 N/m^1.5 (median 2.25e7, half-way up:
2.3e7; 2.3e7-2.5e7 taken), the squeeze film 460 N s/m (median 425, half-way up: 430; 430-450
taken), the fabric bag 0.79 (median 0.755, half-way up: 0.76; 0.76-0.78 taken), the lap belt's
slip force 6100 N (median 6000, taken), the encoder ring 0.45 (median 0.335, half-way up: 0.34;
0.34-0.44 taken), CD's sag 0.66 (median 0.65, taken), each at the rule's first size, in band;
the hysteresis 0.25 (median 0.515, half-way up: 0.52; 0.52-0.58 taken, so 0.59, cost 8.54: CR
9.09, CD 7.99; then 0.59 x 3.5 / 8.54 = 0.242, 0.24, taken, so 0.25, cost 2.44, in band); the
toe 0.63 (median 0.20, taken, so 0.21, cost 0.97: CR 0.91, CD 1.02; then 0.21 x 3.5 / 0.97 =
0.758, clipped to three times, 0.63, not taken, cost 2.17, in band); the late pulse 3.27 ms and
the late BRS 4.64 ms as drawn, in the delay's band; the broken test's hum 6.1 g (rule 5: by
rule 1 only; median 6.0, set F's one, taken; not banded). The two-effect case, the webbing knee
on SLED beside the encoder ring on FULL, at the first sizes, 2.7 (median 2.3; 2.3-2.6 taken)
and 0.45 (the same key's first size, as the single's): the knee alone 2.78 (CR 2.92, CD 2.63),
the ring alone 2.44 (CR 2.94, CD 1.94), the two together 4.48 (CR 4.86, CD 4.10): all three in
band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; 2 cores shared with other work): bumper_r16_sled 93.30 -> 90.13
(3.16; CR 2.52, CD 3.81); squeeze_sled_full 92.03 -> 89.06 (2.96; CR 1.81, CD 4.11);
hysteresis_r16 92.68 -> 90.24 (2.44; CR 2.62, CD 2.25); toe_all 92.15 -> 89.99 (2.17; CR 2.13,
CD 2.20); fabric_sled_full 91.68 -> 87.80 (3.88; CR 4.52, CD 3.24); submarine_sled_full 90.52
-> 86.65 (3.87; CR 1.82, CD 5.92); eccentric_sled_full 88.60 -> 85.38 (3.22; CR 4.05, CD
2.39); two_knee_sled_eccentric_full 92.34 -> 87.85 (4.48; CR 4.86, CD 4.10; the knee alone
2.78, the ring alone 2.44); pulse_late_3p27ms 91.01 -> 87.26 (3.76; CR 4.36, CD 3.15);
brs_late_4p64ms 92.23 -> 87.14 (5.09; CR 5.91, CD 4.26); cd_sag 93.56 -> 88.88 (4.67; CR 1.65,
CD 7.69); broken_cr_hum 90.52 -> 90.49 (0.02; CR 0.04, CD 0.01; flagging the test is the
verdict asked; not banded, by the rule). The clean cases' fits (python -m
benchmarks.heldout.costs --set al --case hal_clean48 --case hal_clean96): clean48 91.3 (CR
92.5, CD 90.1), clean96 91.5 (CR 93.2, CD 89.9). Each effect of the two-effect case alone: the
case's seed with the other effect's size 0 (kept in the case's list, so the dummies and pulses
draw as they do in the case), against the same twin.
No size costed ran away (``test_set_al_has_no_run_aways``'s limits, each against its rig's
median over the set's other cases' tests at the first sizes); the build-up's next size was
found impossible by the spool's radius, uncosted.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AL: list[Case] = [
    Case("hal_clean48", 47103, _mix(0, 6, 0), _mix(5, 1, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on SLED alone, validated there once; "
               "R16 validated five times, never estimated; FULL neither estimated nor "
               "validated"),
    Case("hal_clean96", 47207, _mix(0, 6, 0), _mix(0, 3, 3), 96,
         notes="clean thorax, 96-count BRS; estimated on SLED alone, validated there three "
               "times; FULL validated three times, never estimated; R16 neither estimated nor "
               "validated"),
    Case("hal_bumper_r16_sled", 47309, _mix(0, 3, 3), _mix(6, 0, 0), 64,
         (Effect("rib_bumper", 2.6e7, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the lower sternum meets the spine box's rubber bumper past 15 mm, Hertz, "
               "K pen^1.5 at K 2.6e7 N/m^1.5, on R16 and SLED; R16 validated six times, never "
               "estimated; SLED estimated three times, never validated; FULL clean, 3 "
               "estimation tests, never validated; the pairing set AC's (reused, none free)"),
    Case("hal_squeeze_sled_full", 47411, _mix(3, 0, 3), _mix(3, 1, 2), 48,
         (Effect("rib_squeeze", 460.0, ("SLED", "FULL")),),
         (("chest_rate_damping", "SLED+FULL"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 460 N s/m at "
               "rest, on SLED and FULL; SLED validated once, never estimated; FULL estimated "
               "three times, validated twice; R16 clean, 3 estimation tests, validated three "
               "times; the pairing set S's (reused, none free)"),
    Case("hal_hysteresis_r16", 47515, _mix(3, 3, 0), _mix(6, 0, 0), 96,
         (Effect("webbing_hysteresis", 0.25, ("R16",)),), (("belt_unloading", "R16"),),
         notes="the webbing's elastic force 25 % lower while it shortens (set B's form), on "
               "R16 alone; R16 estimated three times, validated six times; SLED clean, 3 "
               "estimation tests, never validated; FULL neither estimated nor validated"),
    Case("hal_toe_all", 47617, _mix(0, 0, 6), _mix(4, 1, 1), 64,
         (Effect("webbing_toe", 0.63),), (("belt_stiffening", "all"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.63, on "
               "every rig; estimated on FULL alone, validated there once; R16 and SLED "
               "validated (four times, once), never estimated"),
    Case("hal_fabric_sled_full", 47719, _mix(4, 0, 2), _mix(2, 2, 2), 48,
         (Effect("airbag_fabric", 0.79, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="a ventless bag leaking through its fabric at fill 0.79, on SLED and FULL; "
               "SLED validated twice, never estimated; FULL estimated twice, validated twice; "
               "R16 without a bag, 4 estimation tests, validated twice; the pairing set K's "
               "(reused, none free)"),
    Case("hal_submarine_sled_full", 47823, _mix(2, 2, 2), _mix(3, 1, 2), 48,
         (Effect("pelvis_submarine", 6100.0, ("SLED", "FULL")),),
         (("pelvis_coupling", "SLED+FULL"),),
         notes="the pelvis on lap belt and seat (set A's lumbar and lap stiffness), the lap "
               "belt slipping over the iliac wings past 6100 N (submarining), on SLED and "
               "FULL; SLED estimated twice, validated once; FULL estimated twice, validated "
               "twice; R16 clean, 2 estimation tests, validated three times; the pairing set "
               "E's (reused, none free)"),
    Case("hal_eccentric_sled_full", 47927, _mix(3, 3, 0), _mix(2, 0, 4), 48,
         (Effect("brs_eccentric", 0.45, ("SLED", "FULL")),), (("input_gain", "SLED+FULL"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.45 sin(th + phase), on "
               "SLED and FULL; SLED estimated three times, never validated; FULL validated "
               "four times, never estimated; R16 clean, 3 estimation tests, validated twice; "
               "the pairing set AG's (reused, none free; redrawn once)"),
    Case("hal_two_knee_sled_eccentric_full", 47031, _mix(0, 3, 3), _mix(1, 3, 2), 48,
         (Effect("webbing_knee", 2.7, ("SLED",)),
          Effect("brs_eccentric", 0.45, ("FULL",))),
         (("belt_stiffening", "SLED"), ("input_gain", "FULL")),
         notes="two kinds on two rigs: the webbing's stiffness growing by 2.7 x k past its "
               "knee stretch (SLED); the BRS encoder ring off-centre, the angle read th + "
               "0.45 sin(th + phase) (FULL); SLED and FULL each estimated three times; R16 "
               "validated once, never estimated; the pairing set V's (reused, none free)"),
    Case("hal_pulse_late_3p27ms", 47137, _mix(0, 6, 0), _mix(3, 1, 2), 64,
         (Effect("pulse_late", 0.00327),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.27 ms after its record; estimated on SLED alone, "
               "validated there once; R16 and FULL validated (three times, twice), never "
               "estimated"),
    Case("hal_brs_late_4p64ms", 47241, _mix(0, 0, 6), _mix(1, 5, 0), 128,
         (Effect("brs_late", 0.00464),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.64 ms after the BRS records it; estimated on FULL "
               "alone, never validated there; R16 and SLED validated (once, five times), "
               "never estimated"),
    Case("hal_cd_sag", 47343, _mix(0, 6, 0), _mix(4, 2, 0), 64,
         (Effect("cd_sag", 0.66),), (), expect_note=UNEXPLAINED_CD,
         notes="the CD pot's excitation sags after the trigger (not ratiometric): CD reads "
               "d (1 - 0.66 (1 - e^(-t/60 ms))), every test; CR, pulse and BRS untouched: a "
               "residual in cd only"),
    Case("hal_broken_cr_hum", 47447, _mix(0, 6, 0), _mix(1, 5, 0), 48,
         (Effect("cr_hum", 6.1, tests=("SLED_005",)),), (), expect_broken=("SLED_005",),
         notes="SLED_005, an estimation test: its spine accelerometer picks up 50 Hz mains "
               "hum through a ground loop, 6.1 g amplitude, from before the crash to the end "
               "(CFC 180 passes it): a sine on the flat pre-crash line; its other channels "
               "and every other test clean"),
]

BY_NAME_AL = {c.name: c for c in SET_AL}
ONE_PHYSICAL_AL = ("hal_bumper_r16_sled", "hal_squeeze_sled_full", "hal_hysteresis_r16",
                   "hal_toe_all", "hal_fabric_sled_full", "hal_submarine_sled_full",
                   "hal_eccentric_sled_full")
