"""Held-out set Y: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-X (``cases.py`` ... ``cases_x.py``).

Set X's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_y.py`` (``numpy.random.default_rng(34000)``, set W's ``drawn``, the
pairings of A-X taken; ``python -m benchmarks.heldout.draw_y`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_y.py`` wrote down before
the first draw (``SIZING``). ``test_set_y_follows_its_draw`` holds the draw and the cases
together.

(Sizes: the rule's first sizes, not yet costed.)"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_Y: list[Case] = [
    Case("hy_clean48", 34103, _mix(0, 0, 6), _mix(3, 3, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on FULL alone, validated on R16 and SLED, "
               "never estimated there"),
    Case("hy_clean96", 34207, _mix(2, 0, 4), _mix(0, 6, 0), 96,
         notes="clean thorax, 96-count BRS; validated on SLED alone, never estimated there"),
    Case("hy_bumper_r16_sled", 34309, _mix(4, 0, 2), _mix(0, 5, 1), 64,
         (Effect("rib_bumper", 2.1e7, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the lower sternum meets the spine box's rubber stop, Hertz, K = 2.1e7 N/m^1.5, "
               "on R16 and SLED; SLED validated five times, never estimated; FULL clean, 2 "
               "estimation tests"),
    Case("hy_squeeze_r16_sled", 34411, _mix(0, 3, 3), _mix(3, 3, 0), 64,
         (Effect("rib_squeeze", 430.0, ("R16", "SLED")),), (("chest_rate_damping", "R16+SLED"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 430 N s/m at "
               "rest, on R16 and SLED; R16 validated three times, never estimated; FULL clean, "
               "3 estimation tests"),
    Case("hy_capstan_full", 34513, _mix(3, 0, 3), _mix(0, 2, 4), 128,
         (Effect("dring_capstan", 0.59, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the shoulder webbing wraps the car's D-ring as a capstan, mu theta = 0.59, the "
               "car's (FULL) alone; SLED validated twice, never estimated; R16 clean, 3 "
               "estimation tests"),
    Case("hy_power_r16", 34617, _mix(4, 2, 0), _mix(4, 0, 2), 64,
         (Effect("webbing_power", 5.1, ("R16",)),), (("belt_stiffening", "R16"),),
         notes="the webbing stiffens as a power of its stretch, F += 5.1 k e (e/e_ref)^2, on "
               "R16 alone; FULL validated twice, never estimated; SLED clean, 2 estimation "
               "tests"),
    Case("hy_sealed_sled_full", 34719, _mix(4, 0, 2), _mix(0, 2, 4), 96,
         (Effect("airbag_sealed", 0.39, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="an unvented gas bag at fill 0.39 of the vented one's, on SLED and FULL; SLED "
               "validated twice, never estimated; R16 without a bag, 4 estimation tests"),
    Case("hy_pelvis_knee_sled", 34823, _mix(3, 3, 0), _mix(0, 2, 4), 48,
         (Effect("pelvis_knee", 0.21, ("SLED",)),), (("pelvis_coupling", "SLED"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.21, and the knees meeting the knee bolster, the SLED rig's alone; FULL "
               "validated four times, never estimated; R16 clean, 3 estimation tests"),
    Case("hy_eccentric_full", 34927, _mix(0, 3, 3), _mix(2, 0, 4), 48,
         (Effect("brs_eccentric", 0.31, ("FULL",)),), (("input_gain", "FULL"),),
         notes="the car's BRS encoder ring off-centre, the angle read th + 0.31 sin(th + "
               "phase), on FULL alone; R16 validated twice, never estimated; SLED clean, 3 "
               "estimation tests"),
    Case("hy_two_knee_full_fabric_sled", 34031, _mix(0, 2, 4), _mix(0, 3, 3), 64,
         (Effect("webbing_knee", 2.2, ("FULL",)), Effect("airbag_fabric", 0.73, ("SLED",))),
         (("belt_stiffening", "FULL"), ("airbag_contact", "SLED")),
         notes="two kinds on two rigs: the car's webbing stiffening by 2.2 x k past its knee "
               "(FULL); a ventless bag leaking through its fabric at fill 0.73 (SLED); R16 "
               "neither estimated nor validated"),
    Case("hy_pulse_late_4p24ms", 34137, _mix(4, 2, 0), _mix(0, 0, 6), 48,
         (Effect("pulse_late", 0.00424),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.24 ms after its record; validated on FULL alone, "
               "never estimated there"),
    Case("hy_brs_late_2p79ms", 34241, _mix(2, 0, 4), _mix(2, 4, 0), 64,
         (Effect("brs_late", 0.00279),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.79 ms after the BRS records it; SLED validated four "
               "times, never estimated"),
    Case("hy_cr_crosstalk", 34343, _mix(0, 0, 6), _mix(1, 4, 1), 48,
         (Effect("cr_crosstalk", 0.16),), (), expect_note=UNEXPLAINED_CR,
         notes="CR picks up CD on the recorder's multiplexed digitiser, 0.16 g per mm of CD, "
               "every test; CD and the inputs untouched: a residual in cr only"),
    Case("hy_broken_brs_freeze", 34447, _mix(4, 0, 2), _mix(3, 3, 0), 48,
         (Effect("brs_freeze", 0.049, tests=("R16_001",)),), (),
         expect_broken=("R16_001",),
         notes="R16_001, an estimation test: its BRS cable faulted, the count frozen from 49 ms "
               "on; its other channels and every other test clean"),
]

BY_NAME_Y = {c.name: c for c in SET_Y}
ONE_PHYSICAL_Y = ("hy_bumper_r16_sled", "hy_squeeze_r16_sled", "hy_capstan_full",
                  "hy_power_r16", "hy_sealed_sled_full", "hy_pelvis_knee_sled",
                  "hy_eccentric_full")
