"""mypy over the package under its import names: dbc/ as observer_node.dbc, replay/ as
observer_node.replay, as pyproject.toml maps them (setuptools package-dir).

mypy names a file by its folders and does not follow that mapping: a plain ``mypy`` checks
dbc/ and replay/ as top-level ``dbc`` and ``replay`` and, finding no observer_node/dbc, types
every name imported from ``observer_node.dbc`` or ``.replay`` as Any. Here mypy's own build
gets each file under its import name, so those imports are checked. mypy's settings are
pyproject.toml's [tool.mypy]; arguments go to mypy as on its command line.

    python scripts/typecheck.py [MYPY OPTIONS] [FILES]     (from the repository root)
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

from mypy import build
from mypy.errors import CompileError
from mypy.fscache import FileSystemCache
from mypy.main import process_options
from mypy.modulefinder import BuildSource


def package_dirs(pyproject: Path) -> dict[str, str]:
    """{folder as a dotted module prefix: the package it installs as}, from package-dir."""
    mapping = tomllib.loads(pyproject.read_text())["tool"]["setuptools"]["package-dir"]
    return {folder.strip("/").replace("/", "."): pkg for pkg, folder in mapping.items() if pkg}


def import_name(module: str, dirs: dict[str, str]) -> str:
    """The name a module found by its folders (``replay.cli``) is imported as."""
    for folder, pkg in dirs.items():
        if module == folder or module.startswith(folder + "."):
            return pkg + module[len(folder):]
    return module


def main(argv: list[str]) -> int:
    fscache = FileSystemCache()
    sources, options = process_options(argv, fscache=fscache)
    dirs = package_dirs(Path("pyproject.toml"))
    sources = [BuildSource(s.path, import_name(s.module, dirs), s.text, s.base_dir)
               for s in sources]
    try:
        messages = build.build(sources, options, fscache=fscache).errors
    except CompileError as e:  # a syntax error or the like: mypy stops at it
        messages = e.messages
    for m in messages:
        print(m)
    errors = sum(": error:" in m for m in messages)
    if errors:
        print(f"Found {errors} error{'s' * (errors > 1)} (checked {len(sources)} source files)")
        return 1
    print(f"Success: no issues found in {len(sources)} source files")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
