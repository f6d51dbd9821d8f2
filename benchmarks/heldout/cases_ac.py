"""Held-out set AC: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AB (``cases.py`` ... ``cases_ab.py``).

Set AB's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works: ``draw_ac.py`` (``numpy.random.default_rng(38000)``, set W's ``drawn``,
the pairings of A-AB taken, save the two-effect case's: with none free, it reuses one of
A-AB's, ``reuse_two``; ``python -m benchmarks.heldout.draw_ac`` prints the draw). The cases
follow the draw; only the sizes are set, by costs, by the rule ``draw_ac.py`` wrote down before
the first draw (``SIZING``). ``test_set_ac_follows_its_draw`` holds the draw and the cases
together.

The two-effect case's pairing, est 2/2/2, val 4/2/0, is set L's (``hl_brs_eccentric_0p35``):
the one pairing of this set an earlier set ran (``draw_ac.py``'s docstring: none was free for
its rigs).

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_hardening, FULL, 128, est 0/2/4, val 1/0/5; chest_rate_damping:
rib_maxwell, R16+SLED, 128, est 0/3/3, val 6/0/0; belt_unloading: webbing_set, SLED, 64, est
0/2/4, val 1/5/0; belt_stiffening: webbing_toe, R16, 48, est 3/0/3, val 4/2/0; airbag_contact:
airbag_fabric, FULL, 128, est 4/0/2, val 0/3/3; pelvis_coupling: lumbar_path, FULL, 48, est
0/2/4, val 3/0/3 (redrawn by 38002, below); input_gain: brs_eccentric, SLED, 96, est 2/4/0, val
0/4/2 (redrawn by 38001, below); the two-effect case chest_rate_damping (rib_friction) on
R16+FULL beside chest_stiffening (rib_lock) on SLED, 48, est 2/2/2, val 4/2/0 (an earlier
set's pairing, reused); the late pulse 3.87 ms, 64, est 3/3/0, val 0/0/6; the late BRS 3.77 ms,
48, est 2/0/4, val 4/2/0; the transducer error on CD, cd_clock, 96, est 6/0/0, val 4/1/1; the
broken test's channel the pulse, pulse_ms2, 96, est 4/2/0, val 6/0/0, the test R16_001;
clean48 est 6/0/0, val 1/5/0; clean96 est 0/0/6, val 4/2/0.

Redrawn (``draw_ac.REDRAWN``; each whole, by the next seed's generator, in the order found,
after the rest, the pairings of everything drawn before still taken): the input gain, whose
first draw, spool_buildup on SLED (64 counts, est 0/4/2, val 4/2/0), cost the grey-box 0.62
points at the rule's first size, 13 mm of radius per wrap (91.5 -> 90.9; CR 0.45, CD 0.79;
median 0.012, set X's one, taken), below the band; the rule's next, 39 mm (three times, the
clip), would leave the spool's 17 mm radius below zero within 7 rad of pay-out (zero past 15
mm per wrap): a run-away, impossible; drawn again by 38001: brs_eccentric on SLED, 96 counts,
est 2/4/0, val 0/4/2. Then the pelvis coupling, whose first draw, pelvis_submarine on R16 (64
counts, est 4/0/2, val 4/1/1), cost 8.83 at the rule's first size, 5900 N (92.9 -> 84.1; CR
5.17, CD 12.49; median 5800, taken), above the band; the rule takes a slip force as a form
whose effect shrinks as its size grows, so 5900 x 8.83 / 3.5 = 14900, 15000: 12.82 (CR 8.03,
CD 17.61); then 45000 (three times, the clip): 13.32 (CR 8.62, CD 18.02); then 135000: 13.40
(CR 8.68, CD 18.12): four sizes, none in band (the cost rose toward the pelvis path's at scale
1 as the lap belt held; set X's submarine on R16 found the same), impossible; drawn again by
38002: lumbar_path on FULL, 48 counts, est 0/2/4, val 3/0/3. Every other draw found a size in
band within the rule's four.

Sizes (the rule's; A-AB's values stepped off; the medians over every case of A-AB giving the
key; a median half-way rounded up): the hardening 1.3e8 N/m^3 (median 1.05e8, half-way up:
1.1e8, 1.2e8 taken), the Maxwell branch 0.49 (median 1.125, so 1.1, not taken, cost 7.79: CR
0.92, CD 14.66; then 1.1 x 3.5 / 7.79 = 0.494, 0.49, not taken), the set 0.61 (median 0.55:
0.55-0.60 taken), the toe 0.14 (median 0.25, taken, so 0.26, cost 7.20: CR 7.47, CD 6.92; then
0.26 x 3.5 / 7.20 = 0.126, 0.13, taken, so 0.14), the fabric bag 0.76 (median 0.74: 0.74, 0.75
taken), the lumbar path 0.34 (median 0.58, taken, so 0.59, cost 7.98: CR 4.80, CD 11.16; then
0.59 x 3.5 / 7.98 = 0.259, 0.26, cost 1.22: CR -0.02, CD 2.45; then log-linear between them
toward 3.5, 0.343, 0.34, not taken), the encoder ring 0.37 (median 0.30: 0.30-0.36 taken), the
CD module's clock 0.080 (no case of A-AB sized cd_clock: cr_clock's median, set V's 0.08); the
broken pulse in m/s^2 a switch (1 = on; not banded); the two-effect case's rib friction 420 N
(median 405, half-way up: 410, taken) beside the rib lock 0.091 m (median 0.09, taken), each
alone and the two together in band at the rule's first sizes.

What each case cost the grey-box (``costs._fit`` on ``make_sets.make``'s folders, the case
against its twin with every effect off, same seed; validation TOT fit without -> with, points,
and per output, CR and CD; one cost job at a time, 2 cores shared with other work): clean48
91.9, clean96 91.1; hardening_full 93.3 -> 89.2 (4.14; CR 1.80, CD 6.49); maxwell_r16_sled
93.6 -> 90.6 (3.00; CR 0.25, CD 5.75); set_sled 91.4 -> 86.0 (5.42; CR 6.15, CD 4.69); toe_r16
92.5 -> 86.8 (5.73; CR 5.91, CD 5.54); fabric_full 91.7 -> 89.0 (2.71; CR 3.84, CD 1.58);
lumbar_full 90.4 -> 87.9 (2.55; CR 0.71, CD 4.38); eccentric_sled 91.0 -> 87.4 (3.61; CR 4.07,
CD 3.14); two_friction_r16_full_lock_sled 93.4 -> 87.9 (5.43; CR 1.51, CD 9.35; the rib
friction alone 4.92: CR 2.10, CD 7.75; the rib lock alone 4.93: CR 0.15, CD 9.71);
pulse_late_3p87ms 90.0 -> 86.7 (3.30; CR 4.74, CD 1.85); brs_late_3p77ms 89.9 -> 86.6 (3.23;
CR 4.01, CD 2.45); cd_clock 91.9 -> 89.5 (2.41; CR 2.81, CD 2.00); broken_pulse_ms2 92.6 ->
-18.2 (110.74; CR 110.74, CD 110.74; flagging the test is the verdict asked; left in, it wrecks
the fit; not banded, by the rule). Each effect of the two-effect case alone: the case's seed
with the other effect's size 0 (kept in the case's list, so the dummies and pulses draw as they
do in the case), against the same twin.

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CD = "unexplained (or a sensor effect) on cd"

SET_AC: list[Case] = [
    Case("hac_clean48", 38103, _mix(6, 0, 0), _mix(1, 5, 0), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, SLED validated five times, "
               "never estimated; FULL neither estimated nor validated"),
    Case("hac_clean96", 38207, _mix(0, 0, 6), _mix(4, 2, 0), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone, validated on R16 and "
               "SLED, never estimated there"),
    Case("hac_hardening_full", 38309, _mix(0, 2, 4), _mix(1, 0, 5), 128,
         (Effect("rib_hardening", 1.3e8, ("FULL",)),), (("chest_stiffening", "FULL"),),
         notes="the ribs harden from zero, F += k3 d^3 at k3 1.3e8 N/m^3, on FULL alone; SLED "
               "clean, 2 estimation tests, never validated; R16 validated once, never "
               "estimated"),
    Case("hac_maxwell_r16_sled", 38411, _mix(0, 3, 3), _mix(6, 0, 0), 128,
         (Effect("rib_maxwell", 0.49, ("R16", "SLED")),), (("chest_rate_damping", "R16+SLED"),),
         notes="viscoelastic rib material, a Maxwell branch of 0.49 x the rib's stiffness "
               "relaxing in 10 ms, on R16 and SLED; R16 validated six times, never estimated; "
               "SLED estimated three times, never validated; FULL clean, 3 estimation tests, "
               "never validated"),
    Case("hac_set_sled", 38515, _mix(0, 2, 4), _mix(1, 5, 0), 64,
         (Effect("webbing_set", 0.61, ("SLED",)),), (("belt_unloading", "SLED"),),
         notes="the chest-side webbing unloads to a set of 0.61 x its peak stretch, on SLED "
               "alone; FULL clean, 4 estimation tests, never validated; R16 validated once, "
               "never estimated"),
    Case("hac_toe_r16", 38617, _mix(3, 0, 3), _mix(4, 2, 0), 48,
         (Effect("webbing_toe", 0.14, ("R16",)),), (("belt_stiffening", "R16"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.14, on "
               "R16 alone; FULL clean, 3 estimation tests, never validated; SLED validated "
               "twice, never estimated"),
    Case("hac_fabric_full", 38719, _mix(4, 0, 2), _mix(0, 3, 3), 128,
         (Effect("airbag_fabric", 0.76, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="the car's (FULL) driver bag has no vent holes and leaks through its fabric, "
               "fill 0.76, FULL alone; R16 without a bag, 4 estimation tests, never "
               "validated; SLED's bag not fired, validated three times, never estimated"),
    Case("hac_lumbar_full", 38823, _mix(0, 2, 4), _mix(3, 0, 3), 48,
         (Effect("lumbar_path", 0.34, ("FULL",)),), (("pelvis_coupling", "FULL"),),
         notes="the pelvis on lap belt and seat, its lumbar spine to the thoracic spine, at "
               "0.34 x set A's lumbar and lap stiffness, on FULL alone; SLED clean, 2 "
               "estimation tests, never validated; R16 validated three times, never estimated "
               "(redrawn)"),
    Case("hac_eccentric_sled", 38927, _mix(2, 4, 0), _mix(0, 4, 2), 96,
         (Effect("brs_eccentric", 0.37, ("SLED",)),), (("input_gain", "SLED"),),
         notes="the BRS encoder ring off-centre, the angle read th + 0.37 sin(th + phase), on "
               "SLED alone; R16 clean, 2 estimation tests, never validated; FULL validated "
               "twice, never estimated (redrawn)"),
    Case("hac_two_friction_r16_full_lock_sled", 38031, _mix(2, 2, 2), _mix(4, 2, 0), 48,
         (Effect("rib_friction", 420.0, ("R16", "FULL")),
          Effect("rib_lock", 0.091, ("SLED",))),
         (("chest_rate_damping", "R16+FULL"), ("chest_stiffening", "SLED")),
         notes="two kinds on two rigs: the rib cage's dry friction, 420 N per sternum mass "
               "against the chest's rate (R16 and FULL); the chest locking up near a 91 mm "
               "deflection, each rib's force gaining k d^2 / (d_l - d) (SLED); FULL never "
               "validated; the pairing set L's (reused, no pairing left)"),
    Case("hac_pulse_late_3p87ms", 38137, _mix(3, 3, 0), _mix(0, 0, 6), 64,
         (Effect("pulse_late", 0.00387),), (("input_delay", "all"),),
         notes="the chest feels the pulse 3.87 ms after its record; FULL validated six "
               "times, never estimated"),
    Case("hac_brs_late_3p77ms", 38241, _mix(2, 0, 4), _mix(4, 2, 0), 48,
         (Effect("brs_late", 0.00377),), (("input_delay", "all"),),
         notes="the chest feels the belt 3.77 ms after the BRS records it; SLED validated "
               "twice, never estimated"),
    Case("hac_cd_clock", 38343, _mix(6, 0, 0), _mix(4, 1, 1), 96,
         (Effect("cd_clock", 0.080),), (), expect_note=UNEXPLAINED_CD,
         notes="the chest pot's module runs on its own crystal, slow by 8.0 %: CD's time base "
               "stretched from the trigger, its events written early, every test; CR and the "
               "inputs untouched: a residual in cd only"),
    Case("hac_broken_pulse_ms2", 38447, _mix(4, 2, 0), _mix(6, 0, 0), 96,
         (Effect("pulse_ms2", 1.0, tests=("R16_001",)),), (), expect_broken=("R16_001",),
         notes="R16_001, an estimation test: its pulse file in m/s^2 under its header's g "
               "(the channel G times too large); its other channels and every other test "
               "clean"),
]

BY_NAME_AC = {c.name: c for c in SET_AC}
ONE_PHYSICAL_AC = ("hac_hardening_full", "hac_maxwell_r16_sled", "hac_set_sled", "hac_toe_r16",
                   "hac_fabric_full", "hac_lumbar_full", "hac_eccentric_sled")
