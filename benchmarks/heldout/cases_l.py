"""Held-out set L: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-K (``cases.py`` ... ``cases_k.py``), which the loop's engineers
have looked at.

Against sets A-K: other seeds (21xxx), other sizes of each effect, and (estimation, validation)
pairings of (R16, SLED, FULL) counts no case of A-K ran (A-K had used every pairing with all
three rigs in both parts, so every case here leaves a rig out of one part). One physical class
comes in a form no earlier set used, written from the physics (``physics.EFFECTS``,
``pelvis_knee``): the pelvis path (set A's lumbar spine, lap belt and seat, here soft, at 0.2
of A's stiffness) with the knees meeting the knee bolster of the rigs with an interior once the
pelvis has moved 45 mm forward in the car, bolster foam and femurs in series at 250 kN/m up to
the foam's 5 kN crush plateau (A-K: pelvis paths without knee contact). It acts on SLED and
FULL only, in the case where R16 has no estimation test (2 R16 validation tests only). The
other physical cases use forms of A-K at sizes none used: the encoder ring off-centre at the
largest size of any set (0.35 rad) and at a modest one (0.18 rad); a vented bag on the sled
only, resting on 2 SLED estimation and 2 validation tests beside 4 and 4 clean ones. Two cases
carry two effects of different kinds on the same setups, a large one and a small one that adds
little beside it. The broken test fails no channel check: the tunnel accelerometer of one
full-scale test went through a module sampling at 12.5 kHz while its file states 10 kHz (the
pulse reads 25 % longer and slower, its speed change 25 % too large; A-K: a pulse offset in
time, not stretched). The transducer error is on CD: the chest pot's module has its analog
anti-alias filter at 40 Hz, causal, so CD is smoothed and about 10 ms late (A-K on CD: static
maps, a play, a stuck bit, an arm lifting off; none a linear lag).

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``benchmarks.heldout.costs``' make/identify/evaluate, the
plain thesis structure through the project's CLI, validation TOT fit with the effects ->
without, points; 2026-11-26, 2 busy cores, one fit at a time, same seeds and mixes as
committed): clean64 92.0, clean128 91.9; brs_eccentric_0p35 83.4 -> 89.6 (6.3),
brs_eccentric_0p18 90.2 -> 91.9 (1.7), two_effects_same_a 84.6 -> 90.5 (6.0; the ribs alone
4.7, the webbing's hysteresis alone 1.1: the pair costs 1.3 more than the ribs alone),
two_effects_same_b 86.2 -> 90.0 (3.9; the bag alone 4.8, the hysteresis alone 1.0: the pair
costs 0.9 less than the bag alone, the two partly offsetting in the grey-box's fit),
knee_bolster 87.9 -> 91.9 (4.0), few_tests 87.2 -> 90.2 (3.1), pulse_late_1p8ms 91.0 -> 92.3
(1.2), brs_late_2p2ms 90.3 -> 91.4 (1.0), broken_pulse_rate 86.9 -> 93.6 (6.7; flagging the
test is the verdict asked; left in, it moves the fit), cd_aa_filter 89.5 -> 92.0 (2.5),
webbing_set 88.9 -> 92.7 (3.8), rib_visco 92.2 -> 93.7 (1.6). ("Alone": the other effect's size
set to 0, every draw the same.)

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): brs_eccentric 0.4 cost 7.0, so 0.35 (6.3); the modest one 0.16 cost 1.4, so
0.18 (1.7); two_effects_same_a was rib hardening 1.15e8 with hysteresis 0.2 on R16+SLED, cost
9.8 (the ribs alone 8.5), so 5e7 (4.7 alone; with hysteresis 0.1 instead of 0.2 the pair cost
5.3, 0.6 more than the ribs, the hysteresis 0.1 alone 0.4); two_effects_same_b was a bag of
fill 0.7 with rib damping (rib_visco) 1200 on SLED+FULL, cost 6.4 (the bag alone 8.9, the
damping alone 4.1), so the bag at 0.4 (4.5 alone); with damping 400 the pair cost 3.0 (with the
bag at 0.4), with a webbing power law (the small effect as belt stiffening) 0.5 it cost 9.4
(0.25: 8.5; 0.5 alone 5.3), so the webbing's hysteresis 0.15 as the small effect (with the bag
at 0.4 the pair cost 3.7), and the bag at 0.42, not 0.4 (a size set H used; measured again at
0.42 as above); no size tried gave the pair 0.3-0.6 more than the bag alone (the aim), and the
time to try more ran out; knee_bolster at pelvis path 0.6 cost 10.4 (0.8: 12.1, 1.0: 13.0; 0.3:
5.9), so 0.2 (the clean R16 validation tests ride on a model estimated only where the pelvis
path is); few_tests was a bag of fill 0.5, cost 0.7 (1.2: 4.7), so 0.9; cd_aa_filter was 150 Hz
(2.8 ms), cost -0.1 (60 Hz: 0.9), so 40 Hz; rib_visco 1600 cost 1.2, so 2100. broken_pulse_rate
was first written on FULL_002, a validation test (10.8); moved to FULL_003, an estimation test,
before any verdict.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

# (R16, SLED, FULL) counts, estimation / validation: every (estimation, validation) pairing
# below is one no case of A-K ran


UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_L: list[Case] = [
    Case("hl_clean64", 21103, _mix(3, 2, 1), _mix(0, 3, 3), 64,
         notes="clean thorax, 64-count BRS, estimated on every rig, validated without R16"),
    Case("hl_clean128", 21207, _mix(1, 2, 3), _mix(0, 5, 1), 128,
         notes="clean thorax, 128-count BRS, estimated on every rig, validated without R16"),
    Case("hl_brs_eccentric_0p35", 21311, _mix(2, 2, 2), _mix(4, 2, 0), 96,
         (Effect("brs_eccentric", 0.35),), (("input_gain", "all"),),
         notes="the BRS's encoder ring off its spindle's centre: the angle read with an error "
               "e sin(th + phase), e = 0.35 rad, so the BRS's gain (counts per radian of "
               "spool) drifts by up to 35 % with the spool's angle, every setup (A: 0.3, K: "
               "0.2): the largest of any set"),
    Case("hl_brs_eccentric_0p18", 21419, _mix(1, 4, 1), _mix(3, 3, 0), 48,
         (Effect("brs_eccentric", 0.18),), (("input_gain", "all"),),
         notes="the same ring off-centre at a modest e = 0.18 rad (the gain drifting by up to "
               "18 %), every setup; the coarsest BRS of the set (48 counts/rev)"),
    Case("hl_two_effects_same_a", 21523, _mix(2, 3, 1), _mix(0, 3, 3), 64,
         (Effect("rib_hardening", 5.0e7, ("R16", "SLED")),
          Effect("webbing_hysteresis", 0.2, ("R16", "SLED"))),
         (("chest_stiffening", "R16+SLED"), ("belt_unloading", "R16+SLED")),
         notes="R16 and SLED: ribs harden from zero, F += k3 d^3, k3 = 5e7 N/m^3 (B: 1e8, "
               "D: 1.5e8, E: 7e7 on R16, G: 1.2e8, J: 1.35e8), the large effect (4.7 alone), "
               "and both webbing segments' elastic force 20 % lower while they shorten (B: "
               "0.45 ... I: 0.35 on R16), the small one (1.1 alone); together 6.0, the "
               "hysteresis adding 1.3 beside the ribs. FULL clean of both (1 estimation and 3 "
               "validation tests); no R16 validation test"),
    Case("hl_two_effects_same_b", 21627, _mix(1, 2, 3), _mix(2, 4, 0), 96,
         (Effect("airbag", 0.42, ("SLED", "FULL")),
          Effect("webbing_hysteresis", 0.15, ("SLED", "FULL"))),
         (("airbag_contact", "SLED+FULL"), ("belt_unloading", "SLED+FULL")),
         notes="SLED and FULL: a vented driver bag (set A's form) at fill 0.42 of set A's (A: "
               "1.0, F: 0.6 on SLED+FULL, H: 0.4 on FULL), the large effect (4.8 alone), and "
               "both webbing segments' elastic force 15 % lower while they shorten, the small "
               "one (1.0 alone); together 3.9, 0.9 less than the bag alone. R16 clean of both "
               "(1 estimation and 2 validation tests)"),
    Case("hl_knee_bolster", 21731, _mix(0, 3, 3), _mix(2, 1, 3), 64,
         (Effect("pelvis_knee", 0.2, ("SLED", "FULL")),), (("pelvis_coupling", "SLED+FULL"),),
         notes="the rigs with an interior (SLED, FULL): the pelvis on lap belt and seat and "
               "the lumbar spine (set A's pelvis path at 0.2 of its stiffness: a soft seat "
               "and lap belt), and the knees meeting the knee bolster once the pelvis has "
               "moved 45 mm forward in the car: bolster foam and femurs in series, 250 kN/m "
               "up to the foam's 5 kN crush plateau (a new form: A-K's pelvis paths had no "
               "knee contact). R16's rigid seat and ramp hold the pelvis to the sled, and it "
               "has no interior: no pelvis path, no bolster, and no estimation test: 2 R16 "
               "validation tests only, beside 6 SLED+FULL estimation and 4 validation tests"),
    Case("hl_few_tests", 21833, _mix(3, 2, 1), _mix(0, 2, 4), 48,
         (Effect("airbag", 0.9, ("SLED",)),), (("airbag_contact", "SLED"),),
         notes="a vented driver bag (set A's form) at fill 0.9 of set A's (A: 1.0 and F: 0.6 "
               "on SLED+FULL, H: 0.4 on FULL), on the sled with "
               "interior only: 2 SLED estimation tests beside 4 clean ones (3 R16, 1 FULL), "
               "2 SLED validation tests beside 4 clean FULL ones"),
    Case("hl_pulse_late_1p8ms", 21937, _mix(4, 1, 1), _mix(0, 3, 3), 96,
         (Effect("pulse_late", 0.0018),), (("input_delay", "all"),),
         notes="the chest feels the pulse 1.8 ms after its record (A-K: 1.5, 2, 2.25, 2.4, "
               "2.6, 2.75, 3 on FULL, 3.25, 3.5, 3.6, 3.9, 4, 4.25 ms)"),
    Case("hl_brs_late_2p2ms", 21041, _mix(1, 3, 2), _mix(4, 2, 0), 64,
         (Effect("brs_late", 0.0022),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.2 ms after the BRS records it (A-K: BRS 1, 2.5, "
               "2.8, 3, 3.2, 3.4, 3.6, 3.75, 4.1, 4.4, 4.5, 4.75, 5 ms)"),
    Case("hl_broken_pulse_rate", 21143, _mix(2, 1, 3), _mix(0, 4, 2), 96,
         (Effect("pulse_rate", 1.25, tests=("FULL_003",)),), (), expect_broken=("FULL_003",),
         notes="FULL_003's tunnel accelerometer went through a module sampling at 12.5 kHz "
               "while the file states 10 kHz (the others' rate): its samples, counted from "
               "the trigger, stand at 1.25 x their true time. The pulse reads as a crash "
               "25 % longer and slower, its speed change 25 % too large; a whole, clean "
               "channel (no channel check sees it), the physics clean"),
    Case("hl_cd_aa_filter", 21247, _mix(2, 2, 2), _mix(2, 4, 0), 64,
         (Effect("cd_aa_filter", 40.0),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's recorder module has its analog anti-alias filter set for a "
               "quasi-static channel: a causal 4-pole Butterworth at 40 Hz ahead of the "
               "digitiser (a CFC 600 channel wants it above 1 kHz): CD is smoothed and "
               "delayed by its group delay (about 10 ms at low frequency, the peak read low "
               "and late), every test; CR and the "
               "inputs untouched: a residual in cd only, a lag, not a static function of cd "
               "(A-K on CD: a dead band, a play, a knee, compression, over-reading, a stuck "
               "bit, an arm lifting off)"),
    Case("hl_webbing_set", 21349, _mix(1, 1, 4), _mix(3, 3, 0), 48,
         (Effect("webbing_set", 0.6),), (("belt_unloading", "all"),),
         notes="the chest-side webbing takes a permanent set, unloading to 0.6 of its peak "
               "stretch, every setup (C: 0.5, E: 0.65, F: 0.4 on SLED, H: 0.35, I: 0.45, J: "
               "0.55 on R16)"),
    Case("hl_rib_visco", 21451, _mix(3, 1, 2), _mix(0, 2, 4), 128,
         (Effect("rib_visco", 2100.0),), (("chest_rate_damping", "all"),),
         notes="rib damping F += c |d'|^1.5 sign(d'), c = 2100 N/(m/s)^1.5, every setup (B: "
               "2500, E: 3800, G: 5500, J: 500 on FULL)"),
]

BY_NAME_L = {c.name: c for c in SET_L}
