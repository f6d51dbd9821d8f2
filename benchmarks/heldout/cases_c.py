"""Held-out set C: twelve new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A and B (``cases.py``, ``cases_b.py``), which the loop's engineers
have looked at.

Against sets A and B: other seeds (12xxx), other BRS resolutions (64 and 128 counts/rev besides
48 and 96), and other setup mixes: A and B between them used every mix with all three setups in
a part, so each C case runs on two setups only, in proportions neither set used (the estimation
and validation parts of a case on the same two). Each library effect appears once in a physical
form (``physics.EFFECTS``) or size neither set used; the broken test fails another way (a
tunnel accelerometer's zero shifting mid-crash); and one case carries physics outside the
loop's vocabulary, where the honest verdict is "none named; unexplained".

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1-6 points of validation fit against its effect-free twin.

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set c``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-24, 2 busy cores): clean64 92.5, clean128 92.9; rib_bilinear
87.5 -> 90.1, rib_valve 85.4 -> 91.0, webbing_set 88.4 -> 91.1, webbing_knee 87.7 -> 89.1,
airbag_sealed 86.9 -> 91.9, pelvis_firm 92.0 -> 93.3, pulse_late_2p75ms 91.0 -> 92.8,
two_effects 86.1 -> 92.5, broken_pulse_shift 90.8 -> 91.5 (flagging it is the verdict asked),
neck_head 88.5 -> 91.9. Changed after a first look at these costs, before any loop run:
neck_head 5 -> 3.5 kg (cost 7.8); two_effects' lumbar 1.3 -> 0.8 and webbing knee 0.8 -> 1.2
(11.6); webbing_knee's knees 8/14 -> 22/16 mm (cost -0.1: far below the stretch the belt works
at, a bilinear belt is a linear one with an offset) and its size 1.0 -> 3.0 (1.5 cost 0.7,
5.0 cost 2.1).
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts per part. A: 2-2-2 3-1-2 1-3-2 2-1-3 6-0-0 0-3-3;
# B: 1-2-3 3-2-1 2-3-1 1-1-4 4-1-1 1-4-1.
MIX_K = ("R16", "R16", "R16", "FULL", "FULL", "FULL")  # 3-0-3
MIX_L = ("R16", "R16", "FULL", "FULL", "FULL", "FULL")  # 2-0-4
MIX_M = ("R16", "R16", "R16", "R16", "FULL", "FULL")  # 4-0-2
MIX_N = ("SLED", "SLED", "FULL", "FULL", "FULL", "FULL")  # 0-2-4
MIX_O = ("SLED", "SLED", "SLED", "SLED", "FULL", "FULL")  # 0-4-2
MIX_P = ("R16", "R16", "R16", "R16", "SLED", "SLED")  # 4-2-0
MIX_Q = ("R16", "R16", "SLED", "SLED", "SLED", "SLED")  # 2-4-0
MIX_R = ("R16", "R16", "R16", "SLED", "SLED", "SLED")  # 3-3-0
MIX_S = ("R16", "FULL", "FULL", "FULL", "FULL", "FULL")  # 1-0-5

NONE_NAMED = "none named; unexplained"

SET_C: list[Case] = [
    Case("hc_clean64", 12101, MIX_P, MIX_Q, 64,
         notes="clean thorax, 64-count BRS (a resolution neither set used), R16 and SLED only"),
    Case("hc_clean128", 12203, MIX_N, MIX_O, 128,
         notes="clean thorax, fine 128-count BRS, SLED and FULL only"),
    Case("hc_rib_bilinear", 12301, MIX_K, MIX_L, 96,
         (Effect("rib_bilinear", 1.6),), (("chest_stiffening", "all"),),
         notes="ribs take up a second load path beyond 16 mm deflection: each rib's stiffness "
               "grows by 1.6 x its own beyond the onset, F += 1.6 k_r (|d| - 16 mm) sign(d), "
               "a kink, no power law (A: power 2.5 past 12 mm; B: cubic from zero)"),
    Case("hc_rib_valve", 12409, MIX_R, MIX_P, 64,
         (Effect("rib_valve", 4000.0),), (("chest_rate_damping", "all"),),
         notes="rib damping material that resists compression only, like a one-way valve: "
               "F += c d'^2 while the rib compresses (d' > 0), nothing while it recovers "
               "(A: |d'|^2.2, B: |d'|^1.5, both symmetric)"),
    Case("hc_webbing_set", 12503, MIX_L, MIX_M, 96,
         (Effect("webbing_set", 0.5),), (("belt_unloading", "all"),),
         notes="chest-side webbing takes a permanent set: it loads on its elastic path, and "
               "once past its peak stretch unloads on a straight line to half that peak (zero "
               "force below it), so the belt gives back far less than it took (A: slack webbing "
               "that cannot push; B: a 45 % softer unloading path in both segments)"),
    Case("hc_webbing_knee", 12607, MIX_O, MIX_N, 64,
         (Effect("webbing_knee", 3.0),), (("belt_stiffening", "all"),),
         notes="webbing with a bilinear characteristic, a soft toe then 4 x stiffer beyond "
               "22 mm stretch chest side (webbing and flesh; peaks 31-41 mm) and 16 mm up to "
               "the retractor (peaks 19-27 mm) (A: exponential toe; B: cubic)"),
    Case("hc_airbag_sealed", 12709, MIX_M, MIX_K, 96,
         (Effect("airbag_sealed", 0.7, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="the car's own driver bag, unvented (a sealed cushion, the gas only "
               "compresses), fill 0.7 of set A's, in the full-scale tests only; the R16 rig "
               "has no interior (A: vented bag, B: relief vent, both on SLED+FULL)"),
    Case("hc_pelvis_firm", 12811, MIX_Q, MIX_R, 128,
         (Effect("lumbar_path", 1.5),), (("pelvis_coupling", "all"),),
         notes="pelvis on a firmer seat pan and anti-submarining ramp: 1.5 x set A's lumbar "
               "and lap stiffness (A: 1.0, B: 0.6)"),
    Case("hc_pulse_late_2p75ms", 12907, MIX_S, MIX_L, 96,
         (Effect("pulse_late", 0.00275),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.75 ms after it is recorded (no delay of A or B: "
               "pulse 1.5, 2, 3, 3.5, 4 ms; BRS 1, 2.5, 3, 4.5, 5 ms)"),
    Case("hc_two_effects", 13001, MIX_K, MIX_M, 96,
         (Effect("lumbar_path", 0.8, ("R16",)), Effect("webbing_knee", 1.2, ("FULL",))),
         (("pelvis_coupling", "R16"), ("belt_stiffening", "FULL")),
         notes="R16: the rig's seat and lap belt tie the pelvis to the sled (0.8 x set A's "
               "lumbar path); FULL: the car's own belt webbing is bilinear, 2.2 x stiffer "
               "beyond its knee; each setup clean of the other's effect"),
    Case("hc_broken_pulse_shift", 13109, MIX_N, MIX_O, 96,
         (Effect("pulse_zero_shift", 4.0, tests=("FULL_005",)),), (),
         expect_broken=("FULL_005",),
         notes="FULL_005's tunnel accelerometer shifts its zero by 4 g at 11 ms, in the "
               "crash-box spike (a piezoresistive sensor's zero shift after a shock): the "
               "channel reads 4 g too much from then on, still 4 g after the car is at rest, "
               "and its integral misses the test's speed change by ~8 m/s; physics clean"),
    Case("hc_neck_head", 13207, MIX_L, MIX_K, 64,
         (Effect("neck_head", 3.5),), (), expect_note=NONE_NAMED,
         notes="the head on a soft, hardening neck, 3.5 kg effective in x at T1 (~6.6 Hz "
               "small-amplitude, secant stiffness tripled at 80 mm, 25 % damped) tied to the "
               "thoracic spine only, not to the car. Expected residual, in every setup: "
               "mainly in CR, not a static function of cr or cd and not a lag of an input: "
               "the head lags the torso (~85 mm behind T1), the neck stretches and pulls the "
               "spine forward (1.4-2.0 kN, peaking at 58-73 ms), so the spine's retardation "
               "is lower than the thesis structure predicts while the neck stretches, then "
               "higher as the head is brought back, a slow swing at the head-neck frequency; "
               "CD a little larger (the belt carries what the neck takes off the spine). "
               "Nearest library effect: pelvis_coupling (a mass on the spine), but its path "
               "goes to the car through the lap belt and seat; naming it (or any other) is a "
               "wrong verdict here"),
]

BY_NAME_C = {c.name: c for c in SET_C}
