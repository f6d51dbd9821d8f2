"""Set W's designer's choices, drawn rather than picked: ``numpy.random.default_rng(32000)``
draws, in this order, for each physical kind of the library (one case each) the simulator's
form that realises it (any set's ``physics.EFFECTS`` key mapped to that kind; ``input_gain``
only among the BRS's forms, not the pulse accelerometer's), the rigs it acts on (all three,
two or one, uniformly among the scopes allowed; never a bag on R16), its BRS counts and its
(estimation, validation) mix; then the two-effect case's two kinds, forms and disjoint rigs;
the late pulse's and the late BRS's delays (1-5 ms, to 0.01 ms); which output carries the
transducer error, its counts, its mix and its form (among every lab-side transducer form the
simulator has on that output, ``TRANSDUCER``, set W's new ``cd_clock`` among them); which
channel the broken test breaks, its counts, its mix, which estimation test it is and its form
(among every lab-side broken-channel form the simulator has on that channel, ``BROKEN``); and
the mixes of the clean cases; then, each by the next seed's generator, a case again where its
first draw proved impossible (``REDRAWN``). The sizes are not drawn: they are set by costs
(see ``cases_w.py``).

Set V's process (``draw_v.py``) with a new seed family (32xxx), the pairings of sets A-V taken,
and two draws V left to its designer drawn as well: the transducer error's form and the broken
test's form. A mix is drawn uniformly among the (estimation, validation) pairings of rig counts
that no case of sets A-V (nor an earlier draw of W) ran and that the scope rules allow: every
rig the estimation part holds is held twice or more; an effect's rigs all appear in its case;
an effect on some rigs only acts on two or more estimation and two or more validation tests of
them, beside an estimation test of a rig it spares; in the two-effect case every rig of either
effect is estimated twice or more.

    python -m benchmarks.heldout.draw_w [--seed 32000]
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

from . import physics as ph
from .cases import ALL
from .draw_v import BRS_GAIN, EST_MIXES, KINDS, VAL_MIXES, _ok, forms, scopes
from .sets import before, case_set

SEED = 32000
# a case whose draw proved impossible, drawn again, whole, by the next seed's generator (one per
# redraw, in this order, after the rest), the pairings of everything drawn before still taken:
# the two-effect case's first draw, airbag_contact on FULL beside chest_stiffening on R16+SLED
# (airbag_sealed, rib_bumper; 128 counts), had no pairing left (sets A-V ran all twelve the
# rules allow for those rigs); belt_unloading's first draw, webbing_slack (a switch, no size to
# set) on all three rigs, cost the grey-box 8.0 points, above the band; the two-effect case's
# second draw, webbing_slack on SLED beside lumbar_path on FULL, cost 13.8 together and the
# slack alone 10.8 on SLED (CR 11.9, CD 9.7), above the band with nothing to size; its third
# and fourth draws (by 32003: spool_buildup on R16 beside rib_loss on FULL; by 32004:
# webbing_hysteresis on SLED+FULL beside spool_buildup on R16) had no pairing left. Each
# rejected draw is kept in ``draw()["rejected"]`` with the seed that drew it again; the late
# BRS's first draw, 1.48 ms, cost the grey-box 0.0 points (a delay is its own size: nothing to
# set), below the delay's 1 point, and the late pulse's, 1.10 ms, 0.99 (CR 0.97, CD 1.01)
REDRAWN: tuple[tuple[str, int], ...] = (("two", 32001), ("belt_unloading", 32002),
                                         ("two", 32003), ("two", 32004), ("two", 32005),
                                         ("brs_late", 32006), ("pulse_late", 32007))
EARLIER = before("w")
# the lab-side forms the simulator has (``physics.EFFECTS``, named nothing physical), by what
# they are and the channel they act on: a transducer error on every test of one output, or a
# broken channel on one test. Not in the pools: ``zero_offset`` (a named kind, sensor_offset),
# ``neck_head`` (physics outside the library), ``dummy_scale`` and ``dummy_soak`` (a broken
# test, but of the dummy, not of a channel)
TRANSDUCER = {
    "cr": ("cr_ac_coupled", "cr_clock", "cr_creep", "cr_crosstalk", "cr_damped", "cr_drift",
           "cr_gain", "cr_late", "cr_progressive", "cr_soft_clip", "cr_zero_shift"),
    "cd": ("cd_aa_filter", "cd_arm_lift", "cd_arm_ring", "cd_backlash", "cd_clock",
           "cd_compress", "cd_dead_band", "cd_knee", "cd_pot_loading", "cd_pot_nonlinear",
           "cd_rc_filter", "cd_sag", "cd_slew"),
}
BROKEN = {
    "pulse": ("pulse_cable_break", "pulse_from", "pulse_ms2", "pulse_rail", "pulse_rate",
              "pulse_sync", "pulse_zero_shift"),
    "brs": ("brs_counts", "brs_freeze", "brs_poll", "brs_quadrature", "brs_reset",
            "brs_reversed", "brs_swap", "brs_wrap"),
    "cr": ("cr_cable_break", "cr_hum", "cr_lost_block", "cr_loose_mount", "cr_rail",
           "cr_reversed"),
    "cd": ("cd_dropout", "cd_rail", "cd_reversed", "cd_spikes", "cd_stuck_bit"),
}
__all__ = ["BROKEN", "BRS_GAIN", "KINDS", "REDRAWN", "SEED", "TRANSDUCER", "draw", "drawn", "forms",
           "scopes", "show"]


def draw(seed: int = SEED) -> dict:
    """Set W's choices: :func:`drawn` by ``seed``, after sets A-V, its redraws at its own seed."""
    return drawn(seed, EARLIER, REDRAWN if seed == SEED else ())


def drawn(seed: int, earlier: tuple[str, ...], redrawn: tuple[tuple[str, int], ...] = (),
          reuse_two: bool = False, reuse_all: bool = False) -> dict:
    """A set's choices drawn by ``default_rng(seed)`` in the order the module docstring gives,
    the (estimation, validation) pairings of the sets ``earlier`` (their names) taken; then
    each case of ``redrawn`` drawn again, whole, by its seed's generator, in that order (set
    W's and set X's ``draw``: each its own seed, earlier sets and redraws).

    ``reuse_two`` (set Z's rule; off for sets W-Y, whose draws it leaves as they were): when
    no pairing is free for the two-effect case, its pairing is drawn by the same generator,
    uniformly, among the pairings the ``earlier`` sets ran that its rules allow (every rig of
    either effect estimated twice or more, and the rest), instead of none; the case then
    carries ``"reused": True`` (``False`` when a free one was drawn).

    ``reuse_all`` (set AL's rule; off for sets W-AK, whose draws it leaves as they were): set
    Z's rule extended to every case, the one-effect cases, the delays, the transducer error,
    the broken test and the clean cases as well as the two-effect case: when no pairing is free
    for a case's rigs, its pairing is drawn by the same generator, uniformly, among the pairings
    the ``earlier`` sets ran that its rules allow (the pool is theirs alone, as set Z's, not
    narrowed by this draw's own picks); every case then carries ``"reused"``."""
    if isinstance(earlier, str):  # "abc...zaa" would read set AA as set A twice
        raise TypeError("earlier: the sets' names (sets.before), not a string of letters")
    rng = np.random.default_rng(seed)
    used = {(tuple(c.est.count(r) for r in ALL), tuple(c.val.count(r) for r in ALL))
            for s in earlier for c in case_set(s)}
    ran = frozenset(used)  # the earlier sets' pairings alone
    used_delays = {e.size for s in earlier for c in case_set(s) for e in c.effects
                   if ph.EFFECTS[e.key] == "input_delay"}

    def mix(effects: list[tuple[str, ...]], each: bool = False, reuse: bool = False
            ) -> tuple[tuple[int, ...], tuple[int, ...]] | None:
        free = [(e, v) for e in EST_MIXES for v in VAL_MIXES
                if (e, v) not in used and _ok(e, v, effects, each)]
        if not free and reuse:  # none free: among those the earlier sets ran (reuse_two, _all)
            free = [(e, v) for e in EST_MIXES for v in VAL_MIXES
                    if (e, v) in ran and _ok(e, v, effects, each)]
        if not free:  # every pairing the rules allow already run: impossible as drawn
            return None
        pick = free[int(rng.integers(len(free)))]
        used.add(pick)
        return pick

    def counts() -> int:
        return int(rng.choice([48, 64, 96, 128]))

    def single(kind: str) -> dict:
        f = forms(kind)
        form = f[int(rng.integers(len(f)))]
        sc = scopes(kind)
        scope = sc[int(rng.integers(len(sc)))]
        n = counts()
        est, val = mix([scope], reuse=reuse_all) or (None, None)
        return {"form": form, "rigs": scope, "counts": n, "est": est, "val": val,
                **reused(est, val)}

    def reused(est: tuple[int, ...] | None, val: tuple[int, ...] | None) -> dict:
        return {"reused": (est, val) in ran} if reuse_all else {}

    def pair() -> dict:  # the two-effect case: two kinds, their forms, disjoint rigs
        while True:  # (no bag on R16)
            ka, kb = (KINDS[i] for i in rng.choice(len(KINDS), 2, replace=False))
            sa = scopes(ka)[int(rng.integers(len(scopes(ka))))]
            sb = scopes(kb)[int(rng.integers(len(scopes(kb))))]
            if not set(sa) & set(sb):
                break
        fa, fb = forms(ka), forms(kb)
        two = {"kinds": (ka, kb), "forms": (fa[int(rng.integers(len(fa)))],
                                             fb[int(rng.integers(len(fb)))]),
               "rigs": (sa, sb), "counts": counts()}
        two["est"], two["val"] = mix([sa, sb], each=True, reuse=reuse_two or reuse_all
                                     ) or (None, None)
        if reuse_two or reuse_all:
            two["reused"] = (two["est"], two["val"]) in ran
        return two

    def late() -> dict:
        while True:
            d = round(float(rng.uniform(0.001, 0.005)), 5)
            if d not in used_delays:
                break
        used_delays.add(d)
        est, val = mix([ALL], reuse=reuse_all) or (None, None)
        return {"delay_s": d, "counts": counts(), "est": est, "val": val, **reused(est, val)}

    out: dict = {"seed": seed, "single": {}, "rejected": []}
    for kind in KINDS:
        out["single"][kind] = single(kind)
    out["two"] = pair()
    for key in ("pulse_late", "brs_late"):
        out[key] = late()
    output = str(rng.choice(["cr", "cd"]))
    transducer: dict[str, Any] = {"output": output, "counts": counts()}
    transducer["est"], transducer["val"] = mix([], reuse=reuse_all) or (None, None)
    transducer.update(reused(transducer["est"], transducer["val"]))
    out["transducer"] = transducer
    pool = TRANSDUCER[output]
    transducer["form"] = pool[int(rng.integers(len(pool)))]
    channel = str(rng.choice(["pulse", "brs", "cr", "cd"]))
    broken: dict[str, Any] = {"channel": channel, "counts": counts()}
    broken["est"], broken["val"] = mix([], reuse=reuse_all) or (None, None)
    broken.update(reused(broken["est"], broken["val"]))
    est_rigs = [r for r, n in zip(ALL, broken["est"], strict=True) for _ in range(n)]
    k = int(rng.integers(6))
    broken["test"] = f"{est_rigs[k]}_{1 + 2 * est_rigs[:k].count(est_rigs[k]):03d}"
    broken["form"] = BROKEN[channel][int(rng.integers(len(BROKEN[channel])))]
    out["broken"] = broken
    for n in (48, 96):
        est, val = mix([], reuse=reuse_all) or (None, None)
        out[f"clean{n}"] = {"est": est, "val": val, **reused(est, val)}
    if redrawn:  # the draws found impossible, drawn again (in this order, after the rest)
        for what, again in redrawn:
            rng = np.random.default_rng(again)
            if what == "two":
                out["rejected"].append((what, again, out["two"]))
                out["two"] = pair()
            elif what in ("pulse_late", "brs_late"):
                out["rejected"].append((what, again, out[what]))
                out[what] = late()
            else:
                out["rejected"].append((what, again, out["single"][what]))
                out["single"][what] = single(what)
        if out["two"]["est"] is None:
            raise RuntimeError("the two-effect case has no pairing left: draw it again")
    return out


def main(argv: list[str] | None = None) -> int:
    return cli("draw_w", __doc__ or "", draw, SEED, argv)


def cli(module: str, doc: str, draw_: Callable[[int], dict], seed: int,
        argv: list[str] | None) -> int:
    """A set's draw as its command line prints it (sets W and after): ``--seed``, then
    :func:`show`. ``doc``: the set's module docstring, whose first paragraph is the help."""
    ap = argparse.ArgumentParser(prog=f"python -m benchmarks.heldout.{module}",
                                 description=doc.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=seed)
    show(draw_(ap.parse_args(argv).seed))
    return 0


def show(d: dict) -> None:
    """Print a draw of :func:`drawn`, one line per case."""
    for kind, v in d["single"].items():
        print(f"{kind:<19} {v['form']:<18} {'+'.join(v['rigs']):<14} {v['counts']:>3} "
              f"est {v['est']} val {v['val']}"
              + (" (an earlier set's pairing, reused)" if v.get("reused") else ""))
    t = d["two"]
    print(f"two: {t['kinds']} {t['forms']} {t['rigs']} {t['counts']} est {t['est']} "
          f"val {t['val']}" + (" (an earlier set's pairing, reused)" if t.get("reused") else ""))
    for what, again, v in d["rejected"]:
        print(f"rejected, drawn again by {again}: {what} {v}")
    for key in ("pulse_late", "brs_late", "transducer", "broken", "clean48", "clean96"):
        print(key, d[key])


if __name__ == "__main__":
    sys.exit(main())
