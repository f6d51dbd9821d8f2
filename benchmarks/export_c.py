"""The C observer (observer-node export-c) beside the Python one: ns per step, and the code
and data size of the object file, for the thesis grey-box and for the loop's grey-box with
effects, in double and in float.

    python benchmarks/export_c.py [--steps 1000000]

C: compiled with the system compiler at -O2, stepped in a loop over the bundled R16_002
inputs (repeated), timed with clock_gettime. Python: ObserverCore's observer ``step`` per tick,
as the daemon calls it. Sizes: ``size`` of the object file (text = code and constants).
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from observer_node.data import bundled_campaign, read_isomme
from observer_node.evaluation import dataset_for, identify
from observer_node.export_c import export_c
from observer_node.ident.dataset import make_dataset
from observer_node.model.modelfile import ModelFile

BENCH = r"""#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "chest_observer.h"
int main(int argc, char **argv)
{
    long steps = atol(argv[1]), n = 0, k;
    static co_real pulse[4096], brs[4096];
    co_real y[2], sink = 0;
    co_observer obs;
    struct timespec t0, t1;
    FILE *f = fopen(argv[2], "r");
    while (n < 4096 && fscanf(f, "%lf %lf", &(double){0}, &(double){0}) == 2) n++;
    rewind(f);
    for (k = 0; k < n; k++) { double a, b; if (fscanf(f, "%lf %lf", &a, &b) != 2) return 1;
        pulse[k] = (co_real)a; brs[k] = (co_real)b; }
    fclose(f);
    co_reset(&obs);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (k = 0; k < steps; k++) {
        if (k % n == 0) co_reset(&obs);
        co_step(&obs, pulse[k % n], brs[k % n], y);
        sink += y[1];
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("%.2f %g\n", ((t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec)) / steps,
           (double)sink);
    return 0;
}
"""


def c_row(mf: ModelFile, work: Path, real: str, inputs: Path, steps: int) -> tuple[float, str]:
    cc = shutil.which("cc") or "gcc"
    export_c(mf, work)
    (work / "bench.c").write_text(BENCH)
    obj, exe = work / f"obs_{real}.o", work / f"bench_{real}"
    flags = ["-std=c99", "-O2", f"-DCO_REAL={real}"]
    subprocess.run([cc, *flags, "-c", "-o", obj, work / "chest_observer.c"], check=True)
    subprocess.run([cc, *flags, "-o", exe, work / "bench.c", obj, "-lm"], check=True)
    ns = float(subprocess.run([exe, str(steps), inputs], check=True, capture_output=True,
                              text=True).stdout.split()[0])
    size = subprocess.run(["size", obj], check=True, capture_output=True, text=True).stdout
    text, data, bss = size.splitlines()[1].split()[:3]
    return ns, f"text {text} B, data {data} B, bss {bss} B"


def py_ns(mf: ModelFile, pulse: np.ndarray, brs: np.ndarray, steps: int) -> float:
    obs = mf.observer()
    n = len(pulse)
    p, b = pulse.tolist(), brs.tolist()
    t = time.perf_counter()
    for k in range(steps):
        if k % n == 0:
            obs.reset()
        obs.step(p[k % n], b[k % n])
    return (time.perf_counter() - t) / steps * 1e9


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--steps", type=int, default=1_000_000)
    a = ap.parse_args()
    est = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3, 5, 7)]
    thesis = identify("greybox", make_dataset(est, 1000.0), name="thesis grey-box")
    from observer_node.loop.closed_loop import run_loop

    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        run_loop(est, [read_isomme(bundled_campaign() / "R16_002.zip")], work / "loop",
                 verbose=False, plots=False, ratings=False)
        loop = ModelFile.load(work / "loop" / "model.json")
        data = dataset_for(thesis, [read_isomme(bundled_campaign() / "R16_002.zip")])
        pulse, brs = data.pulse_g[0], data.brs_rad[0]
        inputs = work / "inputs.txt"
        np.savetxt(inputs, np.column_stack([pulse, brs]), fmt="%.17g")
        print(f"{a.steps} steps over R16_002's {len(pulse)} ticks at 1000 Hz "
              f"(Python: {a.steps // 10} steps)")
        print(f"  {'model':<44}{'C double':>10}{'C float':>10}{'Python':>10}   object file "
              "(double; float)")
        for mf in (thesis, loop):
            d_ns, d_size = c_row(mf, work, "double", inputs, a.steps)
            f_ns, f_size = c_row(mf, work, "float", inputs, a.steps)
            p_ns = py_ns(mf, pulse, brs, a.steps // 10)
            print(f"  {mf.name[:44]:<44}{d_ns:>8.1f}ns{f_ns:>8.1f}ns{p_ns:>8.0f}ns   "
                  f"{d_size}; {f_size}")


if __name__ == "__main__":
    main()
