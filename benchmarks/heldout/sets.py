"""The held-out sets by name: set A (``cases``), set B (``cases_b``, written after set A had
been looked at by the loop's engineers, kept from them until the loop ran on it), set C
(``cases_c``, written after set B had been looked at, the same way), set D (``cases_d``,
written after set C had been looked at, the same way), set E (``cases_e``, written after set D
had been looked at, the same way), set F (``cases_f``, written after set E had been looked at,
the same way), set G (``cases_g``, written after set F had been looked at, the same way), set H
(``cases_h``, written after set G had been looked at, the same way), set I (``cases_i``,
written after set H had been looked at, the same way), set J (``cases_j``, written after set I
had been looked at, the same way), set K (``cases_k``, written after set J had been looked at,
the same way), set L (``cases_l``, written after set K had been looked at, the same way), set
M (``cases_m``, written after set L had been looked at, the same way), set N (``cases_n``,
written after set M had been looked at, the same way), set O (``cases_o``, written after set N
had been looked at, the same way), set P (``cases_p``, written beside set O by another engineer,
the same way), set Q (``cases_q``, written after sets O and P, the same way), set R
(``cases_r``, written after set Q, the same way), set S (``cases_s``, written after set R by
another engineer, the same way), set T (``cases_t``, written after set S by another engineer,
the same way), set U (``cases_u``, written after set T by another engineer, the same way), set
V (``cases_v``, written after set U by another engineer, its choices drawn, the same way), set W
(``cases_w``, written after set V by another engineer, its choices drawn, the same way), set X
(``cases_x``, written after set W by another engineer, its choices drawn, the same way), set Y
(``cases_y``, written after set X by another engineer, its choices drawn, the same way), set Z
(``cases_z``, written after set Y by another engineer, its choices drawn, the same way), set
AA (``cases_aa``, written after set Z by another engineer, its choices drawn, the same way), set
AB (``cases_ab``, written after set AA by another engineer, its choices drawn, the same way), set
AC (``cases_ac``, written after set AB by another engineer, its choices drawn, the same way), set
AD (``cases_ad``, written after set AC by another engineer, its choices drawn, the same way), set
AE (``cases_ae``, written after set AD by another engineer, its choices drawn, the same way), set
AF (``cases_af``, written after set AE by another engineer, its choices drawn, the same way), set
AG (``cases_ag``, written after set AF by another engineer, its choices drawn, the same way), set
AH (``cases_ah``, written after set AG by another engineer, its choices drawn, the same way), set
AI (``cases_ai``, written after set AH by another engineer, its choices drawn, the same way), set
AJ (``cases_aj``, written after set AI by another engineer, its choices drawn, the same way), set
AK (``cases_ak``, written after set AJ by another engineer, its choices drawn, the same way), set
AL (``cases_al``, written after set AK by another engineer, its choices drawn, the same way but
that any case left no free pairing reuses an earlier set's), set AM (``cases_am``, written after
set AL by another engineer, its choices drawn, set AL's way), set AN (``cases_an``, written after
set AM by another engineer, its choices drawn, set AM's way), set AO (``cases_ao``, written after
set AN by another engineer, its choices drawn, set AN's way), set AP (``cases_ap``, written after
set AO by another engineer, its choices drawn, set AO's way), set AQ (``cases_aq``, written after
set AP by another engineer, its choices drawn, set AP's way), set AR (``cases_ar``, written after
set AQ by another engineer, its choices drawn, set AQ's way), set AS (``cases_as``, written after
set AR by another engineer, its choices drawn, set AR's way), set AT (``cases_at``, written after
set AS by another engineer, its choices drawn, set AS's way), set AU (``cases_au``, written after
set AT by another engineer, its choices drawn, set AT's way), set AV (``cases_av``, written after
set AU by another engineer, its choices drawn, set AU's way)."""

from __future__ import annotations

from .cases import CASES, Case
from .cases_aa import SET_AA
from .cases_ab import SET_AB
from .cases_ac import SET_AC
from .cases_ad import SET_AD
from .cases_ae import SET_AE
from .cases_af import SET_AF
from .cases_ag import SET_AG
from .cases_ah import SET_AH
from .cases_ai import SET_AI
from .cases_aj import SET_AJ
from .cases_ak import SET_AK
from .cases_al import SET_AL
from .cases_am import SET_AM
from .cases_an import SET_AN
from .cases_ao import SET_AO
from .cases_ap import SET_AP
from .cases_aq import SET_AQ
from .cases_ar import SET_AR
from .cases_as import SET_AS
from .cases_at import SET_AT
from .cases_au import SET_AU
from .cases_av import SET_AV
from .cases_b import SET_B
from .cases_c import SET_C
from .cases_d import SET_D
from .cases_e import SET_E
from .cases_f import SET_F
from .cases_g import SET_G
from .cases_h import SET_H
from .cases_i import SET_I
from .cases_j import SET_J
from .cases_k import SET_K
from .cases_l import SET_L
from .cases_m import SET_M
from .cases_n import SET_N
from .cases_o import SET_O
from .cases_p import SET_P
from .cases_q import SET_Q
from .cases_r import SET_R
from .cases_s import SET_S
from .cases_t import SET_T
from .cases_u import SET_U
from .cases_v import SET_V
from .cases_w import SET_W
from .cases_x import SET_X
from .cases_y import SET_Y
from .cases_z import SET_Z

# each set by its letters: set A is ``cases.CASES``, set AA ``cases_aa.SET_AA``
_BY_NAME: dict[str, list[Case]] = {
    "a": CASES, "b": SET_B, "c": SET_C, "d": SET_D, "e": SET_E, "f": SET_F, "g": SET_G,
    "h": SET_H, "i": SET_I, "j": SET_J, "k": SET_K, "l": SET_L, "m": SET_M, "n": SET_N,
    "o": SET_O, "p": SET_P, "q": SET_Q, "r": SET_R, "s": SET_S, "t": SET_T, "u": SET_U,
    "v": SET_V, "w": SET_W, "x": SET_X, "y": SET_Y, "z": SET_Z,
    "aa": SET_AA, "ab": SET_AB, "ac": SET_AC, "ad": SET_AD, "ae": SET_AE,
    "af": SET_AF, "ag": SET_AG, "ah": SET_AH, "ai": SET_AI,
    "aj": SET_AJ, "ak": SET_AK, "al": SET_AL, "am": SET_AM,
    "an": SET_AN, "ao": SET_AO, "ap": SET_AP, "aq": SET_AQ, "ar": SET_AR,
    "as": SET_AS, "at": SET_AT, "au": SET_AU, "av": SET_AV}
SETS = tuple(_BY_NAME)


def before(name: str) -> tuple[str, ...]:
    """The names of the sets written before set ``name``, in order (``before("c")`` is
    ``("a", "b")``; before set AA, ``"a"`` to ``"z"``; before set AB, those and ``"aa"``;
    before set AC, those, ``"aa"`` and ``"ab"``; before set AD, those, ``"aa"``, ``"ab"`` and
    ``"ac"``; before set AE, those, ``"aa"``, ``"ab"``, ``"ac"`` and ``"ad"``; before set AF,
    those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"`` and ``"ae"``; before set AG, those, ``"aa"``,
    ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"`` and ``"af"``; before set AH, those, ``"aa"``,
    ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"`` and ``"ag"``; before set AI, those,
    ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"`` and ``"ah"``; before set
    AJ, those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"`` and
    ``"ai"``; before set AK, those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``,
    ``"ag"``, ``"ah"``, ``"ai"`` and ``"aj"``; before set AL, those, ``"aa"``, ``"ab"``,
    ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"`` and
    ``"ak"``; before set AM, those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``,
    ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"`` and ``"al"``; before set AN, those,
    ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``,
    ``"aj"``, ``"ak"``, ``"al"`` and ``"am"``; before set AO, those, ``"aa"``, ``"ab"``,
    ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``,
    ``"al"``, ``"am"`` and ``"an"``; before set AP, those, ``"aa"``, ``"ab"``, ``"ac"``,
    ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``, ``"al"``,
    ``"am"``, ``"an"`` and ``"ao"``; before set AQ, those, ``"aa"``, ``"ab"``, ``"ac"``,
    ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``, ``"al"``,
    ``"am"``, ``"an"``, ``"ao"`` and ``"ap"``; before set AR, those, ``"aa"``, ``"ab"``,
    ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``,
    ``"al"``, ``"am"``, ``"an"``, ``"ao"``, ``"ap"`` and ``"aq"``; before set AS, those,
    ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``,
    ``"aj"``, ``"ak"``, ``"al"``, ``"am"``, ``"an"``, ``"ao"``, ``"ap"``, ``"aq"`` and
    ``"ar"``; before set AT, those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``,
    ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``, ``"al"``, ``"am"``, ``"an"``, ``"ao"``,
    ``"ap"``, ``"aq"``, ``"ar"`` and ``"as"``; before set AU, those, ``"aa"``, ``"ab"``,
    ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``, ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``,
    ``"al"``, ``"am"``, ``"an"``, ``"ao"``, ``"ap"``, ``"aq"``, ``"ar"``, ``"as"`` and
    ``"at"``; before set AV, those, ``"aa"``, ``"ab"``, ``"ac"``, ``"ad"``, ``"ae"``, ``"af"``,
    ``"ag"``, ``"ah"``, ``"ai"``, ``"aj"``, ``"ak"``, ``"al"``, ``"am"``, ``"an"``, ``"ao"``,
    ``"ap"``, ``"aq"``, ``"ar"``, ``"as"``, ``"at"`` and ``"au"``); ValueError for an unknown
    name. Names, not letters: set AA is one set, not set A twice."""
    _known(name)
    return SETS[:SETS.index(name)]


def case_set(name: str) -> list[Case]:
    """Set A (``cases``), or set B ... Z, AA, AB, AC, AD, AE, AF, AG, AH, AI, AJ, AK, AL, AM,
    AN, AO, AP, AQ, AR, AS, AT, AU, AV (``cases_b`` ... ``cases_z``, ``cases_aa``,
    ``cases_ab``, ``cases_ac``, ``cases_ad``, ``cases_ae``, ``cases_af``, ``cases_ag``,
    ``cases_ah``, ``cases_ai``, ``cases_aj``, ``cases_ak``, ``cases_al``, ``cases_am``,
    ``cases_an``, ``cases_ao``, ``cases_ap``, ``cases_aq``, ``cases_ar``, ``cases_as``,
    ``cases_at``, ``cases_au``, ``cases_av``) by its lower-case letters; ValueError for another
    name."""
    _known(name)
    return list(_BY_NAME[name])


def _known(name: str) -> None:
    if name not in _BY_NAME:
        raise ValueError(f"unknown case set {name!r}; known: {', '.join(SETS)}")


def select(names: list[str] | None, case_set_name: str = "a") -> list[Case]:
    """The cases named from one set (all of that set for None); ValueError naming the first
    unknown one."""
    cases = case_set(case_set_name)
    by_name = {c.name: c for c in cases}
    bad = [n for n in names or [] if n not in by_name]
    if bad:
        raise ValueError(f"unknown case {bad[0]!r} in set {case_set_name}; known: "
                         f"{', '.join(by_name)}")
    return [by_name[n] for n in names] if names else cases
