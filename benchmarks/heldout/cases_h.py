"""Held-out set H: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-G (``cases.py`` ... ``cases_g.py``), which the loop's engineers
have looked at.

Against sets A-G: other seeds (17xxx), other sizes of each effect, and (estimation,
validation) pairings of (R16, SLED, FULL) counts no case of A-G ran. Every effect that acts on
some setups only rests on at least 2 estimation and 2 validation tests of those setups, beside
at least one test of a setup it does not act on. Three of the six physical classes come in a
form no earlier set used, written from the physics (``physics.EFFECTS``): damping in the chest
that grows as the gap between sternum and spine box closes (a squeeze film, linear in the rate:
A-G's rate damping was a power of the rate), a driver bag without vent holes leaking through
its uncoated fabric (Darcy: flow ~ pressure; A-G: an orifice ~ sqrt(pressure), a relief vent,
sealed), and a pelvis submarining under its lap belt (the belt's hold saturating as it slides
over the iliac wings; A-G: a linear pelvis path). The other three use forms of A-G at sizes none
used. The broken tests fail ways a lab records and a reviewer sees on the plot (a data line of
the CD digitiser stuck at 1: a pre-crash line flickering by 6.25 mm and bands of the crash
reading low; a BRS decoder left in x4 mode: one test's belt turning four times as far), and the
transducer error is another (a piezoelectric CR accelerometer on a short time constant: a
high-pass, a dynamic error on CR, CD untouched). The issue's list makes 13 cases; the 14th is
the second broken test.

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin (a delay at
least 1 point).

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set h``, the plain
thesis structure through the project's identify/evaluate, validation TOT fit with the effects
-> without, points; 2026-11-25, 2 busy cores): clean48 92.3, clean96 90.6; rib_bottoming
88.2 -> 92.7, rib_squeeze 91.2 -> 93.7, webbing_set 89.1 -> 91.0, webbing_toe 88.2 -> 90.5,
airbag_fabric 85.9 -> 90.7, pelvis_submarine 85.0 -> 90.0, two_effects 84.9 -> 90.1 (each
alone: the SLED pelvis 3.6, the FULL bag 3.7), broken_cd_stuck_bit 90.3 -> 91.2 (flagging the
test is the verdict asked; one estimation test's CD off by a bit moves the fit little) and
broken_brs_quadrature 79.6 -> 87.0 (left in, it wrecks the fit), cr_ac_coupled 91.0 -> 94.3,
pulse_late_2p6ms 90.1 -> 92.8, brs_late_4p1ms 87.8 -> 90.9.

Changed after a first look at these costs, before the verdicts' commit and any loop run:
rib_squeeze 60 N s/m cost 0.3, 500 cost 5.4; airbag_fabric on seed 17737 (same mixes) cost
-2.0, -1.5 and -0.6 at fill 0.6, 1.0 and 1.5 (its effect-free twin fit worse than the bag case;
a sealed bag of fill 1.0 on those tests cost 4.4), so seed 17741, where fill 1.0 cost 6.0;
pelvis_submarine slipping at 2.5, 4, 5 and 6 kN cost 9.1, 7.1, 5.5 and 4.3 (the pelvis path of
scale 1 without slipping, lumbar_path 1.0: 1.7); two_effects was the lap belt slipping at 2 kN
on SLED with a vented bag of fill 0.8 on FULL, cost 20.1, then 4 kN with 0.8, cost 9.4 (alone
4.6 and 7.7); cr_ac_coupled at 0.1 s cost 22.0, 0.5 s 4.3, 1 s 1.5; webbing_set 0.25 cost 1.6.
The belt_stiffening case was to be a fourth new form, a retractor's film-spool effect (the
wound webbing packing in under tension, feeding out up to 3-14 mm the BRS does not count, the
webbing up to the retractor soft until packed by 4 or 16 mm of its stretch): it cost -0.3 to
-0.2 at every size tried, most likely because the pretensioner (2.3 kN from 7 ms) packs the
wrap before the chest loads; not kept. In its place an exponential webbing toe of 3.5 (1.5 cost
1.2).
"""

from __future__ import annotations

from .cases import Case, Effect

# (R16, SLED, FULL) counts, estimation / validation: pairings no case of A-G used
M222 = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")  # 2-2-2
M231 = ("R16", "R16", "SLED", "SLED", "SLED", "FULL")  # 2-3-1
M141 = ("R16", "SLED", "SLED", "SLED", "SLED", "FULL")  # 1-4-1
M312 = ("R16", "R16", "R16", "SLED", "FULL", "FULL")  # 3-1-2
M321 = ("R16", "R16", "R16", "SLED", "SLED", "FULL")  # 3-2-1
M114 = ("R16", "SLED", "FULL", "FULL", "FULL", "FULL")  # 1-1-4
M213 = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")  # 2-1-3
M411 = ("R16", "R16", "R16", "R16", "SLED", "FULL")  # 4-1-1
M132 = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")  # 1-3-2
M123 = ("R16", "SLED", "SLED", "FULL", "FULL", "FULL")  # 1-2-3

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_H: list[Case] = [
    Case("hh_clean48", 17109, M222, M231, 48,
         notes="clean thorax, coarse 48-count BRS, even estimation, SLED-heavy validation"),
    Case("hh_clean96", 17213, M141, M312, 96,
         notes="clean thorax, 96-count BRS, SLED-heavy estimation, R16-heavy validation"),
    Case("hh_rib_bottoming", 17317, M321, M222, 64,
         (Effect("rib_bottoming", 1.2e8),), (("chest_stiffening", "all"),),
         notes="ribs stiffen past 12 mm deflection, F += k (|d| - 12 mm)^2.5 on each rib, "
               "k = 1.2e8 N/m^2.5 on every setup (A: 9e7, F: 7e7, D: 6e7 on FULL; B, D, E, G: "
               "cubic from zero; C, E: a kink at 16 mm)"),
    Case("hh_rib_squeeze", 17421, M114, M213, 96,
         (Effect("rib_squeeze", 250.0),), (("chest_rate_damping", "all"),),
         notes="squeeze-film damping in the chest: the contents between sternum and spine box "
               "(60 mm apart at rest) are squeezed out through a closing gap, their damping "
               "growing as 1/gap^3 (Reynolds): each rib's force gains c d' ((60 / (60 - d))^3 "
               "- 1), d in mm, c = 250 N s/m (the rib's own damping 550 N s/m): +340 N s/m at "
               "15 mm, +1750 at 30 mm (peak CD 25-32 mm here), nothing at rest or in "
               "extension, taken no further than 48 mm; every setup. Linear in the rate, "
               "growing with deflection (A-G: powers of the rate, |d'|^2.2, |d'|^1.5, "
               "one-way d'^2)"),
    Case("hh_webbing_set", 17527, M213, M411, 128,
         (Effect("webbing_set", 0.35),), (("belt_unloading", "all"),),
         notes="the chest-side webbing takes a permanent set: below its peak stretch it "
               "unloads along a line to 0.35 of that peak, on every setup (C: 0.5, E: 0.65, "
               "F: 0.4 on SLED; A: slack; B, D, F, G: a softer unloading path)"),
    Case("hh_webbing_toe", 17631, M411, M132, 96,
         (Effect("webbing_toe", 3.5),), (("belt_stiffening", "all"),),
         notes="webbing stiffening exponentially with stretch, F += 3.5 k e0 (exp(e/e0) - 1 "
               "- e/e0), e0 = 6 mm chest side and 10 mm up to the retractor (capped at 6 e0), "
               "every setup (A: 2.5; B, D, F: cubic; C, E, G: a knee)"),
    Case("hh_airbag_fabric", 17741, M312, M141, 64,
         (Effect("airbag_fabric", 0.7, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="driver bag without vent holes, of uncoated fabric: the gas seeps through the "
               "fabric by Darcy's law, flow proportional to the over-pressure and to the "
               "fabric the occupant leaves free (0.77 m^2 less the contact, up to 0.06 m^2), "
               "15 /s of its gas at one atmosphere over ambient (A, F: an orifice, ~ "
               "sqrt(pressure); B, D, E: a relief vent; C, E, G: sealed); fill 0.7 of set A's "
               "bag, on both rigs with an interior; the R16 rig has none (3 R16 estimation "
               "tests, 1 validation)"),
    Case("hh_pelvis_submarine", 17843, M231, M312, 48,
         (Effect("pelvis_submarine", 5500.0),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine at set "
               "A's stiffness (1.0), and the pelvis submarines: the lap belt rides over the "
               "iliac wings, the force it holds the pelvis with saturating smoothly at 5.5 kN "
               "(5.5 kN tanh(F / 5.5 kN)), the pelvis sliding on under it; every setup. "
               "Without slipping the lap belt peaked at 6.3-8.2 kN in these tests (A-G: the "
               "linear path at 0.45-1.5 x set A's stiffness)"),
    Case("hh_two_effects", 17947, M132, M123, 96,
         (Effect("pelvis_submarine", 5000.0, ("SLED",)), Effect("airbag", 0.4, ("FULL",))),
         (("pelvis_coupling", "SLED"), ("airbag_contact", "FULL")),
         notes="SLED: the sled rig's flat seat pan has no anti-submarining ramp: the pelvis "
               "path of set A's stiffness with the lap belt slipping at 5 kN; FULL: the "
               "production car's vented driver bag, fill 0.4 of set A's (A: 1.0, F: 0.6); 3 "
               "SLED and 2 FULL estimation tests, 2 SLED and 3 FULL validation ones, the R16 "
               "tests clean of both. Each alone costs 3.6 (SLED) and 3.7 (FULL), together 5.2"),
    Case("hh_broken_cd_stuck_bit", 17053, M123, M213, 96,
         (Effect("cd_stuck_bit", 11.0, tests=("FULL_003",)),), (),
         expect_broken=("FULL_003",),
         notes="FULL_003's CD digitiser has a data line stuck at 1: bit 11 of its 16 over "
               "+-100 mm, worth 6.25 mm. The raw channel (J211 sign) reads 6.25 mm high "
               "wherever that bit should be 0: at rest CD flickers between 0 and -6.25 mm with "
               "the noise, and through the crash every other 6.25 mm band of compression "
               "reads 6.25 mm low (CFC 600 after); the other channels and the physics clean"),
    Case("hh_broken_brs_quadrature", 17159, M312, M321, 64,
         (Effect("brs_quadrature", 4.0, tests=("R16_003",)),), (),
         expect_broken=("R16_003",),
         notes="R16_003's BRS decoder was left in x4 (quadrature) mode, counting every edge "
               "of both tracks, while the test's header keeps the spindle's 64 counts/rev: "
               "its belt reads four times the spool's angle, the pretensioner's pay-in and the "
               "load limiter's pay-out four times those of the other R16 tests, in steps a "
               "quarter as large; physics clean"),
    Case("hh_cr_ac_coupled", 17267, M411, M213, 128,
         (Effect("cr_ac_coupled", 0.6),), (), expect_note=UNEXPLAINED_CR,
         notes="the spine accelerometer is piezoelectric, its charge amplifier set to a short "
               "time constant: CR reads through a first-order high-pass, s tau / (1 + s tau), "
               "tau = 0.6 s, so it reads low by about 1/tau of the velocity change so far "
               "(2-3 g by the end of the loading) and below zero after it, zero at rest (A-G: "
               "CR gain, soft clip, progressive; all static); CD and the inputs untouched: a "
               "residual in cr only, a linear dynamic error, no offset"),
    Case("hh_pulse_late_2p6ms", 17373, M114, M141, 96,
         (Effect("pulse_late", 0.0026),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.6 ms after it is recorded (A-G: pulse 1.5, 2, "
               "2.25, 2.75, 3 on FULL, 3.25, 3.5, 3.9, 4, 4.25 ms; BRS 1, 2.5, 3, 3.4, 3.75, "
               "4.4, 4.5, 4.75, 5 ms)"),
    Case("hh_brs_late_4p1ms", 17479, M231, M132, 48,
         (Effect("brs_late", 0.0041),), (("input_delay", "all"),),
         notes="the chest feels the belt 4.1 ms after the BRS records it (no delay of A-G on "
               "either input)"),
]

BY_NAME_H = {c.name: c for c in SET_H}
