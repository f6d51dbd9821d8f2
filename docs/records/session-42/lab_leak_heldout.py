"""The speed share's reason for a CR named short of its car's change of speed, on campaigns of
the independent held-out simulator (benchmarks/heldout), each in variants: its physical effect
only; every CR leaking at 0.1 s and at 0.2 s; every CR at 0.45 of its sensitivity; one CR at
0.45, leaking at 0.1 s, at 2.3 times. Counts the tests named on CR and those given the leak's
words; and clean tests named beside one broken. Seeds SEED+k (screen_faults' draw). Run from a
checkout:
    PYTHONPATH=. python docs/records/session-42/lab_leak_heldout.py 430000 20"""
import dataclasses
import sys
import tempfile
from collections import Counter
from pathlib import Path

from benchmarks.heldout.cases import Effect, test_names
from benchmarks.heldout.make_sets import make
from benchmarks.screen_faults import draw_campaign, median_sizes
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop.screening import speed_share_outliers

SEED, N = int(sys.argv[1]), int(sys.argv[2])
size = median_sizes()
every = {"clean": (), "leak 0.1 s, all": ("cr_ac_coupled", 0.1),
         "leak 0.2 s, all": ("cr_ac_coupled", 0.2), "x0.45, all": ("cr_gain", -0.55)}
one = {"x0.45, one": ("cr_gain", -0.55), "leak 0.1 s, one": ("cr_ac_coupled", 0.1),
       "x2.3, one": ("cr_gain", 1.3)}
cases, broken = [], {}
for k in range(N):
    c = draw_campaign(k, SEED, size)
    phys = tuple(e for e in c.effects if not e.tests)
    est_names, val_names = test_names(c)
    names = [*est_names, *val_names]
    for v, e in [*every.items(), *one.items()]:
        extra, b = (), ()
        if e and v in every:
            extra = (Effect(e[0], e[1]),)
            b = tuple(names)
        elif e:
            b = (names[k % 12],)
            extra = (Effect(e[0], e[1], tests=b),)
        cases.append(dataclasses.replace(c, name=f"c{k}|{v}", effects=phys + extra,
                                         expect_broken=()))
        broken[cases[-1].name] = set(b)
count: Counter = Counter()
with tempfile.TemporaryDirectory() as tmp:
    make([dataclasses.replace(c, name=c.name.replace("|", "_").replace(" ", "").replace(",", ""))
          for c in cases], Path(tmp), log=False)
    for c in cases:
        v = c.name.split("|")[1]
        d = Path(tmp) / c.name.replace("|", "_").replace(" ", "").replace(",", "")
        tests = load_tests([*sorted((d / "est").iterdir()), *sorted((d / "val").iterdir())])
        assign_setups(tests)
        for b in speed_share_outliers(tests, 0.15):
            side = "broken" if b.test in broken[c.name] else "clean"
            count[v, side, "named"] += 1
            count[v, side, "on cr"] += b.channel == "cr"
            count[v, side, "leak words"] += "leaks away (an AC" in b.reason
            count[v, side, "either"] += ", or its charge leaks away" in b.reason
        count[v, "broken", "drawn"] += len(broken[c.name])
for v in [*every, *one]:
    n = {(side, what): count[v, side, what] for side in ("broken", "clean")
         for what in ("named", "drawn", "on cr", "leak words", "either")}
    print(f"{v:18s} broken: {n['broken', 'named']:3d} of {n['broken', 'drawn']:3d} named, "
          f"{n['broken', 'on cr']:3d} on CR, {n['broken', 'leak words']:3d} with the leak's "
          f"words, {n['broken', 'either']:3d} with either's; clean tests named: "
          f"{n['clean', 'named']} ({n['clean', 'leak words']} with the leak's words, "
          f"{n['clean', 'either']} with either's)")
