"""Held-out set AO: fourteen new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-AN (``cases.py`` ... ``cases_an.py``).

Set AN's process by another engineer, from the simulator and the thesis alone, without reading
how the loop works, with no change: ``draw_ao.py`` (``numpy.random.default_rng(50000)``, set
W's ``drawn``, the pairings of A-AN taken, save where a case has none free for its rigs: it
then reuses one of A-AN's, ``reuse_all``, set AL's rule; ``python -m
benchmarks.heldout.draw_ao`` prints the draw). The cases follow the draw; only the sizes are
set, by costs, by the rule ``draw_ao.py`` wrote down before the first draw (``SIZING``; set
AN's, set AM's, set AL's, set AK's, set AJ's, set AI's, set AH's, set AG's, set AF's, set
AE's, its rule 4 as mended there). ``test_set_ao_follows_its_draw`` holds the draw and the
cases together.

Ten cases run a pairing an earlier set ran (``draw_ao.py``'s docstring: none was free for their
rigs), each drawn uniformly among the pairings its rules allow that A-AN ran: the chest's
stiffening, est 0/2/4, val 1/4/1 (set AA's ``haa_fabric_sled``); the chest's rate damping, est
4/2/0, val 1/4/1 (set AA's ``haa_clean96``); the belt's unloading, est 3/0/3, val 1/2/3 (set
S's ``hs_webbing_power_full``); the belt's stiffening, est 0/3/3, val 1/1/4 (set V's
``hv_fung_r16_full``); the bag, est 2/0/4, val 1/3/2 (set T's ``ht_bumper_sled_full``); the
pelvis, est 4/0/2, val 0/2/4 (set Y's ``hy_sealed_sled_full``); the input gain, est 3/0/3, val
3/2/1 (set T's ``ht_maxwell_r16_sled``); the two-effect case, est 2/2/2, val 1/1/4 (set I's
``hi_pelvis_submarine``, set AM's ``ham_valve_r16_sled``); the late pulse, est 3/0/3, val 0/1/5
(set AA's ``haa_clean48``); the late BRS, est 4/2/0, val 2/1/3 (set T's ``ht_clean48``, set
AN's ``han_hysteresis_sled_full``). The other four cases drew free pairings. No two cases of AO
share a pairing.

The draw, as followed (kind: form, rigs, counts, est R16/SLED/FULL, val R16/SLED/FULL):
chest_stiffening: rib_bilinear, R16+SLED, 48, est 0/2/4, val 1/4/1 (reused);
chest_rate_damping: rib_friction, SLED+FULL, 96, est 4/2/0, val 1/4/1 (reused);
belt_unloading: webbing_hysteresis, FULL, 64, est 3/0/3, val 1/2/3 (reused); belt_stiffening:
webbing_toe, R16+FULL, 48, est 0/3/3, val 1/1/4 (reused); airbag_contact: airbag_fabric, FULL,
48, est 2/0/4, val 1/3/2 (reused); pelvis_coupling: pelvis_submarine, SLED+FULL, 96, est 4/0/2,
val 0/2/4 (reused); input_gain: spool_buildup, R16, 48, est 3/0/3, val 3/2/1 (reused); the
two-effect case chest_stiffening (rib_bilinear) on R16+SLED beside belt_stiffening
(webbing_power) on FULL, 96, est 2/2/2, val 1/1/4 (reused); the late pulse 2.21 ms, 128, est
3/0/3, val 0/1/5 (reused); the late BRS 1.23 ms, 64, est 4/2/0, val 2/1/3 (reused); the
transducer error on CR, cr_late, 48, est 0/6/0, val 0/4/2; the broken test's channel CR,
cr_hum, 64, est 0/0/6, val 0/3/3, the test FULL_007; clean48 est 6/0/0, val 3/0/3; clean96 est
0/0/6, val 1/0/5.

Redrawn: none at the draw (with a pairing always left to draw, no draw is impossible for want
of one; ``draw_ao.REDRAWN`` empty).

Sizes, at the rule's first sizes (A-AN's values stepped off; the medians over every case of
A-AN giving the key; a median half-way rounded up; not yet costed): the bilinear ribs 1.7
(median 1.4; 1.4-1.6 taken), the rib cage's friction 440 N (median 410; 410-430 taken), the
webbing's hysteresis 0.61 (median 0.515, half-way up: 0.52; 0.52-0.60 taken), the webbing's
toe 0.23 (median 0.225, half-way up: 0.23, not taken), the fabric bag 0.81 (median 0.765,
half-way up: 0.77; 0.77-0.80 taken), the slip force 6300 N (median 6050, half-way up: 6100;
6100-6200 taken), the spool's build-up 0.013 m per wrap (median 0.012, set X's one, taken), CR
written 5.1 ms late (median 5.0 ms, set Q's one, taken); the late pulse 2.21 ms and the late
BRS 1.23 ms as drawn; the broken test's CR hum 6.2 g (rule 5: by rule 1 only; median 6.05 g,
half-way up: 6.1; 6.1 taken); the two-effect case's bilinear ribs 1.7 (the key's first size,
as the single's, each case sized on its own) beside the webbing's power 1.9 (median 1.85,
half-way up: 1.9, not taken).

"Visible" means the effect costs the thesis grey-box at least 1.5 points of validation fit
against its effect-free twin (a delay at least 1 point); target band 1.5-6. Every form is an
earlier set's; no new form."""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

UNEXPLAINED_CR = "unexplained (or a sensor effect) on cr"

SET_AO: list[Case] = [
    Case("hao_clean48", 50103, _mix(6, 0, 0), _mix(3, 0, 3), 48,
         notes="clean thorax, 48-count BRS; estimated on R16 alone, validated there three "
               "times; FULL validated three times, never estimated; SLED neither estimated "
               "nor validated"),
    Case("hao_clean96", 50207, _mix(0, 0, 6), _mix(1, 0, 5), 96,
         notes="clean thorax, 96-count BRS; estimated on FULL alone, validated there five "
               "times; R16 validated once, never estimated; SLED neither estimated nor "
               "validated"),
    Case("hao_bilinear_r16_sled", 50309, _mix(0, 2, 4), _mix(1, 4, 1), 48,
         (Effect("rib_bilinear", 1.7, ("R16", "SLED")),), (("chest_stiffening", "R16+SLED"),),
         notes="the ribs' second load path past 16 mm, their stiffness growing by 1.7 x k_r "
               "beyond it, on R16 and SLED; R16 validated once, never estimated; SLED "
               "estimated twice, validated four times; FULL clean, 4 estimation tests, "
               "validated once; the pairing set AA's (reused, none free)"),
    Case("hao_friction_sled_full", 50411, _mix(4, 2, 0), _mix(1, 4, 1), 96,
         (Effect("rib_friction", 440.0, ("SLED", "FULL")),),
         (("chest_rate_damping", "SLED+FULL"),),
         notes="dry (Coulomb) friction in the rib cage, 440 N against the chest's rate, on "
               "SLED and FULL; SLED estimated twice, validated four times; FULL validated "
               "once, never estimated; R16 clean, 4 estimation tests, validated once; the "
               "pairing set AA's (reused, none free)"),
    Case("hao_hysteresis_full", 50515, _mix(3, 0, 3), _mix(1, 2, 3), 64,
         (Effect("webbing_hysteresis", 0.61, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the webbing's elastic force 61 % lower while it shortens (set B's form), on "
               "FULL alone; FULL estimated three times, validated three times; R16 clean, 3 "
               "estimation tests, validated once; SLED validated twice, never estimated; the "
               "pairing set S's (reused, none free)"),
    Case("hao_toe_r16_full", 50617, _mix(0, 3, 3), _mix(1, 1, 4), 48,
         (Effect("webbing_toe", 0.23, ("R16", "FULL")),), (("belt_stiffening", "R16+FULL"),),
         notes="the webbing stiffens exponentially with its stretch (toe), amount 0.23, on R16 "
               "and FULL; R16 validated once, never estimated; FULL estimated three times, "
               "validated four times; SLED clean, 3 estimation tests, validated once; the "
               "pairing set V's (reused, none free)"),
    Case("hao_fabric_full", 50719, _mix(2, 0, 4), _mix(1, 3, 2), 48,
         (Effect("airbag_fabric", 0.81, ("FULL",)),), (("airbag_contact", "FULL"),),
         notes="a ventless bag leaking through its fabric at fill 0.81, on FULL alone; FULL "
               "estimated four times, validated twice; R16 without a bag, 2 estimation tests, "
               "validated once; SLED clean, validated three times, never estimated; the "
               "pairing set T's (reused, none free)"),
    Case("hao_submarine_sled_full", 50823, _mix(4, 0, 2), _mix(0, 2, 4), 96,
         (Effect("pelvis_submarine", 6300.0, ("SLED", "FULL")),),
         (("pelvis_coupling", "SLED+FULL"),),
         notes="the pelvis on lap belt and seat (set A's lumbar and lap stiffness), the lap "
               "belt slipping over the iliac wings past 6300 N (submarining), on SLED and "
               "FULL; SLED validated twice, never estimated; FULL estimated twice, validated "
               "four times; R16 clean, 4 estimation tests, never validated; the pairing set "
               "Y's (reused, none free)"),
    Case("hao_spool_r16", 50927, _mix(3, 0, 3), _mix(3, 2, 1), 48,
         (Effect("spool_buildup", 0.013, ("R16",)),), (("input_gain", "R16"),),
         notes="the spool's effective radius, 17 mm at rest, changing by 13 mm per wrap of "
               "webbing wound (smaller as it pays out): the webbing paid out per radian the "
               "BRS counts is not r0, on R16 alone; R16 estimated three times, validated "
               "three times; FULL clean, 3 estimation tests, validated once; SLED validated "
               "twice, never estimated; the pairing set T's (reused, none free)"),
    Case("hao_two_bilinear_r16_sled_power_full", 50031, _mix(2, 2, 2), _mix(1, 1, 4), 96,
         (Effect("rib_bilinear", 1.7, ("R16", "SLED")),
          Effect("webbing_power", 1.9, ("FULL",))),
         (("chest_stiffening", "R16+SLED"), ("belt_stiffening", "FULL")),
         notes="two kinds on two rigs: the ribs' second load path past 16 mm, their stiffness "
               "growing by 1.7 x k_r beyond it (R16 and SLED); the webbing stiffening with "
               "its stretch, F += a k e (e/e_ref)^2, a = 1.9 (FULL); each rig estimated "
               "twice, R16 and SLED validated once each, FULL four times; the pairing set I's "
               "(reused, none free)"),
    Case("hao_pulse_late_2p21ms", 50137, _mix(3, 0, 3), _mix(0, 1, 5), 128,
         (Effect("pulse_late", 0.00221),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2.21 ms after its record; R16 and FULL each "
               "estimated three times, FULL validated five times, SLED once, R16 never; the "
               "pairing set AA's (reused, none free)"),
    Case("hao_brs_late_1p23ms", 50241, _mix(4, 2, 0), _mix(2, 1, 3), 64,
         (Effect("brs_late", 0.00123),), (("input_delay", "all"),),
         notes="the chest feels the belt 1.23 ms after the BRS records it; R16 estimated four "
               "times, validated twice; SLED estimated twice, validated once; FULL validated "
               "three times, never estimated; the pairing set T's (reused, none free)"),
    Case("hao_cr_late", 50343, _mix(0, 6, 0), _mix(0, 4, 2), 48,
         (Effect("cr_late", 0.0051),), (), expect_note=UNEXPLAINED_CR,
         notes="the CR channel's digitiser module writes its samples 5.1 ms late (a pipeline "
               "delay left in its time stamps, set Q's form), every test: CR late, its values "
               "right; CD and the inputs on time: a residual in cr only, no input late"),
    Case("hao_broken_cr_hum", 50447, _mix(0, 0, 6), _mix(0, 3, 3), 64,
         (Effect("cr_hum", 6.2, tests=("FULL_007",)),), (), expect_broken=("FULL_007",),
         notes="FULL_007, an estimation test: its spine accelerometer picks up 50 Hz mains hum "
               "through a ground loop, 6.2 g amplitude, from before the crash to the end (CFC "
               "180 passes it): a sine on the flat pre-crash line; its other channels and "
               "every other test clean"),
]

BY_NAME_AO = {c.name: c for c in SET_AO}
ONE_PHYSICAL_AO = ("hao_bilinear_r16_sled", "hao_friction_sled_full", "hao_hysteresis_full",
                   "hao_toe_r16_full", "hao_fabric_full", "hao_submarine_sled_full",
                   "hao_spool_r16")
