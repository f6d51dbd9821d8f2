"""Held-out set X: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-W (``cases.py`` ... ``cases_w.py``).

What set X judges is the general list again, written by another engineer from the simulator
and the thesis alone, without reading how the loop works, by set W's process with a new seed
family (33xxx): ``draw_x.py`` (``numpy.random.default_rng(33000)``, ``python -m
benchmarks.heldout.draw_x`` prints the draw) draws for each kind of the library its form among
every set's forms of that kind (the input gain among the BRS's own), the rigs it acts on, the
BRS counts and the (estimation, validation) mix among the pairings no case of A-W ran that the
scope rules allow; the two-effect case's kinds, forms and disjoint rigs; the delays; the
transducer error's output and form and the broken test's channel, test and form (among every
lab-side form the simulator has on that output or channel, set W's pools); the clean cases'
mixes. The cases follow the draw; only the sizes are set, by costs, by the rule
``draw_x.py`` wrote down before the first draw (``SIZING`` in its docstring: the first size
the median of A-W's sizes for the key, stepped off A-W's values; then toward 3.5 points, at
most four sizes). ``test_set_x_follows_its_draw`` holds the draw and the cases together.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bumper (T's stop behind the lower sternum), SLED, 48, est 0/4/2, val
0/3/3; chest_rate_damping: rib_foam (R's damping pad), SLED, 64, est 2/2/2, val 0/6/0;
belt_unloading: webbing_hysteresis (B's), FULL, 96, est 0/2/4, val 0/0/6; belt_stiffening:
webbing_knee (C's knee), R16+FULL, 96, est 0/3/3, val 5/0/1; airbag_contact: airbag_fabric
(H's bag leaking through its fabric), SLED, 64, est 0/3/3, val 0/6/0; pelvis_coupling:
pelvis_knee (L's pelvis path with the knee bolster), FULL, 48, est 2/0/4, val 0/1/5 (redrawn,
see below); input_gain: spool_buildup (the spool's radius
growing with wound webbing, never in a case of A-W), R16+SLED, 96, est 0/2/4, val 5/0/1
(redrawn nine times); the two-effect case chest_rate_damping
(rib_squeeze, H's squeeze film) on R16 beside input_gain (brs_eccentric, A's off-centre encoder
ring) on SLED, 64, est 3/3/0, val 2/3/1; the late pulse 3.62 ms, 64, est 4/0/2, val 4/2/0; the
late BRS 4.49 ms, 96, est 0/0/6, val 2/1/3; the transducer error on CR, its form cr_creep (S's
gauges creeping in their adhesive), 96, est 2/0/4, val 4/1/1; the broken test's channel the
pulse, its form pulse_sync (G's pulse recorder on its own trigger, its time base early), 96,
est 6/0/0, val 1/2/3, the test R16_005; clean48 est 0/6/0, val 4/0/2; clean96 est 6/0/0, val
4/0/2.

Redrawn (``draw_x.REDRAWN``; each whole, by the next seed's generator, in the order found, after
the rest, the pairings of everything drawn before still taken). A draw is impossible when the
sizing rule's sizes find no cost in band: for spool_buildup (no case of A-W sized it; its first
size, by the rule, set K's largest try, 4.5 mm of radius per wrap) the rule's second size is
three times it, 13.5 mm per wrap, and its third, 40.5 mm, would leave the spool's 17 mm radius
below zero within 7 rad of pay-out: two sizes, then impossible. Costs as below (validation TOT,
points; CR, CD):
33001, input_gain: its first draw, spool_buildup on R16, 96 counts, est 2/2/2, val 5/1/0: 4.5
mm per wrap 0.27 (CR 0.20, CD 0.33), 13.5 mm 0.59 (CR 0.50, CD 0.67).
33002, input_gain again: 33001's, the spool on R16, 64, est 2/4/0, val 4/0/2: 0.17 (CR 0.32,
CD 0.02), 0.14 (CR 0.17, CD 0.11).
33003, pelvis_coupling: its first draw, pelvis_submarine (H's lap belt slipping) on R16, 96,
est 2/4/0, val 6/0/0: at the rule's first size, 5900 N (5800 taken), 12.06 (CR 7.26, CD 16.86);
the rule took the slip force as a range (its effect shrinking as it grows, as set H's 2.5-6 kN
on all rigs cost 9.1-4.3), so 18000 N (three times): 19.91 (CR 14.17, CD 25.65), the other way;
the third size taken the other way from the first, 2000 N (a third of it; a departure from the
rule's step, which would have gone on up to 54000 N): 14.78 (CR 14.13, CD 15.43). Above the
band both sides of its lowest cost: no size in band, impossible (three sizes of the four
allowed).
33004, input_gain again: 33002's, the spool on SLED+FULL, 64, est 2/0/4, val 0/2/4: 0.38 (CR
0.33, CD 0.42), 0.90 (CR 0.98, CD 0.82).
33005: 33004's, the spool on R16+SLED, 96, est 2/0/4, val 4/2/0: 0.00 (CR 0.16, CD -0.17),
0.82 (CR 1.43, CD 0.20).
33006: 33005's, the spool on FULL, 96, est 4/0/2, val 0/4/2: 0.16 (CR 0.45, CD -0.13), 0.65
(CR 1.16, CD 0.14).
33007: 33006's, the spool on SLED+FULL, 64, est 3/3/0, val 4/0/2: 0.03 (CR 0.17, CD -0.11),
0.61 (CR 0.81, CD 0.41).
33008: 33007's, the spool on R16, 48, est 2/0/4, val 5/0/1: 0.50 (CR 0.50, CD 0.49), 1.21 (CR
1.34, CD 1.08); the rule's next, 39 mm, below zero radius.
33009: 33008's, the spool on SLED, 64, est 0/2/4, val 1/5/0: -0.56 (CR -0.58, CD -0.53), -0.16
(CR -0.08, CD -0.24).
33010: 33009's, the spool on R16+SLED, 64, est 0/4/2, val 1/1/4: 0.20 (CR 0.08, CD 0.33), 0.29
(CR 0.33, CD 0.25).
33010's draw is the case's: the spool on R16+SLED, 96, est 0/2/4, val 5/0/1: 4.5 mm per wrap
cost 1.29 (CR 1.24, CD 1.34), below the band but above a third of 3.5, so the rule's next size
4.5 x 3.5 / 1.29 = 12 mm per wrap: 2.61 (CR 2.58, CD 2.63), in band. The spool's radius, 17 mm
at rest, 3.6 mm at 7 rad of pay-out and zero at 8.9 rad (510 degrees); the case's largest
pay-out on R16 and SLED is 248 degrees (4.3 rad, the radius there 8.7 mm).

Seeds 33000-33013 all happen to draw the input gain's first form (numpy's first
``integers(2)`` of each of those generators is 0), the spool; every spool draw was costed by
the rule all the same, never in band (at most 1.21 points; as set K found at
2.4-4.5 mm: the webbing paid out stays all but linear in the spool angle over one pay-out).

Against sets A-W: other seeds (33xxx), pairings no case of A-W ran (drawn among those), effect
sizes no case of A-W used for its key (sizes in each key's units, ``physics.EFFECTS``): the
bumper 4.9e7 N/m^1.5 on SLED alone (A-W: 1.5e7, 2e7), the foam pad 870 N s/m on SLED alone (R:
2500 on all), the hysteresis 0.51 on FULL alone (0.15-0.7, none 0.51), the knee 2.1 on R16+FULL
(0.5-9.0, none 2.1), the fabric bag's fill 1.8 on SLED alone (0.6-0.85), the pelvis path with
the knee bolster at 0.29 on FULL alone (0.1, 0.2), the spool's radius 12 mm per wrap on R16+SLED
(no case of A-W sized it), the squeeze film 420 N s/m on R16 alone (250-600, none 420) beside
the encoder ring 0.29 on SLED (0.18-0.35, none 0.29), the creep's share 0.21 (S: 0.2), the
pulse's time base 11 ms early (G: 10 ms); the delays 3.62 ms (pulse) and 4.49 ms (BRS), no
input's in A-W. Every form is an earlier set's; no new form.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6.

What each case cost the grey-box (the plain thesis structure through the project's CLI
identify/evaluate, ``costs._fit`` on ``make_sets.make``'s folders, the case against its twin
with every effect off, same seed, dummies, pulses and noise; validation TOT fit without -> with,
points, and the same per output, CR and CD; 2026-11-27 15:04-15:45 UTC, 2 cores shared with
other work, two cost jobs at a time): clean48 91.8, clean96 88.6; bumper_sled 90.3 -> 88.5
(1.85; CR 1.39, CD 2.31), foam_sled 91.1 -> 88.0 (3.01; CR 1.29, CD 4.73), hysteresis_full 94.0
-> 89.5 (4.51; CR 5.09, CD 3.92), knee_r16_full 94.0 -> 88.8 (5.16; CR 5.44, CD 4.88),
fabric_sled 90.9 -> 86.9 (3.94; CR 6.86, CD 1.01), pelvis_knee_full 88.2 -> 83.1 (5.12; CR 4.83,
CD 5.42), spool_r16_sled 89.6 -> 87.0 (2.61; CR 2.58, CD 2.63), two_squeeze_r16_eccentric_sled
91.0 -> 86.3 (4.68; CR 3.56, CD 5.80; the squeeze film alone 3.22: CR 1.79, CD 4.65; the encoder
ring alone 1.55: CR 1.88, CD 1.21), pulse_late_3p62ms 92.0 -> 88.5 (3.51; CR 4.37, CD 2.65),
brs_late_4p49ms 92.6 -> 88.0 (4.58; CR 5.36, CD 3.80), cr_creep 92.0 -> 86.4 (5.65; CR 9.22, CD
2.08: mostly in CR, the grey-box's parameters pulled by CR's misfit cost CD some),
broken_pulse_sync 90.6 -> 86.0 (4.53; CR 5.08, CD 3.98; flagging the test is the verdict asked;
left in, it costs the fit; not banded, by the rule). Each effect of the two-effect case alone:
the case's seed with the other effect's size 0, against the same twin.

The sizes the rule tried before these (same seeds, mixes, forms and rigs): the bumper 1.8e7
(the median of T's and W's, 1.75e7) cost 1.29 (CR 1.20, CD 1.37), below the band, so 4.9e7
(times 3.5 / 1.29); the foam pad 2600 (R's 2500 taken) cost 11.32 (CR 4.82, CD 17.82), so 870
(a third of it, the step's clip); the fabric bag 0.71 (0.7 taken) cost 1.37 (CR 2.83, CD
-0.08), so 1.8; the pelvis path and knee bolster 0.15 cost 1.07 (CR -0.15, CD 2.30), then 0.49
cost 8.72 (CR 8.59, CD 8.86), so 0.29 (log-linear between them toward 3.5). The hysteresis
0.51, the knee 2.1, the squeeze film 420 beside the encoder ring 0.29, the creep 0.21 and the
pulse's 11 ms are the rule's first sizes; the delays are drawn.

Run-aways: none. Over set X's 168 tests, as committed, the BRS files' angle pays out 146-484
degrees at its lowest (counts x 360 / counts per rev) against its rig's median over the set of
241-284 (0.57-1.95 times it: all within 3x either way; the broken test's BRS is sound, so none
left out), the true chest deflection peaks at 21.3-33.8 mm and CR at 25.6-44.1 g, no channel NaN
(``test_set_x_has_no_run_aways``). After the sizes were set, ``python -m
benchmarks.heldout.costs --set x --case hx_spool_r16_sled --case hx_pelvis_knee_full`` gave the
same 2.6 and 5.1, to the tenth."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_X: list[Case] = [
    Case("hx_clean48", 33103, _mix(0, 6, 0), _mix(4, 0, 2), 48,
         notes="clean thorax, 48-count BRS; estimated on SLED alone, validated on R16 and FULL, "
               "never estimated there"),
    Case("hx_clean96", 33207, _mix(6, 0, 0), _mix(4, 0, 2), 96,
         notes="clean thorax, 96-count BRS; estimated on R16 alone, FULL validated twice, never "
               "estimated"),
    Case("hx_bumper_sled", 33309, _mix(0, 4, 2), _mix(0, 3, 3), 48,
         (Effect("rib_bumper", 4.9e7, ("SLED",)),), (("chest_stiffening", "SLED"),),
         notes="the lower sternum meets the spine box's rubber stop past 15 mm, Hertz, "
               "K = 4.9e7 N/m^1.5, on SLED alone; FULL clean, 2 estimation tests"),
    Case("hx_foam_sled", 33411, _mix(2, 2, 2), _mix(0, 6, 0), 64,
         (Effect("rib_foam", 870.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="the sternum's damping pad engaging as the chest closes, c (d / 30 mm) d' in "
               "compression, c = 870 N s/m, on SLED alone; validated on SLED alone; R16 and "
               "FULL clean, 2 estimation tests each"),
    Case("hx_hysteresis_full", 33513, _mix(0, 2, 4), _mix(0, 0, 6), 96,
         (Effect("webbing_hysteresis", 0.51, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the webbing's elastic force 51 % lower while it shortens (set B's form), the "
               "car's (FULL) alone; validated on FULL alone; SLED clean, 2 estimation tests"),
    Case("hx_knee_r16_full", 33617, _mix(0, 3, 3), _mix(5, 0, 1), 96,
         (Effect("webbing_knee", 2.1, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens by 2.1 x k past its knee (set C's form), on R16 and FULL; "
               "R16 validated five times, never estimated; SLED clean, 3 estimation tests"),
    Case("hx_fabric_sled", 33719, _mix(0, 3, 3), _mix(0, 6, 0), 64,
         (Effect("airbag_fabric", 1.8, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a ventless bag leaking through its fabric (set H's form) at fill 1.8, the SLED "
               "rig's alone; validated on SLED alone; FULL's bag not fired, 3 estimation tests; "
               "R16 without a bag"),
    Case("hx_pelvis_knee_full", 33823, _mix(2, 0, 4), _mix(0, 1, 5), 48,
         (Effect("pelvis_knee", 0.29, ("FULL",)),), (("pelvis_coupling", "FULL"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "scale 0.29, and the knees meeting the knee bolster (set L's form), the car's "
               "(FULL) alone; SLED validated once, never estimated; R16 clean, 2 estimation "
               "tests (redrawn)"),
    Case("hx_spool_r16_sled", 33927, _mix(0, 2, 4), _mix(5, 0, 1), 96,
         (Effect("spool_buildup", 0.012, ("R16", "SLED")),), (("input_gain", "R16+SLED"),),
         notes="the spool's effective radius, 17 mm at rest, changing by 12 mm per wrap of "
               "webbing wound (smaller as it pays out): the webbing paid out per radian the BRS "
               "counts is not r0, on R16 and SLED; R16 validated five times, never estimated; "
               "SLED 2 estimation tests, FULL clean, 4 (redrawn)"),
    Case("hx_two_squeeze_r16_eccentric_sled", 33031, _mix(3, 3, 0), _mix(2, 3, 1), 64,
         (Effect("rib_squeeze", 420.0, ("R16",)), Effect("brs_eccentric", 0.29, ("SLED",))),
         (("chest_rate_damping", "R16"), ("input_gain", "SLED")),
         notes="two kinds on two rigs: squeeze-film damping in the R16 dummy's chest (1/gap^3 "
               "from a 60 mm gap), 420 N s/m at rest; the SLED rig's BRS encoder ring "
               "off-centre, the angle read th + 0.29 sin(th + phase); FULL validated once, "
               "never estimated"),
    Case("hx_pulse_late_3p62ms", 33137, _mix(4, 0, 2), _mix(4, 2, 0), 64,
         (Effect("pulse_late", 0.00362),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.62 ms after its record; SLED validated twice, "
               "never estimated"),
    Case("hx_brs_late_4p49ms", 33241, _mix(0, 0, 6), _mix(2, 1, 3), 96,
         (Effect("brs_late", 0.00449),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.49 ms after the BRS records it; estimated on FULL "
               "alone"),
    Case("hx_cr_creep", 33343, _mix(2, 0, 4), _mix(4, 1, 1), 96,
         (Effect("cr_creep", 0.21),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's gauges creep in their adhesive: under a sustained "
               "load CR reads up to 21 % more, with a 15 ms time constant, every test; CD and "
               "the inputs untouched: a residual in cr only"),
    Case("hx_broken_pulse_sync", 33447, _mix(6, 0, 0), _mix(1, 2, 3), 96,
         (Effect("pulse_sync", 0.011, tests=("R16_005",)),), (),
         expect_broken=("R16_005",),
         notes="R16_005, an estimation test: its sled accelerometer went to a second recorder "
               "that triggered on its own contact, its time base 11 ms early, the pulse rising "
               "before time zero; its other channels and every other test clean"),
]

BY_NAME_X = {c.name: c for c in SET_X}
ONE_PHYSICAL_X = ("hx_bumper_sled", "hx_foam_sled", "hx_hysteresis_full", "hx_knee_r16_full",
                  "hx_fabric_sled", "hx_pelvis_knee_full", "hx_spool_r16_sled")
