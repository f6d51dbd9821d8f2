"""A frontal-crash dummy thorax, its belt and retractor, written from the physics.

Independent of the observer's own model and simulator: nothing here is imported from, or
copied out of, ``observer_node``. Its purpose is data that can surprise the loop.

Frame: one axis, positive rearward, in the frame that keeps the vehicle's speed before impact
(an unrestrained occupant stays at 0; the decelerating vehicle moves +). SI units inside.

Bodies (per test, all tests of a batch integrated at once, one column each):

- thoracic spine ``x`` (the CR accelerometer), mass ``m_sp``;
- sternum on two masses, upper ``sa`` (the diagonal belt crosses it) and lower ``sb``, each
  tied to the spine by its ribs (spring + damper) and to each other by the sternum plate;
  the chest pot reads mid-sternum: CD = (sa + sb)/2 - x, compression positive;
- the belt at the chest ``u``: a small lumped mass (webbing, flesh) between a chest-side
  segment (``k_b``, ``c_b``) and the webbing up to the retractor (``k_up``), with Coulomb-like
  friction at the D-ring proportional to the tension (hysteresis between loading and
  unloading);
- the retractor spool ``th`` (what the BRS counts), inertia ``J``: a pyrotechnic pretensioner
  torque pulse, a ratchet lock after ``t_lock``, and a torsion bar (load limiter): elastic up
  to its yield torque, then it flows (viscoplastic), moving the lock reference ``L``;
- optional bodies and forces for the switchable effects (see ``EFFECTS``).

Fixed step RK4 at 20 kHz; outputs every second step (10 kHz).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

G = 9.80665  # m/s^2 per g
FS_HZ = 10_000.0  # recorded rate
T0_S = -0.020  # time of the first recorded sample
N_SAMPLES = 2200
SUB = 2  # integration steps per recorded sample (20 kHz)
GRID = 2 * SUB  # vehicle-kinematics points per recorded sample (stage midpoints)

# Physics effect keys (what this simulator switches) -> the loop library's name for it.
EFFECTS = {
    "rib_bottoming": "chest_stiffening",  # ribs stiffen past an onset deflection (power 2.5)
    "rib_fluid": "chest_rate_damping",  # rate-stiffening rib damping material, |rate|^2.2
    "webbing_slack": "belt_unloading",  # webbing carries no compression (both segments)
    "webbing_toe": "belt_stiffening",  # exponential stiffening of the webbing (both segments)
    "airbag": "airbag_contact",  # vented gas bag beyond a gap, loads spine and sternum
    "lumbar_path": "pelvis_coupling",  # pelvis mass, lap belt/seat to the car, lumbar spine
    "pulse_late": "input_delay",  # the chest feels the pulse this late after its record (s)
    "brs_late": "input_delay",  # the chest feels the belt this late after the BRS record (s)
    "spool_buildup": "input_gain",  # spool radius grows with wound webbing (m per wrap)
    "brs_eccentric": "input_gain",  # encoder ring off-centre: angle read with error e sin(th)
    "zero_offset": "sensor_offset",  # CD channel zeroed wrong (mm, visible at rest)
    "brs_freeze": "",  # broken test: BRS cable fault, the count freezes (time, s)
    "cd_pot_nonlinear": "",  # transducer: CD over-reads at large deflection (CR untouched)
    # set B's forms (cases_b.py)
    "rib_hardening": "chest_stiffening",  # ribs harden from zero, F += k3 d^3 (N/m^3)
    "rib_visco": "chest_rate_damping",  # rib damping, F += c |d'|^1.5 sign(d') (N/(m/s)^1.5)
    "webbing_hysteresis": "belt_unloading",  # elastic force this much lower while shortening
    "webbing_power": "belt_stiffening",  # webbing F += a k e (e/e_ref)^2 (dimensionless a)
    "airbag_relief": "airbag_contact",  # gas bag with a pressure-relief vent (fill scale)
    "pulse_gain": "input_gain",  # pulse accelerometer sensitivity error (relative)
    "cd_dropout": "",  # broken test: CD wiper lifts, raw CD reads 0 for 10 ms (start, s)
    "pulse_rail": "",  # broken test: pulse channel clips at this range (g)
    "cr_gain": "",  # transducer: CR sensitivity error (relative), CD untouched
    "cd_knee": "",  # transducer: CD reads at 0.6 gain beyond this knee (mm), CR untouched
    # set C's forms (cases_c.py)
    "rib_bilinear": "chest_stiffening",  # rib stiffness grows by this x k_r past BILIN_ON_M
    "rib_valve": "chest_rate_damping",  # F += c d'^2 while compressing only (N/(m/s)^2)
    "webbing_set": "belt_unloading",  # chest side unloads to a set of this x its peak stretch
    "webbing_knee": "belt_stiffening",  # webbing stiffness grows by this x k past KNEE_M
    "airbag_sealed": "airbag_contact",  # unvented gas bag (fill scale of the vented one's)
    "pulse_zero_shift": "",  # broken test: pulse channel zero shifts by this at SHIFT_AT_S (g)
    "neck_head": "",  # head and upper neck on the spine through a soft neck (mass, kg)
    # set D's lab-side forms (cases_d.py): recorded channels only, the physics untouched
    "cd_spikes": "",  # broken test: CD connector spikes of this height (mm) at SPIKES_S
    "cr_soft_clip": "",  # transducer: CR amplifier compresses, reads R tanh(cr / R) (R, g)
    "brs_reversed": "",  # broken test: BRS direction set wrong in the recorder (1 = on)
    # set E's lab-side forms (cases_e.py): recorded channels only, the physics untouched
    "cr_cable_break": "",  # broken test: CR cable breaks at this time (s), reads a constant
    "cr_reversed": "",  # broken test: CR recorded at the wrong polarity (1 = on)
    "cr_progressive": "",  # transducer: CR over-reads by this (relative) at CR_PROG_G, ~cr^2
    # set F's lab-side forms (cases_f.py): recorded channels only, the physics untouched
    "brs_reset": "",  # broken test: the BRS counter resets to zero at this time (s)
    "cr_hum": "",  # broken test: mains hum (HUM_HZ) on the CR channel, this amplitude (g)
    "cd_compress": "",  # transducer: CD reads R tanh(cd / R) (R, mm), CR untouched
    # set G's lab-side forms (cases_g.py): recorded channels only, the physics untouched
    "cd_rail": "",  # broken test: CD conditioner's range too small, clips at this (mm)
    "pulse_sync": "",  # broken test: pulse channel's time base this early (s), own trigger
    "cd_dead_band": "",  # transducer: CD reads nothing over the linkage's first b mm (b, mm)
    # set H's forms (cases_h.py): three physical forms no earlier set used, three lab-side
    "rib_squeeze": "chest_rate_damping",  # squeeze-film damping, ~ 1/gap^3 as the chest closes
    "airbag_fabric": "airbag_contact",  # ventless bag leaking through its fabric (fill scale)
    "pelvis_submarine": "pelvis_coupling",  # pelvis path, the lap belt slips at this force (N)
    "cd_stuck_bit": "",  # broken test: a data line of the CD digitiser stuck at 1 (bit number)
    "brs_quadrature": "",  # broken test: BRS decoder counts this many edges a step (x4 mode)
    "cr_ac_coupled": "",  # transducer: piezoelectric CR, charge leaks with this time constant (s)
    # set I's forms (cases_i.py): one physical form no earlier set used, three lab-side
    "rib_lock": "chest_stiffening",  # the chest locks up near this deflection (m): k d^2/(d_l - d)
    "brs_poll": "",  # broken test: the BRS's quadrature tracks polled at this rate (Hz), aliasing
    "cr_lost_block": "",  # broken test: the CR recorder loses a block of this length (s)
    "cd_backlash": "",  # transducer: play of this width (mm) in the chest pot arm's slot
    # set J's forms (cases_j.py): one physical form no earlier set used, three lab-side
    "rib_fung": "chest_stiffening",  # the rib cage stiffens exponentially (Fung), amount a (-)
    "cr_loose_mount": "",  # broken test: CR accelerometer's mount loosened, resonance (Hz)
    "brs_swap": "",  # broken test: BRS channel of another test of the case (its offset, tests)
    "cd_arm_lift": "",  # transducer: chest pot arm returns no faster than this (mm/ms = m/s)
    # set K's forms (cases_k.py): one physical form no earlier set used, two lab-side
    "airbag_dual": "airbag_contact",  # vented bag, two-stage inflator (fill scale of each)
    "pulse_from": "",  # broken test: pulse channel of another test of the case (its offset)
    "cr_zero_shift": "",  # transducer: CR zero shifts by this (g) once it first reads CR_SHIFT_G
    # set L's forms (cases_l.py): one physical form no earlier set used, two lab-side
    "pelvis_knee": "pelvis_coupling",  # pelvis path (lumbar_path's, this scale) + knee bolster
    "pulse_rate": "",  # broken test: pulse module sampled at this x the stated rate (ratio)
    "cd_aa_filter": "",  # transducer: CD through a causal 4-pole anti-alias filter at this (Hz)
    # set M's forms (cases_m.py): two physical forms no earlier set used, two lab-side
    "rib_maxwell": "chest_rate_damping",  # viscoelastic rib material: a Maxwell branch, k x k_r
    "dring_capstan": "belt_unloading",  # D-ring friction as a capstan, exponent mu theta (-)
    "dummy_scale": "",  # broken test: run with another dummy, of this length scale (-)
    "cr_crosstalk": "",  # transducer: CR picks up CD's signal, this many g per mm of CD
    # set N's forms (cases_n.py): two lab-side
    "dummy_soak": "",  # broken test: thorax soaked this many K below its band (K; < 0: above)
    "cd_sag": "",  # transducer: the CD pot's excitation sags after trigger, gain lost (relative)
    # set O's forms (cases_o.py): one physical form no earlier set used, two lab-side
    "rib_friction": "chest_rate_damping",  # dry (Coulomb) friction in the rib cage, this force (N)
    "brs_counts": "",  # broken test: the BRS file holds raw counts under its degrees (1 = on)
    "cr_damped": "",  # transducer: CR through an oil-damped sensing element of this f_n (Hz)
    # set Q's forms (cases_q.py): two lab-side, one timing error of the dummy's recorder
    "cr_late": "",  # transducer: the CR digitiser channel writes its samples this late (s)
    "cd_rc_filter": "",  # transducer: CD through a one-pole RC low-pass at this corner (Hz)
    "dummy_late": "input_delay",  # the dummy's recorder writes CR and CD this late (s)
    # set R's forms (cases_r.py): one physical form no earlier set used, two lab-side
    "rib_foam": "chest_rate_damping",  # damping pad engaging with compression, c at FOAM_D_M
    "cd_reversed": "",  # broken test: CD recorded at the wrong polarity (1 = on)
    "cd_slew": "",  # transducer: CD's amplifier follows no faster than this (mm/ms = m/s)
    # set S's forms (cases_s.py): one physical form no earlier set used, two lab-side
    "rib_loss": "chest_rate_damping",  # the ribs' damping layer's loss factor: eta k d sign(d')
    "brs_wrap": "",  # broken test: the BRS counter holds this many bits (two's complement)
    "cr_creep": "",  # transducer: CR's gauges creep in their adhesive, this share (tau CREEP_TAU_S)
    # set T's forms (cases_t.py): one physical form no earlier set used, three lab-side
    "rib_bumper": "chest_stiffening",  # lower sternum meets the spine box's stop: K pen^1.5
    "pulse_ms2": "",  # broken test: the pulse file in m/s^2 under its header's g (1 = on)
    "cd_arm_ring": "",  # transducer: the chest pot's arm resonates at this (Hz), lightly damped
    "cr_drift": "",  # transducer: CR's zero drifts from the trigger on at this rate (g/s)
    # set U's forms (cases_u.py): two lab-side, its physics the library's ordinary forms
    "pulse_cable_break": "",  # broken test: the pulse cable parts at this time (s), reads 0 g
    "cd_pot_loading": "",  # transducer: the chest pot loaded by its conditioner, R_pot/R_in
    # set V's forms (cases_v.py): two lab-side, its physics any set's forms, drawn (draw_v.py)
    "cr_rail": "",  # broken test: CR conditioner's range too small, clips at this (g)
    "cr_clock": "",  # transducer: CR's module clock slow by this share, its time base stretched
    # set W's form (cases_w.py): one lab-side, drawn into its pools beside every earlier set's
    "cd_clock": "",  # transducer: CD's module clock slow by this share, its time base stretched
}
POW_B_M = (0.015, 0.025)  # webbing_power: reference stretch, chest side and up to the retractor
V_HYST = 0.02  # m/s: webbing_hysteresis switches between its paths within this rate
RELIEF_PA = (40e3, 10e3, 25.0)  # airbag_relief: opens at, fully open after, vent rate (1/s)
BILIN_ON_M = 0.016  # rib_bilinear: deflection where the ribs' second load path starts
KNEE_M = (0.022, 0.016)  # webbing_knee: knee stretch, chest side and up to the retractor
# neck_head: small-amplitude neck stiffness (N/m; ~5.5 Hz with 5 kg), secant stiffness tripled
# at NECK_REF_M, damping ratio. Constants, not NOMINAL keys, so sets A and B draw as before.
NECK_K, NECK_REF_M, NECK_ZETA = 6.0e3, 0.080, 0.25
# rib_squeeze: the gap between sternum and spine box at rest; the film's force is taken no
# further than 80 % closed (the ribs' own bottoming is another form)
SQUEEZE_GAP_M = 0.060
# airbag_fabric: leak rate through the fabric (1/s at one atmosphere over ambient, the whole
# fabric free), and the fabric's area (two 0.7 m panels), part of it covered by the occupant
FABRIC_K, FABRIC_M2 = 15.0, 0.77
# rib_lock: the locking spring is taken no further than this share of its lock deflection
LOCK_MAX = 0.85

# rib_fung: the exponential's deflection scale (the cage's costal cartilage and soft tissue,
# Fung's law for soft tissue), and how far it is taken (exp of at most this multiple)
FUNG_D0_M, FUNG_ZMAX = 0.012, 3.5

# airbag_dual: a driver bag (set A's vented form) on a two-stage inflator. The first stage fills
# it as set A's does; the second fires DUAL_DT_S after the first (the controller's delay for a
# severe, belted crash) and burns for DUAL_BURN_S, adding DUAL_GAS of the first stage's gas at
# a constant rate while the vents go on venting
DUAL_DT_S, DUAL_BURN_S, DUAL_GAS = 0.030, 0.008, 0.3

# pelvis_knee: the knees meet the knee bolster (an interior's lower instrument panel) once the
# pelvis has moved this far forward in the car; the bolster's foam and the femurs in series
# load it at BOLSTER_K (N/m, both knees) up to the foam's crush plateau BOLSTER_F (N), reached
# smoothly (tanh); its unloading taken on the loading curve (the foam's crush hysteresis left
# out). Constants, not NOMINAL keys, so earlier sets draw as before.
BOLSTER_GAP_M, BOLSTER_K, BOLSTER_F = 0.045, 250e3, 5000.0

# rib_maxwell: the rib cage's damping material as a viscoelastic solid (a standard linear solid):
# beside each rib's spring and damper a spring of effect-size x the rib's stiffness in series
# with a dashpot, relaxing with this time constant (s): stiff to a fast load, giving way to a
# slow one. Its force is a state of its own (two: one per sternum mass)
MAXWELL_TAU_S = 0.010
# dring_capstan: the shoulder webbing wraps the D-ring (a capstan): sliding, the tension on the
# chest side is the retractor side's times exp(+a) while the chest draws the webbing out and
# exp(-a) while the retractor takes it back (a = mu theta, friction coefficient times wrap
# angle), in place of the nominal small, linear D-ring friction; it sticks below this slip
# speed (m/s), smoothly (tanh)
CAPSTAN_V_S = 0.15

# rib_friction: the rib cage's dry friction (the ribs' bib and the sternum's guide rubbing on the
# spine box): a force of the effect's size (N) per sternum mass against the chest's rate,
# Coulomb's, smoothed (tanh) within this rate (m/s) so it sticks softly about zero rate
RIB_FRICTION_V_S = 0.02

# rib_foam: the sternum's damping pad (a viscoelastic foam between the bib and the spine box)
# is met over a contact area that grows as the chest closes: its damping grows in proportion to
# the compression, F += c (d / FOAM_D_M) d' (c, the effect's size, N s/m at FOAM_D_M), in
# compression only, from zero at rest, the contact taken no further than FOAM_MAX_M
FOAM_D_M, FOAM_MAX_M = 0.030, 0.060

# rib_loss: the ribs' bonded damping polymer as a constant loss factor (hysteretic, or
# structural, damping: the energy lost per cycle a share of the elastic energy stored, about
# independent of the rate): each rib adds eta k_r d in the sense of its rate, in compression
# only, from zero at rest (stiffer by eta loading, softer by eta unloading); the sense switches
# smoothly (tanh) within this rate (m/s), and the deflection is taken no further than LOSS_MAX_M
LOSS_V_S, LOSS_MAX_M = 0.02, 0.060

# rib_bumper: the sternum's lower edge (the lower sternum mass, below where the diagonal belt
# crosses) meets the spine box's deflection stop, a rubber bumper, once its ribs have closed
# BUMPER_GAP_M: a Hertzian contact (a rubber pad under a rounded edge), F = K pen^1.5 (K, the
# effect's size, N/m^1.5), in compression only, on the lower sternum mass alone (the upper one
# has no stop behind it)
BUMPER_GAP_M = 0.015

# Nominal Hybrid-III-like thorax, belt and retractor (SI), before per-test scatter.
NOMINAL = {
    "m_sp": 22.0, "m_a": 0.45, "m_b": 0.45,
    "k_ra": 120e3, "k_rb": 110e3, "c_ra": 550.0, "c_rb": 500.0,
    "k_ab": 60e3, "c_ab": 80.0, "beta": 0.62,
    "m_u": 0.12, "k_b": 160e3, "c_b": 2600.0, "k_up": 260e3, "c_up": 1800.0,
    "mu_d": 0.10, "v_slip": 0.05,
    "J": 3.0e-4, "r0": 0.017, "c_spool": 0.01,
    "k_tb": 300.0, "tau_y": 62.0, "eta_tb": 0.3,
    "tau_pt": 40.0, "t_pt": 0.007, "d_pt": 0.006, "t_lock": 0.003,
    # pelvis path (used by lumbar_path only)
    "m_p": 14.0, "k_l": 60e3, "c_l": 900.0, "k_lap": 90e3, "c_lap": 1500.0,
    # airbag (used by airbag only)
    "t_bag": 0.018, "gap_bag": 0.085, "V_bag": 0.060, "A_bag": 0.08, "Amax_bag": 0.06,
    "dA_bag": 0.03, "p_fill": 1.35, "k_vent": 9.0, "f_st_bag": 0.45,
}
SCATTER = 0.05  # relative 1-sigma scatter of the dummy, belt and retractor, clipped at 2 sigma
NO_SCATTER = {"t_lock", "v_slip", "beta", "f_st_bag"}
P_ATM = 101_325.0


def _stage_time(j: np.ndarray | int) -> np.ndarray | float:
    return T0_S + np.asarray(j) * (1.0 / FS_HZ / GRID)


@dataclass
class Batch:
    """Parameters (name -> column (n, 1)) and vehicle kinematics on the stage grid (n, m)."""

    p: dict[str, np.ndarray]
    eff: dict[str, np.ndarray]  # effect key -> size per test (n, 1), 0 = off
    xv: np.ndarray  # vehicle displacement, m
    vv: np.ndarray  # vehicle velocity change, m/s


N_STATE = 19  # x vx sa va sb vb u vu th om L p vp q, chest-side peak stretch, head, its speed,
# the two Maxwell branches' forces (N)


def _deriv(b: Batch, j: np.ndarray | int, y: np.ndarray) -> np.ndarray:
    p, e = b.p, b.eff
    t = _stage_time(j)
    x, vx, sa, va, sb, vb, u, vu, th, om, lk, pp, vp, q, pk, hh, vh, ma, mb = y
    if np.ndim(j) == 0:
        xv, vv = b.xv[:, [int(j)]], b.vv[:, [int(j)]]  # (n, 1)
    else:
        xv, vv = b.xv[:, j], b.vv[:, j]

    # ribs: spine <-> each sternum mass
    da, db = sa - x, sb - x
    dva, dvb = va - vx, vb - vx
    fa = p["k_ra"] * da + p["c_ra"] * dva
    fb = p["k_rb"] * db + p["c_rb"] * dvb
    kb = e["rib_bottoming"]  # N/m^2.5 beyond the onset
    if np.any(kb):
        on = 0.012
        fa = fa + kb * np.sign(da) * np.maximum(np.abs(da) - on, 0.0) ** 2.5
        fb = fb + kb * np.sign(db) * np.maximum(np.abs(db) - on, 0.0) ** 2.5
    cf = e["rib_fluid"]  # N/(m/s)^2.2
    if np.any(cf):
        fa = fa + cf * np.sign(dva) * np.abs(dva) ** 2.2
        fb = fb + cf * np.sign(dvb) * np.abs(dvb) ** 2.2
    kh = e["rib_hardening"]
    if np.any(kh):
        fa = fa + kh * da ** 3
        fb = fb + kh * db ** 3
    cv = e["rib_visco"]
    if np.any(cv):
        fa = fa + cv * np.sign(dva) * np.abs(dva) ** 1.5
        fb = fb + cv * np.sign(dvb) * np.abs(dvb) ** 1.5
    kl = e["rib_bilinear"]
    if np.any(kl):
        fa = fa + kl * p["k_ra"] * np.sign(da) * np.maximum(np.abs(da) - BILIN_ON_M, 0.0)
        fb = fb + kl * p["k_rb"] * np.sign(db) * np.maximum(np.abs(db) - BILIN_ON_M, 0.0)
    cvv = e["rib_valve"]
    if np.any(cvv):  # resists compression (d' > 0) only
        fa = fa + cvv * np.maximum(dva, 0.0) ** 2
        fb = fb + cvv * np.maximum(dvb, 0.0) ** 2
    csq = e["rib_squeeze"]  # N s/m: the film's damping at rest, beyond the ribs' own
    if np.any(csq):  # the chest contents squeezed between sternum and spine: c ~ 1/gap^3
        ga = np.clip(da, 0.0, 0.8 * SQUEEZE_GAP_M)
        gb = np.clip(db, 0.0, 0.8 * SQUEEZE_GAP_M)
        fa = fa + csq * dva * ((SQUEEZE_GAP_M / (SQUEEZE_GAP_M - ga)) ** 3 - 1.0)
        fb = fb + csq * dvb * ((SQUEEZE_GAP_M / (SQUEEZE_GAP_M - gb)) ** 3 - 1.0)
    dl = e["rib_lock"]  # m: the deflection where the chest would lock solid
    if np.any(dl):  # ribs straightening, the contents incompressible: a hyperbolic spring
        lock = np.where(dl > 0, dl, 1.0)
        ca = np.clip(da, 0.0, LOCK_MAX * lock)
        cb = np.clip(db, 0.0, LOCK_MAX * lock)
        fa = fa + np.where(dl > 0, p["k_ra"] * ca * ca / (lock - ca), 0.0)
        fb = fb + np.where(dl > 0, p["k_rb"] * cb * cb / (lock - cb), 0.0)
    af = e["rib_fung"]  # dimensionless: the amount of the exponential, in units of k d0
    if np.any(af):  # soft tissue's law (Fung): stiffness grows in proportion to force, so the
        za = np.clip(da / FUNG_D0_M, 0.0, FUNG_ZMAX)  # force is exponential in deflection;
        zb = np.clip(db / FUNG_D0_M, 0.0, FUNG_ZMAX)  # in compression only, from zero
        fa = fa + af * p["k_ra"] * FUNG_D0_M * (np.expm1(za) - za)
        fb = fb + af * p["k_rb"] * FUNG_D0_M * (np.expm1(zb) - zb)
    kmx = e["rib_maxwell"]  # the branch's spring, as a share of the rib's own stiffness
    dma = np.zeros_like(x)
    dmb = np.zeros_like(x)
    if np.any(kmx):  # each branch's force F: F' = k_m d' - F / tau, added to its rib's force
        fa = fa + ma
        fb = fb + mb
        dma = kmx * p["k_ra"] * dva - ma / MAXWELL_TAU_S
        dmb = kmx * p["k_rb"] * dvb - mb / MAXWELL_TAU_S
    ffr = e["rib_friction"]  # N: Coulomb friction, rate-independent once sliding
    if np.any(ffr):
        fa = fa + ffr * np.tanh(dva / RIB_FRICTION_V_S)
        fb = fb + ffr * np.tanh(dvb / RIB_FRICTION_V_S)
    cfo = e["rib_foam"]  # N s/m at FOAM_D_M: a damper whose rate grows with the compression
    if np.any(cfo):
        fa = fa + cfo * np.clip(da, 0.0, FOAM_MAX_M) / FOAM_D_M * dva
        fb = fb + cfo * np.clip(db, 0.0, FOAM_MAX_M) / FOAM_D_M * dvb
    eta = e["rib_loss"]  # the loss factor (dimensionless): a force in phase with the rate's sense
    if np.any(eta):
        fa = fa + eta * p["k_ra"] * np.clip(da, 0.0, LOSS_MAX_M) * np.tanh(dva / LOSS_V_S)
        fb = fb + eta * p["k_rb"] * np.clip(db, 0.0, LOSS_MAX_M) * np.tanh(dvb / LOSS_V_S)
    kbu = e["rib_bumper"]  # N/m^1.5: the lower sternum mass's stop, Hertz past its gap
    if np.any(kbu):
        fb = fb + kbu * np.maximum(db - BUMPER_GAP_M, 0.0) ** 1.5
    fab = p["k_ab"] * (sa - sb) + p["c_ab"] * (va - vb)

    # belt, chest side: pushes the contact point of the sternum rearward
    sc = p["beta"] * sa + (1 - p["beta"]) * sb
    vc = p["beta"] * va + (1 - p["beta"]) * vb
    ext = u - sc
    el = p["k_b"] * ext
    toe = e["webbing_toe"]  # dimensionless amount of exponential toe
    if np.any(toe):
        e0 = 0.006
        z = np.clip(np.maximum(ext, 0.0) / e0, 0.0, 6.0)
        el = el + toe * p["k_b"] * e0 * (np.expm1(z) - z)
    pw = e["webbing_power"]
    if np.any(pw):
        el = el + pw * p["k_b"] * np.maximum(ext, 0.0) ** 3 / POW_B_M[0] ** 2
    hy = e["webbing_hysteresis"]
    if np.any(hy):  # a softer elastic path while the segment shortens
        el = el * (1.0 - hy * 0.5 * (1.0 - np.tanh((vu - vc) / V_HYST)))
    kn = e["webbing_knee"]
    if np.any(kn):
        el = el + kn * p["k_b"] * np.maximum(ext - KNEE_M[0], 0.0)
    st = e["webbing_set"]
    if np.any(st):  # below its peak stretch the webbing unloads to a permanent set
        peak = np.maximum(pk, ext)
        s0 = st * peak
        unl = p["k_b"] * peak * np.maximum(ext - s0, 0.0) / np.maximum(peak - s0, 1e-9)
        el = np.where((st > 0) & (peak > 1e-6) & (ext < peak), unl, el)
    fc = el + p["c_b"] * (vu - vc)

    # webbing to the retractor: retracted length grows with the spool radius
    tw = e["spool_buildup"]  # m of radius per wrap
    r = p["r0"] + tw * th / (2 * np.pi)
    length = p["r0"] * th + tw * th * th / (4 * np.pi)
    stretch = xv + length - u
    tr = p["k_up"] * stretch + p["c_up"] * (vv + r * om - vu)
    if np.any(toe):  # the same webbing up to the retractor: its toe scales with its length
        e1 = 0.010
        z1 = np.clip(np.maximum(stretch, 0.0) / e1, 0.0, 6.0)
        tr = tr + toe * p["k_up"] * e1 * (np.expm1(z1) - z1)
    if np.any(pw):
        tr = tr + pw * p["k_up"] * np.maximum(stretch, 0.0) ** 3 / POW_B_M[1] ** 2
    if np.any(kn):
        tr = tr + kn * p["k_up"] * np.maximum(stretch - KNEE_M[1], 0.0)
    if np.any(hy):  # its elastic part only: the damping stays as it is
        el_up = tr - p["c_up"] * (vv + r * om - vu)
        tr = tr - el_up * hy * 0.5 * (1.0 - np.tanh((vv + r * om - vu) / V_HYST))
    slack = e["webbing_slack"] > 0
    if np.any(slack):
        fc = np.where(slack, np.maximum(fc, 0.0), fc)
        tr = np.where(slack, np.maximum(tr, 0.0), tr)
    # D-ring friction opposes the webbing sliding relative to the car, grows with tension
    fr = p["mu_d"] * np.abs(tr) * np.tanh((vu - vv) / p["v_slip"])
    cap = e["dring_capstan"]  # mu theta of the webbing on its D-ring
    if np.any(cap):  # capstan: chest side = retractor side x exp(a) drawn out, exp(-a) back
        gain = np.where(vu - vv > 0, -np.expm1(-cap), np.expm1(cap))
        fr_cap = np.abs(tr) * gain * np.tanh((vu - vv) / CAPSTAN_V_S)
        fr = np.where(cap > 0, fr_cap, fr)

    # retractor: pretensioner pulse, ratchet + torsion bar once locked
    tpt = (t - p["t_pt"]) / p["d_pt"]
    tau_pt = np.where((tpt > 0) & (tpt < 1), p["tau_pt"] * np.sin(np.pi * np.clip(tpt, 0, 1)), 0.0)
    locked = t >= p["t_lock"]
    tau_tb = np.where(locked, p["k_tb"] * np.maximum(lk - th, 0.0), 0.0)
    dlk = np.where(locked, -np.maximum(tau_tb - p["tau_y"], 0.0) / p["eta_tb"], om)

    # optional: pelvis, lumbar spine, lap belt and seat to the car
    fl = np.zeros_like(x)
    dvp = np.zeros_like(x)
    lum = e["lumbar_path"]  # scale of the lumbar and lap stiffness
    if np.any(lum):
        fl = lum * (p["k_l"] * (pp - x) + p["c_l"] * (vp - vx))
        lap = lum * (p["k_lap"] * (xv - pp) + p["c_lap"] * (vv - vp))
        dvp = (lap - fl) / p["m_p"]

    sub = e["pelvis_submarine"]  # the same path at scale 1, the lap belt slipping at sub (N)
    if np.any(sub):  # beyond it the belt rides over the iliac wings: the pelvis slides under
        fs_l = p["k_l"] * (pp - x) + p["c_l"] * (vp - vx)
        f_slip = np.where(sub > 0, sub, 1.0)
        lap_s = f_slip * np.tanh((p["k_lap"] * (xv - pp) + p["c_lap"] * (vv - vp)) / f_slip)
        fl = np.where(sub > 0, fs_l, fl)
        dvp = np.where(sub > 0, (lap_s - fs_l) / p["m_p"], dvp)

    kne = e["pelvis_knee"]  # lumbar_path's pelvis path at this scale, and the knee bolster:
    if np.any(kne):  # the knees (femurs) push the pelvis rearward once it closes BOLSTER_GAP_M
        fl_k = kne * (p["k_l"] * (pp - x) + p["c_l"] * (vp - vx))
        lap_k = kne * (p["k_lap"] * (xv - pp) + p["c_lap"] * (vv - vp))
        pen_k = np.maximum((xv - pp) - BOLSTER_GAP_M, 0.0)
        knee = BOLSTER_F * np.tanh(BOLSTER_K * pen_k / BOLSTER_F)
        fl = np.where(kne > 0, fl_k, fl)
        dvp = np.where(kne > 0, (lap_k + knee - fl_k) / p["m_p"], dvp)

    # optional: airbag (vented gas bag), contact once deployed and the torso closes the gap
    fbag = np.zeros_like(x)
    dq = np.zeros_like(x)
    bag = e["airbag"]  # scale of the bag's fill pressure above the nominal
    relief = e["airbag_relief"]  # the same, for a bag with a pressure-relief vent
    if np.any(relief):
        bag = bag + relief
    sealed = e["airbag_sealed"]  # the same, for a bag without vents
    if np.any(sealed):
        bag = bag + sealed
    fabric = e["airbag_fabric"]  # the same, for a bag without vent holes, of uncoated fabric
    if np.any(fabric):
        bag = bag + fabric
    dual = e["airbag_dual"]  # the same, for a vented bag on a two-stage inflator
    if np.any(dual):
        bag = bag + dual
    if np.any(bag):
        pen = np.maximum((xv - x) - p["gap_bag"], 0.0)
        deployed = (t > p["t_bag"] + 0.025) & (bag > 0)
        vol = np.maximum(p["V_bag"] - p["A_bag"] * pen, 0.3 * p["V_bag"])
        p_abs = P_ATM * p["p_fill"] * np.maximum(q, 0.0) * (p["V_bag"] / vol) ** 1.3
        p_g = np.maximum(p_abs - P_ATM, 0.0) * bag
        area = p["Amax_bag"] * np.minimum(pen / p["dA_bag"], 1.0)
        fbag = np.where(deployed, area * p_g, 0.0)
        dq = np.where(deployed, -p["k_vent"] * q * np.sqrt(p_g / P_ATM) * 0.1, 0.0)
        if np.any(relief):  # closed below its opening pressure, then vents fast
            opening = np.clip((p_g - RELIEF_PA[0]) / RELIEF_PA[1], 0.0, 1.0)
            dq = np.where(deployed & (relief > 0), -RELIEF_PA[2] * q * opening, dq)
        if np.any(sealed):  # no vent: the gas only compresses
            dq = np.where(sealed > 0, 0.0, dq)
        if np.any(fabric):  # the gas seeps through the free fabric, Darcy: flow ~ pressure
            free = 1.0 - area / FABRIC_M2
            leak = -FABRIC_K * q * (p_g / P_ATM) * free * (p["V_bag"] / vol)
            dq = np.where(deployed & (fabric > 0), leak, dq)
        if np.any(dual):  # the second stage's gas, into the bag as it vents
            burn = (t >= p["t_bag"] + DUAL_DT_S) & (t < p["t_bag"] + DUAL_DT_S + DUAL_BURN_S)
            dq = dq + np.where(burn & (dual > 0), DUAL_GAS / DUAL_BURN_S, 0.0)

    # optional: head and upper neck, tied to the spine only (pulls it forward as it lags)
    fn = np.zeros_like(x)
    dvh = np.zeros_like(x)
    mh = e["neck_head"]
    if np.any(mh):
        z = hh - x
        c_n = 2.0 * NECK_ZETA * np.sqrt(NECK_K * mh)
        fn = NECK_K * z * (1.0 + 2.0 * (z / NECK_REF_M) ** 2) + c_n * (vh - vx)
        fn = np.where(mh > 0, fn, 0.0)
        dvh = -fn / np.where(mh > 0, mh, 1.0)

    f_st = p["f_st_bag"]
    dvx = (fa + fb + fl + (1 - f_st) * fbag) / p["m_sp"]
    if np.any(mh):
        dvx = dvx + fn / p["m_sp"]
    dva = (-fa - fab + p["beta"] * fc + 0.5 * f_st * fbag) / p["m_a"]
    dvb = (-fb + fab + (1 - p["beta"]) * fc + 0.5 * f_st * fbag) / p["m_b"]
    dvu = (tr - fc - fr) / p["m_u"]
    dom = (tau_pt - r * np.maximum(tr, 0.0) + tau_tb - p["c_spool"] * om) / p["J"]
    return np.stack([vx, dvx, va, dva, vb, dvb, vu, dvu, om, dom, dlk, vp, dvp, dq,
                     np.zeros_like(x), vh, dvh, dma, dmb])


def simulate(b: Batch) -> dict[str, np.ndarray]:
    """Integrate from rest at the first recorded sample; return true signals at 10 kHz:
    ``cr`` (spine retardation, m/s^2), ``cd`` (compression, m), ``th`` (spool, rad),
    ``belt`` (chest-side belt force, N), all (n, N_SAMPLES)."""
    n = b.xv.shape[0]
    y = np.zeros((N_STATE, n, 1))
    y[13] = 1.0  # bag gas, relative to full
    h = 1.0 / FS_HZ / SUB
    keep = np.zeros((N_STATE, n, N_SAMPLES))
    keep[:, :, 0] = y[:, :, 0]
    for i in range(1, N_SAMPLES):
        for s in range(SUB):
            j = (i - 1) * GRID + 2 * s
            k1 = _deriv(b, j, y)
            k2 = _deriv(b, j + 1, y + 0.5 * h * k1)
            k3 = _deriv(b, j + 1, y + 0.5 * h * k2)
            k4 = _deriv(b, j + 2, y + h * k3)
            y = y + (h / 6.0) * (k1 + 2 * k2 + 2 * k3 + k4)
            locked = _stage_time(j + 2) >= b.p["t_lock"]
            y[10] = np.where(locked, np.maximum(y[10], y[8]), y[8])  # ratchet follows pay-in
            beta = b.p["beta"]  # webbing_set's peak chest-side stretch so far
            y[14] = np.maximum(y[14], y[6] - (beta * y[2] + (1 - beta) * y[4]))
        keep[:, :, i] = y[:, :, 0]
    jj = np.arange(N_SAMPLES) * GRID
    d = _deriv(b, jj, keep)
    sc = 0.5 * (keep[2] + keep[4])
    return {"cr": d[1], "cd": sc - keep[0], "th": keep[8], "x": keep[0]}


# ------------------------------------------------------------------------------ crash pulses

def pulse_shape(kind: str, rng: np.random.Generator, t: np.ndarray, dv_ms: float
                ) -> np.ndarray:
    """Vehicle (or sled) deceleration in m/s^2 at times ``t`` (s), zero before first contact,
    with ``dv_ms`` change of speed. ``kind``: R16 (sled, trapezoid with brake ripple), SLED
    (sled reproducing a car pulse, skewed bump) or FULL (barrier crush: crash-box spike,
    structure, engine block, ringing of the body, rebound)."""
    tp = np.maximum(t, 0.0)
    onset = 1.0 - np.exp(-tp / 0.0008)
    if kind == "R16":
        tr, tf = rng.uniform(0.010, 0.015), rng.uniform(0.009, 0.013)
        lvl = rng.uniform(24.0, 28.5) * G
        lp = max(dv_ms / lvl - 0.5 * (tr + tf), 0.01)
        rise = 0.5 - 0.5 * np.cos(np.pi * np.clip(tp / tr, 0, 1))
        fall = 0.5 + 0.5 * np.cos(np.pi * np.clip((tp - tr - lp) / tf, 0, 1))
        base = rise * fall
        ripple = 1.0 + 0.06 * np.sin(2 * np.pi * rng.uniform(45, 70) * tp + rng.uniform(0, 6))
        a = base * ripple
    elif kind == "SLED":
        k, tpk = rng.uniform(5.0, 7.0), rng.uniform(0.038, 0.048)
        a = (tp / tpk) ** k * np.exp(k * (1 - tp / tpk))
        a = a * (1.0 + 0.05 * np.sin(2 * np.pi * rng.uniform(70, 95) * tp))
        a = a + 0.25 * np.exp(-(((tp - 0.012) / 0.004) ** 2))  # interior rig engaging
    elif kind == "FULL":
        box = rng.uniform(0.5, 0.8) * np.exp(-(((tp - rng.uniform(0.007, 0.010)) / 0.003) ** 2))
        k, tpk = rng.uniform(6.0, 9.0), rng.uniform(0.040, 0.050)
        body = (tp / tpk) ** k * np.exp(k * (1 - tp / tpk))
        eng = rng.uniform(0.2, 0.4) * np.exp(-(((tp - rng.uniform(0.024, 0.030)) / 0.005) ** 2))
        ring = (rng.uniform(0.12, 0.22) * np.exp(-tp / 0.035)
                * np.sin(2 * np.pi * rng.uniform(110, 170) * tp))
        a = box + body + eng + ring * (box + body + 0.3)
    else:
        raise ValueError(f"unknown pulse kind {kind!r}")
    a = a * onset * (t >= 0)
    dt = t[1] - t[0]
    return a * dv_ms / (np.sum(a) * dt)


def kinematics(a: np.ndarray, dt_s: float) -> tuple[np.ndarray, np.ndarray]:
    """Velocity change and displacement (trapezoid) of deceleration ``a`` (last axis)."""
    v = np.concatenate([np.zeros((*a.shape[:-1], 1)),
                        np.cumsum(0.5 * (a[..., 1:] + a[..., :-1]) * dt_s, axis=-1)], axis=-1)
    x = np.concatenate([np.zeros((*a.shape[:-1], 1)),
                        np.cumsum(0.5 * (v[..., 1:] + v[..., :-1]) * dt_s, axis=-1)], axis=-1)
    return v, x


# --------------------------------------------------------------------------------- the lab

def cfc(x: np.ndarray, cfc_class: int, fs_hz: float = FS_HZ) -> np.ndarray:
    """SAE J211 channel frequency class filter: 2-pole Butterworth at 2.0775 x CFC, run
    forward and backward (phaseless, 4 poles)."""
    bb, aa = signal.butter(2, 2.0775 * cfc_class, fs=fs_hz)
    return signal.filtfilt(bb, aa, x, axis=-1)


def quantise_brs(th_rad: np.ndarray, counts_per_rev: int, phase: np.ndarray) -> np.ndarray:
    """Encoder counts of a spindle with ``counts_per_rev`` magnets: a count at every magnet
    passed, magnets at ``phase`` (fraction of a step) from the rest position."""
    step = 2 * np.pi / counts_per_rev
    ph = phase[:, None] * step
    return np.floor((th_rad + ph) / step) - np.floor(ph / step)
