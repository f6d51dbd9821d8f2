import sys, numpy as np
from pathlib import Path
from observer_node.data import load_tests
from observer_node.data.setups import assign_setups
from observer_node.loop import screening as sc
END_S=0.15
def lags(t, fracs=(0.2,0.35,0.5,0.65,0.8)):
    i0,i1=t.index_of(0.0),t.index_of(END_S)+1
    fl=sc._flight_ms(t,END_S)
    b=np.asarray(t.brs[i0:i1],float); p=sc._paid_counts(b)
    return [int(np.argmax(p>=f*p.max()))*1000/t.fs_hz-fl for f in fracs], p.max()
for folder in sys.argv[1:]:
    folder=Path(folder)
    tests=load_tests([*sorted((folder/"est").iterdir()),*sorted((folder/"val").iterdir())]); assign_setups(tests)
    print(folder.name)
    for t in sorted(tests,key=lambda t:(t.setup,t.name)):
        l,m=lags(t); print(f"  {t.setup:5s} {t.name:9s} max {m:6.0f}  "+" ".join(f"{x:6.1f}" for x in l))
