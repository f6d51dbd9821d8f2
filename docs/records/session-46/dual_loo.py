"""Per estimation test: the grey-box's left-out fit_TOT and its in-sample fit (the loop's
broken-test screen reads the first)."""
import sys
from pathlib import Path

from observer_node.data import load_tests
from observer_node.ident import greybox
from observer_node.ident.dataset import make_dataset
from observer_node.loop.refit import folds, score
from observer_node.loop.rounds import cross_validate


class _One:
    workers = 1

    @staticmethod
    def map(f, args):
        return [f(*a) for a in args]


def main(case_dir: str) -> None:
    tests = load_tests(sorted(Path(case_dir, "est").iterdir()))
    data = make_dataset(tests)
    gb = greybox.fit_greybox(data)
    cv = cross_validate(_One(), [(dict(gb.params), [])], data, folds(data))[0]
    ins = {n: v.total for n, v in score(dict(gb.params), [], data).tests.items()}
    for n in data.names:
        print(f"{n:10s} left out {cv[n]:6.1f}  in-sample {ins[n]:6.1f}")


if __name__ == "__main__":
    main(sys.argv[1])
