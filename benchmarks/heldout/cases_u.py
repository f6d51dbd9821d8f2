"""Held-out set U: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-T (``cases.py`` ... ``cases_t.py``).

What set U judges is the general list again, written by another engineer from the simulator
and the thesis alone, without reading how the loop works, with its emphasis on the ordinary:
each physical kind in the simulator's most ordinary realisation of it, the form an engineer
would first write for that kind (``ORDINARY_U``: no new physical form), on all three rigs or
on two, at sizes that cost the grey-box 2-6 points, four of the seven on all three rigs. A loop
that names the exotic forms of sets H-T but not the plain ones fails here. The list: two clean
cases (48 and 96 counts); each kind of the library a loop can name, as physics, once in a case
of its own (chest_stiffening, chest_rate_damping, belt_unloading, belt_stiffening,
airbag_contact, pelvis_coupling, input_gain; ``ONE_PHYSICAL_U``) and input_delay twice; two
effects of different kinds on different rigs in one case; one broken estimation test; one
transducer error on CD; a late pulse and a late BRS. Every rig that holds estimation tests
holds at least two of them; an effect on some rigs only rests on two or more estimation and
validation tests of them beside an estimation test of a rig it spares; every expected verdict
names the rigs the effect truly acts on ("all" for all three).

Against sets A-T: other seeds (30xxx), (estimation, validation) pairings of (R16, SLED, FULL)
counts no case of A-T ran, effect sizes no case of A-T used (sizes in each key's units,
``physics.EFFECTS``): the ribs hardening as a cubic, k3 d^3, on all three rigs at 1.1e8 N/m^3
(A-T: 0.5e8-1.5e8, none 1.1e8); rate-stiffening rib damping, c |d'|^2.2, on R16+FULL at 2500
(A-T: 600-8000 on R16, SLED or all, none on R16+FULL); the webbing's softer unloading path
(hysteresis) on all three at 0.58 (A-T: 0.15-0.7, none 0.58); the webbing's cubic stiffening on
SLED+FULL at 2.0 (A-T: 0.4-15, none 2.0, none on SLED+FULL); set A's vented driver bag on
SLED+FULL at fill 0.75 (A-T: 0.4-1.0, none 0.75); the pelvis on its lap belt and lumbar spine
on all three at 0.5 (A-T: 0.35-1.5, none 0.5); the pulse accelerometers' sensitivity 7 % high
on all three (A-T: -0.08 on FULL, 0.09 on R16+SLED); the two-effect case's ribs bottoming
(power 2.5 past 12 mm) on R16 alone at 4e7 (A-T: 6e7-1.2e8, none below 6e7, none on R16 alone)
beside the vented bag on FULL alone at fill 1.1 (A-T: none above 1.0), SLED validated once,
never estimated. The delays: the pulse 3.35 ms, the BRS 4.35 ms (A-T: no input 3.35 or 4.35
ms). The input gain is the plainest there is, a sensitivity entered wrong: every lab's pulse
accelerometers calibrated back to back against one reference accelerometer whose own
certificate was 7 % off (the spool's radius growing with its wraps, the other physical cause,
cost set A under 0.5 points: invisible).

Two lab-side forms no earlier set used (``lab.py``), exact (no per-test scatter). The broken
test, SLED_003, an estimation test: its pulse accelerometer's cable parts at 42 ms, mid-crash
(``pulse_cable_break``): the channel's open input reads 0 g from then on, the module's noise
still on it, while the chest goes on loading (A-T's broken pulses: clipped at a rail, a zero
shift, another time base, another test's, another sampling rate, another unit; none a cable
parting; A-T's cable break was on CR, to a constant without noise). The transducer error on
CD, every test: the chest pot read by a conditioner whose input resistance is a fifth of the
pot's (``cd_pot_loading``, r = R_pot / R_in = 5): the wiper's voltage is loaded, the textbook
potentiometer loading error v(x) = x / (1 + r x (1 - x)) over its 100 mm stroke (the chest at
rest 10 % along it), the channel calibrated over the full stroke (where the error vanishes)
and zeroed at rest: CD reads low, the more so towards mid-stroke, about 40 % of the true
deflection at these chests' 24-31 mm (A-T's transducer errors on CD: a cubic over-read, a
knee, a tanh, a dead band, backlash, an arm lifting off, an excitation's sag, a 4-pole
Butterworth and a 1-pole RC low-pass, a slew limit, a resonance; none a loaded pot). CR, pulse
and BRS read right under it; its verdict "unexplained (or a sensor effect) on cd".

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set u``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points, and the same per output, CR and CD, from the fits it keeps with
``--work``; the committed seeds, mixes and sizes, 2026-11-26 22:50-23:20 UTC, 2 cores, two cost
jobs at a time): clean48 90.8, clean96 93.3; hardening_all 87.8 -> 90.6 (2.8; CR 0.7, CD 4.8),
fluid_r16_full 89.0 -> 92.6 (3.6; CR 1.9, CD 5.2), hysteresis_all 89.5 -> 91.9 (2.3; CR 3.2, CD
1.5), power_sled_full 86.8 -> 90.8 (4.0; CR 5.5, CD 2.5), airbag_sled_full 86.7 -> 92.5 (5.8;
CR 6.1, CD 5.5), lumbar_all 90.9 -> 92.8 (1.9; CR -1.0, CD 4.8), pulse_gain_all 89.9 -> 92.0
(2.2; CR 4.3, CD 0.0), pulse_late_3p35ms 89.7 -> 91.9 (2.2; CR 3.5, CD 1.0), brs_late_4p35ms
85.9 -> 88.3 (2.4; CR 3.7, CD 1.1), two_bottoming_r16_airbag_full 82.4 -> 91.1 (8.7; CR 7.7, CD
9.6; the ribs' bottoming alone 87.6 -> 91.1, 3.5: CR 1.9, CD 5.1; the bag alone 88.7 -> 91.1,
2.4: CR 3.1, CD 1.7; together above the band, see below), broken_pulse_cable 82.2 -> 92.3
(10.0; CR 12.4, CD 7.7; flagging the test is the verdict asked; left in, it costs the fit),
cd_pot_loading 85.0 -> 88.4 (3.4; CR -0.5, CD 7.2: in CD, as a CD transducer's must be). Each
effect of the two-effect case alone: the case's seed with the other effect left out (same
dummies, pulses and noise), against the same twin.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes; the in-between sizes costed through the same calls, ``costs._fit`` on
``make_sets.make``'s folders against the same twin, one case at a time): fluid_r16_full was
7000, cost 6.8 (CR 4.7, CD 8.9), then 5200, 6.1, so 2500 (3.6); power_sled_full was 9.0, cost
6.9 (CR 8.8, CD 5.0), then 5.5, 6.0, then 3.0, 4.8, so 2.0 (4.0); the late pulse was 2.3 ms,
cost 1.2 (below the band), so 3.35 ms (2.2), the case renamed from pulse_late_2p3ms; the late
BRS was 3.45 ms, cost 1.2, so 4.35 ms (2.4), renamed from brs_late_3p45ms; cd_pot_loading was r
1, cost 0.1 (CD 0.7: the grey-box took a CD reading about 15 % low almost wholly into its
parameters), then 3, 1.5 (CD 3.8), and 6, 4.3 (CD 8.8), so 5 (3.4); the two-effect case was the
ribs' bottoming at 8e7 beside the bag at fill 0.55, together 5.0 but the bag alone -0.1
(invisible on FULL at that fill); at fill 1.3 the bag alone cost 3.5 and the bottoming alone
5.5, but the two together 10.4 (above the band); then 4e7 and fill 1.1, alone 3.5 and 2.4,
together 8.7; then 2.5e7 and fill 0.95, alone 2.5 and 1.6, together 7.5. The two together cost
more than the sum of each alone (each pulls the parameters the case's rigs share its own way),
so the case could not be brought inside the band without one of its effects falling to the edge
of visible; it is kept at 4e7 and fill 1.1, both effects clearly visible alone, together 8.7,
above the band (the kinds, forms and rigs kept throughout, only the sizes changed). The other
eight cases are as first written: airbag_sled_full at 5.8 and lumbar_all at 1.9 are inside the
band, near its ends, and were left (a rib_fluid at 1500 was started and stopped unread).

Run-aways (set T had one: a capstan whose BRS paid 26 spindle turns out on one test): none.
Over set U's 168 tests, as committed, the BRS pays out 22-150 degrees against its rig's median
over the set of 60-65 (0.34-2.4 times it: all within 3x either way), the true chest deflection
peaks at 19-35 mm and CR at 26-40 g, nothing NaN (``test_set_u_has_no_run_aways`` checks this
on every test).
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_U: list[Case] = [
    Case("hu_clean48", 30113, _mix(2, 4, 0), _mix(4, 1, 1), 48,
         notes="clean thorax, 48-count BRS; FULL validated once, never estimated"),
    Case("hu_clean96", 30217, _mix(0, 2, 4), _mix(4, 1, 1), 96,
         notes="clean thorax, 96-count BRS; R16 validated four times, never estimated"),
    Case("hu_hardening_all", 30319, _mix(2, 2, 2), _mix(0, 0, 6), 96,
         (Effect("rib_hardening", 1.1e8),), (("chest_stiffening", "all"),),
         notes="the ribs harden as a cubic from zero, F += k3 d^3 at k3 1.1e8 N/m^3 (A-T: "
               "0.5e8-1.5e8, none 1.1e8), all three rigs; validated on FULL alone"),
    Case("hu_fluid_r16_full", 30421, _mix(2, 2, 2), _mix(5, 0, 1), 64,
         (Effect("rib_fluid", 2500.0, ("R16", "FULL")),), (("chest_rate_damping", "R16+FULL"),),
         notes="rate-stiffening rib damping, F += c |d'|^2.2 sign(d') at c 2500 (A-T: "
               "600-8000, none on R16+FULL), R16 and FULL; SLED clean, 2 estimation tests"),
    Case("hu_hysteresis_all", 30523, _mix(3, 3, 0), _mix(0, 3, 3), 128,
         (Effect("webbing_hysteresis", 0.58),), (("belt_unloading", "all"),),
         notes="the webbing's elastic force 58 % lower while it shortens (A-T: 0.15-0.7, "
               "none 0.58), all three rigs; FULL validated three times, never estimated"),
    Case("hu_power_sled_full", 30627, _mix(2, 2, 2), _mix(0, 5, 1), 96,
         (Effect("webbing_power", 2.0, ("SLED", "FULL")),), (("belt_stiffening", "SLED+FULL"),),
         notes="the webbing stiffens as a cubic of its stretch, a 2.0 (A-T: 0.4-15, none "
               "2.0, none on SLED+FULL), SLED and FULL; R16 clean, 2 estimation tests"),
    Case("hu_airbag_sled_full", 30729, _mix(2, 2, 2), _mix(1, 0, 5), 64,
         (Effect("airbag", 0.75, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="set A's vented driver bag at fill 0.75 (A-T: 0.4-1.0, none 0.75) on the "
               "rigs with an interior; the R16 rig without a bag, 2 estimation tests"),
    Case("hu_lumbar_all", 30831, _mix(0, 4, 2), _mix(1, 5, 0), 48,
         (Effect("lumbar_path", 0.5),), (("pelvis_coupling", "all"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.5 (A-T: 0.35-1.5, none 0.5), all three rigs; R16 validated once, "
               "never estimated"),
    Case("hu_pulse_gain_all", 30933, _mix(2, 0, 4), _mix(0, 3, 3), 96,
         (Effect("pulse_gain", 0.07),), (("input_gain", "all"),),
         notes="every pulse accelerometer reads 7 % high (calibrated back to back against "
               "one reference accelerometer whose certificate was off; A-T: -0.08 on FULL, "
               "0.09 on R16+SLED), all three rigs; SLED validated three times, never "
               "estimated"),
    Case("hu_pulse_late_3p35ms", 30037, _mix(3, 3, 0), _mix(0, 4, 2), 96,
         (Effect("pulse_late", 0.00335),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.35 ms after its record (A-T: no input 3.35 ms); "
               "FULL validated twice, never estimated"),
    Case("hu_brs_late_4p35ms", 30141, _mix(0, 3, 3), _mix(4, 2, 0), 64,
         (Effect("brs_late", 0.00435),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.35 ms after the BRS records it (A-T: no input "
               "4.35 ms); R16 validated four times, never estimated"),
    Case("hu_two_bottoming_r16_airbag_full", 30243, _mix(4, 0, 2), _mix(3, 1, 2), 96,
         (Effect("rib_bottoming", 4.0e7, ("R16",)), Effect("airbag", 1.1, ("FULL",))),
         (("chest_stiffening", "R16"), ("airbag_contact", "FULL")),
         notes="two kinds on two rigs: the R16 rig's dummy's ribs bottom, power 2.5 past "
               "12 mm at 4e7 (A-T: 6e7-1.2e8, none below 6e7, none on R16 alone), and the "
               "car's (FULL) vented driver bag at fill 1.1 (A-T: none above 1.0); SLED validated "
               "once, never estimated"),
    Case("hu_broken_pulse_cable", 30347, _mix(2, 4, 0), _mix(0, 3, 3), 96,
         (Effect("pulse_cable_break", 0.042, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="SLED_003, an estimation test: its pulse accelerometer's cable parts at 42 ms, "
               "the channel reads 0 g and its noise from then on; its other channels and every "
               "other test clean"),
    Case("hu_cd_pot_loading", 30449, _mix(4, 2, 0), _mix(3, 2, 1), 96,
         (Effect("cd_pot_loading", 5.0),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot read through a conditioner input a fifth of its resistance "
               "(r = 5): the loading error x / (1 + r x (1 - x)), CD reads about 40 % of "
               "the chest's deflection, every test; CR and the inputs untouched: a residual in "
               "cd only"),
]

BY_NAME_U = {c.name: c for c in SET_U}

# the library's ordinary physical forms (the form an engineer would first write for each kind;
# set A's own and set B's simplest): the only physics set U switches
ORDINARY_U = {"rib_bottoming", "rib_hardening", "rib_fluid", "webbing_slack",
              "webbing_hysteresis", "webbing_toe", "webbing_power", "airbag", "lumbar_path",
              "pulse_gain", "pulse_late", "brs_late"}
# the physical cases of one effect (input delays aside), one per kind of the library
ONE_PHYSICAL_U = ("hu_hardening_all", "hu_fluid_r16_full", "hu_hysteresis_all",
                  "hu_power_sled_full", "hu_airbag_sled_full", "hu_lumbar_all",
                  "hu_pulse_gain_all")
