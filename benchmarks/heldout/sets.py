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
(``cases_w``, written after set V by another engineer, its choices drawn, the same way)."""

from __future__ import annotations

from .cases import CASES, Case
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

SETS = ("a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q",
        "r", "s", "t", "u", "v", "w")


def case_set(name: str) -> list[Case]:
    """Set A (``cases``), B (``cases_b``), C (``cases_c``), D (``cases_d``), E (``cases_e``),
    F (``cases_f``), G (``cases_g``), H (``cases_h``), I (``cases_i``), J (``cases_j``), K
    (``cases_k``), L (``cases_l``), M (``cases_m``), N (``cases_n``), O (``cases_o``), P
    (``cases_p``), Q (``cases_q``), R (``cases_r``), S (``cases_s``), T (``cases_t``), U
    (``cases_u``), V (``cases_v``) or W (``cases_w``); ValueError for another name."""
    if name == "a":
        return list(CASES)
    if name == "b":
        return list(SET_B)
    if name == "c":
        return list(SET_C)
    if name == "d":
        return list(SET_D)
    if name == "e":
        return list(SET_E)
    if name == "f":
        return list(SET_F)
    if name == "g":
        return list(SET_G)
    if name == "h":
        return list(SET_H)
    if name == "i":
        return list(SET_I)
    if name == "j":
        return list(SET_J)
    if name == "k":
        return list(SET_K)
    if name == "l":
        return list(SET_L)
    if name == "m":
        return list(SET_M)
    if name == "n":
        return list(SET_N)
    if name == "o":
        return list(SET_O)
    if name == "p":
        return list(SET_P)
    if name == "q":
        return list(SET_Q)
    if name == "r":
        return list(SET_R)
    if name == "s":
        return list(SET_S)
    if name == "t":
        return list(SET_T)
    if name == "u":
        return list(SET_U)
    if name == "v":
        return list(SET_V)
    if name == "w":
        return list(SET_W)
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
