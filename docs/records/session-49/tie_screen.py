"""Session 49's screen of stored ties: every tie neither side of which passed the rule beside
the other ("neither explains the other away"), in the loop reports of sessions 45-48 under
/work/runs (sets T-AG as last run; not in the repository), with each side's mean gain beside
the other and the case's truth (truth.json). The pattern kept: one side over the 1-point bar
beside the other, the other under 0.25 beside it. Output: tie_screen.out."""

import glob
import json
import os
import re

PAST = re.compile(r"beside (\w+), (\w+) gains ([-+\d.]+) points \((\d+) of (\d+) tests\); "
                  r"beside (\w+), (\w+) gains ([-+\d.]+) points \((\d+) of (\d+) tests\): "
                  r"neither explains")


def main() -> None:
    truth = {}
    for t in glob.glob("/work/runs/s*/sets/*/*/truth.json"):
        with open(t) as f:
            case = json.load(f)["case"]
        truth[case["name"]] = [k for k, _ in case["expect"]]
    seen = set()
    for path in sorted(glob.glob("/work/runs/s4[5-8]/**/report.json", recursive=True)):
        case = os.path.basename(os.path.dirname(path))
        with open(path) as f:
            report = json.load(f)
        for p in report.get("possible", []):
            m = PAST.search(p.get("why_not", ""))
            if not m or (path, m.group(0)) in seen:
                continue
            seen.add((path, m.group(0)))
            a, ga, ka, n = m.group(2), float(m.group(3)), m.group(4), m.group(5)
            b, gb, kb = m.group(7), float(m.group(8)), m.group(9)
            kept = (ga >= 1 and gb < 0.25) or (gb >= 1 and ga < 0.25)
            print(f"{path.split('/runs/')[1][:40]:40s} {a}:{ga:+.2f}({ka}/{n}) "
                  f"{b}:{gb:+.2f}({kb}/{n}) truth={truth.get(case, '?')}"
                  + ("  <- over the bar beside a rival adding nothing" if kept else ""))


if __name__ == "__main__":
    main()
