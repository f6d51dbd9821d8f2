"""The daemon under faults: a dying recorder, a full disk, bad record paths, a port that does
not open, counters that wrap. Every run here must end promptly and leave nothing behind."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from observer_node.daemon.harness import CODEC, Harness
from observer_node.daemon.outputs import wrap16
from observer_node.dbc.meanings import RecorderState
from observer_node.recording import read_recording
from observer_node.recording.writer import RecorderError, create_exclusive

ROOT = Path(__file__).resolve().parents[1]
ACC, BRS = CODEC["TunnelAccel"], CODEC["BeltSpindle"]
STATUS, HEALTH = CODEC["ObserverStatus"], CODEC["ObserverHealth"]


def _feed(h: Harness, ticks: range, every=None) -> None:
    for k in ticks:
        h.send(BRS.frame_id, BRS.encode({"BrsCount": 0, "BrsCountsPerRev": 96}, k))
        h.send(ACC.frame_id, ACC.encode({"TunnelAccelX": 0.0}, k))
        if every is not None:
            every(k)
        time.sleep(0.001)


def _status(h: Harness) -> tuple[list[dict], list[dict]]:
    """ObserverStatus and ObserverHealth frames heard so far (the bus is drained)."""
    st, he = [], []
    while (m := h.rx.recv(0)) is not None:
        if m.arbitration_id == STATUS.frame_id:
            st.append(STATUS.decode(m.data))
        elif m.arbitration_id == HEALTH.frame_id:
            he.append(HEALTH.decode(m.data))
    return st, he


def test_killed_writer_restarts_into_a_new_part_and_says_so(model, tmp_path):
    """Only the MCAP writer dies: the daemon keeps estimating, logs it, flags it on the bus
    and records on in run.part2.mcap from the last flushed row, so no tick is missing."""
    logs: list[str] = []
    with Harness(model, "wkill", record=tmp_path / "run.mcap") as h:
        h.node.log = logs.append
        rec = h.node.recorder
        rec.restart_after_s = 0.0

        def kill_writer(k: int) -> None:
            if k == 150:
                os.kill(rec.proc.pid, signal.SIGKILL)
        _feed(h, range(600), kill_writer)
        assert h.settle()
        time.sleep(0.3)  # a status period, for the frames that say so
        status, health = _status(h)
    assert h.node.counters.ticks == 600  # the estimate never stopped
    assert rec.state == RecorderState.RESTARTED and len(rec.parts) == 2
    assert rec.parts[1].name == "run.part2.mcap"
    assert any("recording goes on in" in line and "run.part2.mcap" in line for line in logs)
    assert any(s["Fault_RecordingLost"] for s in status)
    assert any(x["RecorderState"] == RecorderState.RESTARTED for x in health)
    assert h.node.recording_lost  # run_daemon's exit code is then non-zero
    ticks = set()
    for p in rec.parts:
        ticks |= set(read_recording(p).ticks["tick"].tolist())
    assert set(range(600)) <= ticks


@pytest.mark.skipif(os.geteuid() != 0, reason="mounting a small tmpfs needs root")
def test_disk_full_fails_the_recording_loudly_and_estimates_go_on(model, tmp_path):
    mnt = tmp_path / "small"
    mnt.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=512k", "tmpfs", str(mnt)],
                      capture_output=True).returncode != 0:
        pytest.skip("cannot mount a tmpfs here")
    try:
        logs: list[str] = []
        with Harness(model, "enospc", record=mnt / "run.mcap") as h:
            h.node.log = logs.append
            rec = h.node.recorder
            rec.restart_after_s = 0.0
            # Fill the disk behind the writer's back
            with (mnt / "filler").open("wb") as f, pytest.raises(OSError):
                while True:
                    f.write(b"\0" * 65536)
                    f.flush()
            _feed(h, range(800))
            # A writer that dies after the last tick is restarted into a part that has not
            # yet met the full disk: ticks go on (as in a run) until the restart fails too and
            # a 10 Hz health frame says FAILED (on a loaded machine well after tick 800).
            status, health = [], []
            fed = 800
            deadline = time.monotonic() + 10.0
            while time.monotonic() < deadline and not (
                    health and health[-1]["RecorderState"] == RecorderState.FAILED):
                _feed(h, range(fed, fed + 20))
                fed += 20
                st, he = _status(h)
                status += st
                health += he
            assert h.settle()
        assert h.node.counters.ticks == fed
        assert rec.state == RecorderState.FAILED and rec.lost_ticks > 0
        assert any("No space left on device" in line for line in logs)
        assert any("recording stopped" in line for line in logs), logs
        assert health[-1]["RecorderState"] == RecorderState.FAILED and \
            health[-1]["RecorderLostTicks"] > 0
        assert status[-1]["Fault_RecordingLost"]
        # A restarted part that never got its header is removed, not left empty beside
        # the recording; the parts named are the files there.
        assert all(p.exists() for p in rec.parts)
        assert sorted(mnt.glob("run*.mcap")) == sorted(rec.parts)
        assert not any(p.stat().st_size == 0 for p in rec.parts[1:])
    finally:
        subprocess.run(["umount", "-l", str(mnt)], check=False)


def test_an_existing_recording_is_never_overwritten(tmp_path):
    first = tmp_path / "run.mcap"
    first.write_bytes(b"the crashed run")
    p, fd = create_exclusive(first)
    os.close(fd)
    assert p.name == "run.1.mcap" and first.read_bytes() == b"the crashed run"
    p2, fd = create_exclusive(first)
    os.close(fd)
    assert p2.name == "run.2.mcap"


@pytest.mark.parametrize(("make", "says"), [
    (lambda d: (d / "afile").write_text("x") and d / "afile" / "run.mcap", "afile"),
    (lambda d: (d / "adir.mcap").mkdir() or d / "adir.mcap", "is a directory"),
    (lambda d: Path("/proc/1/nosuch/run.mcap"), "/proc/1/nosuch"),
])
def test_bad_record_paths_name_the_cause(tmp_path, make, says):
    with pytest.raises(RecorderError) as e:
        create_exclusive(make(tmp_path))
    assert says in str(e.value) and "\n" not in str(e.value)


def _run_cli(args: list[str], timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "observer_node.cli", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=timeout)


def test_port_that_does_not_open_ends_promptly_with_one_line(model_path, tmp_path):
    """With --record, a port that fails to open (no such interface, or a kernel without
    CAN) ends the daemon with exit code 2 and one line; the recorder process is stopped and
    no empty recording is left behind."""
    t0 = time.monotonic()
    r = _run_cli(["run", "--interface", "socketcan", "--channel", "nosuch0", "--model",
                  str(model_path), "--record", str(tmp_path / "run.mcap"), "--cpu-latency-us",
                  "-1"])
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("observer-node: error: nosuch0")
    assert "Traceback" not in r.stderr
    assert not list(tmp_path.glob("*.mcap"))
    assert time.monotonic() - t0 < 60


def test_bad_record_path_from_the_cli_is_one_line(model_path, tmp_path):
    (tmp_path / "afile").write_text("x")
    r = _run_cli(["run", "--interface", "virtual", "--channel", "x", "--model",
                  str(model_path), "--record", str(tmp_path / "afile" / "run.mcap")])
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stderr.count("\n") == 1 and "afile" in r.stderr


def test_counters_wrap_modulo_65536():
    assert wrap16(65535) == 65535 and wrap16(65536) == 0 and wrap16(70000) == 70000 - 65536


def test_the_recorder_start_timeout_is_the_configs(model, tmp_path, monkeypatch):
    """Under CPU emulation on a busy host the recorder's start-up took over the default 120 s;
    the run was refused. How long to wait is the bench's to say."""
    from observer_node.recording.writer import Recorder

    waited: list[float] = []
    real = Recorder.wait_ready

    def spy(self: Recorder, timeout_s: float = 120.0) -> None:
        waited.append(timeout_s)
        real(self, timeout_s)

    monkeypatch.setattr(Recorder, "wait_ready", spy)
    with Harness(model, "startto", record=tmp_path / "run.mcap",
                 recorder_start_timeout_s=900.0):
        pass
    assert waited == [900.0]
