"""The docs match the tree: the layout table in docs/layout.md names every folder that holds
Python code and nothing that does not exist; every relative link in README.md, CHANGELOG.md and
docs/*.md reaches a file (and a heading, when it names one); every result table that
scripts/readme_figures.py writes sits in exactly one page."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# the folders whose Python code the layout table must cover, themselves and every subfolder
LAYOUT_ROOTS = ("observer_node", "dbc", "replay", "benchmarks", "scripts", "docker", "tests")
SKIP_DIRS = {"__pycache__"}

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE = re.compile(r"`([^`]+)`")
FENCE = re.compile(r"^\s*(```|~~~)")


def pages(root: Path) -> list[Path]:
    """The markdown files whose links are checked."""
    return [p for p in (root / "README.md", root / "CHANGELOG.md") if p.exists()] + sorted(
        (root / "docs").glob("*.md"))


def _prose_lines(text: str) -> list[str]:
    """The lines outside fenced code blocks."""
    out, fenced = [], False
    for line in text.splitlines():
        if FENCE.match(line):
            fenced = not fenced
        elif not fenced:
            out.append(line)
    return out


def layout_paths(layout_md: Path) -> list[str]:
    """The paths in the layout table's first column (every `...` in it), as written."""
    paths = []
    for line in _prose_lines(layout_md.read_text(encoding="utf-8")):
        cells = line.split("|")
        if line.startswith("|") and len(cells) > 2 and "`" in cells[1]:
            paths += CODE.findall(cells[1])
    return paths


def code_folders(root: Path) -> list[str]:
    """LAYOUT_ROOTS and every folder below them that holds a .py file, as 'a/b/'."""
    found = set()
    for top in LAYOUT_ROOTS:
        if not (root / top).is_dir():
            continue
        found.add(f"{top}/")
        for py in (root / top).rglob("*.py"):
            rel = py.parent.relative_to(root)
            if not SKIP_DIRS & set(rel.parts):
                found.add(f"{rel.as_posix()}/")
    return sorted(found)


def layout_problems(root: Path) -> list[str]:
    """What the layout table in docs/layout.md gets wrong about the tree under root."""
    listed = layout_paths(root / "docs" / "layout.md")
    named = {p.rstrip("/") for p in listed}
    problems = [f"docs/layout.md names {p}, which does not exist"
                for p in listed if not (root / p).exists()]
    problems += [f"{folder} holds Python code and is not in docs/layout.md"
                 for folder in code_folders(root) if folder.rstrip("/") not in named]
    return problems


def slug(heading: str) -> str:
    """A heading's anchor as GitHub makes it: markup dropped, lower case, punctuation
    removed, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading).replace("`", "").strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def anchors(page: Path) -> set[str]:
    """Every heading anchor of a markdown page (repeats numbered -1, -2, ... as GitHub does)."""
    seen: dict[str, int] = {}
    for line in _prose_lines(page.read_text(encoding="utf-8")):
        if m := re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line):
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            if n:
                seen[f"{s}-{n}"] = 1
    return set(seen)


def link_problems(root: Path) -> list[str]:
    """Relative links in the pages under root that reach no file, or no heading."""
    problems = []
    for page in pages(root):
        for line in _prose_lines(page.read_text(encoding="utf-8")):
            for target in LINK.findall(line):
                if re.match(r"[a-z][a-z0-9+.-]*:", target):  # https:, mailto:, ...
                    continue
                path, _, fragment = target.partition("#")
                dest = (page.parent / path).resolve() if path else page
                where = f"{page.relative_to(root)}: ({target})"
                if not dest.exists():
                    problems.append(f"{where} reaches no file")
                elif fragment and dest.suffix == ".md" and fragment not in anchors(dest):
                    problems.append(f"{where}: {dest.name} has no heading #{fragment}")
    return problems


def test_the_layout_table_matches_the_tree():
    problems = layout_problems(ROOT)
    assert not problems, "\n".join(problems)


def test_every_relative_link_reaches_a_file_and_heading():
    problems = link_problems(ROOT)
    assert not problems, "\n".join(problems)


def test_every_figures_table_sits_in_exactly_one_page():
    spec = importlib.util.spec_from_file_location("readme_figures",
                                                  ROOT / "scripts" / "readme_figures.py")
    assert spec is not None and spec.loader is not None
    figures = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(figures)
    texts = {p: p.read_text(encoding="utf-8") for p in figures._pages()}
    for name in figures.TABLES:
        assert isinstance(figures._holder(name, texts), Path), figures._holder(name, texts)


def _tree(tmp: Path) -> None:
    """A small tree whose docs are right: one package, its table row, one good link."""
    (tmp / "observer_node" / "sub").mkdir(parents=True)
    (tmp / "observer_node" / "sub" / "m.py").write_text("")
    (tmp / "docs").mkdir()
    (tmp / "docs" / "layout.md").write_text(
        "# Layout\n\n| path | what |\n|---|---|\n| `observer_node/` | the package |\n"
        "| `observer_node/sub/` | a part |\n")
    (tmp / "README.md").write_text("# Top\n\n[layout](docs/layout.md#layout)\n")


def test_the_checks_find_a_missing_folder_a_stale_row_and_a_broken_link(tmp_path):
    _tree(tmp_path)
    assert layout_problems(tmp_path) == [] and link_problems(tmp_path) == []

    (tmp_path / "observer_node" / "new").mkdir()
    (tmp_path / "observer_node" / "new" / "x.py").write_text("")
    (tmp_path / "observer_node" / "sub" / "m.py").rename(tmp_path / "observer_node" / "m.py")
    (tmp_path / "observer_node" / "sub").rmdir()
    assert layout_problems(tmp_path) == [
        "docs/layout.md names observer_node/sub/, which does not exist",
        "observer_node/new/ holds Python code and is not in docs/layout.md"]

    (tmp_path / "README.md").write_text(
        "# Top\n\n[a](docs/gone.md) [b](docs/layout.md#nowhere) [c](#top) [d](https://x.org)\n"
        "```sh\n[e](not/checked.md)\n```\n")
    assert link_problems(tmp_path) == [
        "README.md: (docs/gone.md) reaches no file",
        "README.md: (docs/layout.md#nowhere): layout.md has no heading #nowhere"]


def test_the_readme_opens_with_the_two_commands_and_ci_runs_the_second():
    """The README's first lines are the fresh-machine commands, and .ci/run runs its test
    command as written there."""
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    fence = lines.index("```sh")
    commands = [ln.split("#")[0].strip() for ln in lines[fence + 1:lines.index("```", fence)]]
    assert fence <= 2 and commands[0].startswith("scripts/bootstrap && ")
    ci = [ln.strip() for ln in (ROOT / ".ci" / "run").read_text().splitlines()
          if ln.strip() and not ln.startswith(("#", "set ", "cd "))]
    assert ci == [commands[1]]
