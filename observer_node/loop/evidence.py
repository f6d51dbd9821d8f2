"""The rule an effect must pass to be named: paired, per test, against test-to-test scatter.

A candidate is judged by cross-validation inside the estimation tests: each test's fit_TOT by a
model fitted on the other half, with the candidate and without it. The per-test gains are paired
(the same test, the same fold), so the scatter between tests (dummy, belt routing, pulse) cancels
and what is left is whether the effect helps test after test. An effect is **accepted** only if

- its mean gain over the estimation tests is at least ``margin`` fit points,
- the gain is above test-to-test scatter: the 95 % confidence interval of the mean (Student's
  t, paired) lies above zero, or the sign test says the tests improve too consistently for
  chance (one-sided p <= ``SIGN_P``: with four tests, all four), and
- no setup's mean cross-validated fit falls by more than ``SETUP_TOLERANCE`` points.

Both tests, because a real effect's size varies from test to test (a belt unloads far more in
some crashes than in others): its gains can all be positive while their spread makes the
t-interval reach below zero on a few tests; the sign test sees that consistency whatever the
sizes, and the t-interval sees a large mean gain where one or two tests do not improve.

All tests count, those the effect does not act on too: the model is refitted whole, and a
scoped effect that frees the shared parameters helps (or harms) the other setups' tests as
well. The gain on the tests it acts on is reported beside.

A candidate that gains something but fails the rule is **possible**: reported, never named as a
finding.

A scope is a claim too: "on SLED and FULL only" says the R16 rig does not have the effect. When
the same effect also passes on a wider scope, the narrower one is named only if it beats the
wider one test by test, above the scatter (:func:`above_scatter`); otherwise the wider. """

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import asdict, dataclass

import numpy as np
from scipy import stats

SETUP_TOLERANCE = 0.3  # fit points: refit noise on setups an effect does not act on
SIGN_P = 0.0625  # one-sided sign test: 4 of 4, 5 of 5, 6 of 6 (0.016), 8 of 9, 10 of 12...
POSSIBLE_MIN = 0.25  # fit points: smaller mean gains are not worth listing
MAX_TESTS = 200  # needed_tests looks no further: beyond it, "even 200 would not"
POWER = 0.8  # needed_tests: the chance of passing it plans for (the usual 4 in 5)


@dataclass
class Evidence:
    """How well the data defend a candidate (fit points are eq. 3.15's, CR and CD averaged)."""

    gain_points: float  # mean paired gain over the estimation tests
    ci95_points: tuple[float, float]  # 95 % t-interval of that mean
    gain_in_scope_points: float  # mean paired gain over the tests the effect acts on
    test_gain_points: dict[str, float]  # per test
    tests_improved: int
    tests: int
    sign_test_p: float  # one-sided: P(at least this many improve | no effect)
    setup_gain_points: dict[str, float]  # mean paired gain per setup, over all its tests
    accepted: bool
    reason: str  # why not, when not accepted
    # failed on the scatter alone: the judged estimation tests that, gaining and scattering as
    # these did, would pass the interval test 4 times in 5 (:func:`needed_tests`); else None
    tests_to_defend: int | None = None
    # tests whose fold's refit took no step (refit.fold_scores), counted as gaining nothing
    stalled_tests: tuple[str, ...] = ()

    def as_dict(self) -> dict:
        d = asdict(self)
        d["ci95_points"] = [round(v, 2) for v in self.ci95_points]
        for k in ("gain_points", "sign_test_p", "gain_in_scope_points"):
            d[k] = round(d[k], 3)
        d["test_gain_points"] = {k: round(v, 2) for k, v in self.test_gain_points.items()}
        d["setup_gain_points"] = {k: round(v, 2) for k, v in self.setup_gain_points.items()}
        return d

    @classmethod
    def from_dict(cls, d: dict) -> Evidence:
        """Evidence as :meth:`as_dict` wrote it (rounded)."""
        return cls(**{**d, "ci95_points": tuple(d["ci95_points"]),
                      "stalled_tests": tuple(d.get("stalled_tests", ()))})

    @property
    def confidence(self) -> str:
        """One line for the report: gain, interval, tests improved."""
        lo, hi = self.ci95_points
        n = len(self.stalled_tests)
        stalled = (f"; {n} test{'s' * (n > 1)} whose fold's refit took no step counted as "
                   f"no gain ({', '.join(self.stalled_tests)})" if n else "")
        return (f"{self.gain_points:+.1f} points (95 % CI {lo:+.1f}..{hi:+.1f}), "
                f"{self.tests_improved}/{self.tests} tests improved (sign test p = "
                f"{self.sign_test_p:.3f}){stalled}")


def above_scatter(d: np.ndarray) -> tuple[bool, float, float, int, float]:
    """Whether paired per-test differences ``d`` are above test-to-test scatter: the 95 %
    t-interval of their mean above zero, or the one-sided sign test p <= ``SIGN_P``. Returns
    that, the mean, the interval's half width, the tests that improve and the sign test's p."""
    mean = float(np.mean(d))
    if len(d) > 1 and np.std(d, ddof=1) > 0:
        half = float(stats.t.ppf(0.975, len(d) - 1) * np.std(d, ddof=1) / np.sqrt(len(d)))
    else:
        half = float("inf")
    improved = int(np.sum(d > 0))
    sign_p = float(stats.binomtest(improved, len(d), 0.5, alternative="greater").pvalue)
    return mean - half > 0 or sign_p <= SIGN_P, mean, half, improved, sign_p


def needed_tests(d: np.ndarray) -> int | None:
    """How many tests it would take for the t-interval half of the rule to pass 4 times in 5,
    if tests gained and scattered as the per-test gains ``d`` [fit points] do: the smallest n,
    up to ``MAX_TESTS``, at which the 95 % t-interval of the mean lies above zero with
    probability ``POWER`` (Student's t, non-central by mean sqrt(n) / sd). None when that
    cannot be said (fewer than two tests, gains not finite, a mean not above zero, no spread)
    or n exceeds ``MAX_TESTS``; ``Evidence.tests_to_defend``.

    A planning figure for the engineer, not evidence: a small sample's mean and spread are
    themselves uncertain (and a candidate judged because it gained is likelier to have been
    lucky than not), the sign test may pass sooner, and the rule's other checks still apply."""
    if not _estimable(d):
        return None
    mean, sd = float(np.mean(d)), float(np.std(d, ddof=1))
    n = np.arange(2, MAX_TESTS + 1)
    power = stats.nct.sf(stats.t.ppf(0.975, n - 1), n - 1, mean * np.sqrt(n) / sd)
    enough = power >= POWER
    return int(n[np.argmax(enough)]) if enough.any() else None


def _estimable(d: np.ndarray) -> bool:
    # a gain past 100 points is a run-away fit's stand-in score (refit.finite), not a gain;
    # a spread of rounding alone (equal gains summed in floats) is none: scipy's non-central
    # t gives NaN past a non-centrality of about 3e9; this floor keeps it under
    # sqrt(MAX_TESTS) * 1e6
    if len(d) < 2 or not np.all(np.isfinite(d)) or not np.all(np.abs(d) <= 100):
        return False
    mean, sd = float(np.mean(d)), float(np.std(d, ddof=1))
    return mean > 0 and sd > 1e-6 * max(1.0, mean)


def _more_tests(d: np.ndarray, margin: float) -> tuple[int | None, str]:
    """:func:`needed_tests` and its words for the reason ("" when nothing can be said)."""
    if not _estimable(d):
        return None, ""
    n = needed_tests(d)
    aside = f"the {margin:g}-point bar and the rule's other checks aside"
    if n is not None:
        return n, (f" (about {n} judged estimation tests in all, {len(d)} now, gaining and "
                   "scattering as these did, would put the 95 % interval above zero 4 times "
                   f"in 5, {aside})")
    return None, (f" (even {MAX_TESTS} judged estimation tests gaining and scattering as "
                  "these did would put the 95 % interval above zero less than 4 times in "
                  f"5, {aside})")


def tell_apart(d: np.ndarray) -> tuple[int | None, str]:
    """For a tie: :func:`needed_tests` on the paired differences [fit points] between its
    two sides' per-test cross-validated fits (the side ranked first minus the other), and
    its words for the reason ("" when nothing can be said). Past ``MAX_TESTS`` the words say
    that more tests like these would not tell the two apart: the mean difference is small
    against its scatter. Either side may fit better on the judged tests (the ranking reads
    every estimation test): the question is the same both ways."""
    d = -d if float(np.mean(d)) < 0 else d
    if not _estimable(d):
        return None, ""
    n = needed_tests(d)
    if n is not None:
        return n, (f" (about {n} judged estimation tests in all, {len(d)} now, differing as "
                   "these did, would put the 95 % interval of the difference above zero 4 "
                   "times in 5)")
    return None, (f" (even {MAX_TESTS} judged estimation tests differing as these did would "
                  "put the 95 % interval of the difference above zero less than 4 times in 5: "
                  "more tests like these would not tell the two apart)")


def beats(a: dict[str, float], b: dict[str, float]) -> tuple[bool, int]:
    """Whether per-test fits ``a`` beat ``b`` test by test above the scatter
    (:func:`above_scatter` on the paired differences), and on how many tests ``a`` is better."""
    above, _, _, better, _ = above_scatter(np.array([a[n] - b[n] for n in a if n in b], float))
    return above, better


def over_the_bar(ev: Evidence, margin: float) -> bool:
    """``ev`` failed the rule on the scatter alone: its mean gain over the bar, every gain
    finite, no setup lower, but neither the interval nor the sign test above zero. Such a
    candidate is a rival too: one the winner does not beat test by test is as good an
    explanation, on the tests, as the winner (sets W and AD: an input delay and a rib
    stiffening named for a webbing's toe, the truth over the bar on 4 of 6 tests)."""
    gains = list(ev.test_gain_points.values())
    return (not ev.accepted and bool(gains) and bool(np.all(np.isfinite(gains)))
            and ev.gain_points >= margin
            and min(ev.setup_gain_points.values()) >= -SETUP_TOLERANCE)


def judge(before: dict[str, float], after: dict[str, float], setups: dict[str, str],
          scope: list[str] | None, margin: float, stalled: Iterable[str] = ()) -> Evidence:
    """Judge a candidate from the per-test cross-validated fit_TOT [%] without it (``before``)
    and with it (``after``); ``setups`` maps each test to its setup, ``scope`` is the setups
    the effect acts on (None: every test). Only the tests in ``setups`` are judged.
    ``stalled``: the tests whose fold's refit took no step, which ``after`` already counts as
    the caller chose (``refit.where_stalled``); the evidence lists them."""
    names = [n for n in before if n in after and n in setups]
    stuck = set(stalled)
    gain = {n: after[n] - before[n] for n in names}
    inside = [gain[n] for n in names if scope is None or setups[n] in scope] or [0.0]
    above, mean, half, improved, sign_p = above_scatter(
        np.array([gain[n] for n in names], float))
    per_setup = {s: float(np.mean([gain[n] for n in names if setups[n] == s]))
                 for s in dict.fromkeys(setups[n] for n in names)}
    worst = min(per_setup, key=lambda s: per_setup[s])
    more: int | None = None
    if not np.all(np.isfinite(list(gain.values()))):  # never passed by the loop: refit.finite
        reason = "a test's gain is not finite (a fit that ran away)"
    elif mean < margin:
        reason = f"gains {mean:.2f} < {margin:g} points"
    elif per_setup[worst] < -SETUP_TOLERANCE:
        reason = f"lowers setup {worst}'s cross-validated fit by {-per_setup[worst]:.2f} points"
    elif not above:
        more, words = _more_tests(np.array([gain[n] for n in names], float), margin)
        reason = (f"gains {mean:.2f} points but the 95 % interval reaches "
                  f"{mean - half:+.2f} and only {improved} of {len(names)} tests improve: not "
                  f"above test-to-test scatter{words}")
    else:
        reason = ""
    return Evidence(mean, (mean - half, mean + half), float(np.mean(inside)), gain, improved,
                    len(names), sign_p, per_setup, not reason, reason, more,
                    tuple(n for n in names if n in stuck))


@dataclass
class PastTheTie:
    """Two effects that both pass the rule and cannot be told apart, each judged beside the
    other: the model with both against the model with one. ``named``: the kinds the data
    defend ("a": ``a`` passes the rule beside ``b`` and ``b`` adds nothing beside ``a``, so
    ``a`` explains what ``b`` did, or the two act on different setups (``apart``); "b": the
    reverse; "both": each passes beside the other; "": neither explains the other away, a
    true tie). ``apart``: their scopes share no setup, so the one named may leave the other
    to be judged beside it in the next round. ``over_bar``: the side named gains over the bar
    beside the other without passing the rule there, the other adding nothing beside it."""

    named: str
    a_beside_b: Evidence  # what ``a`` adds to the model that has ``b``
    b_beside_a: Evidence
    apart: bool = False
    over_bar: bool = False


def past_the_tie(cv_a: dict[str, float], cv_b: dict[str, float], cv_both: dict[str, float],
                 setups: dict[str, str], scope_a: list[str] | None,
                 scope_b: list[str] | None, margin: float, b_passes: bool = True
                 ) -> PastTheTie:
    """Look past a tie between effects ``a`` and ``b`` (per-test cross-validated fit_TOT [%]
    with ``a``, with ``b`` and with both): the rule, applied to each beside the other. Where
    one mimics part of the other, it adds nothing once the other is in the model, while the
    other still does (an encompassing test: the better model explains its rival's gain).
    "Nothing" is less than ``POSSIBLE_MIN``: a rival that still adds under the margin on
    most tests is not explained away (held-out set I: a relief-vented airbag still added
    0.88 points on 6 of 6 tests beside a belt stiffening that had gained 1.23 beside it, and
    was given up for it until this was asked).

    Two effects on setups apart are not two explanations of one thing: each acts on tests the
    other does not touch, and meets the other only through the base parameters all setups
    share. One that passes the rule beside the other is then named, whatever the other still
    adds; the other is judged again beside it (held-out set R: rib damping on R16 and an
    airbag on the sled tied, the damping passing beside the bag, the bag gaining 1.39 points
    beside it: neither was named).

    A rival makes a tie when it only gains over the bar, its tests scattering
    (:func:`over_the_bar`); by the same measure, a side that gains over the bar beside the
    other, where the other adds nothing beside it, explains it away (sets T, W, AA and AG: a
    webbing's toe or a knee path over the bar on 4-5 of 6 tests beside an input delay, gain or
    an airbag that added -0.14 to +0.11 points beside it; in the stored runs of the 34 cases
    of sets T-AG with such a tie, no side that was not there gained over the bar beside a
    rival adding under 0.25). A side is named only if it passes the rule on its own, on any
    of these paths: ``a`` does (the round's winner), ``b`` when ``b_passes`` (a rival may be
    one over the bar alone, as W's and AA's toes were, and the rule names no such effect)."""
    a = judge(cv_b, cv_both, setups, scope_a, margin)
    b = judge(cv_a, cv_both, setups, scope_b, margin)
    apart = (scope_a is not None and scope_b is not None
             and not set(scope_a) & set(scope_b))
    named = ("both" if a.accepted and b.accepted
             else "a" if a.accepted and (apart or b.gain_points < POSSIBLE_MIN)
             else "b" if b_passes and b.accepted and (apart or a.gain_points < POSSIBLE_MIN)
             else "")
    if named:
        return PastTheTie(named, a, b, apart)
    # "nothing" under the bar too: at a margin set under 0.25, two sides adding alike beside
    # each other would each be over it and "nothing"
    nothing = min(POSSIBLE_MIN, margin)
    if over_the_bar(a, margin) and b.gain_points < nothing:
        return PastTheTie("a", a, b, apart, over_bar=True)
    if b_passes and over_the_bar(b, margin) and a.gain_points < nothing:
        return PastTheTie("b", a, b, apart, over_bar=True)
    return PastTheTie("", a, b, apart)
