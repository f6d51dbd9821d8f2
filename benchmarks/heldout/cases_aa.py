"""Held-out set AA: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-Z (``cases.py`` ... ``cases_z.py``).

Set Z's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_aa.py`` (``numpy.random.default_rng(36000)``, set W's ``drawn``,
the pairings of A-Z taken, save the two-effect case's: with none free, it reuses one of A-Z's,
``reuse_two``; ``python -m benchmarks.heldout.draw_aa`` prints the draw). The cases follow the
draw; only the sizes are set, by costs, by the rule ``draw_aa.py`` wrote down before the first
draw (``SIZING``). ``test_set_aa_follows_its_draw`` holds the draw and the cases together.

The two-effect case's pairing, est 2/2/2, val 3/0/3, is set J's (``hj_two_effects``): the one
pairing of this set an earlier set ran (``draw_aa.py``'s docstring: none was free for its
rigs).

(Sizes: the rule's first sizes, not yet costed.)"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AA: list[Case] = [
    Case("haa_clean48", 36103, _mix(3, 0, 3), _mix(0, 1, 5), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 and FULL, SLED validated once, "
               "never estimated"),
    Case("haa_clean96", 36207, _mix(4, 2, 0), _mix(1, 4, 1), 96,
         notes="clean thorax, 96-count BRS; estimated on R16 and SLED, FULL validated once, "
               "never estimated"),
    Case("haa_bilinear_sled_full", 36309, _mix(3, 3, 0), _mix(3, 0, 3), 64,
         (Effect("rib_bilinear", 1.4, ("SLED", "FULL")),),
         (("chest_stiffening", "SLED+FULL"),),
         notes="the ribs' second load path past 16 mm, their stiffness growing by 1.4 x k_r "
               "beyond it, on SLED and FULL; FULL validated three times, never estimated; R16 "
               "clean, 3 estimation tests"),
    Case("haa_loss_sled", 36411, _mix(0, 4, 2), _mix(3, 2, 1), 48,
         (Effect("rib_loss", 0.21, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="the ribs' damping layer as a constant loss factor, 0.21 k_r d in the sense of "
               "the rate, on SLED alone; FULL clean, 2 estimation tests; R16 validated three "
               "times, never estimated"),
    Case("haa_set_sled", 36515, _mix(4, 2, 0), _mix(0, 2, 4), 48,
         (Effect("webbing_set", 0.57, ("SLED",)),), (("belt_unloading", "SLED"),),
         notes="the chest-side webbing unloads to a set of 0.57 x its peak stretch, on SLED "
               "alone; R16 clean, 4 estimation tests; FULL validated four times, never "
               "estimated"),
    Case("haa_knee_r16_full", 36617, _mix(2, 4, 0), _mix(0, 0, 6), 48,
         (Effect("webbing_knee", 2.3, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing's stiffness grows by 2.3 x k past its knee stretch, on R16 and "
               "FULL; FULL validated six times, never estimated; R16 estimated twice, never "
               "validated; SLED clean, 4 estimation tests"),
    Case("haa_fabric_sled", 36719, _mix(0, 2, 4), _mix(1, 4, 1), 64,
         (Effect("airbag_fabric", 0.74, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a ventless bag leaking through its fabric at fill 0.74, on SLED alone; FULL "
               "without a bag, 4 estimation tests; R16 validated once, never estimated"),
    Case("haa_pelvis_knee_r16_full", 36823, _mix(0, 3, 3), _mix(2, 4, 0), 48,
         (Effect("pelvis_knee", 0.22, ("R16", "FULL")),), (("pelvis_coupling", "R16+FULL"),),
         notes="the pelvis on lap belt and seat at 0.22 x set A's lumbar and lap stiffness, "
               "its knees meeting a knee bolster past a 45 mm gap, on R16 and FULL; R16 "
               "validated twice, never estimated; SLED clean, 3 estimation tests"),
    Case("haa_eccentric_r16", 36927, _mix(3, 3, 0), _mix(4, 0, 2), 48,
         (Effect("brs_eccentric", 0.34, ("R16",)),), (("input_gain", "R16"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.34 sin(th + phase), on "
               "R16 alone; SLED clean, 3 estimation tests; FULL validated twice, never "
               "estimated"),
    Case("haa_two_hardening_r16_sled_lumbar_full", 36031, _mix(2, 2, 2), _mix(3, 0, 3), 96,
         (Effect("rib_hardening", 1.3e8, ("R16", "SLED")),
          Effect("lumbar_path", 0.61, ("FULL",))),
         (("chest_stiffening", "R16+SLED"), ("pelvis_coupling", "FULL")),
         notes="two kinds on two rigs: the ribs hardening from zero, F += 1.3e8 d^3 N/m^3 (R16 "
               "and SLED); the pelvis on lap belt and seat at 0.61 x set A's lumbar and lap "
               "stiffness (FULL); SLED estimated twice, never validated; the pairing set "
               "J's (reused, no pairing left)"),
    Case("haa_pulse_late_2p89ms", 36137, _mix(3, 3, 0), _mix(1, 0, 5), 64,
         (Effect("pulse_late", 0.00289),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.89 ms after its record; FULL validated five "
               "times, never estimated"),
    Case("haa_brs_late_2p39ms", 36241, _mix(2, 4, 0), _mix(4, 0, 2), 96,
         (Effect("brs_late", 0.00239),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.39 ms after the BRS records it; FULL validated "
               "twice, never estimated"),
    Case("haa_cr_zero_shift", 36343, _mix(4, 0, 2), _mix(5, 0, 1), 96,
         (Effect("cr_zero_shift", 2.1),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's zero shifts under the shock: once its reading first "
               "passes 20 g it moves by +2.1 g over 4 ms and stays there, every test; CD and "
               "the inputs untouched: a residual in cr only, a step at a level"),
    Case("haa_broken_pulse_rail", 36447, _mix(0, 6, 0), _mix(0, 0, 6), 96,
         (Effect("pulse_rail", 26.0, tests=("SLED_011",)),), (),
         expect_broken=("SLED_011",),
         notes="SLED_011, an estimation test: its pulse channel set to a +-26 g range, "
               "clipping flat at its rails; its other channels and every other test clean"),
]

BY_NAME_AA = {c.name: c for c in SET_AA}
ONE_PHYSICAL_AA = ("haa_bilinear_sled_full", "haa_loss_sled", "haa_set_sled",
                   "haa_knee_r16_full", "haa_fabric_sled", "haa_pelvis_knee_r16_full",
                   "haa_eccentric_r16")
