"""Per case: how many of the thesis grey-box's own leave-one-test-out folds took no step
(their held-out test then scores in-sample in the loop's baseline)."""
import sys
from pathlib import Path

from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop.refit import FOLD_NFEV, folds, refit_from


def main(sets: str) -> None:
    for case in sorted(Path(sets).iterdir()):
        if not (case / "est").is_dir():
            continue
        data = make_dataset(load_tests(sorted((case / "est").iterdir())))
        gb = greybox.fit_greybox(data)
        stuck = [data.names[te[0]] for tr, te in folds(data)
                 if not refit_from(dict(gb.params), [], data.subset(tr), FOLD_NFEV).moved]
        print(f"{case.name:32s} m2 {gb.params['m2']:.3g} kg  stalled {len(stuck)}/{data.n_tests}"
              f" {' '.join(stuck)}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1])
