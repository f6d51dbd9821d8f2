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

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bilinear, SLED+FULL, 64, est 3/3/0, val 3/0/3; chest_rate_damping:
rib_loss, SLED, 48, est 0/4/2, val 3/2/1; belt_unloading: webbing_set, SLED, 48, est 4/2/0, val
0/2/4; belt_stiffening: webbing_knee, R16+FULL, 48, est 2/4/0, val 0/0/6; airbag_contact:
airbag_fabric, SLED, 64, est 0/2/4, val 1/4/1; pelvis_coupling: pelvis_knee, R16+FULL, 48, est
0/3/3, val 2/4/0; input_gain: brs_eccentric, R16, 48, est 3/3/0, val 4/0/2; the two-effect case
chest_stiffening (rib_hardening) on R16+SLED beside pelvis_coupling (lumbar_path) on FULL, 96,
est 2/2/2, val 3/0/3 (set J's pairing, reused); the late pulse 2.89 ms, 64, est 3/3/0, val
1/0/5; the late BRS 2.39 ms, 96, est 2/4/0, val 4/0/2; the transducer error on CR,
cr_zero_shift, 96, est 4/0/2, val 5/0/1; the broken test's channel the pulse, pulse_rail, 96,
est 0/6/0, val 0/0/6, the test SLED_011; clean48 est 3/0/3, val 0/1/5; clean96 est 4/2/0, val
1/4/1.

Redrawn: none (``draw_aa.REDRAWN`` is empty): every draw found a size in band within the
rule's four.

Sizes (the rule's; A-Z's values stepped off; the medians over every case of A-Z giving the
key): the bilinear ribs 1.4 (median 1.3, taken), the loss factor 0.21 (0.2, taken), the set
0.57 (median 0.54: 0.54-0.56 taken), the knee 2.3 (median 2.1: 2.1, 2.2 taken), the fabric bag
0.74 (the median, half-way between 0.73 and 0.75, not taken), the pelvis with its knee bolster
0.22 (median 0.205: 0.21, taken), the encoder ring 0.34 (median 0.29: 0.29-0.33 taken), the
zero shift 2.1 g (2.0, taken), the pulse rail 26 g (25, taken; not banded); the two-effect
case's hardening 8.7e7 N/m^3 (median 1.1e8: 1.1e8, 1.2e8 taken, so 1.3e8; see below) beside
the lumbar path 0.37 (median 0.6, taken, so 0.61, alone 8.24: CR 6.86, CD 9.61; then 0.26,
3.5 / 8.24 of it, alone 1.09: CR -0.07, CD 2.25; then log-linear between them toward 3.5,
0.35, taken, 0.36 taken, so 0.37).

The two-effect case at its first sizes cost 6.16 together (CR 5.10, CD 7.23), the hardening
alone 5.24 (CR 0.18, CD 10.29), the lumbar path alone 8.24, above the band: the lumbar path was
set alone by the rule (above); the two together at 1.3e8 and 0.37 cost 6.10 (CR 1.50, CD
10.70), above the band, each alone in it (5.24, 2.94). By rule 4 as ``draw_aa.py`` wrote it
down before the draw (set Z's way), the hardening, whose cost alone lay toward the side the
case left, was stepped by 2 toward 3.5 (it grows with its size: 1.3e8 x 3.5 / 5.24 = 8.68e7,
8.7e7); the lumbar path kept 0.37.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; one core, one cost job at a time): clean48 92.0, clean96 94.6;
bilinear_sled_full 89.4 -> 85.9 (3.54; CR 1.24, CD 5.85); loss_sled 92.2 -> 86.6 (5.61; CR
2.85, CD 8.37); set_sled 92.3 -> 90.5 (1.79; CR 2.04, CD 1.54); knee_r16_full 90.9 -> 86.1
(4.76; CR 5.75, CD 3.78); fabric_sled 91.8 -> 88.4 (3.40; CR 3.63, CD 3.17);
pelvis_knee_r16_full 90.3 -> 85.4 (4.91; CR 4.12, CD 5.69); eccentric_r16 91.1 -> 88.8 (2.29;
CR 2.83, CD 1.75); two_hardening_r16_sled_lumbar_full 92.3 -> 87.7 (4.67; CR 1.31, CD 8.02;
the hardening alone 3.32: CR -0.13, CD 6.76; the lumbar path alone 2.94: CR 2.02, CD 3.86);
pulse_late_2p89ms 92.5 -> 90.5 (2.00; CR 2.56, CD 1.43); brs_late_2p39ms 91.7 -> 90.0 (1.75;
CR 1.74, CD 1.75); cr_zero_shift 92.2 -> 88.6 (3.58; CR 5.86, CD 1.30); broken_pulse_rail
91.2 -> 90.2 (1.01; CR 1.07, CD 0.95; flagging the test is the verdict asked; not banded, by
the rule). Each effect of the two-effect case alone: the case's seed with the other effect's
size 0 (kept in the case's list, so the dummies and pulses draw as they do in the case),
against the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

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
         (Effect("rib_hardening", 8.7e7, ("R16", "SLED")),
          Effect("lumbar_path", 0.37, ("FULL",))),
         (("chest_stiffening", "R16+SLED"), ("pelvis_coupling", "FULL")),
         notes="two kinds on two rigs: the ribs hardening from zero, F += 8.7e7 d^3 N/m^3 (R16 "
               "and SLED); the pelvis on lap belt and seat at 0.37 x set A's lumbar and lap "
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
