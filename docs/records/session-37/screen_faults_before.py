"""benchmarks/screen_faults.py with the pay-out check as it was before session 37: the
function of commit ee0fc91, read from git (the gap to the nearest other test of the rig alone,
no prediction interval, a crossed partner named from one side). Run from the repository's
clone, with the benchmark's arguments (the record ran --campaigns 600, --seed 50000 and
60000):
    PYTHONPATH=. python docs/records/session-37/screen_faults_before.py ARGS"""
import subprocess
import sys
import types
from unittest import mock

from benchmarks import screen_faults
from observer_node.loop import screening

BEFORE = "ee0fc91"
source = subprocess.run(["git", "show", f"{BEFORE}:observer_node/loop/screening.py"],
                        capture_output=True, text=True, check=True).stdout
before = types.ModuleType("observer_node.loop.screening_before")
before.__package__ = "observer_node.loop"
sys.modules[before.__name__] = before  # its dataclass looks itself up there
exec(compile(source, f"{BEFORE}:observer_node/loop/screening.py", "exec"), before.__dict__)

with mock.patch.object(screening, "payout_outliers", before.payout_outliers):
    sys.exit(screen_faults.main(sys.argv[1:]))
