"""Held-out set AE: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AD (``cases.py`` ... ``cases_ad.py``).

Set AD's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_ae.py`` (``numpy.random.default_rng(40000)``, set W's ``drawn``,
the pairings of A-AD taken, save the two-effect case's: with none free, it reuses one of
A-AD's, ``reuse_two``; ``python -m benchmarks.heldout.draw_ae`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_ae.py`` wrote down before
the first draw (``SIZING``; set AD's, its rule 4 mended). ``test_set_ae_follows_its_draw``
holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 2/2/2, is set AB's (``hab_two_pelvis_knee_sled_
toe_r16_full``; set A's too): the one pairing of this set an earlier set ran (``draw_ae.py``'s
docstring: none was free for its rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bottoming, R16, 48, est 4/0/2, val 4/1/1; chest_rate_damping:
rib_visco, R16+FULL, 128, est 0/4/2, val 4/1/1; belt_unloading: webbing_set, R16+SLED+FULL,
64, est 0/0/6, val 3/2/1 (redrawn by 40001, below); belt_stiffening: webbing_toe, SLED, 128,
est 0/4/2, val 0/5/1; airbag_contact: airbag_dual, SLED+FULL, 96, est 4/0/2, val 2/4/0;
pelvis_coupling: pelvis_knee, R16+SLED, 64, est 3/0/3, val 5/1/0; input_gain: brs_eccentric,
SLED, 96, est 0/3/3, val 0/5/1; the two-effect case belt_unloading (webbing_set) on FULL
beside airbag_contact (airbag_fabric) on SLED, 128, est 2/2/2, val 2/2/2 (an earlier set's
pairing, reused); the late pulse 4.39 ms, 96, est 4/2/0, val 5/0/1; the late BRS 4.29 ms, 48,
est 2/0/4, val 0/2/4 (redrawn by 40002, below); the transducer error on CD, cd_pot_nonlinear,
64, est 6/0/0, val 2/0/4; the broken test's channel CD, cd_dropout, 128, est 6/0/0, val 2/1/3,
the test R16_011; clean48 est 4/2/0, val 5/1/0; clean96 est 0/6/0, val 1/4/1.

Redrawn (``draw_ae.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken): the belt unloading,
whose first draw, webbing_slack on SLED (64 counts, est 0/3/3, val 2/3/1), a switch with
nothing to set, cost the grey-box 9.77 points (88.95 -> 79.18; CR 11.57, CD 7.97), above the
band: impossible; drawn again by 40001: webbing_set on every rig, 64 counts, est 0/0/6, val
3/2/1. Then the late BRS, whose first draw, 2.41 ms (96 counts, est 0/0/6, val 1/3/2), cost
0.85 (91.03 -> 90.18; CR 0.90, CD 0.80), below the delay's 1 point, with nothing to set:
impossible; drawn again by 40002: 4.29 ms, 48 counts, est 2/0/4, val 0/2/4. Every other draw
found a size in band within the rule's four.

Sizes (the rule's; A-AD's values stepped off; the medians over every case of A-AD giving the
key; a median half-way rounded up): the bottoming 8.1e7 N/m^2.5 (median 8.0e7, taken), the
visco damping 870 (median 2500, taken, so 2600, cost 13.78: CR 2.56, CD 25.01; then 2600 x 3.5
/ 13.78 = 660, clipped to a third, 867, 870, not taken), the webbing set 0.62 (median 0.555,
half-way up: 0.56; 0.56-0.61 taken), the toe 0.61 (median 0.25, taken, so 0.26, cost 1.48: CR
2.56, CD 0.40, just under the band; then 0.26 x 3.5 / 1.48 = 0.614, 0.61, not taken), the
dual-stage bags 0.35 (median 0.35, not taken), the pelvis and knee bolster 0.14 (median 0.215,
half-way up: 0.22; 0.22, 0.23 taken, so 0.24, cost 6.15: CR 5.33, CD 6.96; then 0.24 x 3.5 /
6.15 = 0.137, 0.14, not taken), the encoder ring 0.39 (median 0.31; 0.31-0.38 taken), the pot's
non-linearity 0.23 (median 0.22, set A's one, taken); the broken CD's dropout at 0.053 s
(median 0.052, set B's one, taken); the two-effect case's webbing set 0.62 (as the belt
unloading's: median 0.555, 0.56-0.61 taken) beside the fabric bag 0.77 (median 0.745,
half-way up: 0.75; 0.75, 0.76 taken), each alone and the two together in band at the rule's
first sizes (rule 4's mended step not needed).

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; 2 cores shared with other work): clean48 92.2, clean96 93.0;
bottoming_r16 91.4 -> 87.5 (3.92; CR 2.02, CD 5.82); visco_r16_full 91.1 -> 86.0 (5.09; CR
1.04, CD 9.14); set_all 93.2 -> 89.7 (3.49; CR 3.72, CD 3.26); toe_sled 90.0 -> 87.7 (2.36; CR
3.75, CD 0.97); dual_sled_full 90.9 -> 85.4 (5.52; CR 7.45, CD 3.59); pelvis_knee_r16_sled 89.8
-> 85.7 (4.11; CR 1.84, CD 6.39); eccentric_sled 90.5 -> 85.6 (4.92; CR 5.65, CD 4.18);
two_set_full_fabric_sled 90.7 -> 85.9 (4.89; CR 6.41, CD 3.36; the webbing set alone 3.32: CR
3.59, CD 3.05; the fabric bag alone 2.38: CR 3.61, CD 1.16); pulse_late_4p39ms 93.2 -> 88.0
(5.20; CR 6.75, CD 3.64); brs_late_4p29ms 89.1 -> 86.1 (3.09; CR 3.95, CD 2.22);
cd_pot_nonlinear 92.5 -> 90.5 (1.99; CR 0.86, CD 3.12); broken_cd_dropout 90.8 -> 90.1 (0.67;
CR 0.48, CD 0.85; flagging the test is the verdict asked; not banded, by the rule). Each effect
of the two-effect case alone: the case's seed with the other effect's size 0 (kept in the
case's list, so the dummies and pulses draw as they do in the case), against the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AE: list[Case] = [
    Case("hae_clean48", 40103, _mix(4, 2, 0), _mix(5, 1, 0), 48,
         notes="clean thorax, 48-count BRS; FULL neither estimated nor validated"),
    Case("hae_clean96", 40207, _mix(0, 6, 0), _mix(1, 4, 1), 96,
         notes="clean thorax, 96-count BRS; estimated on SLED alone; R16 and FULL validated "
               "once each, never estimated"),
    Case("hae_bottoming_r16", 40309, _mix(4, 0, 2), _mix(4, 1, 1), 48,
         (Effect("rib_bottoming", 8.1e7, ("R16",)),), (("chest_stiffening", "R16"),),
         notes="the ribs bottom out past 12 mm, 8.1e7 N/m^2.5 beyond the onset (power 2.5), "
               "on R16 alone; FULL clean, 2 estimation tests, validated once; SLED validated "
               "once, never estimated"),
    Case("hae_visco_r16_full", 40411, _mix(0, 4, 2), _mix(4, 1, 1), 128,
         (Effect("rib_visco", 870.0, ("R16", "FULL")),),
         (("chest_rate_damping", "R16+FULL"),),
         notes="rib damping F += c |d'|^1.5 sign(d'), c = 870 N/(m/s)^1.5, on R16 and FULL; "
               "R16 validated four times, never estimated; FULL estimated twice, validated "
               "once; SLED clean, 4 estimation tests, validated once"),
    Case("hae_set_all", 40515, _mix(0, 0, 6), _mix(3, 2, 1), 64,
         (Effect("webbing_set", 0.62),), (("belt_unloading", "all"),),
         notes="the chest-side webbing unloads to a set of 0.62 x its peak stretch, on every "
               "rig; estimated on FULL alone; R16 and SLED validated (three times, twice), "
               "never estimated (redrawn)"),
    Case("hae_toe_sled", 40617, _mix(0, 4, 2), _mix(0, 5, 1), 128,
         (Effect("webbing_toe", 0.61, ("SLED",)),), (("belt_stiffening", "SLED"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.61, on "
               "SLED alone; FULL clean, 2 estimation tests, validated once; R16 neither "
               "estimated nor validated"),
    Case("hae_dual_sled_full", 40719, _mix(4, 0, 2), _mix(2, 4, 0), 96,
         (Effect("airbag_dual", 0.35, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="the SLED rig's and the car's (FULL) vented bags on two-stage inflators at fill "
               "0.35; SLED validated four times, never estimated; FULL estimated twice, never "
               "validated; R16 without a bag, 4 estimation tests, validated twice"),
    Case("hae_pelvis_knee_r16_sled", 40823, _mix(3, 0, 3), _mix(5, 1, 0), 64,
         (Effect("pelvis_knee", 0.14, ("R16", "SLED")),), (("pelvis_coupling", "R16+SLED"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.14, and the knees meeting the knee bolster, on R16 and SLED; R16 "
               "estimated three times, validated five times; SLED validated once, never "
               "estimated; FULL clean, 3 estimation tests, never validated"),
    Case("hae_eccentric_sled", 40927, _mix(0, 3, 3), _mix(0, 5, 1), 96,
         (Effect("brs_eccentric", 0.39, ("SLED",)),), (("input_gain", "SLED"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.39 sin(th + phase), on "
               "SLED alone; FULL clean, 3 estimation tests, validated once; R16 neither "
               "estimated nor validated"),
    Case("hae_two_set_full_fabric_sled", 40031, _mix(2, 2, 2), _mix(2, 2, 2), 128,
         (Effect("webbing_set", 0.62, ("FULL",)),
          Effect("airbag_fabric", 0.77, ("SLED",))),
         (("belt_unloading", "FULL"), ("airbag_contact", "SLED")),
         notes="two kinds on two rigs: the car's (FULL) chest-side webbing unloading to a set "
               "of 0.62 x its peak stretch; the SLED rig's bag without vent holes, leaking "
               "through its fabric, fill 0.77 (SLED); R16 clean, 2 estimation and 2 "
               "validation tests; the pairing set AB's (reused, no pairing left)"),
    Case("hae_pulse_late_4p39ms", 40137, _mix(4, 2, 0), _mix(5, 0, 1), 96,
         (Effect("pulse_late", 0.00439),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.39 ms after its record; FULL validated once, "
               "never estimated; SLED estimated twice, never validated"),
    Case("hae_brs_late_4p29ms", 40241, _mix(2, 0, 4), _mix(0, 2, 4), 48,
         (Effect("brs_late", 0.00429),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.29 ms after the BRS records it; SLED validated "
               "twice, never estimated; R16 estimated twice, never validated (redrawn)"),
    Case("hae_cd_pot_nonlinear", 40343, _mix(6, 0, 0), _mix(2, 0, 4), 64,
         (Effect("cd_pot_nonlinear", 0.23),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot over-reads at large deflection, CD = d (1 + 0.23 (d / 25 mm)^2) "
               "(a cubic static non-linearity, 23 % high at 25 mm), every test; CR and the "
               "inputs untouched: a residual in cd only, a static function of cd, zero at "
               "rest"),
    Case("hae_broken_cd_dropout", 40447, _mix(6, 0, 0), _mix(2, 1, 3), 128,
         (Effect("cd_dropout", 0.053, tests=("R16_011",)),), (), expect_broken=("R16_011",),
         notes="R16_011, an estimation test: its chest pot's wiper lifts off the track, the "
               "raw CD reads 0 mm from 53 to 63 ms, then recovers (CFC 600 after); its other "
               "channels and every other test clean"),
]

BY_NAME_AE = {c.name: c for c in SET_AE}
ONE_PHYSICAL_AE = ("hae_bottoming_r16", "hae_visco_r16_full", "hae_set_all", "hae_toe_sled",
                   "hae_dual_sled_full", "hae_pelvis_knee_r16_sled", "hae_eccentric_sled")
