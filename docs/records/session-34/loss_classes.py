"""Offline screen (session 34): on every stored held-out report whose expected structure passes
the rule against the grey-box (the latest run of each case), what the loop did instead of
naming it, and whether the expected kinds were among the candidates the rounds tried.
Reads /work/runs/s*/*.json (benchmarks.loop_heldout --json) and their report folders."""
import collections
import glob
import json
import os

R = "/work/runs"
latest = {}
# the latest run of each case by the time its rows were written (not by file name)
for js in sorted(glob.glob(f"{R}/s*/*.json"), key=os.path.getmtime):
    try:
        with open(js) as f:
            rows = json.load(f)
    except (OSError, ValueError):
        continue
    rows = rows.get("cases", []) if isinstance(rows, dict) else rows
    for r in rows:
        if isinstance(r, dict) and r.get("truth") and r["truth"].get("passes") and "found" in r:
            latest[r["case"]] = (js, r)


def folder(js):
    """The run's report folder, from the log the run wrote beside its rows."""
    log = js[:-5] + ".log"
    if not os.path.exists(log):
        log = js[:-5] + "_run.log"
    if os.path.exists(log):
        with open(log) as f:
            for line in f:
                if line.startswith("loop reports in "):
                    return line.split("loop reports in ")[1].split("/CASE/")[0]
    return js[:-5] if os.path.isdir(js[:-5]) else None  # a rerun written without a log


cls, untried, missing = collections.Counter(), [], []
for case, (js, r) in sorted(latest.items()):
    exp = set(r["expected"])
    kinds = {e.split("@")[0] for e in exp}
    found = set(r["found"])
    fk = {f.split("@")[0] for f in found}
    if r["right"]:
        k = "right"
    elif found and not fk & kinds:
        k = "named another kind"
    elif found and not found & exp:
        k = "right kind, wrong scope"
    elif found:
        k = "named the expected effect and one not there"
    elif any(t.split("@")[0] in kinds for t in r.get("tied", [])):
        k = "tie with the expected kind (carried: " + ",".join(r.get("carried") or ["-"]) + ")"
    elif any(t.split("@")[0] in kinds for t in r.get("refused", [])):
        k = "refused by the validation tests"
    else:
        k = "nothing named, expected kind not tied or refused"
    cls[k.split(" (")[0]] += 1
    d = folder(js)
    tried = None
    if d is None or not os.path.exists(f"{d}/{case}/report.json"):
        missing.append(case)
    else:
        with open(f"{d}/{case}/report.json") as f:
            rep = json.load(f)
        tried = {t["kind"] for s in rep["history"] for t in s["tried"]}
        if kinds - tried:
            untried.append((case, sorted(kinds - tried)))
    print(f"{os.path.relpath(js, R):16} {case[:46]:46} {k}")
print(dict(cls))
print(f"cases: {len(latest)}; report not found: {missing}; expected kind never tried: {untried}")
