# false alarms vs sampling rate: healthy chests with rate-dependent damping (physics), 6 tests, 3 seeds, recorded at 10/5/2/1 kHz
from common import *
for setup in ("R16","SLED","FULL"):
  for mag in (3,5,10):
    bases=[clean(setup,6,s,{"chest_rate_damping":mag}) for s in (51,52,53)]
    row=[]
    for d in (1,2,5,10):
        n=0; meds=[]
        for i,b in enumerate(bases):
            ts=relab(b,decim=d,seed=i)
            n+=bool(rate_limited_outputs(ts,END)); meds.append(np.median([p["cd"][1] for _,p in plats(ts)]))
        row.append(f"{10/d:g} kHz: {n}/3 flagged (CD plateau median {min(meds):.1f}-{max(meds):.1f} ms)")
    print(f"{setup} damping={mag}: "+" | ".join(row),flush=True)
