"""Held-out set O: thirteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-N (``cases.py`` ... ``cases_n.py``), which the loop's engineers
have looked at.

What set O judges is two effects on different rigs, and whether a loop invents a second effect
where there is one: 6 estimation tests over R16, SLED and FULL, and every rig an estimation part
holds it holds by two tests or more (2/2/2, 3/3/0, 4/2/0, 2/4/0, 3/0/3, 4/0/2, 0/3/3, 0/2/4,
0/4/2), so the scope of each effect can be judged on every rig the estimation saw. Every
expected verdict names the rigs the effect truly acts on ("all" for all three).

Against sets A-N: other seeds (24xxx), other sizes of each effect, (estimation, validation)
pairings of (R16, SLED, FULL) counts no case of A-N ran, no rig held by a single estimation
test. Four cases of two effects of different kinds on different rigs, each rig of each effect
held by >= 2 estimation and >= 2 validation tests, eight effects of six kinds on the pairs of
rigs R16/FULL, R16/SLED (twice) and SLED/FULL: the R16 lab's dummy's ribs stiffening by Fung's
law beside the car's own webbing unloading to a set (FULL), SLED clean and held twice; the R16
lab's webbing stiffening as a power law beside a sealed bag on SLED, no third rig; the sled
lab's dummy's valve damping (SLED) beside the pelvis path of the car's seat (FULL), R16 clean
and held twice; the R16 lab's webbing hysteresis beside a bag leaking through its fabric on
SLED, no third rig. Three cases of one effect on one rig beside a clean rig held by 2-4
estimation tests, three kinds (a second effect must not be named): the crash lab's dummy's chest
locking up (FULL, R16 clean), a relief-vented bag on SLED (R16 clean), and the sled lab's
dummy's rib cage with dry friction (SLED, FULL clean). Two clean cases (48 and 96 counts), and
both delays (the pulse 4.3 ms, the BRS 3.8 ms, neither size used before).

One physical form no earlier set used (``physics.py``): dry (Coulomb) friction in the rib cage,
``rib_friction``: each sternum mass's rib pulls the spine with a force of the size (N) against
the chest's rate, whatever the rate once sliding (smoothed within 0.02 m/s): the ribs' bib and
the sternum's guide rubbing on the spine box. A-N's chest damping forms all grow with the rate
(linear, power laws, a valve, a squeeze film, a Maxwell branch); this one does not, so a model
with viscous damping must trade it between the loading's fast and slow parts. Mapped to
``chest_rate_damping``, the nearest kind of the library's (a dissipative rib force that follows
the rate's sign).

Two lab-side forms no earlier set used (``lab.py``). The broken test, FULL_001, an estimation
test: its BRS file holds the spindle's raw counts under the header's degrees (the export's unit
step skipped for that test), so with 48 counts a rev it reads 48/360 = 0.13 of the spool's turn
(``brs_counts``; A-N on BRS: frozen, reversed, reset, x4 quadrature, polled too slowly, crossed
with another test's; none a unit slip). The transducer error is on CR, every test: the spine
accelerometer is an oil-damped seismic element of 55 Hz natural frequency, damping ratio 0.7 (a
vehicle-dynamics sensor in a crash dummy): CR reads through w^2 / (s^2 + 1.4 w s + w^2), about
4 ms late and rounded at its peak; CD and the inputs read right (``cr_damped``; A-N on CR: a
gain, a soft clip, a progressive gain, a piezo's high-pass, a loose mount's resonance, a zero
shift, CD crosstalk; none a low-pass sensing element. The nearest is L's causal anti-alias
filter on CD, a 4-pole Butterworth of the conditioner, not the sensor; this one lags CR, not CD,
so a loop that names an input delay has missed that CD reads on time).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set o``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26 10:31 UTC, 2 cores, load 2-4, two cost jobs at a time, the
committed seeds and mixes): clean48 91.2; clean96 88.7; two_fung_r16_set_full 83.8 -> 89.1 (5.2;
the Fung ribs alone 3.7, the webbing set alone 3.2), two_power_r16_sealed_sled 89.4 -> 92.3
(2.8; the webbing power law alone 5.4, the sealed bag alone 2.5: together they cost less than
the webbing alone), two_valve_sled_lumbar_full 85.2 -> 90.7 (5.4; the valve alone 2.8, the
pelvis path alone 2.2), two_hyst_r16_fabric_sled 84.6 -> 89.1 (4.5; each alone 2.3),
rib_lock_full 88.7 -> 93.6 (4.9), airbag_relief_sled 89.9 -> 93.2 (3.3), rib_friction_sled 87.0
-> 91.0 (4.0), broken_brs_counts 86.7 -> 90.1 (3.4; flagging the test is the verdict asked; left
in, it moves the fit), cr_damped 89.7 -> 91.7 (2.0), pulse_late_4p3ms 87.6 -> 90.3 (2.7),
brs_late_3p8ms 87.3 -> 89.9 (2.6). Each effect of a two-effect case alone: the case's seed with
the other effect's rigs emptied (same dummies, pulses and noise), against the same twin.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): two_fung_r16_set_full's ribs were at 0.35, alone 1.4 (the set alone 3.2,
together 3.5), so 0.5; two_power_r16_sealed_sled's webbing power law was 4.0, together 9.7
(alone 12.0; 1.5 alone 9.5, 0.5 alone 6.1, 0.3 alone 4.5: on the R16 rig's belt loads the cubic
term is far stronger per unit than A-N's sizes on all rigs suggest), so 0.4;
two_valve_sled_lumbar_full was valve 2800 with the pelvis path at 0.5, together 8.7 (each alone
4.9), so 1800 and 0.35; two_hyst_r16_fabric_sled was hysteresis 0.3 (alone 1.1) with fabric 0.5
(alone 1.7), together 3.0, so 0.48 and 0.65; rib_lock_full was 70 mm, cost 6.8 (76 mm: 6.1, 82
mm: 5.5), so 90 mm; cr_damped was 150 Hz, cost 0.2 (80 Hz: 0.9), so 55 Hz (low for a crash
sensor: what a sensing element's lag must be to be seen at all). The broken test was first a BRS
hub slipping on the spool shaft as the pretensioner fires, losing 50 deg over the pretensioner's
stroke, cost -0.1 (150 deg: 3.3, but the spool turns only some 30 deg in the pretensioner's
stroke, and an encoder wheel that cannot follow the spool's angular acceleration loses 6-28 deg:
a slip that cost is not physical), so the raw counts form; that was on FULL_003 with 64 counts,
cost 0.9, with 48 counts 1.1 (SLED_001 1.4, FULL_005 3.0, SLED_003 5.0), so FULL_001 with 48
counts. The clean cases, airbag_relief_sled, rib_friction_sled and both delays are as first
written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_O: list[Case] = [
    Case("ho_clean48", 24107, _mix(4, 0, 2), _mix(2, 0, 4), 48,
         notes="clean thorax, 48-count BRS; R16 held by 4 estimation tests, FULL by 2, SLED by "
               "none and not validated: nothing may be named"),
    Case("ho_clean96", 24211, _mix(0, 3, 3), _mix(0, 2, 4), 96,
         notes="clean thorax, 96-count BRS; SLED and FULL held by 3 estimation tests each"),
    Case("ho_two_fung_r16_set_full", 24313, _mix(2, 2, 2), _mix(2, 0, 4), 64,
         (Effect("rib_fung", 0.5, ("R16",)), Effect("webbing_set", 0.52, ("FULL",))),
         (("chest_stiffening", "R16"), ("belt_unloading", "FULL")),
         notes="two kinds on two rigs, a clean third held twice: the R16 lab's dummy's rib "
               "cage stiffens by Fung's law at 0.5 (A-N: 0.2, 0.25, on all), and the car's own "
               "belt (FULL) unloads to a set of 0.52 of its peak stretch (A-N: 0.35-0.65, none "
               "0.52); SLED clean, 2 estimation tests, none validating"),
    Case("ho_two_power_r16_sealed_sled", 24419, _mix(3, 3, 0), _mix(2, 4, 0), 96,
         (Effect("webbing_power", 0.4, ("R16",)), Effect("airbag_sealed", 0.35, ("SLED",))),
         (("belt_stiffening", "R16"), ("airbag_contact", "SLED")),
         notes="two kinds on two rigs, no third: the R16 lab's webbing stock stiffens as a power "
               "law, F += 0.4 k e (e/e_ref)^2 (A-N: 1-15, on all), and an unvented bag at fill "
               "0.35 (A-N: 0.25-0.7, none 0.35) on SLED, the only rig of the case with an "
               "interior"),
    Case("ho_two_valve_sled_lumbar_full", 24523, _mix(2, 2, 2), _mix(0, 4, 2), 48,
         (Effect("rib_valve", 1800.0, ("SLED",)), Effect("lumbar_path", 0.35, ("FULL",))),
         (("chest_rate_damping", "SLED"), ("pelvis_coupling", "FULL")),
         notes="two kinds on two rigs, a clean third held twice: the sled lab's dummy's ribs "
               "damp through a valve, F += 1800 d'^2 while compressing (A-N: 1200-4000, none "
               "1800), and the car's seat and lap belt (FULL) hold the pelvis, the lumbar path "
               "at 0.35 (A-N: 0.45-1.5); R16 clean, 2 estimation tests, none validating"),
    Case("ho_two_hyst_r16_fabric_sled", 24629, _mix(4, 2, 0), _mix(3, 3, 0), 64,
         (Effect("webbing_hysteresis", 0.48, ("R16",)), Effect("airbag_fabric", 0.65, ("SLED",))),
         (("belt_unloading", "R16"), ("airbag_contact", "SLED")),
         notes="two kinds on two rigs, no third: the R16 lab's webbing's elastic force 0.48 "
               "lower while it shortens (A-N: 0.15-0.7, none 0.48), and a ventless bag leaking "
               "through its fabric at fill 0.65 (A-N: 0.6, 0.7, 0.85) on SLED"),
    Case("ho_rib_lock_full", 24731, _mix(3, 0, 3), _mix(3, 0, 3), 96,
         (Effect("rib_lock", 0.09, ("FULL",)),), (("chest_stiffening", "FULL"),),
         notes="one effect, one rig: the crash lab's dummy's chest locks up near 90 mm, F += k "
               "d^2/(d_l - d) (A-N: 65 mm, on all); R16 clean, 3 estimation and 3 validation "
               "tests: no second effect may be named"),
    Case("ho_airbag_relief_sled", 24837, _mix(2, 4, 0), _mix(4, 2, 0), 64,
         (Effect("airbag_relief", 0.35, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="one effect, one rig: a bag with a pressure-relief vent at fill 0.35 (A-N: "
               "0.25-0.8, none 0.35) on SLED; R16 clean (no interior), 2 estimation and 4 "
               "validation tests: no second effect may be named"),
    Case("ho_rib_friction_sled", 24941, _mix(0, 4, 2), _mix(0, 4, 2), 96,
         (Effect("rib_friction", 400.0, ("SLED",)),), (("chest_rate_damping", "SLED"),),
         notes="one effect, one rig: the sled lab's dummy's rib cage with dry friction, 400 N "
               "per sternum mass against the chest's rate (a form no earlier set used); FULL "
               "clean, 2 estimation and 2 validation tests: no second effect may be named"),
    Case("ho_broken_brs_counts", 24043, _mix(0, 2, 4), _mix(0, 2, 4), 48,
         (Effect("brs_counts", 1.0, tests=("FULL_001",)),), (), expect_broken=("FULL_001",),
         notes="FULL_001, an estimation test: its BRS file holds the spindle's raw counts under "
               "its header's degrees, 48/360 of the spool's turn; its other channels and every "
               "other test clean"),
    Case("ho_cr_damped", 24147, _mix(2, 2, 2), _mix(3, 3, 0), 96,
         (Effect("cr_damped", 55.0),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer is an oil-damped element of 55 Hz natural frequency, "
               "damping ratio 0.7, every test: CR lags (about 4 ms) and reads its peaks low; CD "
               "and the inputs untouched: a residual in cr only"),
    Case("ho_pulse_late_4p3ms", 24253, _mix(3, 0, 3), _mix(1, 0, 5), 48,
         (Effect("pulse_late", 0.0043),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.3 ms after its record (A-N: 1.5-4.6 ms, none 4.3)"),
    Case("ho_brs_late_3p8ms", 24359, _mix(0, 3, 3), _mix(0, 4, 2), 64,
         (Effect("brs_late", 0.0038),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.8 ms after the BRS records it (A-N: 1-5 ms, none "
               "3.8)"),
]

BY_NAME_O = {c.name: c for c in SET_O}
