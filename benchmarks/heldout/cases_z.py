"""Held-out set Z: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-Y (``cases.py`` ... ``cases_y.py``).

Set Y's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_z.py`` (``numpy.random.default_rng(35000)``, set W's ``drawn``, the
pairings of A-Y taken, save the two-effect case's: with none free, it reuses one of A-Y's,
``reuse_two``; ``python -m benchmarks.heldout.draw_z`` prints the draw). The cases follow the
draw; only the sizes are set, by costs, by the rule ``draw_z.py`` wrote down before the first
draw (``SIZING``). ``test_set_z_follows_its_draw`` holds the draw and the cases together.

The two-effect case's pairing, est 0/2/4, val 0/2/4, is set O's (``ho_broken_brs_counts``):
the one pairing of this set an earlier set ran (``draw_z.py``'s docstring: all 12 or 24 the
rules allow on each of the six rig splits were run by A-Y).

(Sizes: the rule's first sizes, not yet costed.)"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_Z: list[Case] = [
    Case("hz_clean48", 35103, _mix(0, 0, 6), _mix(2, 0, 4), 48,
         notes="clean thorax, 48-count BRS; estimated on FULL alone, R16 validated twice, "
               "never estimated"),
    Case("hz_clean96", 35207, _mix(6, 0, 0), _mix(0, 5, 1), 96,
         notes="clean thorax, 96-count BRS; estimated on R16 alone, validated on SLED and "
               "FULL, never estimated there"),
    Case("hz_bottoming_sled", 35309, _mix(0, 2, 4), _mix(2, 3, 1), 128,
         (Effect("rib_bottoming", 8.0e7, ("SLED",)),), (("chest_stiffening", "SLED"),),
         notes="the ribs bottom out past 12 mm, 8.0e7 N/m^2.5 beyond the onset (power 2.5), "
               "on SLED alone; FULL clean, 4 estimation tests; R16 validated twice, never "
               "estimated"),
    Case("hz_squeeze_sled", 35411, _mix(2, 4, 0), _mix(0, 2, 4), 128,
         (Effect("rib_squeeze", 440.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 440 N s/m at "
               "rest, on SLED alone; R16 clean, 2 estimation tests; FULL validated four "
               "times, never estimated"),
    Case("hz_hysteresis_sled_full", 35515, _mix(2, 4, 0), _mix(3, 1, 2), 48,
         (Effect("webbing_hysteresis", 0.53, ("SLED", "FULL")),),
         (("belt_unloading", "SLED+FULL"),),
         notes="the webbing unloads on a softer path than it loads, its elastic force 53 % "
               "lower while it shortens, on SLED and FULL; FULL validated twice, never "
               "estimated; R16 clean, 2 estimation tests"),
    Case("hz_power_r16_sled", 35617, _mix(3, 0, 3), _mix(1, 5, 0), 96,
         (Effect("webbing_power", 3.5, ("R16", "SLED")),), (("belt_stiffening", "R16+SLED"),),
         notes="the webbing stiffens as a power of its stretch, F += 3.5 k e (e/e_ref)^2, on "
               "R16 and SLED; SLED validated five times, never estimated; FULL clean, 3 "
               "estimation tests"),
    Case("hz_fabric_sled", 35719, _mix(2, 4, 0), _mix(0, 6, 0), 96,
         (Effect("airbag_fabric", 0.74, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a ventless bag leaking through its fabric at fill 0.74, on SLED alone; "
               "validated on SLED alone; R16 without a bag, 2 estimation tests"),
    Case("hz_lumbar_sled_full", 35823, _mix(3, 0, 3), _mix(4, 1, 1), 96,
         (Effect("lumbar_path", 0.63, ("SLED", "FULL")),), (("pelvis_coupling", "SLED+FULL"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "0.63 x set A's lumbar and lap stiffness, on SLED and FULL; SLED validated "
               "once, never estimated; R16 clean, 3 estimation tests"),
    Case("hz_eccentric_r16_sled", 35927, _mix(0, 3, 3), _mix(5, 1, 0), 48,
         (Effect("brs_eccentric", 0.33, ("R16", "SLED")),), (("input_gain", "R16+SLED"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.33 sin(th + phase), on "
               "R16 and SLED; R16 validated five times, never estimated; FULL clean, 3 "
               "estimation tests"),
    Case("hz_two_lock_sled_set_full", 35031, _mix(0, 2, 4), _mix(0, 2, 4), 64,
         (Effect("rib_lock", 0.078, ("SLED",)), Effect("webbing_set", 0.56, ("FULL",))),
         (("chest_stiffening", "SLED"), ("belt_unloading", "FULL")),
         notes="two kinds on two rigs: the chest locking up near a 78 mm deflection, each "
               "rib's force gaining k d^2 / (d_l - d) (SLED); the car's webbing unloading to a "
               "set of 0.56 x its peak stretch (FULL); R16 neither estimated nor validated; "
               "the pairing set O's (reused, no pairing left)"),
    Case("hz_pulse_late_4p06ms", 35137, _mix(3, 0, 3), _mix(3, 3, 0), 128,
         (Effect("pulse_late", 0.00406),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.06 ms after its record; SLED validated three "
               "times, never estimated"),
    Case("hz_brs_late_3p98ms", 35241, _mix(3, 0, 3), _mix(0, 5, 1), 64,
         (Effect("brs_late", 0.00398),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.98 ms after the BRS records it; SLED validated five "
               "times, never estimated"),
    Case("hz_cr_progressive", 35343, _mix(0, 4, 2), _mix(0, 1, 5), 128,
         (Effect("cr_progressive", 0.11),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer over-reads progressively: CR reads "
               "cr (1 + 0.11 (cr / 25 g)^2), every test; CD and the inputs untouched: a "
               "residual in cr only, a static function of cr"),
    Case("hz_broken_brs_swap", 35447, _mix(2, 4, 0), _mix(2, 1, 3), 64,
         (Effect("brs_swap", 5.0, tests=("SLED_005",)),), (),
         expect_broken=("SLED_005",),
         notes="SLED_005, an estimation test: its BRS channel is FULL_002's spool (five "
               "places on in the case; the files crossed in the lab's export), counted at its "
               "own encoder; its other channels and every other test clean"),
]

BY_NAME_Z = {c.name: c for c in SET_Z}
ONE_PHYSICAL_Z = ("hz_bottoming_sled", "hz_squeeze_sled", "hz_hysteresis_sled_full",
                  "hz_power_r16_sled", "hz_fabric_sled", "hz_lumbar_sled_full",
                  "hz_eccentric_r16_sled")
