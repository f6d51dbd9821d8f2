"""benchmarks/screen_faults.py with the CR lost block and the CR loose mount at sizes other
than the sets' medians (6 ms, 150 Hz), on seeds no one had looked at, with the checks of
session 39 (a CR or CD held over the record's end; a CR line no other test shows). Written,
with its predictions, before the runs:

- ``--block-ms 4 --mount-hz 100``: a 4 ms block leaves about 2-3 ms of held end, so about
  half found; a 100 Hz mount rings far above any clean line, so all found.
- ``--block-ms 10 --mount-hz 200``: every 10 ms block found; a 200 Hz mount rings weakly
  (the chest's signal there is small beside the lab's noise), so few or none found.
- Clean tests named: as at the medians (none on 6291 at seed 90000).

Run from the repository's clone:
    PYTHONPATH=. python docs/records/session-39/screen_sizes.py --block-ms 4 --mount-hz 100 \\
        --campaigns 600 --seed 110000"""
import argparse
import sys
from unittest import mock

from benchmarks import screen_faults

ap = argparse.ArgumentParser()
ap.add_argument("--block-ms", type=float, required=True)
ap.add_argument("--mount-hz", type=float, required=True)
args, rest = ap.parse_known_args()
sizes = screen_faults.median_sizes()
sizes.update(cr_lost_block=args.block_ms / 1000.0, cr_loose_mount=args.mount_hz)
with mock.patch.object(screen_faults, "median_sizes", lambda: sizes):
    sys.exit(screen_faults.main(rest))
