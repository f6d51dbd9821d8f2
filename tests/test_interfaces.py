"""Every interface python-can knows, given to `observer-node run` and to `crash-replay`: the
bus opens (a clean run) or the command ends with exit code 2 and one line, never a
traceback. Backends fail at open in their own ways (CanInterfaceNotImplementedError, an
OSError for a missing driver, kvaser's NameError without canlib, socketcand's TypeError
without a host, an ImportError) and some log a warning of their own on import; each runs in
a process of its own, as a user would start it."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import can
import pytest

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "observer_node/examples/bench-loop/baseline-model.json"
# Each name with the default channel, and kvaser also with an adapter's channel number (it
# fails differently: without canlib a NameError, where vcan0 is a ValueError).
CASES = [(name, "vcan0") for name in sorted(can.interfaces.VALID_INTERFACES)] + \
    [("kvaser", "0")]


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(ROOT), "PYTHONUNBUFFERED": "1"}


def _assert_exit_2_in_one_line(rc: int, err: str, prog: str, interface: str,
                               channel: str) -> None:
    assert "Traceback" not in err, err
    assert rc == 2, err
    (line,) = err.strip().splitlines()
    assert line.startswith(f"{prog}: error:"), line
    assert interface in line or channel in line, line


@pytest.mark.parametrize(("interface", "channel"), CASES)
def test_daemon_opens_or_says_why_in_one_line(interface, channel):
    p = subprocess.Popen([sys.executable, "-m", "observer_node", "run", "--interface", interface,
                          "--channel", channel, "--model", str(MODEL), "--cpu-latency-us", "-1"],
                         cwd=ROOT, env=_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, start_new_session=True)
    try:
        first = p.stderr.readline()  # the start-up line, or the error
        if p.poll() is None and "listening on" in first:  # it opened: stop it cleanly
            time.sleep(0.2)
            p.send_signal(signal.SIGINT)
            _, rest = p.communicate(timeout=60)
            assert p.returncode == 0 and "Traceback" not in rest, first + rest
            return
        _, rest = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    _assert_exit_2_in_one_line(p.returncode, first + rest, "observer-node", interface, channel)


@pytest.mark.parametrize(("interface", "channel"), CASES)
def test_replay_opens_or_says_why_in_one_line(interface, channel):
    r = subprocess.run([sys.executable, "-m", "observer_node.replay", "campaign-a/R16_002",
                        "--interface", interface, "--channel", channel, "--start", "0",
                        "--end", "0.01", "--pre", "0.01", "--quiet"], cwd=ROOT, env=_env(),
                       capture_output=True, text=True, timeout=120)
    if r.returncode == 0:  # it opened and played
        assert "Traceback" not in r.stderr and "frames" in r.stdout, r.stderr
        return
    _assert_exit_2_in_one_line(r.returncode, r.stderr, "crash-replay", interface, channel)
