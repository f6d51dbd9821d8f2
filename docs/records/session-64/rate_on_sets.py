"""Rate-limit check on every case of held-out sets' folders: est+val tests, all outputs."""
import sys, json
from pathlib import Path
sys.path.insert(0, "/work/main")
from observer_node.data import load_tests
from observer_node.loop.rate_limit import rate_limited_outputs, plateau
for root in sys.argv[1:]:
    for case in sorted(Path(root).iterdir()):
        if not (case / "est").is_dir():
            continue
        tests = load_tests([case / "est", case / "val"])
        found = rate_limited_outputs(tests, 0.15)
        longest = {o: max(plateau((t.cr_g if o == "cr" else t.cd_mm)[t.index_of(0.0):t.index_of(0.15)+1], t.fs_hz)[1] for t in tests) for o in ("cr", "cd")}
        print(f"{case.name:45s} cr {longest['cr']:5.1f} cd {longest['cd']:5.1f} ms  found {[(r.output, round(r.rate_per_ms,2), len(r.tests)) for r in found]}", flush=True)
