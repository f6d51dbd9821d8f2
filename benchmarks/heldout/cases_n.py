"""Held-out set N: twelve new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-M (``cases.py`` ... ``cases_m.py``), which the loop's engineers
have looked at.

What set N judges is again scope when a rig is thinly estimated: 6 estimation tests over three
rigs (R16, SLED, FULL), so a rig held by one estimation test or by none is common. Every
expected verdict names the rigs the effect truly acts on ("all" for all three), whatever the
estimation tests hold of them; how a rig with too few estimation tests counts is the scoring's
business, not the truth's.

Against sets A-M: other seeds (23xxx), other sizes of each effect, (estimation, validation)
pairings of (R16, SLED, FULL) counts no case of A-M ran, twelve cases, not fourteen. The scope
cases: a clean set with FULL held by a single estimation test; an effect on one or two rigs
beside a clean rig held by exactly one estimation test, three kinds (the sled lab's dummy's
ribs hardening, SLED, R16 held once; the sled labs' webbing toe, R16+SLED, FULL held once; a
relief-vented bag on the rigs with an interior, R16 held once); an effect on all three rigs
with one rig held by a single estimation test, two kinds other than M's pelvis path (rib
damping as a power law, SLED held once; webbing hysteresis, R16 held once); an effect on two
rigs beside a third with no estimation test and 2 validation tests (a bag leaking through its
fabric on SLED+FULL, R16 none); two effects of different kinds on different rigs, one of them
held by a single estimation test (valve rib damping on R16, the car's own webbing stiffening
past a knee on FULL, FULL held once, SLED clean); and both delays (the pulse 2.8 ms with R16
held once, the BRS 3.3 ms with SLED held once).

Two lab-side forms no earlier set used (``lab.py``), neither a fault any check of one channel
(frozen, saturated, dropout, spikes) can see. The broken test, R16_003, an estimation test, ran
with the dummy's thorax 12 K above its certification band (20.6-22.2 C; the dummy left in a
hot hall): the ribs' damping material is a viscoelastic polymer, so its ribs' dampings are x
exp(-0.05 x 12) = 0.55 and their stiffnesses x exp(-0.015 x 12) = 0.84 (``dummy_soak``, size
in K below the band, negative above; the per-kelvin rates are this simulator's assumption, not
a measured Hybrid III figure); whole, clean channels, the same dummy the file names, only its
chest answers softer and less damped (A-M: recording faults, and M's test run with another,
smaller dummy; none the right dummy off its temperature). The transducer error is on CD: the
chest pot's excitation is not read back by its conditioner (not ratiometric) and sags from the
trigger on, as the on-board recorder's battery takes its write load, with a time constant of
60 ms: CD reads d (1 - 0.6 (1 - e^(-t/60 ms))), 24 % low at 30 ms, 58 % at the record's end
(200 ms), every test; CR and the inputs read right (``cd_sag``; A-M on CD: a static non-linearity,
a knee, a soft compression, a dead band, backlash, an arm lifting off, an anti-alias filter, a
zero offset; none a gain drifting in time).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set n``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26, 2 busy cores, one cost job at a time, the committed
seeds and mixes): clean48 90.5; rib_hardening_sled 85.9 -> 90.8 (4.8), webbing_toe_labs 86.6
-> 90.7 (4.1), airbag_relief_interior 87.5 -> 91.2 (3.6), rib_visco_sled_once 88.9 -> 90.6
(1.7), webbing_hysteresis_r16_once 85.7 -> 89.8 (4.0), airbag_fabric_no_r16 88.1 -> 92.7
(4.6), two_effects_full_once 86.8 -> 92.0 (5.2; each effect alone not measured, time),
broken_warm_dummy 88.3 -> 90.3 (2.0; flagging the test is the verdict asked; left in, it moves
the fit), cd_sag 88.4 -> 90.9 (2.5), pulse_late_2p8ms 91.0 -> 93.5 (2.4), brs_late_3p3ms 89.9
-> 92.6 (2.7).

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): rib_hardening_sled was 2.0e8, cost 6.7, so 1.4e8; webbing_toe_labs was 3.2,
cost 10.9 (1.2: 9.2, 0.25: 5.9; the exponential toe is far stronger per unit than A's sizes
suggest on these two rigs), so 0.1; webbing_hysteresis_r16_once was 0.38, cost 0.9, so 0.65;
two_effects_full_once was valve damping 2600 on R16 with a webbing knee 4.0 on FULL, cost 9.3
(1500 and 2.5: 6.4), so 1200 and 2.0; the broken test was the thorax run 12 K below its band
(cold: stiffer, more damped), cost -1.9 (20 K below: -1.0; the fit better with it than
without), so 12 K above (warm); cd_sag was 0.15 with a 20 ms time constant, cost 0.1 (a near
constant gain over the chest's loading, taken up by the model), then 0.3 with 60 ms, 0.5, and
0.45, 1.3, so 0.6 with 60 ms (large for a battery's sag: what a slow gain drift must be to be
seen at all). airbag_relief_interior, rib_visco_sled_once, airbag_fabric_no_r16 and both
delays are as first written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_N: list[Case] = [
    Case("hn_clean48", 23107, _mix(2, 3, 1), _mix(4, 0, 2), 48,
         notes="clean thorax, 48-count BRS; FULL held by a single estimation test (beside 2 R16 "
               "and 3 SLED) and 2 validation tests"),
    Case("hn_rib_hardening_sled", 23211, _mix(1, 3, 2), _mix(2, 4, 0), 96,
         (Effect("rib_hardening", 1.4e8, ("SLED",)),), (("chest_stiffening", "SLED"),),
         notes="the sled lab's own dummy (SLED) only: its ribs harden from zero, F += k3 d^3, k3 "
               "= 1.4e8 N/m^3 (A-M: 5e7-1.5e8); R16 clean and held "
               "by exactly one estimation test (2 validation tests), FULL clean (2 estimation "
               "tests, none validating)"),
    Case("hn_webbing_toe_labs", 23317, _mix(3, 2, 1), _mix(3, 0, 3), 64,
         (Effect("webbing_toe", 0.1, ("R16", "SLED")),), (("belt_stiffening", "R16+SLED"),),
         notes="the sled labs' webbing stock (R16 and SLED) stiffens exponentially with stretch "
               "(set A's toe form) at 0.1 (A-M: 2.5-3.5 on all); the car's own belt (FULL) clean,"
               " held by exactly one estimation test and 3 validation tests"),
    Case("hn_airbag_relief_interior", 23419, _mix(1, 2, 3), _mix(2, 0, 4), 96,
         (Effect("airbag_relief", 0.4, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="a bag with a pressure-relief vent (set B's form) at fill 0.4 on the rigs with an "
               "interior (A-M: 0.25-0.8); R16 has none and exactly one estimation test (2 "
               "validation tests)"),
    Case("hn_rib_visco_sled_once", 23523, _mix(2, 1, 3), _mix(0, 2, 4), 64,
         (Effect("rib_visco", 3300.0),), (("chest_rate_damping", "all"),),
         notes="rib damping F += c |d'|^1.5 sign(d'), c = 3300 (A-M: 500-5500), every rig; SLED "
               "holds exactly one estimation test (beside 2 R16 and 3 FULL) and 2 validation "
               "tests"),
    Case("hn_webbing_hysteresis_r16_once", 23629, _mix(1, 3, 2), _mix(3, 0, 3), 48,
         (Effect("webbing_hysteresis", 0.65),), (("belt_unloading", "all"),),
         notes="the webbing's elastic force lower by 0.65 (relative) while it shortens (A-M: "
               "0.15-0.7, none 0.65), every rig; R16 holds exactly one estimation test (beside 3 "
               "SLED and 2 FULL) and 3 validation tests"),
    Case("hn_airbag_fabric_no_r16", 23731, _mix(0, 2, 4), _mix(2, 2, 2), 96,
         (Effect("airbag_fabric", 0.6, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="a ventless bag leaking through its fabric at fill 0.6 (A-M: 0.7, 0.85) on the "
               "rigs with an interior; R16 clean, no estimation test, 2 validation tests"),
    Case("hn_two_effects_full_once", 23837, _mix(2, 3, 1), _mix(3, 0, 3), 64,
         (Effect("rib_valve", 1200.0, ("R16",)), Effect("webbing_knee", 2.0, ("FULL",))),
         (("chest_rate_damping", "R16"), ("belt_stiffening", "FULL")),
         notes="two kinds on two rigs: the R16 lab's dummy's ribs damp through a valve, F += c "
               "d'^2 while compressing, c = 1200 (A-M: 1700-4000), and the car's own belt (FULL) "
               "stiffens past a knee by 2.0 x (A-M: 0.5-9, none 2.0); FULL held by exactly one "
               "estimation test (3 validation tests), SLED clean (3 estimation tests, none "
               "validating)"),
    Case("hn_broken_warm_dummy", 23941, _mix(4, 1, 1), _mix(0, 4, 2), 96,
         (Effect("dummy_soak", -12.0, tests=("R16_003",)),), (), expect_broken=("R16_003",),
         notes="R16_003, an estimation test, ran with the dummy's thorax 12 K above its "
               "certification band (left in a hot hall): rib dampings x 0.55, stiffnesses x 0.84 "
               "(see the module's docstring); whole, clean channels, the dummy its file names, "
               "its file silent about the temperature; every other test clean"),
    Case("hn_cd_sag", 23043, _mix(0, 1, 5), _mix(0, 3, 3), 64,
         (Effect("cd_sag", 0.6),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's excitation sags from the trigger on (the recorder's battery under"
               " its write load; the conditioner not ratiometric): CD reads d (1 - 0.6 (1 - "
               "e^(-t/60 ms))), every test; CR and the inputs untouched: a residual in cd only, "
               "growing with time, not a static function of cd"),
    Case("hn_pulse_late_2p8ms", 23147, _mix(1, 2, 3), _mix(3, 0, 3), 96,
         (Effect("pulse_late", 0.0028),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.8 ms after its record; R16 held by exactly one "
               "estimation test and 3 validation tests"),
    Case("hn_brs_late_3p3ms", 23253, _mix(3, 1, 2), _mix(0, 3, 3), 128,
         (Effect("brs_late", 0.0033),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.3 ms after the BRS records it; SLED held by exactly "
               "one estimation test and 3 validation tests"),
]

BY_NAME_N = {c.name: c for c in SET_N}
