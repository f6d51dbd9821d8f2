"""Held-out set AF: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AE (``cases.py`` ... ``cases_ae.py``).

Set AE's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_af.py`` (``numpy.random.default_rng(41000)``, set W's ``drawn``,
the pairings of A-AE taken, save the two-effect case's: with none free, it reuses one of
A-AE's, ``reuse_two``; ``python -m benchmarks.heldout.draw_af`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_af.py`` wrote down before
the first draw (``SIZING``; set AE's, its rule 4 as mended there). ``test_set_af_follows_its_
draw`` holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 2/1/3, is set A's (``h_ribs_bottoming`` and
``h_pulse_late_4ms``): the one pairing of this set an earlier set ran (``draw_af.py``'s
docstring: none was free for its rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_fung, SLED+FULL, 48, est 3/3/0, val 0/1/5; chest_rate_damping:
rib_friction, SLED, 48, est 0/3/3, val 1/5/0; belt_unloading: webbing_hysteresis, R16+FULL,
48, est 0/4/2, val 1/0/5; belt_stiffening: webbing_toe, R16+FULL, 128, est 2/4/0, val 5/0/1;
airbag_contact: airbag_sealed, SLED, 48, est 4/2/0, val 0/5/1; pelvis_coupling: lumbar_path,
R16+SLED, 64, est 2/0/4, val 3/3/0; input_gain: brs_eccentric, SLED, 64, est 0/2/4, val
0/6/0; the two-effect case belt_stiffening (webbing_toe) on FULL beside chest_stiffening
(rib_bumper) on R16+SLED, 96, est 2/2/2, val 2/1/3 (an earlier set's pairing, reused); the
late pulse 4.07 ms, 128, est 2/0/4, val 1/5/0; the late BRS 2.98 ms, 128, est 0/0/6, val
1/1/4 (redrawn by 41001, below); the transducer error on CR, cr_damped, 64, est 6/0/0, val
0/1/5; the broken test's channel BRS, brs_poll, 48, est 0/3/3, val 4/1/1, the test FULL_001;
clean48 est 6/0/0, val 0/6/0; clean96 est 0/6/0, val 6/0/0.

Redrawn (``draw_af.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken): the late BRS, whose
first draw, 1.16 ms (96 counts, est 0/4/2, val 1/4/1), cost the grey-box -0.11 points (92.30
-> 92.41; CR -0.29, CD 0.08), below the delay's 1 point, with nothing to set: impossible;
drawn again by 41001: 2.98 ms, 128 counts, est 0/0/6, val 1/1/4. Every other draw found a
size in band within the rule's four.

Sizes (the rule's; A-AE's values stepped off; the medians over every case of A-AE giving the
key; a median half-way rounded up): the Fung stiffening 0.099 (median 0.255, half-way up:
0.26, taken, so 0.27, cost 9.51: CR 5.12, CD 13.90; then 0.27 x 3.5 / 9.51 = 0.0994, 0.099,
not taken), the rib friction 430 N (median 410; 410, 420 taken), the webbing hysteresis 0.26
(median 0.52; 0.52-0.55 taken, so 0.56, cost 7.63: CR 7.59, CD 7.67; then 0.56 x 3.5 / 7.63 =
0.257, 0.26, not taken), the toe 0.022 (median 0.43, not taken, cost 14.87: CR 16.14, CD
13.60; then 0.43 x 3.5 / 14.87 = 0.101, clipped to a third, 0.143, 0.14, taken, 0.15 taken, so
0.16, cost 11.95: CR 12.99, CD 10.90; then 0.16 x 3.5 / 11.95 = 0.047, clipped to a third,
0.053, cost 8.46: CR 9.23, CD 7.68; then 0.053 x 3.5 / 8.46 = 0.0219, 0.022, the rule's fourth
and last size, in band), the sealed bag 0.24 (median 0.395, half-way up: 0.40; 0.40, 0.41
taken, so 0.42, cost 6.05: CR 6.08, CD 6.03, just over the band; then 0.42 x 3.5 / 6.05 =
0.243, 0.24, not taken), the lumbar path 0.19 (median 0.565, half-way up: 0.57, not taken,
cost 12.19: CR 7.04, CD 17.33; then 0.57 x 3.5 / 12.19 = 0.164, clipped to a third, 0.19, not
taken), the encoder ring 0.40 (median 0.315, half-way up: 0.32; 0.32-0.39 taken), the damped
CR element 41 Hz (median 55, set O's one, taken, so 56, cost 0.15: CR -0.33, CD 0.64; a
natural frequency, whose effect shrinks as it grows: 56 x 0.15 / 3.5 = 2.5, clipped to a
third, 18.7, 19, cost 11.66: CR 14.45, CD 8.87; then log-linear between them toward 3.5,
40.9, 41, not taken, cost 1.50, in band at its edge: 1.502); the broken BRS polled at 1100 Hz
(median 1000, set I's one, taken; not banded). The two-effect case's rubber stop 2.3e7
N/m^1.5 (median 2.1e7; 2.1e7, 2.2e7 taken), alone 4.50 (CR 1.77, CD 7.23), beside the toe
0.015 on FULL: by rules 1-2 alone, 0.43 (median 0.43, not taken), alone 8.81 (CR 9.51, CD
8.10); then 0.43 x 3.5 / 8.81 = 0.171, 0.17, alone 6.49 (CR 7.00, CD 5.99; together 8.89,
written down, not used); then 0.17 x 3.5 / 6.49 = 0.092, alone 5.02 (CR 5.39, CD 4.64), in
band; the two together at 0.092 7.86 (CR 5.50, CD 10.22), above the band with each alone in
it, so rule 4's mended step, on the toe, the higher alone (5.02 against the stop's 4.50), its
0.092 the first of its four: 0.092 x 3.75 / 7.86 = 0.0439, 0.044, together 6.87 (CR 4.26, CD
9.48), alone 3.51 (CR 3.75, CD 3.27); then 0.044 x 3.75 / 6.87 = 0.0240, 0.024, together 6.20
(CR 3.45, CD 8.94), alone 2.47 (CR 2.60, CD 2.34); then 0.024 x 3.75 / 6.20 = 0.0145, 0.015,
the fourth and last, together 5.78, alone 1.82, the stop alone 4.50: all three in band, kept.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; 2 cores shared with other work): clean48 92.6, clean96 92.7;
fung_sled_full 90.7 -> 85.6 (5.03; CR 2.67, CD 7.38); friction_sled 89.3 -> 85.1 (4.22; CR
1.50, CD 6.95); hysteresis_r16_full 89.6 -> 86.4 (3.20; CR 3.09, CD 3.32); toe_r16_full 92.2
-> 86.4 (5.75; CR 6.33, CD 5.18); sealed_sled 89.8 -> 86.8 (3.00; CR 2.86, CD 3.15);
lumbar_r16_sled 91.2 -> 88.6 (2.64; CR 1.12, CD 4.17); eccentric_sled 88.8 -> 84.8 (3.96; CR
5.29, CD 2.62); two_toe_full_bumper_r16_sled 93.1 -> 87.4 (5.78; CR 2.96, CD 8.60; the toe
alone 1.82: CR 1.90, CD 1.75; the rubber stop alone 4.50: CR 1.77, CD 7.23); pulse_late_4p07ms
92.1 -> 88.3 (3.78; CR 4.88, CD 2.69); brs_late_2p98ms 91.3 -> 89.2 (2.10; CR 2.62, CD 1.59);
cr_damped 89.8 -> 88.3 (1.50; CR 1.83, CD 1.17); broken_brs_poll 92.2 -> 92.2 (0.04; CR 0.05,
CD 0.03; flagging the test is the verdict asked; not banded, by the rule). Each effect of the
two-effect case alone: the case's seed with the other effect's size 0 (kept in the case's
list, so the dummies and pulses draw as they do in the case), against the same twin.

The broken test, as drawn and sized, is hardly broken: at 48 counts a rev this test's spool
turns one count a poll at most (every 9th sample, 1.1 kHz), so the decoder loses no count;
its BRS is its twin's held between polls, never more than a count off (set I's form lost
counts at 96 counts a rev and 1 kHz). The rule gives the broken test no band and no redraw;
it is kept as drawn, its cost written down (0.04), and ``test_set_af_brs_poll_holds_between_
polls`` says what the data hold.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AF: list[Case] = [
    Case("haf_clean48", 41103, _mix(6, 0, 0), _mix(0, 6, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, validated on SLED alone; "
               "FULL neither estimated nor validated"),
    Case("haf_clean96", 41207, _mix(0, 6, 0), _mix(6, 0, 0), 96,
         notes="clean thorax, 96-count BRS; estimated on SLED alone, validated on R16 alone; "
               "FULL neither estimated nor validated"),
    Case("haf_fung_sled_full", 41309, _mix(3, 3, 0), _mix(0, 1, 5), 48,
         (Effect("rib_fung", 0.099, ("SLED", "FULL")),), (("chest_stiffening", "SLED+FULL"),),
         notes="the rib cage stiffens exponentially (Fung), amount 0.099, on SLED and FULL; "
               "SLED estimated three times, validated once; FULL validated five times, never "
               "estimated; R16 clean, 3 estimation tests, never validated"),
    Case("haf_friction_sled", 41411, _mix(0, 3, 3), _mix(1, 5, 0), 48,
         (Effect("rib_friction", 430.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="dry (Coulomb) friction in the rib cage, 430 N against the chest's rate, on "
               "SLED alone; SLED estimated three times, validated five times; FULL clean, 3 "
               "estimation tests, never validated; R16 validated once, never estimated"),
    Case("haf_hysteresis_r16_full", 41515, _mix(0, 4, 2), _mix(1, 0, 5), 48,
         (Effect("webbing_hysteresis", 0.26, ("R16", "FULL")),),
         (("belt_unloading", "R16+FULL"),),
         notes="the webbing's elastic force 26 % lower while it shortens (set B's form), on "
               "R16 and FULL; R16 validated once, never estimated; FULL estimated twice, "
               "validated five times; SLED clean, 4 estimation tests, never validated"),
    Case("haf_toe_r16_full", 41617, _mix(2, 4, 0), _mix(5, 0, 1), 128,
         (Effect("webbing_toe", 0.022, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.022, on "
               "R16 and FULL; R16 estimated twice, validated five times; FULL validated "
               "once, never estimated; SLED clean, 4 estimation tests, never validated"),
    Case("haf_sealed_sled", 41719, _mix(4, 2, 0), _mix(0, 5, 1), 48,
         (Effect("airbag_sealed", 0.24, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="an unvented gas bag at fill 0.24 of the vented one's, on SLED alone; SLED "
               "estimated twice, validated five times; R16 without a bag, 4 estimation tests, "
               "never validated; FULL clean, validated once, never estimated"),
    Case("haf_lumbar_r16_sled", 41823, _mix(2, 0, 4), _mix(3, 3, 0), 64,
         (Effect("lumbar_path", 0.19, ("R16", "SLED")),), (("pelvis_coupling", "R16+SLED"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.19, on R16 and SLED; R16 estimated twice, validated three times; SLED "
               "validated three times, never estimated; FULL clean, 4 estimation tests, never "
               "validated"),
    Case("haf_eccentric_sled", 41927, _mix(0, 2, 4), _mix(0, 6, 0), 64,
         (Effect("brs_eccentric", 0.4, ("SLED",)),), (("input_gain", "SLED"),),
         notes="the BRS's encoder ring off-centre: the angle read th + 0.4 sin(th + phase), on "
               "SLED alone; validated on SLED alone; FULL clean, 4 estimation tests, never "
               "validated; R16 neither estimated nor validated"),
    Case("haf_two_toe_full_bumper_r16_sled", 41031, _mix(2, 2, 2), _mix(2, 1, 3), 96,
         (Effect("webbing_toe", 0.015, ("FULL",)),
          Effect("rib_bumper", 2.3e7, ("R16", "SLED"))),
         (("belt_stiffening", "FULL"), ("chest_stiffening", "R16+SLED")),
         notes="two kinds on two rigs: the car's (FULL) webbing stiffening exponentially with "
               "its stretch (toe), amount 0.015; the lower sternum meeting the spine box's "
               "rubber stop, Hertz, K = 2.3e7 N/m^1.5 (R16 and SLED); each rig estimated "
               "twice; the pairing set A's (reused, no pairing left)"),
    Case("haf_pulse_late_4p07ms", 41137, _mix(2, 0, 4), _mix(1, 5, 0), 128,
         (Effect("pulse_late", 0.00407),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.07 ms after its record; SLED validated five "
               "times, never estimated; FULL estimated four times, never validated"),
    Case("haf_brs_late_2p98ms", 41241, _mix(0, 0, 6), _mix(1, 1, 4), 128,
         (Effect("brs_late", 0.00298),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.98 ms after the BRS records it; estimated on FULL "
               "alone; R16 and SLED validated once each, never estimated (redrawn)"),
    Case("haf_cr_damped", 41343, _mix(6, 0, 0), _mix(0, 1, 5), 64,
         (Effect("cr_damped", 41.0),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer is an oil-damped element of 41 Hz natural frequency, "
               "damping ratio 0.7, every test: CR lags and reads its peaks low; CD and the "
               "inputs untouched: a residual in cr only"),
    Case("haf_broken_brs_poll", 41447, _mix(0, 3, 3), _mix(4, 1, 1), 48,
         (Effect("brs_poll", 1100.0, tests=("FULL_001",)),), (), expect_broken=("FULL_001",),
         notes="FULL_001, an estimation test: its spindle electronics poll the encoder's two "
               "tracks at 1.1 kHz (every 9th sample), too slowly for a quadrature decoder, "
               "which sees only their phase (mod 4 counts): a poll's move of 1 is counted, of "
               "2 dropped as invalid, of 3 counted as 1 back; the count held between polls; "
               "its other channels and every other test clean"),
]

BY_NAME_AF = {c.name: c for c in SET_AF}
ONE_PHYSICAL_AF = ("haf_fung_sled_full", "haf_friction_sled", "haf_hysteresis_r16_full",
                   "haf_toe_r16_full", "haf_sealed_sled", "haf_lumbar_r16_sled",
                   "haf_eccentric_sled")
