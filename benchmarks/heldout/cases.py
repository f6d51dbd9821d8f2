"""The held-out cases, as data. Written and committed before the loop ever ran on them; never
tune the loop on them (report them apart from the tuned cases).

Each case: 6 estimation + 6 validation tests (setup per test), BRS counts/rev, the physical
effects switched on (this simulator's own forms, ``physics.EFFECTS``) with their size and the
setups they act on, and the verdict expected in the loop library's terms.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace

ALL = ("R16", "SLED", "FULL")


def mix(r16: int, sled: int, full: int) -> tuple[str, ...]:
    """A test mix: so many tests of each rig, in the order R16, SLED, FULL."""
    return ("R16",) * r16 + ("SLED",) * sled + ("FULL",) * full


@dataclass(frozen=True)
class Effect:
    key: str  # physics.EFFECTS key
    size: float  # units per key: see physics.EFFECTS and the sizes below
    setups: tuple[str, ...] = ALL
    tests: tuple[str, ...] = ()  # only these tests (broken-test cases), else every test


@dataclass(frozen=True)
class Case:
    name: str
    seed: int
    est: tuple[str, ...]  # setup of each estimation test (6)
    val: tuple[str, ...]  # setup of each validation test (6)
    counts_per_rev: int
    effects: tuple[Effect, ...] = ()
    # expected verdict: (library effect, "all" or "+"-joined setups)
    expect: tuple[tuple[str, str], ...] = ()
    expect_broken: tuple[str, ...] = ()  # test names the loop must flag
    expect_note: str = ""
    notes: str = ""

    def as_dict(self) -> dict:
        return asdict(self)


MIX_A = ("R16", "R16", "SLED", "SLED", "FULL", "FULL")
MIX_B = ("R16", "R16", "R16", "SLED", "FULL", "FULL")
MIX_C = ("R16", "SLED", "SLED", "SLED", "FULL", "FULL")
MIX_D = ("R16", "R16", "SLED", "FULL", "FULL", "FULL")
R16_ONLY = ("R16",) * 6
INTERIOR = ("SLED", "SLED", "SLED", "FULL", "FULL", "FULL")

CASES: list[Case] = [
    Case("h_clean48", 7101, MIX_A, MIX_A, 48, notes="clean thorax, coarse 48-count BRS"),
    Case("h_clean96", 7203, MIX_B, MIX_C, 96, notes="clean thorax, 96-count BRS"),
    Case("h_ribs_bottoming", 7307, MIX_A, MIX_D, 96,
         (Effect("rib_bottoming", 9.0e7),), (("chest_stiffening", "all"),),
         notes="ribs stiffen beyond 12 mm deflection, F += k (|d| - 12 mm)^2.5"),
    Case("h_rib_fluid", 7411, MIX_D, MIX_A, 96,
         (Effect("rib_fluid", 8000.0),), (("chest_rate_damping", "all"),),
         notes="rate-stiffening rib damping material, F += c |d'|^2.2 sign(d')"),
    Case("h_slack_webbing", 7523, MIX_B, MIX_B, 96,
         (Effect("webbing_slack", 1.0),), (("belt_unloading", "all"),),
         notes="webbing cannot push, chest side and retractor side"),
    Case("h_webbing_toe", 7621, MIX_C, MIX_A, 48,
         (Effect("webbing_toe", 2.5),), (("belt_stiffening", "all"),),
         notes="webbing stiffens exponentially with stretch (toe 6 mm chest side, 10 mm "
               "up to the retractor)"),
    Case("h_airbag", 7717, MIX_A, MIX_C, 96,
         (Effect("airbag", 1.0, ("SLED", "FULL")),), (("airbag_contact", "SLED+FULL"),),
         notes="vented gas bag beyond an 85 mm gap on the rigs with an interior"),
    Case("h_lumbar", 7829, MIX_B, MIX_D, 96,
         (Effect("lumbar_path", 1.0),), (("pelvis_coupling", "all"),),
         notes="pelvis mass on lap belt and seat, lumbar spine to the thoracic spine"),
    Case("h_brs_eccentric", 7933, MIX_A, MIX_A, 96,
         (Effect("brs_eccentric", 0.3),), (("input_gain", "all"),),
         notes="BRS encoder ring 30 % off-centre: the angle is read as th + 0.3 sin(th + phase), "
               "a BRS gain 1 + 0.3 cos(th + phase) varying with the angle. (A spool radius "
               "growing 4 mm per wrap, the other cause, cost the grey-box < 0.5 points here: "
               "not visible, so not a case)"),
    Case("h_cd_zero_offset", 8039, MIX_D, MIX_B, 96,
         (Effect("zero_offset", 2.2),), (("sensor_offset", "all"),),
         notes="CD channel zeroed 2.2 mm off (compression), visible before t = 0"),
    Case("h_two_effects", 8147, MIX_A, MIX_A, 96,
         (Effect("rib_fluid", 5000.0, ("R16",)), Effect("airbag", 1.0, ("SLED", "FULL"))),
         (("chest_rate_damping", "R16"), ("airbag_contact", "SLED+FULL")),
         notes="rate damping on the R16 dummy only, airbag on the interior rigs"),
    Case("h_broken_brs", 8233, MIX_A, MIX_A, 96,
         (Effect("brs_freeze", 0.048, tests=("SLED_003",)),), (),
         expect_broken=("SLED_003",),
         notes="BRS cable fault: SLED_003's count freezes at 48 ms; physics clean"),
    Case("h_cd_transducer", 8353, MIX_C, MIX_C, 96,
         (Effect("cd_pot_nonlinear", 0.22),), (),
         expect_note="unexplained (or a sensor effect) on cd",
         notes="CD over-reads by 22 % at 25 mm (cubic static non-linearity), CR untouched"),
    Case("h_pulse_late_2ms", 8461, MIX_B, MIX_A, 96,
         (Effect("pulse_late", 0.002),), (("input_delay", "all"),),
         notes="the chest feels the pulse 2 ms after it is recorded"),
    Case("h_pulse_late_4ms", 8563, MIX_A, MIX_D, 48,
         (Effect("pulse_late", 0.004),), (("input_delay", "all"),),
         notes="the chest feels the pulse 4 ms after it is recorded"),
    Case("h_brs_late_1ms", 8669, MIX_C, MIX_B, 96,
         (Effect("brs_late", 0.001),), (("input_delay", "all"),),
         notes="the chest feels the belt 1 ms after the BRS records it"),
    Case("h_brs_late_3ms", 8761, MIX_A, MIX_A, 96,
         (Effect("brs_late", 0.003),), (("input_delay", "all"),),
         notes="the chest feels the belt 3 ms after the BRS records it"),
    Case("h_brs_late_5ms", 8867, MIX_D, MIX_C, 48,
         (Effect("brs_late", 0.005),), (("input_delay", "all"),),
         notes="the chest feels the belt 5 ms after the BRS records it"),
]

BY_NAME = {c.name: c for c in CASES}


# broken-test faults that take a channel from the test so many places away in the case
# (lab.record): on more estimation tests that place holds another test, so another fault
BY_PLACE = ("pulse_from", "brs_swap")


def more_tests(case: Case, times: int, new_crashes: bool = False) -> Case:
    """``case`` on ``times`` as many estimation tests of each rig, the same effects, sizes,
    scopes and validation rigs, every crash drawn again from another seed (the validation
    tests' too), named ``<case>_est<N>``; ``new_crashes`` draws them from yet another seed,
    named ``<case>_est<N>_new`` (at ``times`` 1: the same design on new crashes, the control
    for what more tests change). ``times`` 1 without ``new_crashes``: ``case`` itself.
    ValueError for ``times`` under 1, or a case whose fault pairs tests by their place
    (``BY_PLACE``), which on more or redrawn tests may pair other crashes than described."""
    if times < 1:
        raise ValueError(f"times must be 1 or more, not {times}")
    if times == 1 and not new_crashes:
        return case
    placed = sorted({e.key for e in case.effects if e.key in BY_PLACE})
    if placed:
        raise ValueError(f"{case.name}: its {placed[0]} takes a channel from the test so many "
                         "places away, which on more or redrawn tests may be another crash "
                         "than the case describes")
    est = mix(*(times * case.est.count(r) for r in ALL))
    return replace(case, name=f"{case.name}_est{len(est)}" + ("_new" if new_crashes else ""),
                   est=est, seed=case.seed + 1_000_000 * (times - 1)
                   + (500_000 if new_crashes else 0))


def test_names(case: Case) -> tuple[list[str], list[str]]:
    """Names of the estimation and validation tests: odd numbers estimate, even validate,
    numbered per setup (R16_001, R16_003 estimate; R16_002 validates)."""
    est: list[str] = []
    val: list[str] = []
    for setups, out, first in ((case.est, est, 1), (case.val, val, 2)):
        count: dict[str, int] = {}
        for s in setups:
            k = count.get(s, 0)
            count[s] = k + 1
            out.append(f"{s}_{first + 2 * k:03d}")
    return est, val

