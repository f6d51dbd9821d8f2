"""Held-out set AN: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AM (``cases.py`` ... ``cases_am.py``).

Set AM's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works, with no change: ``draw_an.py`` (``numpy.random.default_rng(49000)``, set
W's ``drawn``, the pairings of A-AM taken, save where a case has none free for its rigs: it
then reuses one of A-AM's, ``reuse_all``, set AL's rule; ``python -m
benchmarks.heldout.draw_an`` prints the draw). The cases follow the draw; only the sizes are
set, by costs, by the rule ``draw_an.py`` wrote down before the first draw (``SIZING``; set
AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's, set AF's, set AE's, its rule
4 as mended there). ``test_set_an_follows_its_draw`` holds the draw and the cases together.

Nine cases run a pairing an earlier set ran (``draw_an.py``'s docstring: none was free for
their rigs), each drawn uniformly among the pairings its rules allow that A-AM ran: the chest's
stiffening, est 0/3/3, val 4/1/1 (set AF's ``haf_broken_brs_poll``); the chest's rate damping,
est 4/2/0, val 3/3/0 (set O's ``ho_two_hyst_r16_fabric_sled``); the belt's unloading, est
0/3/3, val 5/1/0 (set Z's ``hz_eccentric_r16_sled``); the belt's stiffening, est 0/4/2, val
4/1/1 (set AE's ``hae_visco_r16_full``); the bag, est 4/2/0, val 0/4/2 (set AH's
``hah_dual_sled``); the pelvis, est 2/2/2, val 2/2/2 (set A's ``h_clean48`` and four more of
set A's, set AB's and set AE's two-effect cases'); the input gain, est 2/2/2, val 2/4/0 (set
L's ``hl_cd_aa_filter``); the two-effect case, est 2/2/2, val 1/2/3 (set F's
``hf_airbag_vented``); the late BRS, est 6/0/0, val 4/1/1 (set AC's ``hac_cd_clock``). The
other five cases drew free pairings. No two cases of AN share a pairing.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_fung, R16+SLED, 64, est 0/3/3, val 4/1/1 (reused); chest_rate_damping:
rib_squeeze, SLED, 64, est 4/2/0, val 3/3/0 (reused); belt_unloading: dring_capstan, R16+FULL,
128, est 0/3/3, val 5/1/0 (reused); belt_stiffening: webbing_power, R16+SLED, 48, est 0/4/2,
val 4/1/1 (reused); airbag_contact: airbag_dual, SLED+FULL, 96, est 4/2/0, val 0/4/2 (reused);
pelvis_coupling: pelvis_knee, R16+FULL, 64, est 2/2/2, val 2/2/2 (reused); input_gain:
brs_eccentric, SLED+FULL, 96, est 2/2/2, val 2/4/0 (reused); the two-effect case
pelvis_coupling (pelvis_knee) on R16+SLED beside chest_rate_damping (rib_maxwell) on FULL, 96,
est 2/2/2, val 1/2/3 (reused); the late pulse 2.34 ms, 64, est 6/0/0, val 1/3/2; the late BRS
4.65 ms, 48, est 6/0/0, val 4/1/1 (reused); the transducer error on CD, cd_arm_lift, 64, est
3/3/0, val 5/1/0; the broken test's channel CD, cd_dropout, 64, est 0/0/6, val 4/0/2, the test
FULL_011; clean48 est 6/0/0, val 4/2/0; clean96 est 0/0/6, val 3/0/3.

Redrawn: none at the draw (with a pairing always left to draw, no draw is impossible for want
of one; ``draw_an.REDRAWN`` empty).

Sizes, at the rule's first sizes (A-AM's values stepped off; the medians over every case of
A-AM giving the key; a median half-way rounded up; not yet costed): the Fung ribs 0.27 (median
0.235, half-way up: 0.24; 0.24-0.26 taken), the squeeze film 470 N s/m (median 430; 430-460
taken), the capstan 0.59 (median 0.59, not taken), the webbing's power 2.2 (median 2.0;
2.0-2.1 taken), the two-stage bags 0.37 (median 0.35; 0.35-0.36 taken), the pelvis's knee
bolster 0.25 (median 0.20; 0.20-0.24 taken), the encoder ring 0.47 (median 0.35; 0.35-0.46
taken), the pot arm's return 0.61 mm/ms (median 0.6, set J's one, taken); the late pulse 2.34
ms and the late BRS 4.65 ms as drawn; the broken test's dropout at 54 ms (rule 5: by rule 1
only; median 52.5 ms, half-way up: 53; 53 taken); the two-effect case's knee bolster 0.25 (as
the single's, each at the key's first size) beside the Maxwell ribs 0.62 (median 0.62, not
taken).

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AN: list[Case] = [
    Case("han_clean48", 49103, _mix(6, 0, 0), _mix(4, 2, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, validated there four "
               "times; SLED validated twice, never estimated; FULL neither estimated nor "
               "validated"),
    Case("han_clean96", 49207, _mix(0, 0, 6), _mix(3, 0, 3), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone, validated there three "
               "times; R16 validated three times, never estimated; SLED neither estimated nor "
               "validated"),
    Case("han_fung_r16_sled", 49309, _mix(0, 3, 3), _mix(4, 1, 1), 64,
         (Effect("rib_fung", 0.27, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the rib cage stiffens exponentially with its deflection (Fung), amount 0.27, "
               "on R16 and SLED; R16 validated four times, never estimated; SLED estimated "
               "three times, validated once; FULL clean, 3 estimation tests, validated once; "
               "the pairing set AF's (reused, none free)"),
    Case("han_squeeze_sled", 49411, _mix(4, 2, 0), _mix(3, 3, 0), 64,
         (Effect("rib_squeeze", 470.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 470 N s/m at "
               "rest, on SLED alone; SLED estimated twice, validated three times; R16 clean, 4 "
               "estimation tests, validated three times; FULL neither estimated nor "
               "validated; the pairing set O's (reused, none free)"),
    Case("han_capstan_r16_full", 49515, _mix(0, 3, 3), _mix(5, 1, 0), 128,
         (Effect("dring_capstan", 0.59, ("R16", "FULL")),), (("belt_unloading", "R16+FULL"),),
         notes="the shoulder webbing wraps its D-ring as a capstan, mu theta 0.59, the chest "
               "side carrying the retractor side's tension x exp(+0.59) drawn out, x "
               "exp(-0.59) taken back, on R16 and FULL; R16 validated five times, never "
               "estimated; FULL estimated three times, never validated; SLED clean, 3 "
               "estimation tests, validated once; the pairing set Z's (reused, none free)"),
    Case("han_power_r16_sled", 49617, _mix(0, 4, 2), _mix(4, 1, 1), 48,
         (Effect("webbing_power", 2.2, ("R16", "SLED")),), (("belt_stiffening", "R16+SLED"),),
         notes="the webbing stiffens with its stretch, F += a k e (e/e_ref)^2 (e_ref 15 mm "
               "chest side, 25 mm up to the retractor), a = 2.2, on R16 and SLED; R16 "
               "validated four times, never estimated; SLED estimated four times, validated "
               "once; FULL clean, 2 estimation tests, validated once; the pairing set AE's "
               "(reused, none free)"),
    Case("han_dual_sled_full", 49719, _mix(4, 2, 0), _mix(0, 4, 2), 96,
         (Effect("airbag_dual", 0.37, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="the SLED rig's and the car's (FULL) vented bags on two-stage inflators at fill "
               "0.37; SLED estimated twice, validated four times; FULL validated twice, never "
               "estimated; R16 without a bag, 4 estimation tests, never validated; the pairing "
               "set AH's (reused, none free)"),
    Case("han_pelvis_knee_r16_full", 49823, _mix(2, 2, 2), _mix(2, 2, 2), 64,
         (Effect("pelvis_knee", 0.25, ("R16", "FULL")),), (("pelvis_coupling", "R16+FULL"),),
         notes="the pelvis on lap belt and seat at 0.25 x set A's lumbar and lap stiffness, "
               "its knees meeting a knee bolster past a 45 mm gap, on R16 and FULL; each "
               "estimated twice, validated twice; SLED clean, 2 estimation tests, validated "
               "twice; the pairing set A's (reused, none free)"),
    Case("han_eccentric_sled_full", 49927, _mix(2, 2, 2), _mix(2, 4, 0), 96,
         (Effect("brs_eccentric", 0.47, ("SLED", "FULL")),), (("input_gain", "SLED+FULL"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.47 sin(th + phase), on "
               "SLED and FULL; SLED estimated twice, validated four times; FULL estimated "
               "twice, never validated; R16 clean, 2 estimation tests, validated twice; the "
               "pairing set L's (reused, none free)"),
    Case("han_two_pelvis_knee_r16_sled_maxwell_full", 49031, _mix(2, 2, 2), _mix(1, 2, 3), 96,
         (Effect("pelvis_knee", 0.25, ("R16", "SLED")),
          Effect("rib_maxwell", 0.62, ("FULL",))),
         (("pelvis_coupling", "R16+SLED"), ("chest_rate_damping", "FULL")),
         notes="two kinds on two rigs: the pelvis on lap belt and seat at 0.25 x set A's "
               "lumbar and lap stiffness, its knees meeting a knee bolster past a 45 mm gap "
               "(R16 and SLED); viscoelastic rib material, a Maxwell branch of 0.62 x the "
               "rib's stiffness relaxing in 10 ms (FULL); each rig estimated twice, R16 "
               "validated once, SLED twice, FULL three times; the pairing set F's (reused, "
               "none free)"),
    Case("han_pulse_late_2p34ms", 49137, _mix(6, 0, 0), _mix(1, 3, 2), 64,
         (Effect("pulse_late", 0.00234),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.34 ms after its record; estimated on R16 alone, "
               "validated there once; SLED and FULL validated (three times, twice), never "
               "estimated"),
    Case("han_brs_late_4p65ms", 49241, _mix(6, 0, 0), _mix(4, 1, 1), 48,
         (Effect("brs_late", 0.00465),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.65 ms after the BRS records it; estimated on R16 "
               "alone, validated there four times; SLED and FULL validated (once each), never "
               "estimated; the pairing set AC's (reused, none free)"),
    Case("han_cd_arm_lift", 49343, _mix(3, 3, 0), _mix(5, 1, 0), 64,
         (Effect("cd_arm_lift", 0.61),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot arm's return spring has gone weak: the sternum pushes the arm "
               "in, but as the chest opens the arm comes back no faster than 0.61 mm/ms and "
               "lifts off the sternum (set J's form): CD reads the compression right while it "
               "grows and at its peak, then high while the chest opens faster than that, and "
               "right again once it is back on the sternum, every test; CR and the inputs "
               "untouched: a residual in cd only, one-sided, with memory"),
    Case("han_broken_cd_dropout", 49447, _mix(0, 0, 6), _mix(4, 0, 2), 64,
         (Effect("cd_dropout", 0.054, tests=("FULL_011",)),), (), expect_broken=("FULL_011",),
         notes="FULL_011, an estimation test: its chest pot's wiper lifts off the track, the "
               "raw CD reads 0 mm from 54 to 64 ms, then recovers (CFC 600 after); its other "
               "channels and every other test clean"),
]

BY_NAME_AN = {c.name: c for c in SET_AN}
ONE_PHYSICAL_AN = ("han_fung_r16_sled", "han_squeeze_sled", "han_capstan_r16_full",
                   "han_power_r16_sled", "han_dual_sled_full", "han_pelvis_knee_r16_full",
                   "han_eccentric_sled_full")
