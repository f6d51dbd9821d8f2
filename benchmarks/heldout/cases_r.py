"""Held-out set R: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-Q (``cases.py`` ... ``cases_q.py``).

What set R judges is the general list again, the issue's own "done when": two clean cases (48
and 96 counts); each kind of the library a loop can name, as physics from this simulator, at
least once (chest_stiffening, chest_rate_damping twice, belt_unloading, belt_stiffening,
airbag_contact twice, pelvis_coupling, input_gain, input_delay twice); two effects of different
kinds on different rigs in one case; one broken estimation test; one transducer error on CD
alone, where nothing physical must be named, only the output it is on; a late pulse and a late
BRS. Every rig that holds estimation tests holds at least two of them; every expected verdict
names the rigs the effect truly acts on ("all" for all three).

Against sets A-Q: other seeds (27xxx), (estimation, validation) pairings of (R16, SLED, FULL)
counts no case of A-Q ran, effect sizes no case of A-Q used, several on scopes no earlier case
gave their form: the ribs' second load path (``rib_bilinear``) on SLED alone at 1.45 (A-Q: 1.0 on
R16+FULL, 1.3 and 1.6 on all); the webbing's hysteresis on the car's own belt alone (FULL) at
0.42 (A-Q: 0.15-0.7, none 0.42, none on FULL alone); the webbing's exponential toe at 2.8 on
all (A-Q: 0.1-3.5, none 2.8); a two-stage inflator's bag on FULL alone at fill 0.4 (A-Q: 0.45
on SLED+FULL); the pelvis path with its lap belt slipping at 6200 N on all (A-Q: 5000-6800,
none 6200); the sled carriage's accelerometer (R16 and SLED share the channel) reading 9 % high
(``pulse_gain``; A-Q: -8 % on FULL alone); the two-effect case's rib damping |d'|^1.5 on R16
alone at 800 (A-Q: 500-5500, none 800, none on R16 alone) beside a vented bag on SLED alone at
fill 0.45 (A-Q: 0.4-1.0, none 0.45), FULL validated once, never estimated. The delays: the
pulse 3.1 ms, the BRS 4.8 ms (A-Q: no input 3.1 or 4.8 ms). Sizes are in each key's units
(``physics.EFFECTS``).

One physical form no earlier set used (``physics.py``): the sternum's damping pad met over a
contact area that grows as the chest closes, ``rib_foam``: each sternum mass's rib adds c (d /
30 mm) d' in compression (c, the size, in N s/m at 30 mm; from zero at rest, taken no further
than 60 mm), here 2500 on every rig. Mapped to ``chest_rate_damping``. A-Q's chest damping forms
grow with the rate alone (power laws, a valve, a Maxwell branch), not at all (dry friction), or
with the compression from a damping at rest (H's squeeze film, as 1 / gap^3, the nearest); this
one is a damper with nothing at rest, growing in proportion to the compression.

Two lab-side forms no earlier set used (``lab.py``), exact (no per-test scatter). The broken
test, FULL_003, an estimation test: its CD channel's polarity set wrong in the recorder, the
chest read as opening (``cd_reversed``; A-Q reversed CR (E) and the BRS (D), never CD). The
transducer error is on CD, every test: the chest pot's conditioner's output amplifier moves no
faster than 0.7 mm/ms either way (``cd_slew``, a slew rate too low for the channel; the chest
compresses at up to some 1.3 mm/ms, opens at up to some 1 mm/ms), so CD lags its fast loading
and opening and reads right where it is slow; CR and the inputs read right (A-Q's transducer
errors on CD: a non-linear pot, a knee, a tanh, a dead band, backlash, an arm lifting off one
way only (J's ``cd_arm_lift``, a weak return spring: it follows compression at once), an
excitation's sag, a 4-pole and a 1-pole low-pass; none a slew limit both ways).

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set r``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26 13:19-13:36 UTC, 2 busy cores at a load of 2-5, three
cost jobs at a time, the committed seeds and mixes): clean48 88.8, clean96 93.1; rib_foam_all
87.6 -> 92.6 (5.1), rib_bilinear_sled 85.8 -> 91.0 (5.1), hysteresis_full 88.0 -> 90.9 (2.9),
webbing_toe_all 87.8 -> 90.8 (3.0), airbag_dual_full 86.7 -> 92.5 (5.7), submarine_all 89.0 ->
91.8 (2.8), pulse_gain_sleds 87.3 -> 92.7 (5.4), pulse_late_3p1ms 89.1 -> 91.2 (2.1),
brs_late_4p8ms 87.3 -> 92.4 (5.0), two_visco_r16_airbag_sled 83.7 -> 93.0 (9.3; the rib
damping alone 4.3, the bag alone 5.2), broken_cd_reversed 74.6 -> 94.2 (19.6; flagging the test
is the verdict asked; left in, it moves the fit), cd_slew 90.1 -> 92.1 (2.0). Each effect of
the two-effect case alone: the case's seed with the other effect's rigs emptied (same dummies,
pulses and noise), against the same twin.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): the transducer error was first ``cd_gain``, the chest pot's calibration
entered 18 % high (CD x 1.18), cost -0.1 (the grey-box's parameters take a static CD gain up;
a larger gain was not tried); replaced by ``cd_slew`` at 0.7 mm/ms (a form, not a size,
changed: the only such change), and ``cd_gain`` taken out of the simulator; airbag_dual_full
was at fill 0.6, cost 10.1 (above the 1.5-6 band earlier sets kept to), so 0.4;
two_visco_r16_airbag_sled was rib damping 3000 with the bag at 0.75, together 22.3, then 2000
with 0.55, together 16.4 (the rib damping alone 11.8, the bag alone 6.5: on the R16 rig alone
the |d'|^1.5 term costs far more per unit than A-Q's sizes on all rigs suggest), so 800 and
0.45 (together 9.3, kept: each alone is within 1.5-6). The other eleven cases are as first written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_R: list[Case] = [
    Case("hr_clean48", 27103, _mix(2, 4, 0), _mix(2, 2, 2), 48,
         notes="clean thorax, 48-count BRS; FULL validated twice, never estimated"),
    Case("hr_clean96", 27209, _mix(0, 2, 4), _mix(3, 1, 2), 96,
         notes="clean thorax, 96-count BRS; R16 validated three times, never estimated"),
    Case("hr_rib_foam_all", 27311, _mix(4, 0, 2), _mix(2, 3, 1), 64,
         (Effect("rib_foam", 2500.0),), (("chest_rate_damping", "all"),),
         notes="the sternum's damping pad is met over an area growing with the compression: "
               "F += 2500 (d / 30 mm) d' in compression (a form no earlier set used), every "
               "rig"),
    Case("hr_rib_bilinear_sled", 27417, _mix(0, 4, 2), _mix(1, 3, 2), 96,
         (Effect("rib_bilinear", 1.45, ("SLED",)),), (("chest_stiffening", "SLED"),),
         notes="the sled lab's dummy's ribs meet a second load path past 16 mm, stiffness "
               "+1.45 x (A-Q: 1.0 on R16+FULL, 1.3 and 1.6 on all); FULL clean, 2 estimation "
               "tests"),
    Case("hr_hysteresis_full", 27521, _mix(2, 0, 4), _mix(1, 2, 3), 48,
         (Effect("webbing_hysteresis", 0.42, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the car's own belt (FULL): its webbing's elastic force 0.42 lower while it "
               "shortens (A-Q: 0.15-0.7, none 0.42, none on FULL alone); R16 clean, 2 "
               "estimation tests"),
    Case("hr_webbing_toe_all", 27629, _mix(3, 0, 3), _mix(2, 2, 2), 128,
         (Effect("webbing_toe", 2.8),), (("belt_stiffening", "all"),),
         notes="the webbing stiffens exponentially with stretch, amount 2.8 (A-Q: 0.1-3.5, "
               "none 2.8), every rig"),
    Case("hr_airbag_dual_full", 27733, _mix(0, 2, 4), _mix(1, 1, 4), 64,
         (Effect("airbag_dual", 0.4, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="the car's (FULL) driver bag on a two-stage inflator at fill 0.4 (A-Q: 0.45 on "
               "SLED+FULL); SLED's interior without a bag effect, 2 estimation tests"),
    Case("hr_submarine_all", 27839, _mix(4, 2, 0), _mix(1, 2, 3), 96,
         (Effect("pelvis_submarine", 6200.0),), (("pelvis_coupling", "all"),),
         notes="the pelvis on lap belt and seat, the lap belt slipping over the iliac wings "
               "past 6200 N (A-Q: 5000, 5500, 6800), every rig"),
    Case("hr_pulse_gain_sleds", 27941, _mix(3, 3, 0), _mix(1, 1, 4), 48,
         (Effect("pulse_gain", 0.09, ("R16", "SLED")),), (("input_gain", "R16+SLED"),),
         notes="the sled carriage's accelerometer (R16 and SLED share it) reads 9 % high, its "
               "sensitivity entered wrong (A-Q: -0.08 on FULL); the car's tunnel accelerometer "
               "(FULL) right, validated four times, never estimated"),
    Case("hr_pulse_late_3p1ms", 27043, _mix(4, 2, 0), _mix(2, 2, 2), 96,
         (Effect("pulse_late", 0.0031),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.1 ms after its record (A-Q: no input 3.1 ms)"),
    Case("hr_brs_late_4p8ms", 27147, _mix(0, 4, 2), _mix(2, 1, 3), 64,
         (Effect("brs_late", 0.0048),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.8 ms after the BRS records it (A-Q: no input "
               "4.8 ms)"),
    Case("hr_two_visco_r16_airbag_sled", 27251, _mix(2, 4, 0), _mix(2, 3, 1), 96,
         (Effect("rib_visco", 800.0, ("R16",)), Effect("airbag", 0.45, ("SLED",))),
         (("chest_rate_damping", "R16"), ("airbag_contact", "SLED")),
         notes="two kinds on two rigs: the R16 lab's dummy's rib damping F += 800 |d'|^1.5 "
               "(A-Q: 500-5500, none 800, none on R16 alone), and a vented bag at fill 0.45 "
               "on SLED alone (A-Q: 0.4-1.0 on SLED+FULL, 0.9 on SLED); FULL validated once, "
               "never estimated"),
    Case("hr_broken_cd_reversed", 27359, _mix(0, 3, 3), _mix(3, 1, 2), 128,
         (Effect("cd_reversed", 1.0, tests=("FULL_003",)),), (), expect_broken=("FULL_003",),
         notes="FULL_003, an estimation test: its CD channel's polarity set wrong in the "
               "recorder, the chest read as opening; its other channels and every other test "
               "clean"),
    Case("hr_cd_slew", 27461, _mix(2, 0, 4), _mix(3, 2, 1), 96,
         (Effect("cd_slew", 0.7),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's conditioner's output amplifier moves no faster than 0.7 mm/ms "
               "either way, every test (a slew rate too low for the channel; the chest "
               "compresses at up to some 1.3 mm/ms): CD lags its fast loading and opening; CR "
               "and the inputs untouched: a residual in cd only"),
]

BY_NAME_R = {c.name: c for c in SET_R}
