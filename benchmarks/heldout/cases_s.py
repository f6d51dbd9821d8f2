"""Held-out set S: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-R (``cases.py`` ... ``cases_r.py``).

What set S judges is the general list again, the issue's own "done when", written by another
engineer from the simulator and the thesis alone, without reading how the loop works: two clean
cases (48 and 96 counts); each kind of the library a loop can name, as physics from this
simulator, at least once (chest_stiffening twice, chest_rate_damping, belt_unloading twice,
belt_stiffening, airbag_contact, pelvis_coupling, input_gain, input_delay twice); two effects
of different kinds on different rigs in one case; one broken estimation test; one transducer
error on CR alone (set R's was on CD), where nothing physical must be named, only the output it
is on; a late pulse and a late BRS. Every rig that holds estimation tests holds at least two of
them; an effect on some rigs only rests on two or more estimation and validation tests of them
beside an estimation test of a rig it spares; every expected verdict names the rigs the effect
truly acts on ("all" for all three).

Against sets A-R: other seeds (28xxx), (estimation, validation) pairings of (R16, SLED, FULL)
counts no case of A-R ran, effect sizes no case of A-R used, most on scopes no earlier case
gave their form: the rib cage's Fung exponential on SLED alone at 0.3 (A-R: 0.2 and 0.5 on R16,
0.25 on all); the D-ring's capstan on every rig at mu theta 0.56 (A-R: 0.5 and 0.62 on FULL
alone); the webbing's power law on the car's own belt (FULL) at 0.7 (A-R: 0.4-15, none 0.7);
a bag with a pressure-relief vent on FULL alone at fill 0.45 (A-R: 0.25-0.8, none 0.45); the
pelvis path with its lap belt slipping at 5800 N on the R16 rig alone (its rigid seat has no
anti-submarining ramp; A-R: 5000 on SLED, 5500-6800 on all); the BRS ring 25 % off-centre
(A-R: 0.18-0.35, none 0.25); the two-effect case's webbing set at 0.58 on R16 alone (A-R:
0.35-0.75, none 0.58) beside ribs hardening cubically at 6e7 on FULL alone (A-R: 5e7-1.5e8,
none 6e7, none on FULL alone), SLED validated once, never estimated. The delays: the pulse
4.9 ms, the BRS 2.7 ms (A-R: no input 4.9 or 2.7 ms). Sizes are in each key's units
(``physics.EFFECTS``).

One physical form no earlier set used (``physics.py``): the ribs' bonded damping polymer as a
constant loss factor, ``rib_loss`` (hysteretic, or structural, damping: the energy lost per
cycle a share of the elastic energy stored, about independent of the rate, the classical model
of a viscoelastic layer over a wide band): each sternum mass's rib adds eta k_r d in the sense
of its rate (the rib's own stiffness; in compression, from zero at rest; the sense switching
within 0.02 m/s; d taken no further than 60 mm): stiffer by eta loading, softer by eta
unloading, whatever the rate. Here eta 0.2 on every rig. Mapped to ``chest_rate_damping``, the
nearest kind (a loss in the chest, not a stiffness growing with the deflection). A-R's chest
damping forms grow with the rate (power laws, a valve, a Maxwell branch), with the compression
times the rate (R's foam pad, H's squeeze film), or are a constant force (O's dry friction);
this one is a force in proportion to the deflection, independent of the rate.

Two lab-side forms no earlier set used (``lab.py``), exact (no per-test scatter). The broken
test, FULL_003, an estimation test: its spindle encoder's counter holds 7 bits, two's
complement (``brs_wrap``): past -64 counts (half a turn paid out at 128 counts/rev) the count
wraps round to +63 and counts down from there (A-R's broken BRS: frozen, reversed, reset,
x4 decoding, polled too slowly, another test's, raw counts; none wrapping). The transducer
error is on CR, every test: the spine accelerometer's strain gauges creep in their adhesive
(``cr_creep``): under a sustained load its reading grows by a share 0.2 of it with a 15 ms
time constant and falls back the same way once unloaded (CR reads cr + 0.2 x cr through a
one-pole low-pass of 15 ms); CD and the inputs read right (A-R's transducer errors on CR: a
gain, a tanh, a progressive over-read, a piezoelectric high-pass, a zero shift, CD's crosstalk,
an oil-damped 2-pole low-pass, a late digitiser; none a creep, which reads high, not low or
late, and more the longer a load is held).

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set s``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26 16:19-16:28 UTC, 2 cores at a load of 2-4, three cost
jobs at a time, the committed seeds and mixes; the four resized cases 16:29-16:54 UTC at a load
of 4-9): clean48 89.8, clean96 90.2; rib_loss_all 87.5 -> 91.6 (4.1), rib_fung_sled 86.2 ->
91.2 (5.1), capstan_all 88.7 -> 90.3 (1.7), webbing_power_full 83.3 -> 88.3 (5.0),
airbag_relief_full 87.2 -> 92.7 (5.5), submarine_r16 85.6 -> 89.0 (3.4), brs_eccentric_all 89.2
-> 91.6 (2.4), pulse_late_4p9ms 90.1 -> 93.3 (3.2), brs_late_2p7ms 89.5 -> 90.7 (1.3),
two_set_r16_hardening_full 86.0 -> 93.1 (7.1; the webbing set alone 89.5 -> 93.1, 3.6; the
ribs' hardening alone 87.7 -> 93.1, 5.4), broken_brs_wrap 79.0 -> 91.1 (12.1; flagging the test
is the verdict asked; left in, it moves the fit), cr_creep 82.3 -> 86.8 (4.4). Each effect of
the two-effect case alone: the case's seed with the other effect's rigs emptied (same dummies,
pulses and noise), against the same twin.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes; sizes only, no form changed): rib_loss_all was eta 0.3, cost 7.8 (above the
1.5-6 band earlier sets kept to), so 0.2; rib_fung_sled was 0.35, cost 6.3, so 0.3;
webbing_power_full was 10, cost 10.8, then 4 (9.1), 2.5 (8.1), 1.5 (6.8), 1.2 (6.3), so 0.7
(5.0; as set M found, the power law's cost on FULL hardly falls with its size above 1);
two_set_r16_hardening_full's ribs' hardening was 1.1e8, together 9.7 (the hardening alone 8.4,
the set alone 3.6), so 6e7. The other nine cases are as first written; capstan_all (1.7) and
brs_late_2p7ms (1.3, a delay) are visible but near the floor, kept as written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_S: list[Case] = [
    Case("hs_clean48", 28107, _mix(0, 4, 2), _mix(2, 3, 1), 48,
         notes="clean thorax, 48-count BRS; R16 validated twice, never estimated"),
    Case("hs_clean96", 28213, _mix(3, 0, 3), _mix(2, 3, 1), 96,
         notes="clean thorax, 96-count BRS; SLED validated three times, never estimated"),
    Case("hs_rib_loss_all", 28319, _mix(4, 0, 2), _mix(2, 1, 3), 64,
         (Effect("rib_loss", 0.2),), (("chest_rate_damping", "all"),),
         notes="the ribs' bonded damping layer as a constant loss factor 0.2: each rib adds "
               "0.2 k d in the sense of its rate, in compression (a form no earlier set "
               "used), every rig"),
    Case("hs_rib_fung_sled", 28423, _mix(0, 4, 2), _mix(1, 2, 3), 96,
         (Effect("rib_fung", 0.3, ("SLED",)),), (("chest_stiffening", "SLED"),),
         notes="the sled lab's dummy's rib cage stiffens exponentially (Fung), amount 0.3 "
               "(A-R: 0.2 and 0.5 on R16, 0.25 on all); FULL clean, 2 estimation tests"),
    Case("hs_capstan_all", 28529, _mix(3, 3, 0), _mix(3, 2, 1), 128,
         (Effect("dring_capstan", 0.56),), (("belt_unloading", "all"),),
         notes="the shoulder webbing wraps its D-ring as a capstan, mu theta 0.56, on every "
               "rig (A-R: 0.5 and 0.62 on FULL alone)"),
    Case("hs_webbing_power_full", 28631, _mix(3, 0, 3), _mix(1, 2, 3), 48,
         (Effect("webbing_power", 0.7, ("FULL",)),), (("belt_stiffening", "FULL"),),
         notes="the car's own belt (FULL) stiffens with the square of its stretch, amount 0.7 "
               "(A-R: 0.4-15, none 0.7); R16 clean, 3 estimation tests"),
    Case("hs_airbag_relief_full", 28737, _mix(2, 0, 4), _mix(2, 1, 3), 64,
         (Effect("airbag_relief", 0.45, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="the car's (FULL) driver bag with a pressure-relief vent at fill 0.45 (A-R: "
               "0.25-0.8, none 0.45); the R16 rig without a bag, 2 estimation tests"),
    Case("hs_submarine_r16", 28841, _mix(4, 0, 2), _mix(3, 2, 1), 96,
         (Effect("pelvis_submarine", 5800.0, ("R16",)),), (("pelvis_coupling", "R16"),),
         notes="the R16 rig's rigid seat has no anti-submarining ramp: the pelvis on lap belt "
               "and seat, the lap belt slipping over the iliac wings past 5800 N (A-R: 5000 "
               "on SLED, 5500-6800 on all), R16 alone; FULL clean, 2 estimation tests"),
    Case("hs_brs_eccentric_all", 28947, _mix(0, 3, 3), _mix(1, 4, 1), 128,
         (Effect("brs_eccentric", 0.25),), (("input_gain", "all"),),
         notes="the BRS encoder ring 25 % off-centre (A-R: 0.18-0.35, none 0.25), every rig; "
               "R16 validated once, never estimated"),
    Case("hs_pulse_late_4p9ms", 28053, _mix(2, 4, 0), _mix(1, 1, 4), 96,
         (Effect("pulse_late", 0.0049),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.9 ms after its record (A-R: no input 4.9 ms)"),
    Case("hs_brs_late_2p7ms", 28159, _mix(4, 2, 0), _mix(1, 3, 2), 48,
         (Effect("brs_late", 0.0027),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.7 ms after the BRS records it (A-R: no input "
               "2.7 ms)"),
    Case("hs_two_set_r16_hardening_full", 28261, _mix(3, 0, 3), _mix(3, 1, 2), 64,
         (Effect("webbing_set", 0.58, ("R16",)), Effect("rib_hardening", 6e7, ("FULL",))),
         (("belt_unloading", "R16"), ("chest_stiffening", "FULL")),
         notes="two kinds on two rigs: the R16 rig's webbing unloads to a permanent set of "
               "0.58 x its peak stretch (A-R: 0.35-0.75, none 0.58; on R16 alone 0.55), "
               "and the car's (FULL) dummy's ribs harden, F += 6e7 d^3 (A-R: 5e7-1.5e8, "
               "none 6e7, none on FULL alone); SLED validated once, never estimated"),
    Case("hs_broken_brs_wrap", 28367, _mix(2, 0, 4), _mix(1, 4, 1), 128,
         (Effect("brs_wrap", 7.0, tests=("FULL_003",)),), (), expect_broken=("FULL_003",),
         notes="FULL_003, an estimation test: its spindle encoder's counter of 7 bits (two's "
               "complement, -64..63 counts) wraps round once the spool has paid out half a "
               "turn at 128 counts/rev; its other channels and every other test clean"),
    Case("hs_cr_creep", 28471, _mix(0, 2, 4), _mix(1, 3, 2), 96,
         (Effect("cr_creep", 0.2),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer's gauges creep in their adhesive: under a sustained "
               "load CR reads up to 20 % more, with a 15 ms time constant, every test; CD and "
               "the inputs untouched: a residual in cr only"),
]

BY_NAME_S = {c.name: c for c in SET_S}
