"""Held-out set AG: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AF (``cases.py`` ... ``cases_af.py``).

Set AF's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_ag.py`` (``numpy.random.default_rng(42000)``, set W's ``drawn``,
the pairings of A-AF taken, save the two-effect case's: with none free, it reuses one of
A-AF's, ``reuse_two``; ``python -m benchmarks.heldout.draw_ag`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_ag.py`` wrote down before
the first draw (``SIZING``; set AF's, set AE's, its rule 4 as mended there).
``test_set_ag_follows_its_draw`` holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 4/1/1, is set E's (``he_clean48``): the one
pairing of this set an earlier set ran (``draw_ag.py``'s docstring: none was free for its
rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_lock, R16+FULL, 128, est 0/4/2, val 4/2/0; chest_rate_damping:
rib_foam, R16+FULL, 64, est 2/2/2, val 5/1/0; belt_unloading: dring_capstan, all three rigs,
96, est 6/0/0, val 2/3/1; belt_stiffening: webbing_toe, R16+SLED, 64, est 4/0/2, val 1/5/0;
airbag_contact: airbag, SLED+FULL, 48, est 3/3/0, val 2/0/4; pelvis_coupling: lumbar_path,
R16, 48, est 2/2/2, val 6/0/0; input_gain: brs_eccentric, R16, 64, est 4/0/2, val 5/1/0; the
two-effect case pelvis_coupling (pelvis_submarine) on R16 beside chest_rate_damping
(rib_visco) on SLED+FULL, 96, est 2/2/2, val 4/1/1 (an earlier set's pairing, reused); the
late pulse 4.95 ms, 96, est 0/0/6, val 1/2/3; the late BRS 1.79 ms, 96, est 0/6/0, val 2/2/2;
the transducer error on CD, cd_sag, 128, est 0/0/6, val 0/1/5; the broken test's channel BRS,
brs_quadrature, 96, est 3/0/3, val 6/0/0, the test R16_003; clean48 est 0/6/0, val 4/1/1;
clean96 est 3/3/0, val 1/5/0.

Sizes, at the rule's first sizes (A-AF's values stepped off; the medians over every case of
A-AF giving the key; a median half-way rounded up; not yet costed): the rib lock 0.092 m
(median 0.0905, half-way up: 0.091, taken, so 0.092), the foam pad 880 N s/m (median 870,
taken), the D-ring capstan 0.59 (median 0.59, not taken), the toe 0.20 (median 0.20, not
taken), the vented bag 0.61 (median 0.60, taken), the lumbar path 0.56 (median 0.55, taken),
the encoder ring 0.41 (median 0.32; 0.32-0.40 taken), the CD pot's sag 0.65 (median 0.65, not
taken), the BRS decoder's edges a step 5 (a whole number; median 4, set H's one, taken, so
stepped by 1 to 5); the two-effect case's lap belt slipping at 6000 N (median 6000, not
taken) beside the rib damping 2300 N/(m/s)^1.5 (median 2300, not taken).

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AG: list[Case] = [
    Case("hag_clean48", 42103, _mix(0, 6, 0), _mix(4, 1, 1), 48,
         notes="clean thorax, 48-count BRS; estimated on SLED alone; R16 and FULL validated "
               "(four times, once), never estimated"),
    Case("hag_clean96", 42207, _mix(3, 3, 0), _mix(1, 5, 0), 96,
         notes="clean thorax, 96-count BRS; FULL neither estimated nor validated"),
    Case("hag_lock_r16_full", 42309, _mix(0, 4, 2), _mix(4, 2, 0), 128,
         (Effect("rib_lock", 0.092, ("R16", "FULL")),), (("chest_stiffening", "R16+FULL"),),
         notes="the chest locking up near a 92 mm deflection, each rib's force gaining "
               "k d^2 / (d_l - d), on R16 and FULL; R16 validated four times, never estimated; "
               "FULL estimated twice, never validated; SLED clean, 4 estimation tests, "
               "validated twice"),
    Case("hag_foam_r16_full", 42411, _mix(2, 2, 2), _mix(5, 1, 0), 64,
         (Effect("rib_foam", 880.0, ("R16", "FULL")),), (("chest_rate_damping", "R16+FULL"),),
         notes="the sternum's damping pad engaging as the chest closes, c (d / 30 mm) d' in "
               "compression, c = 880 N s/m, on R16 and FULL; R16 estimated twice, validated "
               "five times; FULL estimated twice, never validated; SLED clean, 2 estimation "
               "tests, validated once"),
    Case("hag_capstan_all", 42515, _mix(6, 0, 0), _mix(2, 3, 1), 96,
         (Effect("dring_capstan", 0.59),), (("belt_unloading", "all"),),
         notes="the shoulder webbing wraps its D-ring as a capstan, mu theta 0.59, on every "
               "rig; estimated on R16 alone; SLED and FULL validated (three times, once), never "
               "estimated"),
    Case("hag_toe_r16_sled", 42617, _mix(4, 0, 2), _mix(1, 5, 0), 64,
         (Effect("webbing_toe", 0.2, ("R16", "SLED")),), (("belt_stiffening", "R16+SLED"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.2, on "
               "R16 and SLED; R16 estimated four times, validated once; SLED validated five "
               "times, never estimated; FULL clean, 2 estimation tests, never validated"),
    Case("hag_airbag_sled_full", 42719, _mix(3, 3, 0), _mix(2, 0, 4), 48,
         (Effect("airbag", 0.61, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="set A's vented driver bag at fill 0.61 on the rigs with an interior, SLED and "
               "FULL; SLED estimated three times, never validated; FULL validated four times, "
               "never estimated; R16 without a bag, 3 estimation tests, validated twice"),
    Case("hag_lumbar_r16", 42823, _mix(2, 2, 2), _mix(6, 0, 0), 48,
         (Effect("lumbar_path", 0.56, ("R16",)),), (("pelvis_coupling", "R16"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.56, on R16 alone; R16 estimated twice, validated six times; SLED and "
               "FULL clean, 2 estimation tests each, never validated"),
    Case("hag_eccentric_r16", 42927, _mix(4, 0, 2), _mix(5, 1, 0), 64,
         (Effect("brs_eccentric", 0.41, ("R16",)),), (("input_gain", "R16"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.41 sin(th + phase), on "
               "R16 alone; R16 estimated four times, validated five times; FULL clean, 2 "
               "estimation tests, never validated; SLED validated once, never estimated"),
    Case("hag_two_submarine_r16_visco_sled_full", 42031, _mix(2, 2, 2), _mix(4, 1, 1), 96,
         (Effect("pelvis_submarine", 6000.0, ("R16",)),
          Effect("rib_visco", 2300.0, ("SLED", "FULL"))),
         (("pelvis_coupling", "R16"), ("chest_rate_damping", "SLED+FULL")),
         notes="two kinds on two rigs: the R16 rig's rigid seat without an anti-submarining "
               "ramp, the pelvis on lap belt and seat, the lap belt slipping over the iliac "
               "wings past 6000 N (R16); rib damping F += c |d'|^1.5 sign(d'), c = 2300 "
               "N/(m/s)^1.5 (SLED and FULL); each rig estimated twice; the pairing set E's "
               "(reused, no pairing left)"),
    Case("hag_pulse_late_4p95ms", 42137, _mix(0, 0, 6), _mix(1, 2, 3), 96,
         (Effect("pulse_late", 0.00495),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.95 ms after its record; estimated on FULL alone; "
               "R16 and SLED validated (once, twice), never estimated"),
    Case("hag_brs_late_1p79ms", 42241, _mix(0, 6, 0), _mix(2, 2, 2), 96,
         (Effect("brs_late", 0.00179),), (("input_delay", "all"),),
         notes="the chest feels the belt 1.79 ms after the BRS records it; estimated on SLED "
               "alone; R16 and FULL validated twice each, never estimated"),
    Case("hag_cd_sag", 42343, _mix(0, 0, 6), _mix(0, 1, 5), 128,
         (Effect("cd_sag", 0.65),), (), expect_note=UNEXPLAINED_CD,
         notes="the CD pot's excitation sags after the trigger (not ratiometric): CD reads "
               "d (1 - 0.65 (1 - e^(-t/60 ms))), every test; CR, pulse and BRS untouched: a "
               "residual in cd only"),
    Case("hag_broken_brs_quadrature", 42447, _mix(3, 0, 3), _mix(6, 0, 0), 96,
         (Effect("brs_quadrature", 5.0, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="R16_003, an estimation test: its BRS decoder counts five edges a step while "
               "the test's header keeps the spindle's 96 counts/rev: its belt reads five times "
               "the spool's angle, the pretensioner's pay-in and the load limiter's pay-out "
               "five times those of the other R16 tests; its other channels and every other "
               "test clean"),
]

BY_NAME_AG = {c.name: c for c in SET_AG}
ONE_PHYSICAL_AG = ("hag_lock_r16_full", "hag_foam_r16_full", "hag_capstan_all",
                   "hag_toe_r16_sled", "hag_airbag_sled_full", "hag_lumbar_r16",
                   "hag_eccentric_r16")
