"""Held-out set D: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A, B and C (``cases.py``, ``cases_b.py``, ``cases_c.py``), which
the loop's engineers have looked at.

Against sets A, B and C: other seeds (13301-13887), other sizes of each effect, and the setup
mixes none of them used in a part: all that is left are lopsided two-setup mixes (5 of one
setup, 1 of another) and single-setup ones (the estimation and validation parts of a case on
the same setups). The broken tests fail other ways (an intermittent CD connector
spiking; a BRS recorded at the wrong polarity) and the transducer error is another (a CR
channel compressing near its range, a static non-linearity, CD untouched). The issue's list
makes 13 cases; the 14th is the second broken test.

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set d``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-24, 2 busy cores): clean48 92.1, clean96 90.7; rib_hardening
88.6 -> 92.7, rib_valve 88.9 -> 93.3, webbing_hysteresis 86.9 -> 90.4, webbing_power 87.9 ->
89.8, airbag_relief 87.2 -> 90.3, pelvis_soft 90.8 -> 93.2, two_effects 90.8 -> 94.0,
broken_cd_spikes 91.6 -> 91.6 (flagging it is the verdict asked; the filtered spikes barely
move the fit), broken_brs_reversed 85.2 -> 92.8, cr_soft_clip 86.5 -> 91.1, pulse_late_4p25ms
87.7 -> 90.9, brs_late_3p75ms 85.2 -> 87.2. Changed after a first look at these costs, before
any commit or loop run (same seeds): the transducer case was a CD gain of +12 % (cost 0.0:
the plain structure absorbs it whole), its CR compression at 30 g cost 9.2, at 55 g 2.0; BRS
late 1.75 ms cost -0.2, 3.25 ms 1.4; two_effects: see its notes.
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts per part. A: 2-2-2 3-1-2 1-3-2 2-1-3 6-0-0 0-3-3;
# B: 1-2-3 3-2-1 2-3-1 1-1-4 4-1-1 1-4-1; C: 3-0-3 2-0-4 4-0-2 0-2-4 0-4-2 4-2-0 2-4-0 3-3-0
# 1-0-5. Left: the lopsided two-setup mixes and the single-setup ones but R16's.
MIX_RS = ("R16", "R16", "R16", "R16", "R16", "SLED")  # 5-1-0
MIX_SR = ("R16", "SLED", "SLED", "SLED", "SLED", "SLED")  # 1-5-0
MIX_SF = ("SLED", "SLED", "SLED", "SLED", "SLED", "FULL")  # 0-5-1
MIX_FS = ("SLED", "FULL", "FULL", "FULL", "FULL", "FULL")  # 0-1-5
MIX_RF = ("R16", "R16", "R16", "R16", "R16", "FULL")  # 5-0-1
SLED_ONLY = ("SLED",) * 6  # 0-6-0
FULL_ONLY = ("FULL",) * 6  # 0-0-6

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_D: list[Case] = [
    Case("hd_clean48", 13301, MIX_RF, MIX_RF, 48,
         notes="clean thorax, coarse 48-count BRS, R16 with one full-scale test per part"),
    Case("hd_clean96", 13347, MIX_FS, MIX_SF, 96,
         notes="clean thorax, 96-count BRS, FULL-heavy estimation, SLED-heavy validation"),
    Case("hd_rib_hardening", 13391, MIX_SF, MIX_FS, 96,
         (Effect("rib_hardening", 1.5e8),), (("chest_stiffening", "all"),),
         notes="ribs harden progressively from zero deflection, F += k3 d^3 on each rib, "
               "1.5 x set B's k3: +50 % rib force at 20 mm (A: power 2.5 past 12 mm, "
               "B: this cubic at 1e8, C: a kink at 16 mm)"),
    Case("hd_rib_valve", 13433, MIX_SR, MIX_RS, 128,
         (Effect("rib_valve", 2200.0),), (("chest_rate_damping", "all"),),
         notes="rib damping material that resists compression only, F += c d'^2 while the "
               "rib compresses, at 0.55 x set C's c (A: |d'|^2.2, B: |d'|^1.5, both "
               "symmetric; C: this one-way law at 4000)"),
    Case("hd_webbing_hysteresis", 13477, FULL_ONLY, FULL_ONLY, 96,
         (Effect("webbing_hysteresis", 0.6),), (("belt_unloading", "all"),),
         notes="the car's belt webbing unloads on a path 60 % softer than it loads (both "
               "segments, smooth in the rate), full-scale tests only (B: 45 % on every "
               "setup; A: slack webbing; C: a permanent set)"),
    Case("hd_webbing_power", 13523, MIX_RS, MIX_SR, 48,
         (Effect("webbing_power", 11.0),), (("belt_stiffening", "all"),),
         notes="webbing stiffens with the square of its stretch, F += a k e (e/e_ref)^2 at "
               "a = 11 (B: 6 alone, 5 in its two-effect case; A: exponential toe; C: a knee)"),
    Case("hd_airbag_relief", 13567, MIX_SR, MIX_SR, 64,
         (Effect("airbag_relief", 0.5, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="gas bag with a pressure-relief vent, fill 0.5 of set A's (B: 0.8 on "
               "SLED+FULL), on the sled with an interior only; the R16 rig has none"),
    Case("hd_pelvis_soft", 13613, SLED_ONLY, SLED_ONLY, 96,
         (Effect("lumbar_path", 0.45),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on a soft seat cushion and lap belt, lumbar spine to the thoracic "
               "spine, 0.45 x set A's lumbar and lap stiffness (A: 1.0, B: 0.6, C: 1.5 and "
               "0.8)"),
    Case("hd_two_effects", 13659, MIX_SF, MIX_SF, 96,
         (Effect("webbing_hysteresis", 0.4, ("SLED",)), Effect("rib_bottoming", 6e7, ("FULL",))),
         (("belt_unloading", "SLED"), ("chest_stiffening", "FULL")),
         notes="SLED: the rig's own, much-used webbing unloads on a path 40 % softer than it "
               "loads (B: 45 % everywhere); FULL: the crash lab's dummy, its ribs bottoming "
               "past 12 mm (6e7, A: 9e7 everywhere), one test in each part; each setup clean "
               "of the other's effect. Each alone costs 1.9 (SLED) and 2.5 (FULL). Chosen "
               "after a first look at costs, before any commit: an exponential toe 3.5 on "
               "SLED with bottoming 1.2e8 on FULL, estimated on 0-1-5 and validated on 0-5-1, "
               "cost 19.2 (toe alone 19.2, the bottoming alone 8.9); a webbing power law 1.5-8 "
               "on SLED beside it, 7.2-9.5 on either lopsided pairing; a lumbar path 0.7 on "
               "SLED, 7.1"),
    Case("hd_broken_cd_spikes", 13703, MIX_RS, MIX_RS, 96,
         (Effect("cd_spikes", 35.0, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="R16_003's CD connector is intermittent: six 0.3 ms spikes of 35 mm in the raw "
               "channel, alternating in sign, from 16 to 84 ms (CFC 600 after, as the lab "
               "filters it); physics clean"),
    Case("hd_broken_brs_reversed", 13887, MIX_SF, MIX_SF, 96,
         (Effect("brs_reversed", 1.0, tests=("SLED_005",)),), (),
         expect_broken=("SLED_005",),
         notes="SLED_005's spindle encoder recorded with its count direction set wrong: the "
               "pretensioner's pay-in reads as pay-out and the load limiter's pay-out as "
               "pay-in, every count at its right size and time; physics clean"),
    Case("hd_cr_soft_clip", 13751, MIX_RF, MIX_RF, 64,
         (Effect("cr_soft_clip", 40.0),), (), expect_note=UNEXPLAINED_CR,
         notes="the CR channel's signal conditioner works near its output range and "
               "compresses: CR reads 40 g tanh(cr / 40 g), 1.4 % low at 8 g, 6 % at 20 g, "
               "13 % at 30 g (B: a CR gain, 12 % at every level; A and B: CD non-linear), CD "
               "and the inputs untouched: a residual in cr only, a static function of cr. "
               "Replaces a CD gain of +12 %, which the plain structure absorbs whole (cost "
               "0.0: not visible)"),
    Case("hd_pulse_late_4p25ms", 13797, MIX_SF, MIX_FS, 128,
         (Effect("pulse_late", 0.00425),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4.25 ms after it is recorded (no delay of A, B or "
               "C: pulse 1.5, 2, 2.75, 3.5, 4 ms; BRS 1, 2.5, 3, 4.5, 5 ms)"),
    Case("hd_brs_late_3p75ms", 13841, MIX_SR, MIX_RS, 48,
         (Effect("brs_late", 0.00375),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.75 ms after the BRS records it (1.75 ms cost the "
               "grey-box -0.2 points on these tests: not visible; 3.25 ms cost 1.4)"),
]

BY_NAME_D = {c.name: c for c in SET_D}
