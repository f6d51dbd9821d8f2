# the thesis grey-box's judged fit of each test the pay-out check would flag, against its setup's
# others: the pay-out check switched off so the suspect stays in (est: left-out fit; val: the
# estimation model's fit)
import glob, json, sys, itertools
import numpy as np
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.data.crashtest import THESIS_WINDOW_S
from observer_node.ident.progress import Progress
from observer_node.loop import closed_loop as CL
from observer_node.loop import screening as S
from observer_node.loop.cluster import cluster
from observer_node.loop.refit import score
real_payout = S.payout_outliers
CL.payout_outliers = lambda tests, end: []
def run(label, est, val, runner):
    tests = est + val; assign_setups(tests)
    sus = real_payout(tests, 0.15)
    if not sus: print(label, 'no suspect'); return
    scr = CL._screened(est, val, 1000.0, THESIS_WINDOW_S, runner, Progress('x', False))
    fits = dict(scr.cv_now)
    fits.update({n: v.total for n, v in score(dict(scr.gb.params), [], scr.val).tests.items()})
    setup = {t.name: t.setup for t in tests}
    for b in sus:
        peers = [fits[n] for n in fits if setup[n] == setup[b.test] and n != b.test]
        print(label, b.test, 'est' if b.test in {t.name for t in est} else 'val',
              'fit', round(fits.get(b.test, float('nan')), 1), 'setup others', np.round(sorted(peers), 1).tolist(),
              'all median', round(float(np.median([v for n, v in fits.items() if n != b.test])), 1),
              'left out by others:', [x.test for x in scr.broken], flush=True)
if __name__ == '__main__':
    with cluster(None, 1) as runner:
        for case in sys.argv[1:]:
            if case.startswith('bund:'):
                est_n, val_n = case[5:].split('/')
                allt = {t.name: t for t in load_tests(sorted(glob.glob('/work/hostile/clean/*.zip')))}
                run(case, [allt[n] for n in est_n.split(',')], [allt[n] for n in val_n.split(',')], runner)
            else:
                d = glob.glob(f'/work/runs/s36/sets/*/{case}/')[0]
                run(case, load_tests(sorted(glob.glob(d + 'est/*'))), load_tests(sorted(glob.glob(d + 'val/*'))), runner)
