"""Held-out set W: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-V (``cases.py`` ... ``cases_v.py``).

What set W judges is the general list again, written by another engineer from the simulator
and the thesis alone, without reading how the loop works, by set V's process: every choice
drawn, not picked. ``draw_w.py`` (``numpy.random.default_rng(32000)``, ``python -m
benchmarks.heldout.draw_w`` prints the draw) draws for each kind of the library its form among
every set's forms of that kind (the input gain among the BRS's own), the rigs it acts on, the
BRS counts and the (estimation, validation) mix among the pairings no case of A-V ran that the
scope rules allow; the two-effect case's kinds, forms and disjoint rigs; the delays; the
transducer error's output and, unlike V, its form (among every lab-side transducer form the
simulator has on that output); the broken test's channel, test and, unlike V, its form (among
every lab-side broken-channel form on that channel); the clean cases' mixes. The cases follow
the draw; only the sizes are chosen, by costs. ``test_set_w_follows_its_draw`` holds the two
together.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bumper (T's stop behind the lower sternum), R16+SLED, 48, est 4/0/2, val
0/6/0; chest_rate_damping: rib_squeeze (H's squeeze film), SLED+FULL, 64, est 3/3/0, val 1/3/2;
belt_unloading: webbing_hysteresis (B's), all, 128, est 0/3/3, val 1/0/5 (redrawn, see below);
belt_stiffening: webbing_toe (A's), R16+FULL, 96, est 0/2/4, val 6/0/0; airbag_contact:
airbag_dual (K's two-stage inflator), FULL, 96, est 3/0/3, val 0/3/3; pelvis_coupling:
lumbar_path (A's), SLED, 96, est 3/3/0, val 0/6/0; input_gain: brs_eccentric (A's off-centre
encoder ring), SLED, 48, est 2/4/0, val 0/5/1; the two-effect case belt_unloading (webbing_set,
C's permanent set) on SLED beside belt_stiffening (webbing_knee, C's knee) on FULL, 64, est
0/2/4, val 1/2/3 (redrawn); the late pulse 3.23 ms, 48, est 3/0/3, val 0/4/2 (redrawn); the
late BRS 4.17 ms, 128, est 3/0/3, val 2/4/0 (redrawn); the transducer error on CD, its form
cd_sag (N's pot excitation sagging after the trigger), 48, est 0/0/6, val 2/2/2; the broken
test's channel the BRS, its form brs_reversed (D's count direction set wrong in the recorder),
128, est 4/0/2, val 1/3/2, the test R16_003; clean48 est 4/0/2, val 6/0/0; clean96 est 0/4/2,
val 6/0/0.

Redrawn (``draw_w.REDRAWN``; each whole, by the next seed's generator, in this order after the
rest, the pairings of everything drawn before still taken):
32001, the two-effect case: its first draw, airbag_sealed on FULL beside rib_bumper on
R16+SLED, 128 counts, had no pairing left (sets A-V ran all twelve the rules allow).
32002, belt_unloading: its first draw was webbing_slack on all three rigs, 64 counts, est 0/6/0,
val 1/2/3; the slack is a switch (nothing to size) and cost the grey-box 8.0 points (CR 9.6, CD
6.4), above the band (as in V, where it cost 8.6).
32003, the two-effect case again: 32001's draw was webbing_slack on SLED beside lumbar_path on
FULL, 48 counts, est 0/4/2, val 0/3/3; together (the pelvis path at 0.38) 13.8 points (CR 12.7,
CD 14.9), the slack alone 10.8 (CR 11.9, CD 9.7): above the band with nothing to size.
32004 and 32005, the two-effect case again: 32003's draw (spool_buildup on R16 beside rib_loss
on FULL) and 32004's (webbing_hysteresis on SLED+FULL beside spool_buildup on R16) had no
pairing left. 32005's is the case's.
32006, the late BRS: its first draw, 1.48 ms (128 counts, est 2/4/0, val 1/0/5), cost 0.0
points (CR 0.1, CD -0.1): a delay's size is its draw, and below the delay's 1 point.
32007, the late pulse: its first draw, 1.10 ms (48 counts, est 0/4/2, val 4/1/1), cost 0.99
(CR 0.97, CD 1.01), below the delay's 1 point.

One lab-side form no earlier set had, drawn into the CD transducer pool beside the others
(``lab.py``, ``cd_clock``: the chest pot's digitiser module on its own crystal, slow, CD's time
base stretched from the trigger, as V's ``cr_clock`` on CR); the draw did not pick it (it
picked N's ``cd_sag``). The draw picked earlier sets' lab-side forms for both the transducer
error and the broken test, so unlike A-V their keys are not new; their sizes are (a switch's
aside: brs_reversed is on or off).

Against sets A-V: other seeds (32xxx), pairings no case of A-V ran (drawn among those), effect
sizes no case of A-V used for its key (sizes in each key's units, ``physics.EFFECTS``): the
bumper 1.5e7 N/m^1.5 (A-V: 2e7), the squeeze film 450 N s/m (250, 380, 600), the hysteresis
0.57 (0.15-0.7, none 0.57), the toe 0.13 (none 0.13), the two-stage bag's fill 0.3 (0.4, 0.45),
the pelvis path 0.4 on SLED alone (A-V: none 0.4, none on SLED alone), the encoder ring 0.32 on
SLED alone (0.18-0.35, none 0.32, none on one rig), the permanent set 0.53 (0.35-0.75, none
0.53) beside the knee 1.4 on FULL alone (0.5-9.0, none 1.4), the sag 0.7 (N: 0.6); the
delays 3.23 ms (pulse) and 4.17 ms (BRS), no input's in A-V.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6.

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set w``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points, and the same per output, CR and CD, from the fits kept with
``--work``; 2026-11-27 06:55-07:40 UTC, 2 cores shared with another job, two to five cost jobs
at a time; the cases whose size changed, and the two-effect case's effects alone, costed again
through ``costs._fit`` on ``make_sets.make``'s folders against the same twin): clean48 86.6,
clean96 91.0; bumper_r16_sled 86.2 -> 89.8 (3.6; CR 2.0, CD 5.3), squeeze_sled_full 87.0 -> 91.9
(5.0; CR 4.3, CD 5.6), hysteresis_all 89.1 -> 93.5 (4.4; CR 5.0, CD 3.8), toe_r16_full 89.2 ->
93.0 (3.7; CR 4.6, CD 2.8), airbag_dual_full 87.2 -> 92.7 (5.5; CR 5.9, CD 5.2), lumbar_sled
88.3 -> 93.0 (4.7; CR 2.1, CD 7.2), eccentric_sled 88.0 -> 91.5 (3.5; CR 3.8, CD 3.3),
two_set_sled_knee_full 89.3 -> 92.1 (2.8; CR 3.3, CD 2.4; the set alone 90.2 -> 92.1, 1.9: CR
2.3, CD 1.6; the knee alone 89.9 -> 92.1, 2.2: CR 2.6, CD 1.8), pulse_late_3p23ms 86.6 -> 88.4
(1.8; CR 2.1, CD 1.4), brs_late_4p17ms 86.0 -> 89.0 (3.0; CR 4.6, CD 1.4), cd_sag 87.3 -> 91.5
(4.2; CR 3.4, CD 5.0: mostly in CD, the grey-box's parameters pulled by CD's misfit cost CR
some), broken_brs_reversed 85.1 -> 92.1 (6.9; CR 7.8, CD 6.1; flagging the test is the verdict
asked; left in, it costs the fit). Each effect of the two-effect case alone: the case's seed
with the other effect's size 0 (same dummies, pulses and noise), against the same twin.

Changed after a first look at these costs, before any loop run (same seeds, mixes, forms and
rigs; only sizes): cd_sag was 0.2, cost 0.1 (CR 0.3, CD -0.1), then 0.45, 1.1 (CR 1.3, CD 0.9)
and 0.7, 4.2, so 0.7; the two-effect case's permanent set was 0.42, together 2.6 (CR 3.0, CD
2.2) but the set alone 1.46 (CR 1.7, CD 1.2), below the band, so 0.53 (alone 1.9, together 2.8).
The others are as first written.

Run-aways: none. Over set W's 168 tests, as committed, the BRS files' angle pays out 135-532
degrees at its lowest (counts x 360 / counts per rev) against its rig's median over the set of
248-290 (0.47-1.83 times it: all within 3x either way), R16_003 of the broken case left out (its
count reversed, its lowest 7 counts: the fault, not the spool), the true chest deflection peaks
at 21.2-33.9 mm and CR at 25.6-38.0 g, no channel NaN (``test_set_w_has_no_run_aways`` checks
this on every test; the shared check now compares the pay-out in degrees, as V's note counted
it, not in counts, which differ 48 to 128 between cases)."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_W: list[Case] = [
    Case("hw_clean48", 32103, _mix(4, 0, 2), _mix(6, 0, 0), 48,
         notes="clean thorax, 48-count BRS; validated on R16 alone; SLED never run"),
    Case("hw_clean96", 32207, _mix(0, 4, 2), _mix(6, 0, 0), 96,
         notes="clean thorax, 96-count BRS; validated on R16 alone, never estimated there"),
    Case("hw_bumper_r16_sled", 32309, _mix(4, 0, 2), _mix(0, 6, 0), 48,
         (Effect("rib_bumper", 1.5e7, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the lower sternum meets the spine box's rubber stop past 15 mm, Hertz, "
               "K = 1.5e7 N/m^1.5, on R16 and SLED; validated on SLED alone, never estimated "
               "there; FULL clean, 2 estimation tests"),
    Case("hw_squeeze_sled_full", 32411, _mix(3, 3, 0), _mix(1, 3, 2), 64,
         (Effect("rib_squeeze", 450.0, ("SLED", "FULL")),),
         (("chest_rate_damping", "SLED+FULL"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 450 N s/m at "
               "rest, on SLED and FULL; FULL validated twice, never estimated; R16 clean, 3 "
               "estimation tests"),
    Case("hw_hysteresis_all", 32513, _mix(0, 3, 3), _mix(1, 0, 5), 128,
         (Effect("webbing_hysteresis", 0.57),), (("belt_unloading", "all"),),
         notes="the webbing's elastic force 57 % lower while it shortens (set B's form), all "
               "three rigs; R16 validated once, never estimated"),
    Case("hw_toe_r16_full", 32617, _mix(0, 2, 4), _mix(6, 0, 0), 96,
         (Effect("webbing_toe", 0.13, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.13, on "
               "R16 and FULL; validated on R16 alone, never estimated there; SLED clean, 2 "
               "estimation tests"),
    Case("hw_airbag_dual_full", 32719, _mix(3, 0, 3), _mix(0, 3, 3), 96,
         (Effect("airbag_dual", 0.3, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="set K's vented driver bag on a two-stage inflator at fill 0.3, the car's (FULL) "
               "alone; the SLED rig's bag not fired (validated three times, never estimated); R16 "
               "without a bag"),
    Case("hw_lumbar_sled", 32823, _mix(3, 3, 0), _mix(0, 6, 0), 96,
         (Effect("lumbar_path", 0.4, ("SLED",)),), (("pelvis_coupling", "SLED"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.4, on SLED alone; validated on SLED alone; R16 clean, 3 estimation tests"),
    Case("hw_eccentric_sled", 32927, _mix(2, 4, 0), _mix(0, 5, 1), 48,
         (Effect("brs_eccentric", 0.32, ("SLED",)),), (("input_gain", "SLED"),),
         notes="the BRS's encoder ring off-centre: the angle read th + 0.32 sin(th + phase), "
               "on SLED alone; FULL validated once, never estimated; R16 clean, 2 estimation "
               "tests"),
    Case("hw_two_set_sled_knee_full", 32031, _mix(0, 2, 4), _mix(1, 2, 3), 64,
         (Effect("webbing_set", 0.53, ("SLED",)), Effect("webbing_knee", 1.4, ("FULL",))),
         (("belt_unloading", "SLED"), ("belt_stiffening", "FULL")),
         notes="two kinds on two rigs: the SLED rig's webbing unloads to a permanent set of 0.53 "
               "x its peak stretch, the car's (FULL) webbing stiffens by 1.4 x k past its knee; "
               "R16 validated once, never estimated"),
    Case("hw_pulse_late_3p23ms", 32137, _mix(3, 0, 3), _mix(0, 4, 2), 48,
         (Effect("pulse_late", 0.00323),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.23 ms after its record; SLED validated four "
               "times, never estimated"),
    Case("hw_brs_late_4p17ms", 32241, _mix(3, 0, 3), _mix(2, 4, 0), 128,
         (Effect("brs_late", 0.00417),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.17 ms after the BRS records it; SLED validated "
               "four times, never estimated"),
    Case("hw_cd_sag", 32343, _mix(0, 0, 6), _mix(2, 2, 2), 48,
         (Effect("cd_sag", 0.7),), (), expect_note=UNEXPLAINED_CD,
         notes="the CD pot's excitation sags after the trigger (not ratiometric): CD reads "
               "d (1 - 0.7 (1 - e^(-t/60 ms))), every test; CR, pulse and BRS untouched: a "
               "residual in cd only"),
    Case("hw_broken_brs_reversed", 32447, _mix(4, 0, 2), _mix(1, 3, 2), 128,
         (Effect("brs_reversed", 1.0, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="R16_003, an estimation test: its BRS recorder's count direction set wrong, "
               "pay-in read as pay-out; its other channels and every other test clean"),
]

BY_NAME_W = {c.name: c for c in SET_W}
ONE_PHYSICAL_W = ("hw_bumper_r16_sled", "hw_squeeze_sled_full", "hw_hysteresis_all",
                  "hw_toe_r16_full", "hw_airbag_dual_full", "hw_lumbar_sled", "hw_eccentric_sled")
