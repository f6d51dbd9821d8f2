"""Offline screen: candidates the rule refused on the scatter alone, and what a Wilcoxon
signed-rank test (one-sided) would say of their per-test gains. Reads stored reports only."""
import json, sys
from pathlib import Path
import numpy as np
from scipy import stats

R = Path('/work/runs')
pairs = [('s30/aa_out', 's30/aa.json'), ('s32/ctl_out', 's32/ctl.json'), ('s32/x2_out', 's32/x2.json'),
         ('s32/y_ctl_out', 's32/y_ctl.json'), ('s32/y_x2_out', 's32/y_x2.json'),
         ('s32/z_ctl_out', 's32/z_ctl.json'), ('s32/z_x2_out', 's32/z_x2.json')]
ALPHA = float(sys.argv[1]) if len(sys.argv) > 1 else 0.0625
rows = []
for out, js in pairs:
    exp = {r['case']: r for r in json.load(open(R / js))}
    for d in sorted((R / out).iterdir()):
        rep = json.load(open(d / 'report.json'))
        e = exp[d.name]
        kinds = {x.split('@')[0] for x in e['expected']}
        for i, step in enumerate(rep['history']):
            for t in step['tried']:
                ev = t['evidence']
                g = np.array(ev['test_gain_points'] if isinstance(ev['test_gain_points'], list) else list(ev['test_gain_points'].values()), float)
                scatter_only = 'not above test-to-test scatter' in ev['reason']
                if not scatter_only:
                    continue
                p = stats.wilcoxon(g, alternative='greater').pvalue if np.any(g != 0) else 1.0
                rows.append((out.split('/')[1], d.name, i, t['kind'], t['scope'], round(float(g.mean()), 2),
                             int((g > 0).sum()), len(g), round(float(p), 4), t['kind'] in kinds, e['right']))
for r in rows:
    if r[8] <= ALPHA:
        print(*r)
n_pass = [r for r in rows if r[8] <= ALPHA]
print(f"scatter-only refusals: {len(rows)}; Wilcoxon p <= {ALPHA}: {len(n_pass)}; of them kind there: {sum(r[9] for r in n_pass)}, not there: {sum(not r[9] for r in n_pass)}")
