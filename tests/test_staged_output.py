"""Results are written beside the output folder and moved in when the command ends well: an
interrupted or failed `evaluate`, `loop`, `analyze` or `export-c` leaves the folder as it was
(a hostile user's finding, session 57: Ctrl-C in `evaluate` left half the models and plots
beside an older run's evaluation.json)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from observer_node.options import staged


def _tree(folder: Path) -> dict[str, str]:
    return {str(p.relative_to(folder)): p.read_text() for p in sorted(folder.rglob("*"))
            if p.is_file()}


def test_a_run_that_ends_well_replaces_its_files_and_keeps_the_others(tmp_path):
    out = tmp_path / "out"
    (out / "plots").mkdir(parents=True)
    (out / "plots" / "a.png").write_text("old a")
    (out / "plots" / "mine.png").write_text("the user's")
    (out / "notes.txt").write_text("the user's")
    with staged(out) as tmp:
        assert tmp.parent == out.parent.absolute() and tmp != out.absolute()
        (tmp / "plots").mkdir()
        (tmp / "plots" / "a.png").write_text("new a")
        (tmp / "evaluation.json").write_text("new")
        assert _tree(out)["plots/a.png"] == "old a"  # nothing moves before the end
    assert _tree(out) == {"evaluation.json": "new", "notes.txt": "the user's",
                          "plots/a.png": "new a", "plots/mine.png": "the user's"}
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_a_run_that_fails_leaves_the_folder_and_makes_no_parents(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "evaluation.json").write_text("an older run")
    for error in (KeyboardInterrupt, OSError):
        with pytest.raises(error), staged(out) as tmp:
            (tmp / "evaluation.json").write_text("half")
            raise error
    assert _tree(out) == {"evaluation.json": "an older run"}
    assert [p.name for p in tmp_path.iterdir()] == ["out"]
    deep = tmp_path / "a" / "b" / "out"
    with pytest.raises(ValueError), staged(deep) as tmp:
        raise ValueError
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def _sigint_default() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)  # as a terminal starts a program
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def test_ctrl_c_during_evaluate_leaves_the_older_results_whole(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "evaluation.json").write_text("an older run\n")
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "evaluate", "--data",
                          "campaign-a/R16_00[1-4]", "--out", str(out)],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         start_new_session=True, preexec_fn=_sigint_default)
    assert p.stderr is not None
    seen = []
    for line in p.stderr:  # interrupt once the first models and plots are written
        seen.append(line)
        if "ARX Nmax=6 [" in line:
            os.killpg(p.pid, signal.SIGINT)
            break
    rest = p.stderr.read()
    assert p.wait(timeout=120) == 130, "".join(seen) + rest
    assert rest.strip().splitlines()[-1] == "observer-node: interrupted", rest
    assert _tree(out) == {"evaluation.json": "an older run\n"}
    assert [x.name for x in tmp_path.iterdir()] == ["out"]
