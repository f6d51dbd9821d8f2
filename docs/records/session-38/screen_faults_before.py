"""benchmarks/screen_faults.py with the checks before the fit as they were at the start of
session 38 (commit 6ab39f1, read from git: no check of a chest channel quieter during the crash
than at rest or back at rest while loaded, none of a channel at the wrong polarity); the
reader is today's in both, so campaigns it refuses are refused alike. Run from the
repository's clone, with the benchmark's arguments (the record ran --campaigns 600 --seed
90000):
    PYTHONPATH=. python docs/records/session-38/screen_faults_before.py ARGS"""
import os
import sys
from unittest import mock

from before import screening_at

from benchmarks import screen_faults

BEFORE = os.environ.get("BEFORE", "6ab39f1")  # session 39 ran it with b8486ee
before = screening_at(BEFORE)

with mock.patch.object(screen_faults, "broken_before_fit", before.broken_before_fit):
    sys.exit(screen_faults.main(sys.argv[1:]))
