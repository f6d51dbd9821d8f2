"""Results are written beside the output folder and moved in when the command ends well: an
interrupted or failed `evaluate`, `loop`, `analyze` or `export-c` leaves the folder as it was
(a hostile user's finding, session 57: Ctrl-C in `evaluate` left half the models and plots
beside an older run's evaluation.json)."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from observer_node.options import OutputClash, staged

from .runners import sigint_default


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
        assert tmp.parent == out and tmp.name.startswith(".partial-")  # one file system
        (tmp / "plots").mkdir()
        (tmp / "plots" / "a.png").write_text("new a")
        (tmp / "evaluation.json").write_text("new")
        assert (out / "plots" / "a.png").read_text() == "old a"  # nothing moves before the end
    assert _tree(out) == {"evaluation.json": "new", "notes.txt": "the user's",
                          "plots/a.png": "new a", "plots/mine.png": "the user's"}
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_a_run_that_fails_leaves_the_folder_and_makes_no_folders(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "evaluation.json").write_text("an older run")
    for error in (KeyboardInterrupt, OSError):
        with pytest.raises(error), staged(out) as tmp:
            (tmp / "evaluation.json").write_text("half")
            raise error
    assert _tree(out) == {"evaluation.json": "an older run"}
    assert sorted(p.name for p in out.iterdir()) == ["evaluation.json"]
    for deep in (tmp_path / "a" / "b" / "out", tmp_path / "new" / ".."):
        with pytest.raises(ValueError), staged(deep) as tmp:
            (tmp / "x").write_text("half")
            raise ValueError
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


@pytest.mark.parametrize("there", ["folder", "file"])
def test_another_kind_where_a_result_goes_stops_the_move_and_keeps_both(tmp_path, there):
    """A folder where the run writes a file, or a file where it writes a folder, was deleted
    to make room (a hostile user's finding, session 58): now nothing moves, one line names
    it, and the results wait in the hidden folder."""
    out = tmp_path / "out"
    out.mkdir()
    if there == "folder":
        (out / "evaluation.json").mkdir()
        (out / "evaluation.json" / "notes.txt").write_text("the user's")
    else:
        (out / "plots").write_text("the user's")
    (out / "old.json").write_text("old")
    before = _tree(out)
    said = r"out/(evaluation\.json|plots): a (folder|file) where this run writes a (file|fol"
    with pytest.raises(OutputClash, match=said + r"der); nothing was moved"), \
            staged(out) as tmp:
        (tmp / "old.json").write_text("new")
        (tmp / "evaluation.json").write_text("new")
        (tmp / "plots").mkdir()
        (tmp / "plots" / "a.png").write_text("new a")
    assert {k: v for k, v in _tree(out).items() if not k.startswith(".partial-")} == before
    (kept,) = out.glob(".partial-*")
    assert _tree(kept) == {"evaluation.json": "new", "old.json": "new", "plots/a.png": "new a"}


def test_results_move_into_a_folder_linked_to_another_file_system(tmp_path):
    """--out a link to another disk, or a folder in it that is one: os.replace cannot cross,
    and the merge had deleted the old file before it failed (session 58)."""
    other = Path(tempfile.mkdtemp(dir="/dev/shm"))
    try:
        if os.stat(other).st_dev == os.stat(tmp_path).st_dev:
            pytest.skip("/dev/shm is on the same file system here")
        (other / "plots").mkdir()
        (other / "plots" / "a.png").write_text("old a")
        (other / "c.h").write_text("old")
        out = tmp_path / "out"
        out.mkdir()
        (out / "plots").symlink_to(other / "plots")  # a folder in --out on another disk
        with staged(out) as tmp:
            (tmp / "plots").mkdir()
            (tmp / "plots" / "a.png").write_text("new a")
            (tmp / "plots" / "sub").mkdir()
            (tmp / "plots" / "sub" / "b.png").write_text("new b")
        assert _tree(other) == {"c.h": "old", "plots/a.png": "new a", "plots/sub/b.png": "new b"}
        link = tmp_path / "link"
        link.symlink_to(other)  # --out itself a link: its hidden folder is on that disk
        with staged(link) as tmp:
            (tmp / "c.h").write_text("new")
        assert _tree(other)["c.h"] == "new" and not list(other.glob(".partial-*"))
    finally:
        shutil.rmtree(other)


def test_a_default_out_that_is_the_recording_itself_is_refused_before_the_work(tmp_path,
                                                                                capsys):
    """`analyze norec` (no .mcap suffix): its default --out is the file itself; the whole
    analysis ran before "File exists" (session 58)."""
    from observer_node import cli

    rec = tmp_path / "norec"
    rec.write_bytes(b"not read")
    assert cli.main(["analyze", str(rec)]) == 2
    err = capsys.readouterr().err
    assert "--out (not given: the recording's path less .mcap)" in err and "is a file" in err
    for bad, said in (("", "--out: empty"), (str(tmp_path / "dangling"), "does not exist")):
        if bad:
            Path(bad).symlink_to(tmp_path / "nowhere")
        assert cli.main(["export-c", str(rec), "--out", bad]) == 2
        assert said in capsys.readouterr().err


def test_sigterm_during_evaluate_cleans_up_as_ctrl_c_does(tmp_path):
    """SIGTERM (systemd, kill, a CI's timeout) killed the command where it stood: its hidden
    folder and the folders made for --out stayed (session 58). Now one line, exit 143."""
    out = tmp_path / "new" / "out"
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "evaluate", "--data",
                          "campaign-a/R16_00[1-4]", "--out", str(out)],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    assert p.stderr is not None
    for line in p.stderr:
        if "ARX Nmax=6 [" in line:
            p.terminate()
            break
    rest = p.stderr.read()
    assert p.wait(timeout=120) == 143, rest
    assert rest.strip().splitlines()[-1] == "observer-node: terminated", rest
    assert list(tmp_path.iterdir()) == []


def test_a_stop_while_the_command_loads_is_one_line():
    """Ctrl-C in the second numpy and friends take to import was a page of traceback."""
    code = ("import signal, observer_node.entry as e\n"
            "def load():\n    raise KeyboardInterrupt\n"
            "def load_term():\n    signal.raise_signal(signal.SIGTERM)\n"
            "print(e._run('observer-node', load), e._run('crash-replay', load_term))\n"
            "print(signal.getsignal(signal.SIGINT) == signal.SIG_IGN)\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=60)
    assert r.stdout.split() == ["130", "143", "True"], r.stdout + r.stderr
    assert r.stderr.splitlines() == ["observer-node: interrupted", "crash-replay: terminated"]


def test_ctrl_c_during_evaluate_leaves_the_older_results_whole(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "evaluation.json").write_text("an older run\n")
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "evaluate", "--data",
                          "campaign-a/R16_00[1-4]", "--out", str(out)],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         start_new_session=True, preexec_fn=sigint_default)
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


def test_a_failure_names_the_file_in_the_output_folder_and_a_full_disk_names_the_folder(
        tmp_path):
    """A full disk while `evaluate` wrote its models named the hidden folder's file, removed
    by then; a write that names no file said "No space left on device" alone (session 58's
    hostile user)."""
    import errno

    from observer_node.errors import ObserverError

    out = tmp_path / "out"
    with pytest.raises(ObserverError) as bad, staged(out) as tmp:
        raise ObserverError(f"{tmp / 'models' / 'm.json'}: cannot write the model file: "
                            "No space left on device")
    assert str(bad.value) == (f"{out / 'models' / 'm.json'}: cannot write the model file: "
                              "No space left on device")
    with pytest.raises(OSError) as full, staged(out):
        raise OSError(errno.ENOSPC, "No space left on device")
    assert full.value.filename == str(out)
    with pytest.raises(OSError) as named, staged(out) as tmp:
        raise OSError(errno.ENOSPC, "No space left on device", str(tmp / "fits.json"))
    assert named.value.filename == str(out / "fits.json")
    assert list(tmp_path.iterdir()) == []  # the folder made for the run removed again


def test_signals_after_the_command_returns_are_ignored():
    """A second SIGTERM right after `run`'s clean stop came in the interpreter's teardown,
    where the handlers are back at their defaults: exit 143 and no line for a whole run
    (session 59's hostile user). Once a command returns, both signals are ignored."""
    from observer_node import entry

    old = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        assert entry._run("observer-node", lambda: lambda: 0) == 0
        assert signal.getsignal(signal.SIGTERM) is signal.SIG_IGN
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    finally:
        for s, h in old.items():
            signal.signal(s, h)
