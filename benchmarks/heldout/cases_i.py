"""Held-out set I: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-H (``cases.py`` ... ``cases_h.py``), which the loop's engineers
have looked at.

Against sets A-H: other seeds (18xxx), other sizes of each effect, and (estimation,
validation) pairings of (R16, SLED, FULL) counts no case of A-H ran. Every effect that acts on
some setups only rests on at least 2 estimation and 2 validation tests of those setups, beside
at least one test of a setup it does not act on. One physical class comes in a form no earlier
set used, written from the physics (``physics.EFFECTS``): a chest that locks up as it nears a
limit deflection (the ribs straightening and the contents incompressible: a hyperbolic spring,
k d^2 / (d_l - d); A-H: a power 2.5 past an onset, a cubic from zero, a kink). The other five
use forms of A-H at sizes none used. The broken tests fail ways a lab records and a reviewer
sees on the plot (a BRS whose two tracks are polled too slowly by its quadrature decoder: the
pay-out counts lost; a CR recorder losing a block of samples mid-loading: a jump), and the
transducer error is another (play in the chest pot arm's worn slot: CD low while the chest
closes, high as it opens, CR untouched). The issue's list makes 13 cases; the 14th is the
second broken test.

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set i``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-25, 2 busy cores): clean48 91.0, clean96 93.6; rib_lock 89.8
-> 93.7, rib_squeeze 90.0 -> 92.2, webbing_set 91.2 -> 94.4, webbing_knee 90.5 -> 92.6,
airbag_relief 88.5 -> 92.2, pelvis_submarine 86.5 -> 89.4, two_effects 88.1 -> 92.2 (each
alone: the R16 webbing 2.6, the SLED bag 2.4), broken_brs_poll 92.5 -> 93.9 and
broken_cr_lost_block 87.6 -> 88.9 (flagging the test is the verdict asked; one estimation
test's channel moves the fit little), cd_backlash 92.3 -> 94.1, pulse_late_3p6ms 89.2 -> 92.2,
brs_late_2p8ms 89.3 -> 90.6.

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): webbing_knee 4.0 cost 1.0, 6.0 cost 1.5, so 9.0; two_effects was webbing
hysteresis 0.65 on R16 with a sealed bag of fill 0.5 on SLED, cost 8.2 (alone 5.6 and 4.8),
then 0.35 with 0.3; the transducer case was to be a lag of the chest pot on a springy, greased
linkage (a first-order low-pass on CD, ``cd_linkage_lag``): it cost 0.1, 0.4 and 0.7 at 3, 6
and 10 ms (most likely the plain structure takes a lagging CD up in its chest parameters), so
play in the arm's slot instead, 3 mm cost 0.8, 5 mm 1.8.
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: pairings no case of A-H used
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M411 = ("R16", "R16", "R16", "R16", "SLED", "FULL")  # 4-1-1
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3
M114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_I: list[Case] = [
    Case("hi_clean48", 18107, M312, M411, 48,
         notes="clean thorax, coarse 48-count BRS, R16-heavy estimation and validation"),
    Case("hi_clean96", 18211, M213, M123, 96,
         notes="clean thorax, 96-count BRS, FULL-heavy estimation and validation"),
    Case("hi_rib_lock", 18313, M114, M222, 128,
         (Effect("rib_lock", 0.065),), (("chest_stiffening", "all"),),
         notes="the chest locks up as it nears a limit deflection: the ribs straighten and the "
               "contents between sternum and spine cannot be squeezed further, so each rib's "
               "force gains k d^2 / (d_l - d) in compression (k the rib's own stiffness, "
               "d_l = 65 mm; nothing in extension; taken no further than 0.85 d_l): +18 % "
               "of the rib's force at 10 mm, +38 % at 18 mm, +86 % at 30 mm, every setup. "
               "Peak CD 17-20 mm with it, 23-30 mm without (A-H: a power 2.5 past 12 mm, a "
               "cubic from zero, a kink at 16 mm)"),
    Case("hi_rib_squeeze", 18419, M132, M321, 64,
         (Effect("rib_squeeze", 380.0),), (("chest_rate_damping", "all"),),
         notes="squeeze-film damping in the chest (set H's form, 1/gap^3 from a 60 mm gap): "
               "each rib's force gains c d' ((60 / (60 - d))^3 - 1), c = 380 N s/m (H: 250): "
               "+520 N s/m at 15 mm, +2660 at 30 mm (the rib's own 500-550 N s/m); every "
               "setup; peak CD 21-29 mm with it, 23-33 mm without"),
    Case("hi_webbing_set", 18523, M321, M312, 96,
         (Effect("webbing_set", 0.45),), (("belt_unloading", "all"),),
         notes="the chest-side webbing takes a permanent set: below its peak stretch it "
               "unloads along a line to 0.45 of that peak, every setup (C: 0.5, E: 0.65, F: "
               "0.4 on SLED, H: 0.35); loading untouched, peak CD as without it"),
    Case("hi_webbing_knee", 18627, M141, M213, 48,
         (Effect("webbing_knee", 9.0),), (("belt_stiffening", "all"),),
         notes="webbing stiffness grows by 9 x its own past a knee, 22 mm of stretch on the "
               "chest side and 16 mm up to the retractor, every setup (C: 3 and 1.2 on FULL, "
               "E: 7, G: 5 and 1.5 on FULL)"),
    Case("hi_airbag_relief", 18731, M123, M132, 128,
         (Effect("airbag_relief", 0.55, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="driver bag with a pressure-relief vent (shut below 40 kPa over ambient, fully "
               "open 10 kPa above, 25 /s of its gas then), fill 0.55 of set A's bag (B: 0.8, "
               "D: 0.5 on SLED, E: 0.3 on FULL), on both rigs with an interior; the R16 rig "
               "has none (1 R16 estimation test, 1 validation); peak CR 33-38 g with it, "
               "28-31 g without"),
    Case("hi_pelvis_submarine", 18839, M222, M114, 64,
         (Effect("pelvis_submarine", 6800.0),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine at set "
               "A's stiffness, the lap belt riding over the iliac wings: its hold saturates "
               "smoothly at 6.8 kN (6.8 kN tanh(F / 6.8 kN)), every setup (H: 5.5 kN all, 5 "
               "kN on SLED); peak CR 31-36 g with it, 28-33 g without"),
    Case("hi_two_effects", 18941, M231, M321, 96,
         (Effect("webbing_hysteresis", 0.35, ("R16",)), Effect("airbag_sealed", 0.3, ("SLED",))),
         (("belt_unloading", "R16"), ("airbag_contact", "SLED")),
         notes="R16: the certification rig's own webbing, its elastic force 35 % lower while "
               "it shortens than while it stretches (B: 0.45, D: 0.6 and 0.4 on SLED, F: 0.5, "
               "G: 0.7); SLED: the sled's interior with a driver bag "
               "without vents, fill 0.3 of set A's (C: 0.7 on FULL, E: 0.45, G: 0.4); FULL "
               "clean of both; 2 R16 and 3 SLED estimation tests, 3 R16 and 2 SLED validation "
               "ones. Each alone costs 2.6 (R16 webbing) and 2.4 (SLED bag), together 4.0"),
    Case("hi_broken_brs_poll", 18043, M411, M123, 96,
         (Effect("brs_poll", 1000.0, tests=("R16_005",)),), (), expect_broken=("R16_005",),
         notes="R16_005's spindle electronics poll the encoder's two tracks at 1 kHz, too "
               "slowly for a quadrature decoder, which sees only their phase (mod 4 counts): "
               "a poll's move of 1 is counted, of 2 dropped as invalid, of 3 counted as 1 "
               "back; the count held between polls. Through the load limiter's pay-out the "
               "spool turns up to 2 counts a poll (96 counts/rev): the channel ends at -16 "
               "counts where the spool is at -52, in 1 ms stairs; physics clean"),
    Case("hi_broken_cr_lost_block", 18151, M132, M114, 64,
         (Effect("cr_lost_block", 0.006, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="SLED_003's CR recorder overran its buffer at 30 ms and lost 6 ms of samples: "
               "the raw channel reads the spine's signal 6 ms early from 30 ms on (a jump of "
               "about 4 g in the loading, 9 g to 14 g within a millisecond after CFC 180) and "
               "its last 6 ms repeat the final sample; the other channels and the physics "
               "clean"),
    Case("hi_cd_backlash", 18257, M213, M231, 128,
         (Effect("cd_backlash", 5.0),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's arm has 5 mm of play in its worn slot: the pot moves only once "
               "the sternum has taken up the play, so CD reads 2.5 mm low while the chest "
               "compresses (the peak 2.5 mm low), holds at the peak's reading until the chest "
               "has come back 5 mm, then reads 2.5 mm high; zero at rest (A-H: a CD dead band "
               "reading low both ways, a CD knee, compression, over-reading; all static); CR "
               "and the inputs untouched: a residual in cd only, with memory, no offset"),
    Case("hi_pulse_late_3p6ms", 18361, M123, M141, 64,
         (Effect("pulse_late", 0.0036),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.6 ms after it is recorded (A-H: pulse 1.5, 2, "
               "2.25, 2.6, 2.75, 3 on FULL, 3.25, 3.5, 3.9, 4, 4.25 ms; BRS 1, 2.5, 3, 3.4, "
               "3.75, 4.1, 4.4, 4.5, 4.75, 5 ms)"),
    Case("hi_brs_late_2p8ms", 18463, M411, M312, 128,
         (Effect("brs_late", 0.0028),), (("input_delay", "all"),),
         notes="the chest feels the belt 2.8 ms after the BRS records it (no delay of A-H on "
               "either input)"),
]

BY_NAME_I = {c.name: c for c in SET_I}
