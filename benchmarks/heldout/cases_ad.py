"""Held-out set AD: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AC (``cases.py`` ... ``cases_ac.py``).

Set AC's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_ad.py`` (``numpy.random.default_rng(39000)``, set W's ``drawn``,
the pairings of A-AC taken, save the two-effect case's: with none free, it reuses one of
A-AC's, ``reuse_two``; ``python -m benchmarks.heldout.draw_ad`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_ad.py`` wrote down before
the first draw (``SIZING``). ``test_set_ad_follows_its_draw`` holds the draw and the cases
together.

The two-effect case's pairing, est 2/2/2, val 3/3/0, is set O's (``ho_cr_damped``): the one
pairing of this set an earlier set ran (``draw_ad.py``'s docstring: none was free for its
rigs; its first draw's, est 3/0/3, val 3/0/3, was set O's too, ``ho_rib_lock_full``).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_hardening, FULL, 128, est 4/0/2, val 0/4/2; chest_rate_damping:
rib_foam, SLED, 64, est 0/2/4, val 0/5/1; belt_unloading: webbing_hysteresis, R16+SLED+FULL,
48, est 0/6/0, val 5/0/1 (redrawn by 39001, below); belt_stiffening: webbing_toe,
R16+SLED+FULL, 48, est 6/0/0, val 0/2/4; airbag_contact: airbag_relief, SLED, 128, est 0/2/4,
val 3/3/0; pelvis_coupling: pelvis_submarine, R16+SLED+FULL, 48, est 0/6/0, val 1/0/5;
input_gain: brs_eccentric, R16+SLED+FULL, 48, est 4/2/0, val 1/0/5 (redrawn by 39002, below);
the two-effect case airbag_contact (airbag_sealed) on SLED beside chest_stiffening (rib_fung)
on R16, 64, est 2/2/2, val 3/3/0 (an earlier set's pairing, reused; redrawn by 39004, below);
the late pulse 3.58 ms, 128, est 0/0/6, val 2/3/1; the late BRS 3.99 ms, 96, est 0/6/0, val
3/0/3 (redrawn by 39003, below); the transducer error on CD, cd_dead_band, 128, est 2/0/4, val
0/5/1; the broken test's channel CR, cr_reversed, 64, est 6/0/0, val 3/2/1, the test R16_009;
clean48 est 0/4/2, val 3/0/3; clean96 est 0/0/6, val 6/0/0.

Redrawn (``draw_ad.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken): the belt unloading, whose
first draw, dring_capstan on SLED (96 counts, est 3/3/0, val 1/5/0), cost the grey-box 3.24
points at the rule's first size, mu theta 0.59 (92.8 -> 89.6; CR 3.83, CD 2.65; median 0.59,
not taken), in band, but ran away by ``test_set_ad_has_no_run_aways``'s limits (found by the
test at the first sizes): five of its eight SLED tests paid out less than a third of the set's
SLED median (30-68 deg against 205; the others 71-135); impossible; drawn again by 39001:
webbing_hysteresis on every rig, 48 counts, est 0/6/0, val 5/0/1. Then the input gain, whose
first draw, spool_buildup on R16+FULL (96 counts, est 4/2/0, val 5/0/1), cost 0.53 at the
rule's first size, 13 mm of radius per wrap (93.2 -> 92.7; CR 1.10, CD -0.05; median 0.012,
set X's one, taken), below the band; the rule's next, 39 mm (three times, the clip), would
leave the spool's 17 mm radius below zero within 7 rad of pay-out (zero past 15 mm per wrap):
a run-away, impossible; drawn again by 39002: brs_eccentric on every rig, 48 counts, est 4/2/0,
val 1/0/5. Then the late BRS, whose first draw, 1.03 ms (48 counts, est 2/0/4, val 2/3/1), cost
-0.24 (90.7 -> 90.9; CR -0.33, CD -0.14), below the delay's 1 point, with nothing to set:
impossible; drawn again by 39003: 3.99 ms, 96 counts, est 0/6/0, val 3/0/3. Then the
two-effect case, whose first draw, webbing_knee on R16 beside rib_maxwell on FULL (96 counts,
est 3/0/3, val 3/0/3, set O's pairing, reused), cost 7.04 together at the rule's first sizes,
the knee 2.4 (median 2.2: 2.2, 2.3 taken) and the Maxwell branch 0.76 (median 0.75, taken)
(91.6 -> 84.5; CR 3.75, CD 10.33), above the band, each alone in it (the knee 3.13: CR 3.88,
CD 2.39; the Maxwell branch 3.84: CR 0.84, CD 6.83); by rule 4 the Maxwell branch, its cost
alone the higher (toward the side the case left), was stepped by 2 toward 3.5, the knee kept
2.4: 0.76 x 3.5 / 3.84 = 0.693, 0.69 (alone 3.25, together 6.54); 0.69 x 3.5 / 3.25 = 0.743,
0.74 (alone 3.65, together 6.88); 0.74 x 3.5 / 3.65 = 0.710, 0.71 (alone 3.42, together 6.68):
four sizes, the two together never in band (each step toward 3.5 alone, from below it, moved
the pair up, as the rule has it), impossible; drawn again by 39004: airbag_sealed on SLED
beside rib_fung on R16, 64 counts, est 2/2/2, val 3/3/0 (set O's pairing, reused). Every
other draw found a size in band within the rule's four.

Sizes (the rule's; A-AC's values stepped off; the medians over every case of A-AC giving the
key; a median half-way rounded up): the hardening 7.1e7 N/m^3 (median 1.1e8: 1.1e8-1.5e8
taken, so 1.6e8, cost 7.91: CR 2.25, CD 13.58; then 1.6e8 x 3.5 / 7.91 = 7.08e7, 7.1e7, not
taken), the foam 830 N s/m (median 1685: 1700, not taken, cost 7.15: CR 3.74, CD 10.56; then
1700 x 3.5 / 7.15 = 832, 830, not taken), the hysteresis 0.54 (median 0.515, half-way up: 0.52,
0.53 taken), the toe 0.66 (median 0.20, not taken, cost 1.06: CR 1.49, CD 0.64; then 0.20 x
3.5 / 1.06 = 0.660, 0.66, not taken), the relief bag 0.43 (median 0.425, half-way up: 0.43,
not taken), the lap belt's slip force 10000 N (median 5800, taken, so 5900, cost 6.14: CR 2.21,
CD 10.07; a slip force, its effect taken to shrink as it grows: 5900 x 6.14 / 3.5 = 10350,
10000, not taken), the encoder ring 0.38 (median 0.305, half-way up: 0.31; 0.31-0.37 taken),
the CD pot's dead band 3.1 mm (median 3.0, set G's one, taken); the broken CR's polarity a
switch (1 = on; not banded); the two-effect case's sealed bag 0.41 (median 0.39: 0.39, 0.40
taken) beside the rib cage's Fung amount 0.26 (median 0.25, taken), each alone and the two
together in band at the rule's first sizes.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; one cost job at a time, 2 cores shared with other work; ``python -m
benchmarks.heldout.costs --set ad`` gives the same to its one decimal): clean48 92.6, clean96
92.2; hardening_full 93.9 -> 90.5 (3.35; CR 1.32, CD 5.38); foam_sled 91.7 -> 88.7 (3.03; CR
1.57, CD 4.49); hysteresis_all 89.2 -> 86.5 (2.76; CR 3.72, CD 1.79); toe_all 90.6 -> 89.0
(1.61; CR 2.17, CD 1.06); relief_sled 91.8 -> 87.5 (4.30; CR 4.29, CD 4.31); submarine_all
92.2 -> 88.5 (3.73; CR -1.08, CD 8.54); eccentric_all 91.9 -> 88.7 (3.26; CR 3.57, CD 2.95);
two_sealed_sled_fung_r16 90.8 -> 85.7 (5.06; CR 3.06, CD 7.05; the sealed bag alone 2.81: CR
2.30, CD 3.32; the Fung ribs alone 4.85: CR 1.69, CD 8.01); pulse_late_3p58ms 94.5 -> 90.8
(3.67; CR 4.12, CD 3.23); brs_late_3p99ms 90.1 -> 86.5 (3.62; CR 4.37, CD 2.86); cd_dead_band
92.8 -> 88.3 (4.52; CR 3.56, CD 5.48); broken_cr_reversed 90.8 -> 84.0 (6.80; CR 8.05, CD
5.54; flagging the test is the verdict asked; left in, it costs the fit; not banded, by the
rule). Each effect of the two-effect case alone: the case's seed with the other effect's size
0 (kept in the case's list, so the dummies and pulses draw as they do in the case), against
the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AD: list[Case] = [
    Case("had_clean48", 39103, _mix(0, 4, 2), _mix(3, 0, 3), 48,
         notes="clean thorax, 48-count BRS; R16 validated three times, never estimated; SLED "
               "estimated four times, never validated"),
    Case("had_clean96", 39207, _mix(0, 0, 6), _mix(6, 0, 0), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone, validated on R16 alone; "
               "SLED neither estimated nor validated"),
    Case("had_hardening_full", 39309, _mix(4, 0, 2), _mix(0, 4, 2), 128,
         (Effect("rib_hardening", 7.1e7, ("FULL",)),), (("chest_stiffening", "FULL"),),
         notes="the ribs harden from zero, F += k3 d^3 at k3 7.1e7 N/m^3, on FULL alone; R16 "
               "clean, 4 estimation tests, never validated; SLED validated four times, never "
               "estimated"),
    Case("had_foam_sled", 39411, _mix(0, 2, 4), _mix(0, 5, 1), 64,
         (Effect("rib_foam", 830.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="the sternum's damping pad engaging as the chest closes, c (d / 30 mm) d' in "
               "compression, c = 830 N s/m, on SLED alone; FULL clean, 4 estimation tests, "
               "validated once; R16 neither estimated nor validated"),
    Case("had_hysteresis_all", 39515, _mix(0, 6, 0), _mix(5, 0, 1), 48,
         (Effect("webbing_hysteresis", 0.54),), (("belt_unloading", "all"),),
         notes="the webbing's elastic force 54 % lower while it shortens (set B's form), on "
               "every rig; estimated on SLED alone, never validated there; R16 and FULL "
               "validated (five times, once), never estimated (redrawn)"),
    Case("had_toe_all", 39617, _mix(6, 0, 0), _mix(0, 2, 4), 48,
         (Effect("webbing_toe", 0.66),), (("belt_stiffening", "all"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.66, on "
               "every rig; estimated on R16 alone, never validated there; SLED and FULL "
               "validated (twice, four times), never estimated"),
    Case("had_relief_sled", 39719, _mix(0, 2, 4), _mix(3, 3, 0), 128,
         (Effect("airbag_relief", 0.43, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="the SLED rig's bag (its interior) with a pressure-relief vent, fill 0.43, on "
               "SLED alone; FULL's bag not fired, 4 estimation tests, never validated; R16 "
               "without a bag, validated three times, never estimated"),
    Case("had_submarine_all", 39823, _mix(0, 6, 0), _mix(1, 0, 5), 48,
         (Effect("pelvis_submarine", 10000.0),), (("pelvis_coupling", "all"),),
         notes="the pelvis on lap belt and seat (set A's lumbar and lap stiffness), the lap "
               "belt slipping over the iliac wings at 10000 N (submarining), on every rig; "
               "estimated on SLED alone, never validated there; R16 and FULL validated (once, "
               "five times), never estimated"),
    Case("had_eccentric_all", 39927, _mix(4, 2, 0), _mix(1, 0, 5), 48,
         (Effect("brs_eccentric", 0.38),), (("input_gain", "all"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.38 sin(th + phase), on "
               "every rig; R16 estimated four times, validated once; SLED estimated twice, "
               "never validated; FULL validated five times, never estimated (redrawn)"),
    Case("had_two_sealed_sled_fung_r16", 39031, _mix(2, 2, 2), _mix(3, 3, 0), 64,
         (Effect("airbag_sealed", 0.41, ("SLED",)),
          Effect("rib_fung", 0.26, ("R16",))),
         (("airbag_contact", "SLED"), ("chest_stiffening", "R16")),
         notes="two kinds on two rigs: the SLED rig's bag (its interior) without vents, the "
               "gas only compressing, fill 0.41 (SLED); the rib cage stiffening exponentially "
               "with its deflection (Fung), amount 0.26 (R16); FULL's bag not fired, 2 "
               "estimation tests, never validated; the pairing set O's (reused, no pairing "
               "left) (redrawn)"),
    Case("had_pulse_late_3p58ms", 39137, _mix(0, 0, 6), _mix(2, 3, 1), 128,
         (Effect("pulse_late", 0.00358),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.58 ms after its record; estimated on FULL alone; "
               "R16 and SLED validated, never estimated"),
    Case("had_brs_late_3p99ms", 39241, _mix(0, 6, 0), _mix(3, 0, 3), 96,
         (Effect("brs_late", 0.00399),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.99 ms after the BRS records it; estimated on SLED "
               "alone, never validated there; R16 and FULL validated, never estimated "
               "(redrawn)"),
    Case("had_cd_dead_band", 39343, _mix(2, 0, 4), _mix(0, 5, 1), 128,
         (Effect("cd_dead_band", 3.1),), (), expect_note=UNEXPLAINED_CD,
         notes="slack in the chest pot's linkage, held one way by its return spring: CD reads "
               "nothing over the first 3.1 mm of deflection and 3.1 mm low beyond, every "
               "test; CR and the inputs untouched: a residual in cd only, a static function of "
               "cd, zero at rest (not a zero offset)"),
    Case("had_broken_cr_reversed", 39447, _mix(6, 0, 0), _mix(3, 2, 1), 64,
         (Effect("cr_reversed", 1.0, tests=("R16_009",)),), (), expect_broken=("R16_009",),
         notes="R16_009, an estimation test: its spine accelerometer recorded at the wrong "
               "polarity (its sign entered wrong in the recorder), the chest's retardation "
               "read as a negative acceleration, every sample its right size; its other "
               "channels and every other test clean"),
]

BY_NAME_AD = {c.name: c for c in SET_AD}
ONE_PHYSICAL_AD = ("had_hardening_full", "had_foam_sled", "had_hysteresis_all", "had_toe_all",
                   "had_relief_sled", "had_submarine_all", "had_eccentric_all")
