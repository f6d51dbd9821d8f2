"""The docs' result tables, from what the code prints today, so they cannot drift.

Each table sits between ``<!-- figures:NAME -->`` and ``<!-- /figures:NAME -->`` in whichever
markdown file holds it (README.md or one of docs/*.md; exactly one may) and is made by running
the product on the bundled campaign:

    evaluate         observer-node evaluate (the thesis's Tables 4.1-4.3), in docs/evaluation.md
    loop-campaign-a  observer-node loop, odd tests estimate, even tests validate (and the
                     picture docs/loop-campaign-a-cd.png), in docs/loop.md
    bench            observer-node bench on the in-process bus (daemon vs offline; the picture
                     docs/bench-full-002-on-the-bus.png), in README.md, with the
                     loop run here; its result is shipped in observer_node/examples/bench-loop
                     (--check: and must equal the shipped one, parameters within 2 %)

    .venv/bin/python scripts/readme_figures.py            rewrite the tables (about 50 s)
    .venv/bin/python scripts/readme_figures.py --check    exit 1 if a table drifted (CI)

``--check`` allows 0.3 points on every number: BLAS builds differ in the last bits, which a
least-squares fit can carry into the first decimal.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import re
import shutil
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from observer_node.loop.evidence import Evidence

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
DOCS = ROOT / "docs"
TOLERANCE = 0.3
PICTURES: list[tuple[Path, Path]] = []  # (made, where the docs show it)
SHIPPED: list[tuple[Path, Path]] = []  # (a loop's result made here, where the package ships it)
PARAM_RTOL = 0.02  # shipped vs new loop parameters: the fits' 0.3 points, in parameter terms


def _num(x: float) -> str:
    return f"{x:.1f}".replace("-", "−")


def evaluate_table(tmp: Path) -> str:
    from observer_node.cli import main

    with contextlib.redirect_stdout(io.StringIO()):
        main(["evaluate", "--out", str(tmp / "evaluate"), "--quiet"])
    d = json.loads((tmp / "evaluate" / "evaluation.json").read_text())
    rows = ["| setup | model | fit CR | fit CD | fit TOT | thesis TOT |",
            "|---|---|---|---|---|---|"]
    for setup, s in d["setups"].items():
        for name, m in s["models"].items():
            f = m["validation"]["fit"]
            thesis = s["thesis"].get(name, {}).get("total")
            rows.append(f"| {setup} | {name} | {_num(f['cr'])} | {_num(f['cd'])} | "
                        f"{_num(f['total'])} | {'' if thesis is None else _num(thesis)} |")
    return "\n".join(rows)


def loop_table(tmp: Path) -> str:
    from observer_node.cli import main
    from observer_node.loop.report import AcceptedEffect
    from observer_node.model.effects import EFFECTS

    out = tmp / "loop"
    with contextlib.redirect_stdout(io.StringIO()):
        main(["loop", "--estimate", "campaign-a/*[13579]", "--validate", "campaign-a/*[02468]",
              "--out", str(out), "--quiet"])
    r = json.loads((out / "report.json").read_text())
    PICTURES.append((out / "fit_after_cd.png", ROOT / "docs" / "loop-campaign-a-cd.png"))
    rows = ["| model | acts on | fit CR | fit CD | fit TOT | cross-validated fit_TOT "
            "(estimation tests) | paired gain (95 % CI), tests improved | runner-up (its "
            "cross-validated fit_TOT) |",
            "|---|---|---|---|---|---|---|---|"]
    b = r["baseline"]["fit"]
    effects = [AcceptedEffect.from_dict(e) for e in r["effects"]]
    cv0 = effects[0].evidence.cv_fit_before if effects else None
    rows.append(f"| thesis grey-box | all | {_num(b['cr'])} | {_num(b['cd'])} | "
                f"{_num(b['total'])} | {'' if cv0 is None else _num(cv0)} | | |")
    for e in effects:
        units = EFFECTS[e.kind].units if e.kind in EFFECTS else {}
        se = e.std_err
        params = ", ".join(f"{k} = {v:.3g}" + (f" ± {se[k]:.2g}" if k in se else "")
                           + f" {units.get(k, '')}".rstrip()
                           for k, v in e.parameters.items())
        f, ev = e.fit, e.evidence
        ru = ev.runner_up
        rows.append(f"| + {e.kind}{f' ({params})' if params else ''} | "
                    f"{', '.join(e.setups or ['all'])} | {_num(f.cr)} | "
                    f"{_num(f.cd)} | {_num(f.total)} | {_num(ev.cv_fit_after)} | "
                    f"{_gain(ev.rule)} | "
                    + (f"{ru.kind} on {ru.scope} ({_num(ru.cv_fit)}) |" if ru else "|"))
    return "\n".join(rows)


def _gain(rule: Evidence) -> str:
    lo, hi = rule.ci95_points
    return (f"{_num(rule.gain_points)} ({_num(lo)}..{_num(hi)}), "
            f"{rule.tests_improved}/{rule.tests}")


def bench_table(tmp: Path) -> str:
    from observer_node.bench import SHIPPED_LOOP, daemon_cd_max_err_mm, run_bench

    with contextlib.redirect_stdout(io.StringIO()):  # the loop runs here, never the shipped one
        result = run_bench(tmp / "bench", interface="virtual", rerun_loop=True)
    SHIPPED.append((tmp / "bench" / "loop", SHIPPED_LOOP))
    full = tmp / "bench" / "FULL"  # a session per setup when the loop's model is scoped
    PICTURES.append((full / "event0.png" if full.is_dir() else tmp / "bench" / "event2.png",
                     ROOT / "docs" / "bench-full-002-on-the-bus.png"))
    rows = ["| test | thesis grey-box: fit CR | fit CD | CD max error [mm] | loop's model on the "
            "bus: fit CR | fit CD | CD max error [mm] | measured CD max [mm] | "
            "max abs(daemon − offline) |", "|---|---|---|---|---|---|---|---|---|"]
    base = result.baseline_offline or {}
    for name, ev in result.events.items():
        off, b = result.offline[name], base[name]
        if ev is None or ev.fit_vs_reference is None:
            rows.append(f"| {name} | {_num(b.cr)} | {_num(b.cd)} | {_num(b.cd_max_err_mm)} | "
                        f"{'did not trigger' if ev is None else 'no reference'} | | | "
                        f"{_num(off.cd_max_ref_mm)} | |")
            continue
        live = ev.fit_vs_reference
        diff = max(ev.max_abs_diff_offline.as_dict().values())
        rows.append(f"| {name} | {_num(b.cr)} | {_num(b.cd)} | {_num(b.cd_max_err_mm)} | "
                    f"{_num(live.cr)} | {_num(live.cd)} | {_num(daemon_cd_max_err_mm(ev))} | "
                    f"{_num(off.cd_max_ref_mm)} | {'< 1e-9' if diff < 1e-9 else f'{diff:.2g}'} |")
    return "\n".join(rows)


TABLES: dict[str, Callable[[Path], str]] = {
    "evaluate": evaluate_table, "loop-campaign-a": loop_table, "bench": bench_table}


def _models(folder: Path) -> dict[str, object]:
    """What a loop's result says, without the numbers' last bits: each model's parameters,
    and its effects' kinds, scopes and parameters; and what it was made from."""
    from observer_node.bench import STAMP

    out: dict[str, object] = {"made_from": json.loads((folder / STAMP).read_text())}
    for name in ("baseline-model.json", "model.json"):
        m = json.loads((folder / name).read_text())
        out[name] = {"parameters": m["parameters"],
                     "effects": [(e["kind"], e.get("setups"), e.get("parameters", {}))
                                 for e in m.get("effects", [])]}
    return out


def _loop_drift(made: Path, shipped: Path) -> str | None:
    """Where the shipped loop result differs from the one just made, or None."""
    import numpy as np

    if not shipped.is_dir():
        return f"{shipped} does not exist"
    a, b = _models(made), _models(shipped)

    def walk(x: object, y: object, where: str) -> str | None:
        if isinstance(x, dict) and isinstance(y, dict):
            if x.keys() != y.keys():
                return f"{where}: keys {sorted(x)} now, {sorted(y)} shipped"
            pairs = [(x[k], y[k], f"{where}.{k}") for k in x]
        elif isinstance(x, (list, tuple)) and isinstance(y, (list, tuple)):
            if len(x) != len(y):
                return f"{where}: {len(x)} items now, {len(y)} shipped"
            pairs = [(u, v, f"{where}[{i}]") for i, (u, v) in enumerate(zip(x, y, strict=True))]
        elif isinstance(x, float) and isinstance(y, (int, float)):
            return None if np.isclose(x, y, rtol=PARAM_RTOL, atol=0) else \
                f"{where}: {x:.6g} now, {y:.6g} shipped"
        else:
            return None if x == y else f"{where}: {x!r} now, {y!r} shipped"
        for u, v, w in pairs:
            if (d := walk(u, v, w)) is not None:
                return d
        return None

    return walk(a, b, "loop")


def _block(name: str) -> re.Pattern[str]:
    return re.compile(rf"(<!-- figures:{name} -->\n)(.*?)(\n<!-- /figures:{name} -->)", re.S)


def _same(old: str, new: str) -> bool:
    """Equal but for numbers within TOLERANCE."""
    split = re.compile(r"(−?\d+\.\d+)")
    a, b = split.split(old), split.split(new)
    if len(a) != len(b):
        return False
    for x, y in zip(a, b, strict=True):
        if x == y:
            continue
        try:
            if abs(float(x.replace("−", "-")) - float(y.replace("−", "-"))) > TOLERANCE:
                return False
        except ValueError:
            return False
    return True


def _pages() -> list[Path]:
    """The markdown files a table may sit in."""
    return [README, *sorted(DOCS.glob("*.md"))]


def _holder(name: str, texts: dict[Path, str]) -> Path | str:
    """The one file holding the table NAME, or why there is none."""
    found = [f for f, t in texts.items() if _block(name).search(t)]
    if len(found) == 1:
        return found[0]
    where = ", ".join(str(f.relative_to(ROOT)) for f in found) or "no file"
    return f"figures:{name} must be in exactly one of README.md and docs/*.md, not in {where}"


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--check", action="store_true", help="exit 1 if a table drifted")
    p.add_argument("--only", choices=sorted(TABLES), action="append", help="these tables")
    a = p.parse_args(argv)
    texts = {f: f.read_text(encoding="utf-8") for f in _pages()}
    holders: dict[str, Path] = {}
    for name in a.only or TABLES:  # every block found before anything runs
        holder = _holder(name, texts)
        if isinstance(holder, str):
            print(f"readme-figures: {holder}", file=sys.stderr)
            return 2
        holders[name] = holder
    drifted = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, holder in holders.items():
            text = texts[holder]
            m = _block(name).search(text)
            assert m is not None  # found above
            where = holder.relative_to(ROOT)
            print(f"readme-figures: {name} ({where}) ...", file=sys.stderr)
            new = TABLES[name](Path(tmp))
            if not _same(m.group(2), new):
                drifted.append(name)
                print(f"readme-figures: {name} differs:\n--- {where}\n{m.group(2)}\n--- now\n"
                      f"{new}", file=sys.stderr)
            texts[holder] = text[:m.start(2)] + new + text[m.end(2):]
        for made, shipped in SHIPPED:  # the bench's loop result, shipped in the package
            drift = _loop_drift(made, shipped)
            if drift and a.check:
                drifted.append(str(shipped.relative_to(ROOT)))
                print(f"readme-figures: the shipped loop result differs: {drift}",
                      file=sys.stderr)
            elif not a.check:
                from observer_node.bench import LOOP_FILES

                shipped.mkdir(parents=True, exist_ok=True)
                for f in LOOP_FILES:
                    shutil.copyfile(made / f, shipped / f)
        if not a.check:  # the pictures the docs show, from the same runs
            for made, shown in PICTURES:
                shown.parent.mkdir(exist_ok=True)
                shutil.copyfile(made, shown)
    if a.check:
        if drifted:
            print(f"readme-figures: drifted: {', '.join(drifted)} (rerun without --check)",
                  file=sys.stderr)
            return 1
        print("readme-figures: every table is what the code prints", file=sys.stderr)
        return 0
    for holder in sorted(set(holders.values())):
        holder.write_text(texts[holder], encoding="utf-8")
    print(f"readme-figures: wrote {len(holders)} table(s) into "
          f"{', '.join(str(h.relative_to(ROOT)) for h in sorted(set(holders.values())))}",
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
