"""Screened before the change (session 46): in each round that named an effect, its best
runner-up of another kind that failed the rule on the scatter alone (mean gain >= 1 point,
every gain finite, no setup lower by more than 0.3, neither the interval nor the sign test
above zero). Would the named effect beat it test by test above the scatter? Counted by
whether the named kind is there (in the case's expected structure).

    PYTHONPATH=. python docs/records/session-46/rival_screen.py SET.json ...

SET.json is `benchmarks.loop_heldout --json`'s; the reports are read from the folder beside
it named after it (SET/CASE/report.json).
"""

import json
import sys
from pathlib import Path

from observer_node.loop.evidence import beats


def _over_bar(ev: dict) -> bool:
    return (not ev["accepted"] and ev["gain_points"] >= 1.0
            and min(ev["setup_gain_points"].values()) >= -0.3
            and "not above test-to-test scatter" in ev["reason"])


def rows(js: Path) -> list[tuple]:
    out = []
    for case in json.loads(js.read_text()):
        rep = js.parent / js.stem / case["case"] / "report.json"
        if not rep.exists():
            continue
        expected = {e.split("@")[0] for e in case["expected"]}
        for h in json.loads(rep.read_text())["history"]:
            named = [t for t in h["tried"] if t["evidence"]["accepted"]
                     and h["decision"].startswith(f"accepted {t['kind']} on {t['scope']}")]
            if not named:
                continue
            w = named[0]
            near = [t for t in h["tried"] if t["kind"] != w["kind"] and _over_bar(t["evidence"])]
            if not near:
                out.append((js.stem, case["case"], w["kind"], w["kind"] in expected, "-", "-"))
                continue
            r = max(near, key=lambda t: t["cv_fit"])
            told, _ = beats(w["evidence"]["test_gain_points"], r["evidence"]["test_gain_points"])
            out.append((js.stem, case["case"], w["kind"], w["kind"] in expected,
                        f"{r['kind']}{' (there)' if r['kind'] in expected else ''}",
                        "told apart" if told else "NOT told apart"))
    return out


def main() -> None:
    every = [r for a in sys.argv[1:] for r in rows(Path(a))]
    for r in every:
        print(*r)
    there = [r for r in every if r[3]]
    not_there = [r for r in every if not r[3]]
    def ties(rs: list[tuple]) -> int:
        return sum(r[5] == "NOT told apart" for r in rs)
    print(f"named and there {len(there)}: would tie {ties(there)}; "
          f"named and not there {len(not_there)}: would tie {ties(not_there)}")


if __name__ == "__main__":
    main()
