"""Held-out set P: eight new cases the loop has never seen, committed with their expected
verdicts before the loop ever runs on them. Never tune the loop on them; report them apart from
the tuned cases and from sets A-N (``cases.py`` ... ``cases_n.py``), which the loop's engineers
have looked at.

What set P judges is how the belt gives back what it took when the chest unloads (the belt's
unloading path): four cases of a belt that unloads below its loading path, of three physical
kinds, at sizes and on scopes no earlier set used; two clean cases; and two cases of another
effect each whose residual also differs between loading and unloading (ribs damped through a
valve while compressing only; webbing stiffening past a knee), where a belt unloading must not
be named. Every rig that holds estimation tests holds at least two of them.

Against sets A-N: other seeds (25xxx), other sizes of each effect, (estimation, validation)
pairings of (R16, SLED, FULL) counts no case of A-N ran, eight cases. The belt-unloading
forms are A-N's, at new sizes and scopes (named ``belt_unloading`` as earlier sets name them):
the webbing's permanent set (``webbing_set``, C's form: below its peak stretch the chest-side
webbing unloads on a straight line to a set of this share of its peak) at 0.64 on every rig
(A-N: 0.25-0.65 on all, 0.4 and 0.55 on one rig, 0.48 on R16+SLED; none 0.64) and at 0.75 on
the car's own belt only (FULL; A-N: none above 0.65, none on FULL alone); the webbing's
hysteresis (``webbing_hysteresis``, B's form: the elastic force lower by this share while a
segment shortens) at 0.52 on the sled labs' webbing stock only (R16+SLED; A-N: 0.15-0.7, none
0.52, on R16+SLED only at 0.2 beside rib hardening); and the car's D-ring as a capstan
(``dring_capstan``, M's form, mu theta) at 0.62 on FULL only (M: 0.5 on FULL). The two
other effects: the ribs damped through a valve, F += c d'^2 while compressing only
(``rib_valve``, chest_rate_damping) at 2800 on every rig (A-N: 1200-4000, none 2800): a force
that is there on the loading and gone on the unloading, as a belt's unloading loss is, but in
the ribs; and the webbing stiffening past a knee (``webbing_knee``, belt_stiffening) at 4.5 on
every rig (A-N: 0.5-9, none 4.5). No new form.

Sizes are in each key's units (``physics.EFFECTS``); "visible" means the effect costs the
thesis grey-box roughly 1.5-6 points of validation fit against its effect-free twin.

What each case cost the grey-box (``python -m benchmarks.heldout.costs --set p``, the plain
thesis structure through the project's CLI identify/evaluate, validation TOT fit with the
effects -> without, points; 2026-11-26, 2 busy cores at a load of 4-6, two cost jobs at a time,
the committed seeds and mixes): clean48 88.5, clean128 90.6; webbing_set_all 85.5 -> 87.6
(2.1), hysteresis_labs 87.8 -> 92.2 (4.5), capstan_full 85.3 -> 90.6 (5.3), webbing_set_full
89.5 -> 93.9 (4.4), rib_valve_all 87.0 -> 90.1 (3.2), webbing_knee_all 89.3 -> 91.8 (2.5).

Changed after a first look at these costs, before the verdicts' commit and any loop run (same
seeds and mixes): webbing_set_all was 0.58, cost 1.8 (at the bar's edge), so 0.64;
hysteresis_labs was 0.62, cost 6.1 (above the bar), so 0.52. The capstan at 0.62 on FULL costs
5.3 where M's 0.5 on FULL cost 1.7 (other mixes; steep in mu theta), kept. capstan_full,
webbing_set_full, rib_valve_all, webbing_knee_all and both clean cases are as first written.
"""

from __future__ import annotations

from .cases import Case, Effect
from .cases import mix as _mix

SET_P: list[Case] = [
    Case("hp_clean48", 25107, _mix(2, 4, 0), _mix(3, 2, 1), 48,
         notes="clean thorax, 48-count BRS; FULL validated once, never estimated"),
    Case("hp_clean128", 25211, _mix(0, 3, 3), _mix(1, 2, 3), 128,
         notes="clean thorax, 128-count BRS; R16 validated once, never estimated"),
    Case("hp_webbing_set_all", 25317, _mix(2, 2, 2), _mix(0, 4, 2), 96,
         (Effect("webbing_set", 0.64),), (("belt_unloading", "all"),),
         notes="the webbing's permanent set: below its peak stretch the chest-side webbing "
               "unloads on a line to a set of 0.64 x its peak (A-N: 0.25-0.65, none 0.64), "
               "every rig"),
    Case("hp_hysteresis_labs", 25419, _mix(4, 2, 0), _mix(2, 3, 1), 64,
         (Effect("webbing_hysteresis", 0.52, ("R16", "SLED")),),
         (("belt_unloading", "R16+SLED"),),
         notes="the sled labs' webbing stock (R16 and SLED): its elastic force 0.52 lower "
               "(relative) while it shortens (A-N: 0.15-0.7, none 0.52); the car's own belt "
               "(FULL) clean, not estimated, validated once"),
    Case("hp_capstan_full", 25523, _mix(2, 0, 4), _mix(1, 1, 4), 48,
         (Effect("dring_capstan", 0.62, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the car's own D-ring (FULL): the shoulder webbing wraps it as a capstan, mu "
               "theta = 0.62 (M: 0.5), the chest side carrying the retractor side's tension x "
               "exp(+0.62) drawn out, x exp(-0.62) taken back; R16 and SLED clean"),
    Case("hp_webbing_set_full", 25629, _mix(3, 0, 3), _mix(1, 1, 4), 96,
         (Effect("webbing_set", 0.75, ("FULL",)),), (("belt_unloading", "FULL"),),
         notes="the car's own belt (FULL) takes a permanent set of 0.75 x its peak stretch "
               "(A-N: none above 0.65, none on FULL alone); the sled labs' webbing (R16, SLED) "
               "clean"),
    Case("hp_rib_valve_all", 25731, _mix(3, 0, 3), _mix(2, 1, 3), 128,
         (Effect("rib_valve", 2800.0),), (("chest_rate_damping", "all"),),
         notes="the ribs damp through a valve, F += c d'^2 while compressing only, c = 2800 "
               "(A-N: 1200-4000, none 2800), every rig: a loading/unloading asymmetry in the "
               "ribs, not the belt; a belt unloading must not be named"),
    Case("hp_webbing_knee_all", 25837, _mix(2, 2, 2), _mix(2, 0, 4), 64,
         (Effect("webbing_knee", 4.5),), (("belt_stiffening", "all"),),
         notes="the webbing stiffens past a knee by 4.5 x (A-N: 0.5-9, none 4.5), every rig: "
               "its loading and unloading on one path; a belt unloading must not be named"),
]

BY_NAME_P = {c.name: c for c in SET_P}
