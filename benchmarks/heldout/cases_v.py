"""Held-out set V: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-U (``cases.py`` ... ``cases_u.py``).

What set V judges is the general list again, written by another engineer from the simulator
and the thesis alone, without reading how the loop works, with its emphasis on choices not
picked by a designer's taste but drawn: ``draw_v.py`` (``numpy.random.default_rng(31000)``,
``python -m benchmarks.heldout.draw_v`` prints the draw) draws for each kind of the library its
form among every set's forms of that kind (the input gain among the BRS's own: the encoder
ring off-centre, the spool's radius growing), the rigs it acts on, the BRS counts and the
(estimation, validation) mix among the pairings no case of A-U ran that the scope rules allow;
the two-effect case's kinds, forms and disjoint rigs; the delays; the transducer error's
output; the broken test's channel and test; the clean cases' mixes. The cases follow the draw;
only the sizes are chosen, by costs. ``test_set_v_follows_its_draw`` holds the two together.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_fung (J's Fung exponential), R16+FULL, 128, est 0/3/3, val 1/1/4;
chest_rate_damping: rib_squeeze (H's squeeze film), FULL, 96, est 0/3/3, val 1/3/2;
belt_unloading: webbing_hysteresis (B's softer unloading path), all, 64, est 0/4/2, val 2/4/0
(redrawn, see below); belt_stiffening: webbing_toe (A's exponential toe), SLED+FULL, 64, est
3/0/3, val 0/6/0; airbag_contact: airbag (A's vented bag), FULL, 64, est 2/0/4, val 0/4/2;
pelvis_coupling: lumbar_path (A's pelvis path), R16+FULL, 128, est 0/3/3, val 3/0/3;
input_gain: brs_eccentric (A's off-centre encoder ring), SLED+FULL, 96, est 4/2/0, val 2/0/4;
the two-effect case chest_rate_damping (rib_valve, C's valve) on FULL beside pelvis_coupling
(lumbar_path) on R16, 64, est 4/0/2, val 4/0/2; the late pulse 3.66 ms, 96, est 0/2/4, val
2/1/3; the late BRS 2.53 ms, 48, est 4/2/0, val 4/1/1; the transducer error on CR, 96, est
6/0/0, val 0/0/6; the broken test's channel CR, 64, est 3/3/0, val 0/5/1, the test SLED_003;
clean48 est 4/2/0, val 3/1/2; clean96 est 0/4/2, val 0/6/0.

Redrawn: belt_unloading's first draw was webbing_slack (A's webbing that cannot push) on all
three rigs, 128 counts, est 2/0/4, val 4/1/1. The slack is a switch (its size 1 = on, nothing
to set), and it cost the grey-box 8.6 points (CR 11.1, CD 6.0), above the band: impossible as
drawn. Its case was drawn again, form, rigs, counts and mix, by ``default_rng(31001)`` (the
next seed; ``draw_v.REDRAWN``), which gave B's hysteresis on all three rigs.

Two lab-side forms no earlier set used (``lab.py``), exact (no per-test scatter), both on CR as
drawn. The broken test, SLED_003, an estimation test: its spine accelerometer's conditioner on
too small a range (``cr_rail``), the raw channel flat at +-18 g, its noise clipped with it,
before CFC 180, while its spine decelerates at up to 34 g (A-U's broken CR: a cable breaking to a
constant, a reversed polarity, mains hum, a lost block, a loose mount; no CR rail; G's rail was
on CD, B's on the pulse). The transducer error on CR, every test: the CR digitiser module's own
clock 8 % slow (``cr_clock``): the sample stamped t holds the spine's deceleration at t (1 +
0.08) from the common trigger on, CR's time base stretched, its events written early by a share
of their time (about 4 ms at 50 ms; A-U's CR errors: a gain, a soft clip, a progressive
over-read, AC coupling, a zero shift, a zero drift, crosstalk from CD, an oil-damped element,
creeping gauges, a constant late write (Q's cr_late); none a stretched time base). CD, pulse
and BRS read right under it; its verdict "unexplained (or a sensor effect) on cr".

Against sets A-U: other seeds (31xxx), pairings no case of A-U ran (drawn among those), effect
sizes no case of A-U used for its key (sizes in each key's units, ``physics.EFFECTS``): Fung
0.13 (A-U: 0.2-0.5), the squeeze film 600 N s/m (A-U: 250, 380), the hysteresis 0.62 (A-U:
0.15-0.7, none 0.62), the toe 0.12 (A-U: 0.1-3.5, none 0.12), the bag's fill 0.25 on FULL alone
(A-U: 0.4-1.1, none below 0.4), the pelvis path 0.3 on R16+FULL (A-U: 0.35-1.5, none below
0.35, none on R16+FULL), the encoder ring 0.27 (A-U: 0.18-0.35, none 0.27), the valve 1400
N/(m/s)^2 on FULL alone (A-U: 1200-4000, none 1400) beside the pelvis path at 0.42 on R16 alone
(A-U: none 0.42); the delays 3.66 ms (pulse) and 2.53 ms (BRS), no input's in A-U.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6.

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set v``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points, and the same per output, CR and CD, from the fits kept with
``--work``; the committed seeds, mixes and sizes, 2026-11-27 02:58-03:50 UTC, 2 cores, two cost
jobs at a time; the cases whose size changed costed again one at a time through the same calls,
``costs._fit`` on ``make_sets.make``'s folders against the same twin): clean48 93.4, clean96
91.5; fung_r16_full 85.2 -> 90.2 (5.0; CR 1.9, CD 8.1), squeeze_full 87.4 -> 92.0 (4.6; CR 2.6,
CD 6.6), hysteresis_all 88.5 -> 93.6 (5.1; CR 5.8, CD 4.3), toe_sled_full 89.8 -> 93.5 (3.6; CR
4.0, CD 3.3), airbag_full 89.5 -> 93.1 (3.6; CR 2.8, CD 4.3), lumbar_r16_full 90.8 -> 93.4
(2.6; CR -0.3, CD 5.4), eccentric_sled_full 89.6 -> 91.7 (2.1; CR 2.7, CD 1.4),
two_valve_full_lumbar_r16 87.7 -> 93.5 (5.8; CR 2.6, CD 8.9; the valve alone 90.8 -> 93.5, 2.6:
CR 1.1, CD 4.2; the pelvis path alone 90.1 -> 93.5, 3.4: CR 1.0, CD 5.8), pulse_late_3p66ms
87.7 -> 91.3 (3.6; CR 4.6, CD 2.6), brs_late_2p53ms 90.5 -> 91.9 (1.4; CR 1.6, CD 1.3),
cr_clock 88.6 -> 93.6 (5.1; CR 6.6, CD 3.5: mostly in CR, the grey-box's parameters pulled by
CR's misfit cost CD some), broken_cr_rail 91.7 -> 92.8 (1.0; CR 1.7, CD 0.4; flagging the test
is the verdict asked; left in, it costs the fit). Each effect of the two-effect case alone: the
case's seed with the other effect's size 0 (same dummies, pulses and noise), against the same
twin. After the commit, airbag_full and lumbar_r16_full costed again through
``costs --set v --case`` itself (04:00-04:04 UTC): the same 3.6 and 2.6, to the tenth.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds, mixes, forms and rigs; only sizes): fung_r16_full was 0.22, cost 7.4 (CR 2.8, CD 12.0),
so 0.13 (5.0); eccentric_sled_full was 0.22, cost 1.5 (CR 2.0, CD 0.9: on the band's edge), so
0.27 (2.1); airbag_full was 1.2, cost 17.7 (CR 16.4, CD 19.1: the car's bag on the FULL tests
that make up four of six estimation tests), then 0.8, 12.8, then 0.35, 5.4 (CR 4.5, CD 6.3) and
0.25, 3.6, so 0.25; lumbar_r16_full was 0.95, cost 12.7 (CR 9.4, CD 16.0), then 0.57, 7.8 (CR
4.6, CD 11.0), so 0.3 (2.6); the two-effect case was the valve at 2400 beside the pelvis path
at 0.72, together 9.7 (CR 6.7, CD 12.7), so 1400 and 0.42 (5.8, each alone 2.6 and 3.4). The
hysteresis (0.62, 5.1) is the redraw's first size; the squeeze film (600, 4.6), the toe (0.12,
3.6), the delays (3.66 ms, 3.6; 2.53 ms, 1.4, above the delay's 1 point) and the clock (0.08,
5.1) are as first written.

Run-aways (set T had one: a capstan whose BRS paid 26 spindle turns out on one test): none.
Over set V's 168 tests, as committed, the BRS files' angle pays out 112-472 degrees at its
lowest against its rig's median over the set of 248-266 (0.45-1.81 times it: all within 3x
either way), the true chest deflection peaks at 20.8-33.3 mm and CR at 25.1-36.1 g, no channel
NaN (``test_set_v_has_no_run_aways`` checks this on every test).
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_V: list[Case] = [
    Case("hv_clean48", 31103, _mix(4, 2, 0), _mix(3, 1, 2), 48,
         notes="clean thorax, 48-count BRS; FULL validated twice, never estimated"),
    Case("hv_clean96", 31207, _mix(0, 4, 2), _mix(0, 6, 0), 96,
         notes="clean thorax, 96-count BRS; validated on SLED alone"),
    Case("hv_fung_r16_full", 31309, _mix(0, 3, 3), _mix(1, 1, 4), 128,
         (Effect("rib_fung", 0.13, ("R16", "FULL")),), (("chest_stiffening", "R16+FULL"),),
         notes="the rib cage stiffens exponentially (Fung), amount 0.13, on R16 and FULL; "
               "R16 validated once, never estimated; SLED clean, 3 estimation tests"),
    Case("hv_squeeze_full", 31411, _mix(0, 3, 3), _mix(1, 3, 2), 96,
         (Effect("rib_squeeze", 600.0, ("FULL",)),), (("chest_rate_damping", "FULL"),),
         notes="squeeze-film damping in the chest (1/gap^3 from a 60 mm gap), 600 N s/m at "
               "rest, on FULL alone; SLED clean, 3 estimation tests"),
    Case("hv_hysteresis_all", 31513, _mix(0, 4, 2), _mix(2, 4, 0), 64,
         (Effect("webbing_hysteresis", 0.62),), (("belt_unloading", "all"),),
         notes="the webbing's elastic force 62 % lower while it shortens (set B's form), all "
               "three rigs; R16 validated twice, never estimated"),
    Case("hv_toe_sled_full", 31617, _mix(3, 0, 3), _mix(0, 6, 0), 64,
         (Effect("webbing_toe", 0.12, ("SLED", "FULL")),), (("belt_stiffening", "SLED+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.12, on "
               "SLED and FULL; validated on SLED alone, never estimated there; R16 clean"),
    Case("hv_airbag_full", 31719, _mix(2, 0, 4), _mix(0, 4, 2), 64,
         (Effect("airbag", 0.25, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="set A's vented driver bag at fill 0.25, the car's (FULL) alone; the SLED rig's "
               "bag not fired (validated four times, never estimated); R16 without a bag"),
    Case("hv_lumbar_r16_full", 31823, _mix(0, 3, 3), _mix(3, 0, 3), 128,
         (Effect("lumbar_path", 0.3, ("R16", "FULL")),), (("pelvis_coupling", "R16+FULL"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.3, on R16 and FULL; R16 validated three times, never estimated; SLED "
               "clean, 3 estimation tests"),
    Case("hv_eccentric_sled_full", 31927, _mix(4, 2, 0), _mix(2, 0, 4), 96,
         (Effect("brs_eccentric", 0.27, ("SLED", "FULL")),), (("input_gain", "SLED+FULL"),),
         notes="the BRS's encoder ring off-centre: the angle read th + 0.27 sin(th + phase), "
               "a gain varying with the angle, on SLED and FULL; FULL validated four times, "
               "never estimated; R16 clean, 4 estimation tests"),
    Case("hv_two_valve_full_lumbar_r16", 31031, _mix(4, 0, 2), _mix(4, 0, 2), 64,
         (Effect("rib_valve", 1400.0, ("FULL",)), Effect("lumbar_path", 0.42, ("R16",))),
         (("chest_rate_damping", "FULL"), ("pelvis_coupling", "R16")),
         notes="two kinds on two rigs: the car's (FULL) dummy's ribs damp through a valve, "
               "F += 1400 d'^2 while compressing, and the R16 rig's seat and lap belt carry "
               "the pelvis (lumbar path at 0.42); SLED never run"),
    Case("hv_pulse_late_3p66ms", 31137, _mix(0, 2, 4), _mix(2, 1, 3), 96,
         (Effect("pulse_late", 0.00366),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.66 ms after its record; R16 validated twice, "
               "never estimated"),
    Case("hv_brs_late_2p53ms", 31241, _mix(4, 2, 0), _mix(4, 1, 1), 48,
         (Effect("brs_late", 0.00253),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.53 ms after the BRS records it; FULL validated "
               "once, never estimated"),
    Case("hv_cr_clock", 31343, _mix(6, 0, 0), _mix(0, 0, 6), 96,
         (Effect("cr_clock", 0.08),), (), expect_note=UNEXPLAINED_CR,
         notes="the CR module's clock 8 % slow: CR's time base stretched from the trigger "
               "on, every test; CD, pulse and BRS untouched: a residual in cr only"),
    Case("hv_broken_cr_rail", 31447, _mix(3, 3, 0), _mix(0, 5, 1), 64,
         (Effect("cr_rail", 18.0, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="SLED_003, an estimation test: its CR conditioner on too small a range, the "
               "raw channel clipped at 18 g; its other channels and every other test clean"),
]

BY_NAME_V = {c.name: c for c in SET_V}
# the physical cases of one effect (input delays aside), one per kind of the library, as drawn
ONE_PHYSICAL_V = ("hv_fung_r16_full", "hv_squeeze_full", "hv_hysteresis_all", "hv_toe_sled_full",
                  "hv_airbag_full", "hv_lumbar_r16_full", "hv_eccentric_sled_full")
