"""export-c: the generated C99 observer compiles warning-free and steps as the Python one."""

from __future__ import annotations

import ctypes
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from observer_node.data import bundled_campaign, read_isomme
from observer_node.evaluation import dataset_for, identify
from observer_node.export_c import export_c
from observer_node.ident.dataset import make_dataset
from observer_node.model.modelfile import ModelFile

CC = shutil.which("cc") or shutil.which("gcc")
pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler")

HARNESS = """#include <stddef.h>
#include "chest_observer.h"
size_t co_size(void) { return sizeof(co_observer); }
void co_run(const co_real *pulse, const co_real *brs, int n, co_real *y)
{
    co_observer obs;
    int k;
    co_reset(&obs);
    for (k = 0; k < n; k++) co_step(&obs, pulse[k], brs[k], y + 2 * k);
}
"""


def build(mf: ModelFile, tmp: Path, real: str) -> tuple[ctypes.CDLL, type]:
    export_c(mf, tmp)
    (tmp / "harness.c").write_text(HARNESS)
    lib = tmp / f"obs_{real}.so"
    subprocess.run([CC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                    "-shared", "-fPIC", f"-DCO_REAL={real}", "-o", str(lib),
                    str(tmp / "chest_observer.c"), str(tmp / "harness.c"), "-lm"],
                   check=True, capture_output=True, text=True)
    ct = ctypes.c_double if real == "double" else ctypes.c_float
    return ctypes.CDLL(str(lib)), ct


def run_c(mf: ModelFile, tmp: Path, real: str, pulse: np.ndarray, brs: np.ndarray) -> np.ndarray:
    lib, ct = build(mf, tmp, real)
    dtype = np.float64 if real == "double" else np.float32
    p, b = np.ascontiguousarray(pulse, dtype), np.ascontiguousarray(brs, dtype)
    y = np.zeros((len(p), 2), dtype)
    ptr = ctypes.POINTER(ct)
    lib.co_run.argtypes = [ptr, ptr, ctypes.c_int, ptr]
    lib.co_run(p.ctypes.data_as(ptr), b.ctypes.data_as(ptr), len(p), y.ctypes.data_as(ptr))
    return y.astype(float)


def _inputs(mf: ModelFile) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The bundled validation tests' inputs at the model's rate, end to end, and the Python
    observer's outputs on them."""
    tests = [read_isomme(bundled_campaign() / f"{n}.zip") for n in ("R16_002", "FULL_002")]
    data = dataset_for(mf, tests)
    pulse, brs = data.pulse_g.ravel(), data.brs_rad.ravel()
    return pulse, brs, mf.observer().simulate(pulse, brs)


@pytest.fixture(scope="module")
def models(tmp_path_factory) -> dict[str, ModelFile]:
    est = [read_isomme(bundled_campaign() / f"R16_00{i}.zip") for i in (1, 3, 5)]
    data = make_dataset(est, 1000.0)
    return {"greybox": identify("greybox", data), "arx": identify("arx", data, nmax=4),
            "n4sid": identify("n4sid", data, order=7)}


@pytest.mark.parametrize("kind", ["greybox", "arx", "n4sid"])
def test_linear_models_in_c_equal_python(models, kind, tmp_path):
    mf = models[kind]
    pulse, brs, y_py = _inputs(mf)
    y_c = run_c(mf, tmp_path, "double", pulse, brs)
    scale = np.max(np.abs(y_py), axis=0)
    assert np.max(np.abs(y_c - y_py) / scale) < 1e-9
    y_f = run_c(mf, tmp_path, "float", pulse, brs)
    err = np.max(np.abs(y_f - y_py) / scale)
    print(f"{kind}: float's largest error {err:.2e} of the output's range")
    assert err < 1e-3


def test_every_exportable_effect_with_delays_and_offsets(models, tmp_path):
    """Each effect's force (the slack-belt switch and a fitted formula with every term among
    them), the delays and the offsets, at once, against Python."""
    base = {n: v["value"] for n, v in models["greybox"].parameters.items()}
    effects = [
        {"kind": "chest_stiffening", "parameters": {"k3": 3e7}},
        {"kind": "chest_rate_damping", "parameters": {"c3": 50.0}},
        {"kind": "belt_unloading", "parameters": {}},
        {"kind": "belt_stiffening", "parameters": {"kb3": 5e6}},
        {"kind": "airbag_contact", "parameters": {"kab": 3e4, "gap": 0.05, "cab": 300.0}},
        {"kind": "pelvis_coupling", "parameters": {"kp": 1e4, "cp": 300.0}},
        {"kind": "input_gain", "parameters": {"g": 0.02}},
        {"kind": "input_delay", "parameters": {"n_pulse": 2.4, "n_brs": 3.7}},
        {"kind": "sensor_offset", "parameters": {"cr_g": 0.5, "cd_mm": -1.0}},
        {"kind": "other", "parameters": {"rib": {"d^2": 2e5, "d'|d'|": 20.0, "d d'": 100.0},
                                         "belt": {"e^3": 1e6, "e'|e'|": 10.0, "d e": 1e4,
                                                  "e^2": 1e4, "d^3": 1e6}}},
    ]
    from observer_node.model.chest import PARAM_NAMES, model_matrices

    Ad, Bd, C, D = model_matrices(base, 1000.0, True)
    mf = ModelFile(kind="greybox", name="all-effects", tick_rate_hz=1000.0,
                   input_transform="velocity_brs_rate", A=Ad, B=Bd, C=C, D=D,
                   parameters={n: {"value": base[n]} for n in PARAM_NAMES}, effects=effects)
    mf = ModelFile.from_dict(mf.to_dict())  # what the loader accepts
    pulse, brs, y_py = _inputs(mf)
    assert np.all(np.isfinite(y_py)) and np.max(np.abs(y_py[:, 1])) > 5  # a real response
    y_c = run_c(mf, tmp_path, "double", pulse, brs)
    scale = np.max(np.abs(y_py), axis=0)
    assert np.max(np.abs(y_c - y_py) / scale) < 1e-9


def test_the_c_codec_from_the_dbc_round_trips_python_frames(tmp_path):
    """cantools' C codec of the DBC: every frame the Python codec makes (random values, E2E
    protected) unpacks and packs back to the same bytes, and a signal reads the same."""
    import random
    import re

    from observer_node.dbc import Codec
    from observer_node.export_c import export_codec

    codec = Codec()
    h, c = export_codec(tmp_path)
    names = re.findall(r"^int chest_observer_can_(\w+)_pack\(", h.read_text(), re.M)
    assert len(names) == len(codec.frames)
    cases = "\n".join(
        f"    case {k}: {{ struct chest_observer_can_{n}_t m;\n"
        f"        if (chest_observer_can_{n}_unpack(&m, in, n) != 0) return -1;\n"
        f"        return chest_observer_can_{n}_pack(out, &m, n); }}"
        for k, n in enumerate(names))
    (tmp_path / "rt.c").write_text(
        '#include "chest_observer_can.h"\n'
        "int roundtrip(int which, const uint8_t *in, uint8_t *out, size_t n)\n{\n"
        f"    switch (which) {{\n{cases}\n    }}\n    return -2;\n}}\n")
    lib = tmp_path / "codec.so"
    subprocess.run([CC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-O2", "-shared", "-fPIC",
                    "-o", str(lib), str(c), str(tmp_path / "rt.c")], check=True,
                   capture_output=True, text=True)
    so = ctypes.CDLL(str(lib))
    by_snake = {re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower(): fc
                for name, fc in codec.frames.items()}
    rng = random.Random(3)
    for k, n in enumerate(names):
        fc = by_snake[n]
        for j in range(50):
            raw = [rng.randint(*fc.raw_range(s)) for s in fc.signal_names]
            frame = fc.with_counter(fc.pack(raw), j)
            out = ctypes.create_string_buffer(fc.length)
            assert so.roundtrip(k, frame, out, fc.length) == fc.length, n
            assert out.raw == frame, n


CORE_HARNESS = """#include <stddef.h>
#include "chest_observer.h"
void core_run(const co_real *decel, const co_real *brs, int n, co_real *out)
{
    static co_core c;
    int k;
    co_core_init(&c);
    for (k = 0; k < n; k++) {
        co_core_set_brs(&c, brs[k], 96);
        co_core_tick(&c, decel[k]);
        out[6 * k] = c.cr_g; out[6 * k + 1] = c.cd_mm; out[6 * k + 2] = c.state;
        out[6 * k + 3] = co_core_valid(&c); out[6 * k + 4] = c.event;
        out[6 * k + 5] = c.faults;
    }
}
"""


def test_the_daemons_core_in_c_steps_as_the_python_core(models, tmp_path):
    """Arming, bias, trigger, onset catch-up, event end, re-arming on a shifted zero, a BRS
    counter reset: the C core and ObserverCore tick for tick."""
    from observer_node.daemon.core import ObserverCore
    from observer_node.data.crashtest import resample_inputs

    mf = models["greybox"]
    t = read_isomme(bundled_campaign() / "R16_002.zip")
    p, b, step = resample_inputs(t.pulse_g, t.brs, t.fs_hz, 1000.0)
    after = t.t0_s + np.arange(len(p)) * step / t.fs_hz >= 0
    pulse, counts = p[after], b[after].astype(float)
    rng = np.random.default_rng(4)
    decel = np.concatenate([0.2 * rng.normal(size=300), pulse, 1.5 + 0.2 * rng.normal(size=400),
                            1.5 + pulse, 1.5 + 0.2 * rng.normal(size=300)])
    brs = np.concatenate([np.zeros(300), counts, np.full(400, counts[-1]), counts[-1] + counts,
                          np.full(300, 0.0)])  # the last: a counter reset, a BRS jump
    core = ObserverCore(mf.observer())
    want = []
    for d, c in zip(decel, brs, strict=True):
        core.set_brs(c, 96)
        core.tick(d)
        want.append((core.cr_g, core.cd_mm, core.state, core.valid, core.event, core.faults))
    want_a = np.array(want, dtype=float)
    assert set(want_a[:, 4]) >= {0.0, 1.0} and core.brs_jumps == 1  # two events, one jump
    export_c(mf, tmp_path)
    (tmp_path / "core.c").write_text(CORE_HARNESS)
    lib = tmp_path / "core.so"
    subprocess.run([CC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                    "-shared", "-fPIC", "-o", str(lib), str(tmp_path / "chest_observer.c"),
                    str(tmp_path / "core.c"), "-lm"], check=True, capture_output=True, text=True)
    so = ctypes.CDLL(str(lib))
    out = np.zeros((len(decel), 6))
    ptr = ctypes.POINTER(ctypes.c_double)
    so.core_run.argtypes = [ptr, ptr, ctypes.c_int, ptr]
    d_, b_ = np.ascontiguousarray(decel), np.ascontiguousarray(brs)
    so.core_run(d_.ctypes.data_as(ptr), b_.ctypes.data_as(ptr), len(decel),
                out.ctypes.data_as(ptr))
    np.testing.assert_array_equal(out[:, 2:], want_a[:, 2:])  # state, valid, event, faults
    scale = np.max(np.abs(want_a[:, :2]), axis=0)
    assert np.max(np.abs(out[:, :2] - want_a[:, :2]) / scale) < 1e-9


def test_a_name_that_is_no_c_identifier_is_refused_and_a_model_name_stays_in_its_comment(
        models, tmp_path, capsys):
    """A hostile user's names (2026-12-03): --name ../x wrote outside --out, the codec's name
    overwrote the codec, '' wrote hidden files, a/b a traceback; a model named with "*/"
    ended the header's comment and injected C. Now one line each, nothing written, and the
    model's name cannot leave its comment."""
    from dataclasses import replace

    from observer_node import cli
    from observer_node.export_c import ExportError

    model = tmp_path / "m.json"
    replace(models["greybox"], name='evil */ #error injected /*\nnext').save(model)
    for name in ("../esc", "chest_observer_can", "", "a/b", "9lives", "x y"):
        code = cli.main(["export-c", str(model), "--out", str(tmp_path / "c"), "--name", name])
        err = capsys.readouterr().err
        assert code == 2 and len(err.strip().splitlines()) == 1 and "--name" in err, err
    assert not (tmp_path / "c").exists() and not (tmp_path / "esc.c").exists()
    with pytest.raises(ExportError, match="C identifier"):
        export_c(models["greybox"], tmp_path / "c", "../esc")
    assert cli.main(["export-c", str(model), "--out", str(tmp_path / "c")]) == 0
    assert "evil * / #error injected / * next" in (tmp_path / "c" / "chest_observer.h").read_text()
    (tmp_path / "c" / "harness.c").write_text(HARNESS)
    subprocess.run([CC, "-std=c99", "-Wall", "-Werror", "-pedantic", "-c", "-o",
                    str(tmp_path / "h.o"), str(tmp_path / "c" / "harness.c")],
                   check=True, capture_output=True, text=True)
