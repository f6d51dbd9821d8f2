"""One package: dbc/ and replay/ are mapped into observer_node by pyproject.toml (package-dir),
every module loads once under one name, and nothing relies on links or on the test suite."""

from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ("observer_node", "dbc", "replay", "tests", "benchmarks", "scripts")
MAPPED = ("dbc", "replay")  # the folders that import as observer_node.<folder>


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())


def test_the_product_loads_dbc_and_replay_once_from_their_folders():
    """From the repository root, where ``import replay`` would find the folder too, the
    product's entry points import no top-level ``dbc`` or ``replay``, and observer_node.dbc
    and observer_node.replay are this checkout's dbc/ and replay/ (not a link, not another
    checkout's copy)."""
    probe = (
        "import json, sys\n"
        "import observer_node.bench, observer_node.cli, observer_node.daemon.harness\n"
        "import observer_node.replay.cli, observer_node.replay.sources\n"
        "import observer_node.dbc, observer_node.replay\n"
        "print(json.dumps({'top': sorted(m for m in sys.modules\n"
        "                                if m.split('.')[0] in ('dbc', 'replay', 'tests')),\n"
        "                  'dbc': observer_node.dbc.__file__,\n"
        "                  'replay': observer_node.replay.__file__}))\n")
    out = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True,
                         text=True, timeout=120, check=True).stdout
    seen = json.loads(out)
    assert seen["top"] == []
    assert Path(seen["dbc"]) == ROOT / "dbc" / "__init__.py"
    assert Path(seen["replay"]) == ROOT / "replay" / "__init__.py"


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


def test_no_links_in_the_sources():
    links = [str(p.relative_to(ROOT)) for folder in SOURCES
             for p in [ROOT / folder, *(ROOT / folder).rglob("*")] if p.is_symlink()]
    assert links == []


def test_pyproject_lists_every_package_of_the_tree_where_it_is():
    """The package list is explicit (discovery cannot map folders): a subpackage left out of
    it would be missing from the wheel while the editable install still finds it."""
    st = _pyproject()["tool"]["setuptools"]
    dirs = st["package-dir"]
    assert {dirs[f"observer_node.{f}"] for f in MAPPED} == set(MAPPED)

    def folder(pkg: str) -> Path:
        for mapped, where in dirs.items():
            if pkg == mapped or pkg.startswith(mapped + "."):
                return ROOT / where / pkg[len(mapped):].lstrip(".").replace(".", "/")
        return ROOT / pkg.replace(".", "/")

    in_tree = {".".join(p.parent.relative_to(ROOT).parts)
               for p in (ROOT / "observer_node").rglob("__init__.py")}
    for f in MAPPED:
        in_tree |= {".".join(("observer_node", *p.parent.relative_to(ROOT).parts))
                    for p in (ROOT / f).rglob("__init__.py")}
    assert set(st["packages"]) == in_tree
    assert all((folder(p) / "__init__.py").is_file() for p in st["packages"])
    assert (folder("observer_node.dbc") / "chest_observer.dbc").is_file()
    assert st["package-data"]["observer_node.dbc"] == ["*.dbc"]


def test_typecheck_checks_mapped_folders_under_their_import_names(tmp_path):
    """scripts/typecheck.py gives mypy each file under its import name: a wrong type that
    crosses from the package into a mapped folder is reported (plain mypy sees Any there)."""
    (tmp_path / "pyproject.toml").write_text(
        '[tool.setuptools.package-dir]\n"pkg.sub" = "sub"\n\n'
        '[tool.mypy]\nfiles = ["pkg", "sub"]\nignore_missing_imports = true\n')
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "__init__.py").write_text("from .sub import f\n\nx: int = f()\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "__init__.py").write_text('def f() -> str:\n    return ""\n')
    env = {**os.environ, "MYPY_CACHE_DIR": str(tmp_path / "cache")}
    run = subprocess.run([sys.executable, str(ROOT / "scripts" / "typecheck.py")],
                         cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
    assert run.returncode == 1, run.stdout + run.stderr
    assert 'pkg/__init__.py:3: error: Incompatible types in assignment (expression has type ' \
           '"str", variable has type "int")' in run.stdout
