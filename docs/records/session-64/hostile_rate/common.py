import sys, time, dataclasses
import numpy as np
sys.path.insert(0, "/work/main/tests")
from observer_node.simulator import PlantConfig, simulate_campaign, EFFECTS
from observer_node.loop.rate_limit import plateau, rate_limited_outputs
from observer_node.data.filters import cfc_filter
from test_rate_limit import _slewed, _limited
END=0.15
def plats(tests, end=END):
    out=[]
    for t in tests:
        row={}
        for o,x in (("cr",t.cr_g),("cd",t.cd_mm)):
            if x is None: row[o]=None; continue
            row[o]=plateau(x[t.index_of(0.0):t.index_of(end)+1], t.fs_hz)
        out.append((t.name,row))
    return out
def summ(tests,label=""):
    p=plats(tests)
    s=label
    for o in ("cr","cd"):
        ms=[r[o][1] for _,r in p if r[o]]
        tops=[r[o][0] for _,r in p if r[o]]
        if ms: s+=f" | {o}: plateau max {max(ms):.1f} med {np.median(ms):.1f} ms, n>=8: {sum(m>=8 for m in ms)}/{len(ms)} tops {min(tops):.2f}-{max(tops):.2f}"
    f=rate_limited_outputs(tests,END)
    s+=" | FLAG: "+("; ".join(f"{r.output} {r.rate_per_ms:.2f} n={len(r.tests)} {r.setups} {r.plateau_ms}" for r in f) if f else "-")
    return s
def relab(tests, cr_cfc=180, cd_cfc=600, seed=5, cr_sd=0.3, cd_sd=0.05, q_cd=None, q_cr=None, decim=1, pre=None):
    """Tests simulated noise-free, re-recorded: optional pre(x, fs, key) (e.g. a slew limit), noise, CFC, quantisation, decimation."""
    rng=np.random.default_rng(seed); out=[]
    for t in tests:
        new={}
        for key,sd,cfc,q in (("cr_g",cr_sd,cr_cfc,q_cr),("cd_mm",cd_sd,cd_cfc,q_cd)):
            x=getattr(t,key).copy()
            if pre is not None: x=pre(x,t.fs_hz,key,t)
            x=x+rng.normal(0,sd,len(x))
            if cfc: x=cfc_filter(x,t.fs_hz,cfc)
            if q: x=np.round(x/q)*q
            new[key]=x[::decim]
        out.append(dataclasses.replace(t, fs_hz=t.fs_hz/decim, pulse_g=t.pulse_g[::decim], brs=t.brs[::decim], **new))
    return out
def clean(setup,n,seed,eff=None,prefix=None):
    return simulate_campaign(setup,n,seed=seed,config=PlantConfig(effects=eff or {},noise=False),prefix=prefix)
