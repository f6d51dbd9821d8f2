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

The two-effect case's pairing, est 0/2/4, val 0/2/4, is set O's (``ho_broken_brs_counts``; set
Z's two-effect case ran it too): the one pairing of this set an earlier set ran
(``draw_ai.py``'s docstring: none was free for its rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_lock, R16+SLED, 48, est 0/4/2, val 4/0/2; chest_rate_damping: rib_foam,
R16+SLED, 96, est 0/2/4, val 5/1/0; belt_unloading: dring_capstan, SLED, 96, est 0/3/3, val
2/3/1; belt_stiffening: webbing_power, SLED+FULL, 48, est 3/3/0, val 3/1/2; airbag_contact:
airbag, SLED+FULL, 48, est 3/3/0, val 4/1/1; pelvis_coupling: pelvis_submarine, SLED, 48, est
0/4/2, val 1/4/1; input_gain: spool_buildup, SLED+FULL, 64, est 2/4/0, val 3/0/3; the
two-effect case airbag_contact (airbag_relief) on FULL beside chest_rate_damping (rib_squeeze)
on SLED, 96, est 0/2/4, val 0/2/4 (an earlier set's pairing, reused); the late pulse 3.69 ms,
64, est 6/0/0, val 0/3/3; the late BRS 3.26 ms, 48, est 6/0/0, val 1/1/4; the transducer error
on CD, cd_pot_nonlinear, 96, est 0/0/6, val 0/6/0; the broken test's channel BRS,
brs_quadrature, 128, est 0/4/2, val 2/0/4, the test FULL_001; clean48 est 0/6/0, val 0/1/5;
clean96 est 0/0/6, val 0/4/2.

Sizes, at the rule's first sizes (A-AH's values stepped off; the medians over every case of
A-AH giving the key; a median half-way rounded up; not yet costed): the rib lock 0.093 m
(median 0.091, taken; 0.092 taken), the foam pad 890 N s/m (median 875, half-way up: 880,
taken), the D-ring capstan 0.59 (median 0.59, not taken), the webbing's power law 2.2 (median
2.05, half-way up: 2.1, taken), the vented bag 0.62 (median 0.605, half-way up: 0.61, taken),
the lap belt's slip force 6000 N (median 6000, not taken), the spool's build-up 0.013 m per
wrap (median 0.012, set X's one, taken), the CD pot's non-linearity 0.24 (median 0.225,
half-way up: 0.23, taken), the BRS decoder's 6 edges a step (a whole number; median 4.5,
half-way up: 5, set AG's, taken, so stepped by 1 to 6); the two-effect case's relief-vented bag
0.44 (median 0.43, taken) beside the squeeze film 460 N s/m (median 430; 430-450 taken).

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
         (Effect("rib_foam", 890.0, ("R16", "SLED")),), (("chest_rate_damping", "R16+SLED"),),
         notes="the sternum's damping pad engaging as the chest closes, c (d / 30 mm) d' in "
               "compression, c = 890 N s/m, on R16 and SLED; R16 validated five times, never "
               "estimated; SLED estimated twice, validated once; FULL clean, 4 estimation "
               "tests, never validated"),
    Case("hai_capstan_sled", 44515, _mix(0, 3, 3), _mix(2, 3, 1), 96,
         (Effect("dring_capstan", 0.59, ("SLED",)),), (("belt_unloading", "SLED"),),
         notes="the SLED rig's shoulder webbing wraps its D-ring as a capstan, mu theta 0.59, "
               "the chest side carrying the retractor side's tension x exp(+0.59) drawn out, "
               "x exp(-0.59) taken back, on SLED alone; SLED estimated three times, validated "
               "three times; FULL clean, 3 estimation tests, validated once; R16 validated "
               "twice, never estimated"),
    Case("hai_power_sled_full", 44617, _mix(3, 3, 0), _mix(3, 1, 2), 48,
         (Effect("webbing_power", 2.2, ("SLED", "FULL")),), (("belt_stiffening", "SLED+FULL"),),
         notes="the webbing stiffens with its stretch, F += a k e (e/e_ref)^2 (e_ref 15 mm "
               "chest side, 25 mm up to the retractor), a = 2.2, on SLED and FULL; SLED "
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
    Case("hai_spool_sled_full", 44927, _mix(2, 4, 0), _mix(3, 0, 3), 64,
         (Effect("spool_buildup", 0.013, ("SLED", "FULL")),), (("input_gain", "SLED+FULL"),),
         notes="the spool's effective radius, 17 mm at rest, changing by 13 mm per wrap of "
               "webbing wound (smaller as it pays out): the webbing paid out per radian the BRS "
               "counts is not r0, on SLED and FULL; SLED estimated four times, never "
               "validated; FULL validated three times, never estimated; R16 clean, 2 "
               "estimation tests, validated three times"),
    Case("hai_two_relief_full_squeeze_sled", 44031, _mix(0, 2, 4), _mix(0, 2, 4), 96,
         (Effect("airbag_relief", 0.44, ("FULL",)),
          Effect("rib_squeeze", 460.0, ("SLED",))),
         (("airbag_contact", "FULL"), ("chest_rate_damping", "SLED")),
         notes="two kinds on two rigs: the car's (FULL) driver bag with a pressure-relief "
               "vent at fill 0.44; squeeze-film damping in the SLED dummy's chest (1/gap^3 "
               "from a 60 mm gap), 460 N s/m at rest; SLED estimated twice, validated twice; "
               "FULL estimated four times, validated four times; R16 neither estimated nor "
               "validated; the pairing set O's (reused, no pairing left)"),
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
ONE_PHYSICAL_AI = ("hai_lock_r16_sled", "hai_foam_r16_sled", "hai_capstan_sled",
                   "hai_power_sled_full", "hai_airbag_sled_full", "hai_submarine_sled",
                   "hai_spool_sled_full")
