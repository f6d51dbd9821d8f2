"""``observer-node export-c``: a model file as a dependency-free C99 observer for an ECU.

The generated ``chest_observer.c`` and ``chest_observer.h`` step exactly what the daemon's
Python observer steps (:mod:`observer_node.model.observer`, :mod:`observer_node.model.nonlinear`):
the input transform (integrated pulse and BRS rate, or raw inputs), the discrete state space,
and for a grey-box with effects, every effect's force held over the tick (its C code is in its
definition, :mod:`observer_node.model.effects`; the fitted formula's too), the slack-belt
switch to the belt-free matrices, input delays and sensor offsets; and the daemon's core around
it (:mod:`observer_node.daemon.core`: arming, bias, trigger, validity). Numbers are written
with 17 significant digits, so the C model is the model file's.

The arithmetic type is ``co_real``: ``double`` unless compiled with ``-DCO_REAL=float``. No
heap, no libm beyond ``fabs``, no state outside the caller's ``co_observer``.

The frame codec comes from the DBC through cantools' C generator (:func:`export_codec`:
``chest_observer_can.c/.h``, a pack and unpack function and a struct per frame), so the C side
reads the same database as the Python codec. Its E2E CRCs are not in it: an ECU's AUTOSAR
E2E library protects and checks the frames (the profiles and data IDs are in the DBC).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from observer_node.dbc.meanings import InvalidCause, ObserverState

from .daemon.core import CoreConfig
from .errors import ObserverError
from .model.chest import discrete
from .model.effects import EFFECTS
from .model.modelfile import ModelFile
from .model.nonlinear import NonlinearGreyBox
from .model.observer import LinearObserver


def supported_effects() -> list[str]:
    """The effects with a C form: every force with its C code, and the delays, offsets and
    the belt switch, which the generator writes itself."""
    return [k for k, e in EFFECTS.items() if e.acts != "force" or e.c_code is not None]


CODEC_NAME = "chest_observer_can"  # the frame codec's files


class ExportError(ObserverError, ValueError):
    """A model file this generator cannot turn into C; the message says which part."""


def _num(v: float) -> str:
    return f"{float(v):.17g}" if np.isfinite(v) else "0.0"


def _matrix(name: str, m: np.ndarray) -> str:
    rows = ",\n".join("    {" + ", ".join(_num(v) for v in row) + "}" for row in np.atleast_2d(m))
    return f"static const co_real {name}[{m.shape[0]}][{m.shape[1]}] = {{\n{rows}\n}};\n"


def _matvec(out: str, name: str, rows: int, cols: int, vec: str, acc: bool) -> str:
    """C lines: out[i] (+)= sum_j name[i][j] * vec[j], unrolled over j."""
    lines = []
    for i in range(rows):
        terms = " + ".join(f"{name}[{i}][{j}] * {vec}[{j}]" for j in range(cols))
        lines.append(f"    {out}[{i}] {'+=' if acc else '='} {terms};")
    return "\n".join(lines)


CORE_H = """
/* The daemon's core (observer_node/daemon/core.py): arming on a learned accelerometer zero,
 * the crash trigger, the onset search and catch-up, the event's end, re-arming when the pulse
 * is quiet again, and the estimate's validity. Per accelerometer sample:
 *     co_core_set_brs(&core, brs_count, counts_per_rev);   (when a BRS count arrives)
 *     co_core_tick(&core, decel_g);                         (deceleration positive, with bias)
 * then core.cr_g, core.cd_mm, core.state, co_core_valid(&core). Faults: co_core_fault. */
{enums}
#define CO_N_BIAS {n_bias}
#define CO_N_PRE {n_pre}

typedef struct {{
    co_observer obs;
    int state;
    long tick_index, invalid_until, onset_tick, brs_tick;
    int event, events, run_ticks, above, hold, pre_i, pre_n, bias_n, bias_i;
    int unsettled, bias_bad, brs_seen;
    unsigned cause, faults;
    long hold_timeouts, bias_faults, brs_jumps, events_cut;
    co_real bias_g, bias_sum, bias_sq, last_pulse, brs_count, brs_ref, rad_per_count;
    co_real cr_g, cd_mm;
    co_real bias_ring[CO_N_BIAS], pre_pulse[CO_N_PRE], pre_brs[CO_N_PRE];
}} co_core;

void co_core_init(co_core *c);
void co_core_reset(co_core *c);
void co_core_set_brs(co_core *c, co_real count, int counts_per_rev);
void co_core_fault(co_core *c, unsigned cause);
void co_core_tick(co_core *c, co_real decel_g);
void co_core_bridge(co_core *c, int missing);
void co_core_end_event(co_core *c);
int co_core_armed(const co_core *c);
int co_core_valid(const co_core *c);
"""

def _c_enums() -> str:
    """The core's states and cause bits as C enums, valued as the DBC's (dbc/meanings.py);
    INIT is the bus's only (the core starts ARMED)."""
    states = ", ".join(f"CO_{s.name} = {s.value}" for s in ObserverState
                       if s != ObserverState.INIT)
    causes = [f"CO_{c.name} = {c.value}" for c in InvalidCause]
    return (f"enum {{ {states} }};\n"
            f"enum {{ {', '.join(causes[:4])},\n       {', '.join(causes[4:])} }};")


CORE_C = """
/* ---- the daemon's core: see chest_observer.h and observer_node/daemon/core.py ---- */
#define CO_TRIGGER_G ((co_real){trigger_g})
#define CO_TRIGGER_TICKS {trigger_ticks}
#define CO_ONSET_G ((co_real){onset_g})
#define CO_N_EVENT {n_event}
#define CO_N_REARM {n_rearm}
#define CO_N_HOLD_MAX {n_hold_max}
#define CO_QUIET_VAR ((co_real){quiet_var})
#define CO_BIAS_MAX_G ((co_real){bias_max_g})
#define CO_BRS_MAX_STEP ((co_real){brs_max_step})
#define CO_RECOVER_TICKS {recover_ticks}
#define CO_MAX_BRIDGE {max_bridge}
#define CO_RAD_PER_COUNT ((co_real){rad_per_count})

static void clear_window(co_core *c) {{ c->bias_n = c->bias_i = 0; c->bias_sum = c->bias_sq = 0; }}

void co_core_init(co_core *c) {{ c->rad_per_count = CO_RAD_PER_COUNT; c->hold_timeouts =
    c->bias_faults = c->brs_jumps = c->events_cut = 0; co_core_reset(c); }}

void co_core_reset(co_core *c)
{{
    c->state = CO_ARMED; c->tick_index = -1; clear_window(c); c->bias_g = 0;
    c->pre_i = c->pre_n = c->above = c->hold = 0; c->unsettled = c->bias_bad = 0;
    c->brs_count = 0; c->brs_tick = -1; c->brs_seen = 0; c->brs_ref = 0;
    c->event = -1; c->events = 0; c->onset_tick = -1; c->run_ticks = 0;
    c->cr_g = c->cd_mm = 0; c->invalid_until = 0; c->cause = c->faults = 0;
    c->last_pulse = 0; co_reset(&c->obs);
}}

void co_core_fault(co_core *c, unsigned cause)
{{
    c->cause |= cause; c->faults |= cause;
    c->invalid_until = c->tick_index + 1 + CO_RECOVER_TICKS;
}}

void co_core_set_brs(co_core *c, co_real count, int counts_per_rev)
{{
    if (counts_per_rev > 0) c->rad_per_count = (co_real)(6.283185307179586 / counts_per_rev);
    if (c->brs_seen) {{
        long ticks = c->tick_index - c->brs_tick;
        co_real step = count - c->brs_count;
        if (ticks < 1) ticks = 1;
        if (fabs(step) * c->rad_per_count > CO_BRS_MAX_STEP * ticks) {{
            c->brs_jumps++; c->brs_ref += step; co_core_fault(c, CO_SENSOR_FAULT);
        }}
    }}
    c->brs_seen = 1; c->brs_tick = c->tick_index; c->brs_count = count;
}}

int co_core_armed(const co_core *c)
{{
    if (c->state == CO_RUNNING) return 1;
    return c->state == CO_ARMED && c->bias_n > 0 && !c->unsettled;
}}

int co_core_valid(const co_core *c)
{{
    return c->tick_index >= c->invalid_until && co_core_armed(c);
}}

static void to_hold(co_core *c)
{{
    c->state = CO_HOLD; c->hold = 0; c->event = -1; clear_window(c);
}}

static void push(co_core *c, co_real v)
{{
    int j = c->bias_i, k;
    if (c->bias_n == CO_N_BIAS) {{
        co_real old = c->bias_ring[j];
        c->bias_sum -= old; c->bias_sq -= old * old;
    }} else c->bias_n++;
    c->bias_ring[j] = v; c->bias_sum += v; c->bias_sq += v * v;
    if (++j == CO_N_BIAS) {{  /* once per window: exact again, no drift over days */
        j = 0; c->bias_sum = c->bias_sq = 0;
        for (k = 0; k < CO_N_BIAS; k++) {{
            c->bias_sum += c->bias_ring[k]; c->bias_sq += c->bias_ring[k] * c->bias_ring[k];
        }}
    }}
    c->bias_i = j;
}}

static int quiet(const co_core *c)
{{
    co_real mean;
    if (c->bias_n < CO_N_BIAS) return 0;
    mean = c->bias_sum / c->bias_n;
    return c->bias_sq / c->bias_n - mean * mean < CO_QUIET_VAR;
}}

static void learn_bias(co_core *c)
{{
    int bad;
    c->bias_g = c->bias_sum / c->bias_n;
    bad = fabs(c->bias_g) > CO_BIAS_MAX_G;
    if (bad) {{ if (!c->bias_bad) c->bias_faults++; co_core_fault(c, CO_SENSOR_FAULT); }}
    c->bias_bad = bad;
}}

static void step(co_core *c, co_real decel_g)
{{
    co_real y[2];
    co_step(&c->obs, decel_g - c->bias_g, (c->brs_count - c->brs_ref) * c->rad_per_count, y);
    c->cr_g = y[0]; c->cd_mm = y[1];
}}

static void start(co_core *c)
{{
    int n = c->pre_n, last = (c->pre_i - 1 + CO_N_PRE) % CO_N_PRE, back = 0, first, m;
    co_real brs_now = c->brs_count;
    while (back + 1 < n) {{
        int k = ((last - back - 1) % CO_N_PRE + CO_N_PRE) % CO_N_PRE;
        if (c->pre_pulse[k] - c->bias_g < CO_ONSET_G) break;
        back++;
    }}
    first = ((last - back) % CO_N_PRE + CO_N_PRE) % CO_N_PRE;
    c->onset_tick = c->tick_index - back;
    c->brs_ref = c->pre_brs[first];
    co_reset(&c->obs);
    c->state = CO_RUNNING; c->event = c->events++; c->run_ticks = back + 1;
    for (m = 0; m <= back; m++) {{
        int k = (first + m) % CO_N_PRE;
        c->brs_count = c->pre_brs[k];
        step(c, c->pre_pulse[k]);
    }}
    c->brs_count = brs_now;
}}

static void armed(co_core *c, co_real decel_g)
{{
    int i = c->pre_i;
    c->cr_g = c->cd_mm = 0;
    c->pre_pulse[i] = decel_g; c->pre_brs[i] = c->brs_count;
    c->pre_i = (i + 1) % CO_N_PRE;
    if (c->pre_n < CO_N_PRE) c->pre_n++;
    if (c->bias_n && decel_g - c->bias_g >= CO_TRIGGER_G) {{
        if (++c->above >= CO_TRIGGER_TICKS) start(c);
        return;
    }}
    c->above = 0;
    push(c, decel_g);
    learn_bias(c);
    if (c->unsettled) {{
        if (quiet(c)) c->unsettled = 0; else co_core_fault(c, CO_SENSOR_FAULT);
    }}
}}

static void holding(co_core *c, co_real decel_g)
{{
    int q;
    c->cr_g = c->cd_mm = 0;
    c->hold++;
    push(c, decel_g);
    q = quiet(c);
    if ((q && c->hold >= CO_N_REARM) || c->hold >= CO_N_HOLD_MAX) {{
        if (!q) {{ c->hold_timeouts++; c->unsettled = 1; co_core_fault(c, CO_SENSOR_FAULT); }}
        learn_bias(c);
        c->state = CO_ARMED; c->pre_n = 0; c->above = 0;
    }}
}}

static void tick(co_core *c, co_real decel_g, int bridged)
{{
    c->tick_index++;
    if (!bridged) {{
        c->last_pulse = decel_g;
        if (c->tick_index >= c->invalid_until) c->cause = 0;
    }}
    if (c->state == CO_ARMED) armed(c, decel_g);
    else if (c->state == CO_RUNNING) {{
        step(c, decel_g);
        if (++c->run_ticks >= CO_N_EVENT) to_hold(c);
    }} else holding(c, decel_g);
}}

void co_core_tick(co_core *c, co_real decel_g) {{ tick(c, decel_g, 0); }}

void co_core_bridge(co_core *c, int missing)
{{
    int k;
    co_core_fault(c, CO_LOST_FRAME);
    for (k = 0; k < missing && k < CO_MAX_BRIDGE; k++) tick(c, c->last_pulse, 1);
}}

void co_core_end_event(co_core *c)
{{
    if (c->state == CO_RUNNING) {{ c->events_cut++; to_hold(c); }}
}}
"""

HEADER = """/* {name}: chest observer generated by observer-node export-c {version} from a {kind}
 * model file ({model}), tick rate {rate:g} Hz. Do not edit: regenerate from the model file.
 *
 * Per tick: co_step(&obs, pulse_g, brs_rad, y) with the bias-free crash pulse in g
 * (vehicle deceleration positive) and the belt spindle angle in rad (+ = webbing
 * retracted, counts * 2 pi / counts_per_rev); y[0] = chest acceleration CR in g
 * (retardation positive), y[1] = chest deflection CD in mm (compression positive).
 * co_reset(&obs) puts the observer at rest (state zero, the next BRS sample its reference).
 */
#ifndef CHEST_OBSERVER_H
#define CHEST_OBSERVER_H

#ifndef CO_REAL
#define CO_REAL double
#endif
typedef CO_REAL co_real;

#define CO_TICK_RATE_HZ {rate:.17g}
#define CO_STATES {nx}

typedef struct {{
    co_real x[CO_STATES];      /* state */
    co_real velocity;          /* integral of the pulse, m/s */
    co_real brs_prev;          /* last BRS angle, rad */
    int has_prev;              /* 0: the next BRS sample is the reference */
    long k;                    /* ticks since reset */
    co_real pulse_ring[{np1}]; /* input delay of the pulse (whole ticks + 2) */
    co_real brs_ring[{nb1}];   /* input delay of the BRS */
    co_real brs_first;         /* first BRS sample: the delayed BRS before it exists */
}} co_observer;

void co_reset(co_observer *obs);
void co_step(co_observer *obs, co_real pulse_g, co_real brs_rad, co_real y[2]);
{core}
#endif
"""


def export_c(mf: ModelFile, out_dir: str | Path, name: str = "chest_observer",
             core: CoreConfig | None = None, setup: str | None = None) -> list[Path]:
    """Write ``name``.h and ``name``.c for ``mf`` into ``out_dir``, with the daemon's core
    at ``core`` (default: the daemon's defaults); returns the paths. ``setup``: the bench's
    setup, for a model with effects scoped to setups (only that setup's effects are
    exported)."""
    from . import __version__

    check_c_name(name)
    cfg = core or CoreConfig()
    fs = mf.tick_rate_hz
    n_bias = max(2, round(cfg.bias_window_s * fs))
    n_rearm = round(cfg.rearm_s * fs)
    consts = {"enums": _c_enums(), "n_bias": n_bias, "n_pre": max(2, round(cfg.pretrigger_s * fs)
                                             + cfg.trigger_ticks + 1),
              "trigger_g": _num(cfg.trigger_g), "trigger_ticks": cfg.trigger_ticks,
              "onset_g": _num(cfg.onset_g), "n_event": round(cfg.event_s * fs),
              "n_rearm": n_rearm,
              "n_hold_max": max(n_bias, n_rearm, round(cfg.hold_max_s * fs)),
              "quiet_var": _num(cfg.quiet_g ** 2), "bias_max_g": _num(cfg.bias_max_g),
              "brs_max_step": _num(cfg.brs_max_rate_rad_s / fs),
              "recover_ticks": cfg.recover_ticks, "max_bridge": cfg.max_bridge_ticks,
              "rad_per_count": _num(2 * np.pi / cfg.counts_per_rev)}

    out = Path(out_dir)
    obs = mf.observer(setup)
    if isinstance(obs, NonlinearGreyBox):
        body, nx, n_pulse, n_brs = _nonlinear(obs)
    else:
        body, nx, n_pulse, n_brs = _linear(obs), obs.A.shape[0], 0, 0
    header = HEADER.format(name=name, version=__version__, kind=mf.kind,
                           model=_in_comment(mf.name) or "-",
                           rate=mf.tick_rate_hz, nx=nx, np1=n_pulse + 1, nb1=n_brs + 1,
                           core=CORE_H.format(**consts))
    source = (f"/* Generated by observer-node export-c {__version__}: see {name}.h. */\n"
              f"#include <math.h>\n#include \"{name}.h\"\n\n{body}"
              + CORE_C.format(**consts))
    out.mkdir(parents=True, exist_ok=True)
    h, c = out / f"{name}.h", out / f"{name}.c"
    h.write_text(header, encoding="utf-8")
    c.write_text(source, encoding="utf-8")
    return [h, c]


def check_c_name(name: str) -> None:
    """``name`` names the files and the include guard: a C identifier, not the codec's (a
    path such as ../x would write outside the folder, chest_observer_can over the codec)."""
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,62}", name):
        raise ExportError(f"--name {name!r}: must be a C identifier (letters, digits and _, "
                          "not starting with a digit)")
    if name == CODEC_NAME:
        raise ExportError(f"--name {name}: is the frame codec's name; choose another")


def _in_comment(text: str) -> str:
    """``text`` made safe inside a C block comment: one line, no end of comment, no start of
    one (-Wcomment)."""
    return " ".join(text.replace("*/", "* /").replace("/*", "/ *").split())


def export_codec(out_dir: str | Path, dbc_path: str | Path | None = None,
                 name: str = CODEC_NAME) -> list[Path]:
    """Write ``name``.h and ``name``.c, the frame codec cantools generates from the DBC."""
    import cantools
    from cantools.database.can.c_source import generate

    from .dbc import DBC_PATH

    db = cantools.database.load_file(str(dbc_path or DBC_PATH))
    if not isinstance(db, cantools.database.can.Database):
        raise ExportError(f"{dbc_path}: not a CAN database")
    header, source, _, _ = generate(db, name, f"{name}.h", f"{name}.c", f"{name}_fuzzer.c")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    h, c = out / f"{name}.h", out / f"{name}.c"
    h.write_text(header, encoding="utf-8")
    c.write_text(source, encoding="utf-8")
    return [h, c]


def _inputs(transform: str, fs_hz: float) -> str:
    """C lines setting u[0], u[1] from pulse_g and brs_rad (the model's input transform)."""
    if transform == "raw":
        return "    u[0] = pulse_g;\n    u[1] = brs_rad;\n"
    return (f"    obs->velocity += pulse_g * (co_real){_num(9.80665 / fs_hz)};\n"
            "    if (!obs->has_prev) { obs->brs_prev = brs_rad; obs->has_prev = 1; }\n"
            "    u[0] = obs->velocity;\n"
            f"    u[1] = (brs_rad - obs->brs_prev) * (co_real){_num(fs_hz)};\n"
            "    obs->brs_prev = brs_rad;\n")


RESET = """void co_reset(co_observer *obs)
{
    int i;
    for (i = 0; i < CO_STATES; i++) obs->x[i] = 0;
    obs->velocity = 0;
    obs->brs_prev = 0;
    obs->has_prev = 0;
    obs->k = 0;
    obs->brs_first = 0;
    for (i = 0; i < (int)(sizeof obs->pulse_ring / sizeof obs->pulse_ring[0]); i++)
        obs->pulse_ring[i] = 0;
    for (i = 0; i < (int)(sizeof obs->brs_ring / sizeof obs->brs_ring[0]); i++)
        obs->brs_ring[i] = 0;
}

"""


def _linear(obs: LinearObserver) -> str:
    nx = obs.A.shape[0]
    return (_matrix("A", obs.A) + _matrix("B", obs.B) + _matrix("C", obs.C)
            + _matrix("D", obs.D) + "\n" + RESET
            + "void co_step(co_observer *obs, co_real pulse_g, co_real brs_rad, co_real y[2])\n"
            "{\n    co_real u[2], xn[CO_STATES];\n    int i;\n"
            + _inputs(obs.transform, obs.fs_hz)
            + _matvec("y", "C", 2, nx, "obs->x", False) + "\n"
            + _matvec("y", "D", 2, 2, "u", True) + "\n"
            + _matvec("xn", "A", nx, nx, "obs->x", False) + "\n"
            + _matvec("xn", "B", nx, 2, "u", True) + "\n"
            + "    for (i = 0; i < CO_STATES; i++) obs->x[i] = xn[i];\n    obs->k++;\n}\n")


def _force(kind: str, p: dict, base: dict) -> str:
    """C lines adding one effect's forces to fs (spine) and fn (sternum), as its definition's
    formula (:mod:`observer_node.model.effects`) computes them."""
    code = EFFECTS[kind].c_code
    if code is None:
        raise ExportError(f"effect {kind!r} has no C form (supported: "
                          f"{', '.join(supported_effects())})")
    return code(p, _num, {n: _num(base[n]) for n in ("k2", "c2", "R")})


def _nonlinear(obs: NonlinearGreyBox) -> tuple[str, int, int, int]:
    supported = supported_effects()
    for e in obs.effects:
        if e["kind"] not in supported:
            raise ExportError(f"effect {e['kind']!r} has no C form (supported: "
                              f"{', '.join(supported)}; in Python: "
                              f"{', '.join(EFFECTS)})")
    nx = obs.Ad.shape[0]
    slack = discrete({**obs.base, "k2": 0.0, "c2": 0.0}, obs.fs_hz) if obs.unloading else None
    tables = (_matrix("Ad", obs.Ad) + _matrix("Bd", obs.Bd) + _matrix("Gd", obs.Gd)
              + _matrix("C", obs.C) + _matrix("Df", obs.Df))
    if slack is not None:
        tables += (_matrix("Ad_slack", slack[0]) + _matrix("Bd_slack", slack[1])
                   + _matrix("Gd_slack", slack[2]))
    k2, c2, R = (_num(obs.base[n]) for n in ("k2", "c2", "R"))
    forces = "".join(_force(kind, p, obs.base) for kind, p, _ in obs.force_effects)
    delay = ""
    for sig, n, before in (("pulse_g", obs.n_pulse, "0"), ("brs_rad", obs.n_brs, "obs->brs_first")):
        if not n:
            continue
        # the input n ticks ago, n = i + f: linear between the samples i and i + 1 ticks ago
        # (``before`` until they exist: 0 for the pulse, the first sample for the BRS)
        i, f, ring = int(n), n - int(n), sig.split("_")[0] + "_ring"
        first = "    if (obs->k == 0) obs->brs_first = brs_rad;\n" if sig == "brs_rad" else ""
        delay += (first + f"    obs->{ring}[obs->k % {i + 2}] = {sig};\n"
                  f"    {{ co_real a = obs->k >= {i} ? obs->{ring}[(obs->k - {i}) % {i + 2}]"
                  f" : {before};\n"
                  f"      co_real b = obs->k >= {i + 1} ? obs->{ring}[(obs->k - {i + 1}) % {i + 2}]"
                  f" : {before};\n"
                  f"      {sig} = a + {_num(f)} * (b - a); }}\n")
    # the effects' forces at a state (and whether the belt is slack there), used for the
    # update and, with the output after the tick's inputs, again at the new state
    forces_fn = ("static int co_forces(const co_real *z, const co_real u[2], co_real theta, "
                 "co_real f[2])\n{\n"
                 "    co_real d = z[3] - z[1];       /* chest compression s - x */\n"
                 "    co_real dd = z[2] - z[0];\n"
                 "    co_real e = z[4] - z[3];       /* belt penetration w - s */\n"
                 "    co_real pos = z[5];            /* vehicle displacement */\n"
                 f"    co_real ed = u[0] + {R} * u[1] - z[2];\n"
                 "    co_real fs = 0, fn = 0;\n"
                 "    (void)d; (void)dd; (void)e; (void)pos; (void)ed; (void)theta;\n"
                 + forces + "    f[0] = fs;\n    f[1] = fn;\n"
                 + (f"    return {k2} * e + {c2} * ed < 0;\n}}\n\n" if slack is not None
                    else "    return 0;\n}\n\n"))

    def output(state: str) -> str:
        return (_matvec("y", "C", 2, nx, state, False) + "\n"
                + _matvec("y", "Df", 2, 2, "f", True) + "\n"
                + f"    y[0] += {_num(obs.offset[0])};\n    y[1] += {_num(obs.offset[1])};\n")

    step = ("void co_step(co_observer *obs, co_real pulse_g, co_real brs_rad, co_real y[2])\n"
            "{\n    co_real u[2], f[2], xn[CO_STATES];\n"
            "    const co_real *z = obs->x;\n"
            "    int i, slack;\n"
            + delay + _inputs("velocity_brs_rate", obs.fs_hz)
            + "    slack = co_forces(z, u, brs_rad, f);\n"
            + ("" if obs.after_input else output("z"))
            + ("    if (slack) {\n" + _matvec("xn", "Ad_slack", nx, nx, "z", False) + "\n"
               + _matvec("xn", "Bd_slack", nx, 2, "u", True) + "\n"
               + _matvec("xn", "Gd_slack", nx, 2, "f", True) + "\n    } else {\n"
               if slack is not None else "    {\n")
            + _matvec("xn", "Ad", nx, nx, "z", False) + "\n"
            + _matvec("xn", "Bd", nx, 2, "u", True) + "\n"
            + _matvec("xn", "Gd", nx, 2, "f", True) + "\n    }\n"
            + "    (void)slack;\n"
            "    for (i = 0; i < CO_STATES; i++) obs->x[i] = xn[i];\n    obs->k++;\n"
            + ("    /* the output of the state after this tick's inputs */\n"
               "    (void)co_forces(obs->x, u, brs_rad, f);\n" + output("obs->x")
               if obs.after_input else "")
            + "}\n")
    return (tables + "\n" + RESET + forces_fn + step, nx, int(obs.n_pulse) + 1,
            int(obs.n_brs) + 1)
