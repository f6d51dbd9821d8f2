"""Held-out set T: fifteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-S (``cases.py`` ... ``cases_s.py``).

What set T judges is the general list again, written by another engineer from the simulator
and the thesis alone, without reading how the loop works, with its emphasis on sensor against
physics: two transducer errors, one on CD alone and one on CR alone, where nothing physical must
be named, only the output each is on; beside three physical cases whose effect shows mostly in
one output (CD) but truly is physics acting on both outputs, where the physical kind must be
named, not a sensor. And the rest of the list: two clean cases (48 and 96 counts); each kind of
the library a loop can name, as physics from this simulator, at least once (chest_stiffening
twice, chest_rate_damping, belt_unloading, belt_stiffening, airbag_contact twice,
pelvis_coupling, input_gain, input_delay twice); two effects of different kinds on different
rigs in one case; one broken estimation test; a late pulse and a late BRS. Every rig that holds
estimation tests holds at least two of them; an effect on some rigs only rests on two or more
estimation and validation tests of them beside an estimation test of a rig it spares; every
expected verdict names the rigs the effect truly acts on ("all" for all three).

Against sets A-S: other seeds (29xxx), (estimation, validation) pairings of (R16, SLED, FULL)
counts no case of A-S ran, effect sizes no case of A-S used, on scopes of one or two rigs:
viscoelastic ribs (a Maxwell branch) on R16+SLED at 0.75 (A-S: 1.5 on all); the D-ring's
capstan on R16+SLED at mu theta 0.68 (A-S: 0.5 and 0.62 on FULL, 0.56 on all); the webbing's
exponential toe on R16+FULL at 0.15 (A-S: 0.1 on R16+SLED, 2.5-3.5 on all); a bag leaking
through its fabric on SLED alone at fill 0.75 (A-S: 0.6-0.85, none 0.75); the pelvis path with
a knee bolster on FULL alone at 0.1 (A-S: 0.2 on SLED+FULL); the BRS ring 28 % off-centre on
SLED+FULL (A-S: 0.18-0.35 on all, none 0.28); the two-effect case's ribs' second load path on
R16 alone at 1.2 (A-S: 1.0-1.6, none 1.2, none on R16 alone) beside an unvented bag on FULL
alone at fill 0.38 (A-S: 0.25-0.7, none 0.38), SLED validated once, never estimated. The
delays: the pulse 2.9 ms, the BRS 4.7 ms (A-S: no input 2.9 or 4.7 ms). Sizes are in each
key's units (``physics.EFFECTS``).

One physical form no earlier set used (``physics.py``): a stop behind the lower sternum,
``rib_bumper``: once the lower sternum mass's ribs have closed BUMPER_GAP_M (15 mm) its lower
edge meets the spine box's rubber bumper, a Hertzian contact, F = K pen^1.5 (K, the size, in
N/m^1.5), on the lower sternum mass alone (the upper one, where the diagonal belt crosses, has
no stop behind it); here 2e7 on SLED+FULL. Mapped to ``chest_stiffening``. A-S's chest
stiffening forms act on both sternum masses alike (a power 2.5 past 12 mm, a cubic, a second
load path, a lock, Fung's exponential); this one is a contact on one of the two, a power 1.5.

Three lab-side forms no earlier set used (``lab.py``), exact (no per-test scatter). The broken
test, SLED_005, an estimation test: its pulse file exported in m/s^2 where its header (and
every other test's file) states g (``pulse_ms2``: the channel reads G times the deceleration,
its noise with it; A-S's broken pulses: clipped at a rail, a zero shift, another time base,
another test's, another sampling rate; none in other units). The transducer error on CD, every
test: the chest pot's arm (its slider and the rod to the sternum) a mass on a spring, lightly
damped by the wiper (``cd_arm_ring``): CD reads the sternum through a 2-pole low-pass of
damping ratio 0.12 at the arm's natural frequency, 35 Hz, causal: it overshoots a fast loading
and rings (A-S's transducer errors on CD: a non-linear pot, a knee, a tanh, a dead band,
backlash, an arm lifting off, an excitation's sag, a 4-pole Butterworth and a 1-pole RC
low-pass, a slew limit; none a resonance). The transducer error on CR, every test: the recorder
switches the spine accelerometer's bridge excitation on only at the trigger and its zero drifts
as its gauges warm (``cr_drift``): CR reads cr + 24 g/s x t from the trigger on, nothing before
(A-S's on CR: a gain, a tanh, a progressive over-read, a piezoelectric high-pass, a zero step
at a shock level, CD's crosstalk, an oil-damped low-pass, a late digitiser, a creep; none a
zero growing with time). CD, pulse and BRS read right under cr_drift; CR, pulse and BRS under
cd_arm_ring.

Sensor against physics: the three physical cases whose effect shows mostly in one output
(``MOSTLY_ONE_OUTPUT``) move CD far more than CR, as their per-output costs below show, while
both outputs truly move (the chest's forces act on spine and sternum alike): the lower
sternum's stop (chest_stiffening, CD 5.2 points, CR 1.7), the viscoelastic ribs
(chest_rate_damping, CD 10.6, CR 0.9) and the pelvis on its knee bolster (pelvis_coupling, CD
6.7, CR 0.5). Their verdict is the physical kind; the CD transducer's (cd_arm_ring: CD 3.8, CR
1.3) is a sensor effect on CD. The CR transducer (cr_drift: CR 6.4, CD 2.0) is a sensor effect
on CR. (The bag leaking through its fabric costs CR more than CD, 3.7 against 1.9, and the
unvented bag alone in the two-effect case CR 2.7 against CD 0.7, but both move CR and CD about
alike in the signals: they are not counted among the cases mostly in one output.)

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set t``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points, and where it says so the same per output, CR and CD, from the fits
it keeps with ``--work``; the committed seeds, mixes and sizes, 2026-11-26 19:37-19:45 UTC, 2
cores, two cost jobs at a time): clean48 93.7, clean96 92.9; bumper_sled_full 87.8 -> 91.2 (3.4;
CR 1.7, CD 5.2), maxwell_r16_sled 84.6 -> 90.3 (5.7; CR 0.9, CD 10.6), capstan_r16_sled 89.4 ->
93.2 (3.8; CR 2.5, CD 5.1), webbing_toe_r16_full 87.8 -> 91.8 (4.0; CR 4.3, CD 3.8),
airbag_fabric_sled 89.0 -> 91.8 (2.8; CR 3.7, CD 1.9), knee_full 89.7 -> 93.3 (3.6; CR 0.5, CD
6.7), brs_eccentric_sled_full 87.6 -> 91.8 (4.1), pulse_late_2p9ms 88.3 -> 90.9 (2.6),
brs_late_4p7ms 87.9 -> 92.7 (4.8), two_bilinear_r16_sealed_full 85.7 -> 90.4 (4.7; CR 3.9, CD
5.6; the second load path alone 4.3, the unvented bag alone 1.7: CR 2.7, CD 0.7),
broken_pulse_ms2 -14.4 -> 90.6 (105.0; flagging the test is the verdict asked; left in, it
wrecks the fit), cd_arm_ring 90.0 -> 92.5 (2.5; CR 1.3, CD 3.8), cr_drift 87.8 -> 92.0 (4.2; CR
6.4, CD 2.0). Each effect of the two-effect case alone: the case's seed with the other effect's
rigs emptied (same dummies, pulses and noise), against the same twin.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): bumper_sled_full was K 3e6 with the stop 18 mm off, cost 0.7 (CR 0.4, CD 1.0),
then 8e6, 1.1 (CR 0.6, CD 1.7), so the form's gap was set to 15 mm (a constant of the new form,
before the forms' commit) and K 2e7 (3.4); maxwell_r16_sled was 1.1, cost 8.2 (above the 1.5-6
band earlier sets kept to), so 0.75; capstan_r16_sled was 0.45, cost 1.0, then 0.75, where the
physics ran away on R16_001 (its BRS past 1e6 degrees, which the project's reader refuses), then
0.6, 1.3, so 0.68 (webbing_hysteresis at 0.32 in its place cost 1.7, not taken);
webbing_toe_r16_full was 1.6, cost 10.7, then 0.9, 9.1 (between 1.6 and 0.9 its cost hardly
moved), so 0.15; it was meant as a belt effect showing mostly in CR, but it cost CR 11.6 and CD
9.8 alike, so it is not counted among the cases mostly in one output; knee_full was 0.3, cost
11.0, so 0.1; the two-effect case's second effect was a webbing set of 0.47 on FULL
(belt_unloading), together 3.8 but the set alone -0.2 (invisible on FULL here), so it was
replaced by the unvented bag on FULL at 0.38 (a form and a kind, not only a size, changed; the
case renamed from two_bilinear_r16_set_full); cd_arm_ring was 60 Hz, cost 0.9, so 35 Hz;
cr_drift was 30 g/s, cost 6.0 (at the band's top), so 24. The other seven cases are as first
written. The in-between sizes were costed through the same calls (``costs._fit`` on
``make_sets.make``'s folders, the same twin), one case at a time.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"
UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_T: list[Case] = [
    Case("ht_clean48", 29113, _mix(4, 2, 0), _mix(2, 1, 3), 48,
         notes="clean thorax, 48-count BRS; FULL validated three times, never estimated"),
    Case("ht_clean96", 29219, _mix(0, 3, 3), _mix(3, 2, 1), 96,
         notes="clean thorax, 96-count BRS; R16 validated three times, never estimated"),
    Case("ht_bumper_sled_full", 29323, _mix(2, 0, 4), _mix(1, 3, 2), 64,
         (Effect("rib_bumper", 2.0e7, ("SLED", "FULL")),), (("chest_stiffening", "SLED+FULL"),),
         notes="the lower sternum meets the spine box's rubber bumper past 15 mm, Hertz, "
               "K pen^1.5 at K 2e7 (a form no earlier set used), SLED and FULL; R16 clean, "
               "2 estimation tests; shows mostly in CD"),
    Case("ht_maxwell_r16_sled", 29427, _mix(3, 0, 3), _mix(3, 2, 1), 96,
         (Effect("rib_maxwell", 0.75, ("R16", "SLED")),),
         (("chest_rate_damping", "R16+SLED"),),
         notes="viscoelastic rib material, a Maxwell branch of 0.75 x the rib's "
               "stiffness (A-S: 1.5 on all), R16 and SLED; FULL clean, 3 estimation tests; "
               "shows mostly in CD"),
    Case("ht_capstan_r16_sled", 29531, _mix(4, 0, 2), _mix(1, 4, 1), 128,
         (Effect("dring_capstan", 0.68, ("R16", "SLED")),), (("belt_unloading", "R16+SLED"),),
         notes="the shoulder webbing wraps its D-ring as a capstan, mu theta 0.68, on "
               "R16 and SLED (A-S: 0.5 and 0.62 on FULL, 0.56 on all); FULL clean, 2 "
               "estimation tests"),
    Case("ht_webbing_toe_r16_full", 29637, _mix(2, 4, 0), _mix(2, 0, 4), 48,
         (Effect("webbing_toe", 0.15, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.15 "
               "(A-S: 0.1 on R16+SLED, 2.5-3.5 on all), R16 and FULL; SLED clean, 4 "
               "estimation tests"),
    Case("ht_airbag_fabric_sled", 29741, _mix(3, 3, 0), _mix(1, 4, 1), 96,
         (Effect("airbag_fabric", 0.75, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="the sled lab's driver bag has no vent holes and leaks through its fabric, "
               "fill 0.75 (A-S: 0.6-0.85, none 0.75), SLED alone; the R16 rig without a bag, "
               "3 estimation tests"),
    Case("ht_knee_full", 29843, _mix(4, 0, 2), _mix(1, 1, 4), 64,
         (Effect("pelvis_knee", 0.1, ("FULL",)),), (("pelvis_coupling", "FULL"),),
         notes="the car's (FULL) pelvis path at scale 0.1 with its knees on the knee "
               "bolster (A-S: 0.2 on SLED+FULL); R16 clean, 4 estimation tests; shows mostly "
               "in CD"),
    Case("ht_brs_eccentric_sled_full", 29947, _mix(2, 2, 2), _mix(0, 1, 5), 128,
         (Effect("brs_eccentric", 0.28, ("SLED", "FULL")),), (("input_gain", "SLED+FULL"),),
         notes="the BRS encoder ring 28 % off-centre (A-S: 0.18-0.35 on all, none 0.28) "
               "on the sled lab's and the car's retractors; R16 clean, 2 estimation tests, "
               "never validated"),
    Case("ht_pulse_late_2p9ms", 29053, _mix(6, 0, 0), _mix(2, 2, 2), 96,
         (Effect("pulse_late", 0.0029),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.9 ms after its record (A-S: no input 2.9 "
               "ms); R16 alone estimated"),
    Case("ht_brs_late_4p7ms", 29159, _mix(0, 2, 4), _mix(2, 0, 4), 64,
         (Effect("brs_late", 0.0047),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.7 ms after the BRS records it (A-S: no input "
               "4.7 ms); R16 validated twice, never estimated"),
    Case("ht_two_bilinear_r16_sealed_full", 29263, _mix(2, 0, 4), _mix(3, 1, 2), 96,
         (Effect("rib_bilinear", 1.2, ("R16",)), Effect("airbag_sealed", 0.38, ("FULL",))),
         (("chest_stiffening", "R16"), ("airbag_contact", "FULL")),
         notes="two kinds on two rigs: the R16 rig's dummy's ribs take a second load path "
               "past 16 mm, 1.2 x their stiffness (A-S: 1.0-1.6, none 1.2, none on R16 "
               "alone), and the car's (FULL) driver bag is unvented, fill 0.38 (A-S: "
               "0.25-0.7, none 0.38); SLED validated once, never estimated"),
    Case("ht_broken_pulse_ms2", 29367, _mix(0, 6, 0), _mix(1, 3, 2), 48,
         (Effect("pulse_ms2", 1.0, tests=("SLED_005",)),), (), expect_broken=("SLED_005",),
         notes="SLED_005, an estimation test: its pulse file in m/s^2 under its header's "
               "g (the channel G times too large); its other channels and every other test "
               "clean"),
    Case("ht_cd_arm_ring", 29471, _mix(4, 2, 0), _mix(0, 3, 3), 96,
         (Effect("cd_arm_ring", 35.0),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's arm resonates at 35 Hz, damping ratio 0.12: CD overshoots "
               "and rings, every test; CR and the inputs untouched: a residual in cd only"),
    Case("ht_cr_drift", 29577, _mix(0, 4, 2), _mix(3, 3, 0), 64,
         (Effect("cr_drift", 24.0),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's zero drifts 24 g/s from the trigger on (its "
               "bridge warming), every test; CD and the inputs untouched: a residual in cr "
               "only"),
]

BY_NAME_T = {c.name: c for c in SET_T}

# the physical cases whose effect shows mostly in one output (that output), physics on both
MOSTLY_ONE_OUTPUT = {"ht_bumper_sled_full": "cd", "ht_maxwell_r16_sled": "cd",
                     "ht_knee_full": "cd"}
