"""Each rerun case's named effects with what its report says of them (the rule's gain, its
95 % interval, tests improved, the sign test's p, the gain on the tests it acts on and on the
others, the runner-up and whether it passes the rule, the warnings).

python named_table.py DIR [DIR...]: each DIR a loop output folder (report.json) named after
its case; ``named_rerun.sh`` made them (and AK's knee and pelvis_knee cases by hand, same
command)."""

import json
import sys
from pathlib import Path

# the kinds each case's design put there (benchmarks/heldout/cases_*.py), kinds only
THERE: dict[str, set[str]] = {
    "had_toe_all": set(), "had_submarine_all": {"pelvis_coupling"},
    "hae_bottoming_r16": {"chest_stiffening"}, "haf_hysteresis_r16_full": set(),
    "haf_toe_r16_full": {"belt_stiffening"}, "hah_power_all": set(),
    "hah_lumbar_full": {"pelvis_coupling"},
    "hah_two_maxwell_r16_full_dual_sled": {"airbag_contact", "chest_rate_damping"},
    "hai_power_sled_full": {"belt_stiffening"}, "haj_bumper_sled_full": {"chest_stiffening"},
    "haj_sealed_sled": {"airbag_contact"}, "hak_fluid_r16": {"chest_rate_damping"},
    "hak_knee_r16_sled": set(), "hak_pelvis_knee_sled": set(),
}


def mean(xs: list[float]) -> str:
    return f"{sum(xs) / len(xs):+.2f}({len(xs)})" if xs else "-"


def rows(d: Path) -> list[str]:
    r = json.loads((d / "report.json").read_text())
    if not r["effects"]:
        return [f"{d.name:36s} (none)"]
    out = []
    for e in r["effects"]:
        ev = e["evidence"]["rule"]
        inside = set(e.get("applies_to") or ev["test_gain_points"])
        g = ev["test_gain_points"]
        ru = e["evidence"]["runner_up"]
        ru_word = "-" if ru is None else "pass" if ru["passes_rule"] else \
            "bar" if ru["over_bar"] else "fails"
        scope = "+".join(e.get("setups") or ["all"])
        lo, hi = ev["ci95_points"]
        out.append(
            f"{d.name:36s} {e['kind'] + '@' + scope:28s} "
            f"{'THERE' if e['kind'] in THERE[d.name] else 'NOT  '} gain {ev['gain_points']:+.2f}"
            f" ci [{lo:+.2f},{hi:+.2f}] {ev['tests_improved']}/{ev['tests']}"
            f" p={ev['sign_test_p']:.3f} in {mean([v for n, v in g.items() if n in inside])}"
            f" out {mean([v for n, v in g.items() if n not in inside])}"
            f" ru={ru['kind'] if ru else '-'}:{ru_word} | "
            + "; ".join(w[:40] for w in e["warnings"]))
    return out


if __name__ == "__main__":
    for arg in sys.argv[1:]:
        print("\n".join(rows(Path(arg))))
