"""Screen (session 56): a scoped candidate judged by the rule on the tests it acts on only,
a setup counted as lowered only when every one of its tests falls, recomputed from stored
reports' candidates (report.json's history) against the rule as it stands.

    python screen_rule.py OUT_DIR...   (each OUT_DIR holds CASE/report.json)
"""
import glob
import json
import sys

import numpy as np

from observer_node.loop.evidence import SETUP_TOLERANCE, above_scatter


def variant(ev: dict, scope: str, margin: float = 1.0) -> tuple[bool, str]:
    g = ev["test_gain_points"]
    setup_of = {n: n.split("_")[0] for n in g}
    ins = [n for n in g if scope == "all" or setup_of[n] in scope.split("+")]
    d = np.array([g[n] for n in ins], float)
    if not len(d) or not np.all(np.isfinite(d)):
        return False, "nonfinite"
    ok, mean, _, imp, _ = above_scatter(d)
    if mean < margin:
        return False, f"in-scope mean {mean:.2f}"
    for s in set(setup_of.values()):
        v = [g[n] for n in g if setup_of[n] == s]
        if np.mean(v) < -SETUP_TOLERANCE and all(x < 0 for x in v):
            return False, f"lowers {s}"
    return ok, "" if ok else f"scatter {imp}/{len(d)}"


if __name__ == "__main__":
    for root in sys.argv[1:]:
        for f in sorted(glob.glob(root + "/*/report.json")):
            case = f.split("/")[-2]
            with open(f) as fh:
                r = json.load(fh)
            for k, h in enumerate(r["history"]):
                for t in h["tried"]:
                    ev = t["evidence"]
                    a1, why = variant(ev, t["scope"])
                    if ev["accepted"] != a1:
                        print(f"{case:34s} round {k} {t['kind']}@{t['scope']}: "
                              f"{ev['accepted']} -> {a1} {why} gains {ev['test_gain_points']}")
