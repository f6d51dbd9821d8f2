"""One package: every module loads once under one name, and nothing relies on the test suite."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ("observer_node", "dbc", "replay", "tests", "benchmarks", "scripts")


def test_no_source_imports_the_folders_or_the_tests_by_top_level_name():
    """``dbc.x`` or ``replay.x`` would load a second copy of a module beside
    ``observer_node.dbc.x``; benchmarks and product import nothing from ``tests``."""
    bad = []
    for folder in SOURCES:
        for path in sorted((ROOT / folder).rglob("*.py")):
            forbidden = {"dbc", "replay"} | ({"tests"} if folder != "tests" else set())
            for node in ast.walk(ast.parse(path.read_text(), str(path))):
                if isinstance(node, ast.Import):
                    names = [a.name for a in node.names]
                elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                    names = [node.module]
                else:
                    continue
                bad += [f"{path.relative_to(ROOT)}:{node.lineno} {n}" for n in names
                        if n.split(".")[0] in forbidden]
    assert bad == []
