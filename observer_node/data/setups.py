"""Setups: which crash tests share a rig, told from the tests' own metadata.

The rule, in order:

1. ``--group NAME=PATTERN`` (a shell pattern on the test name; the first that matches wins)
   puts a test in setup NAME.
2. Otherwise tests whose ``.mme`` gives the same ``Type of the test``, ``Title`` and
   ``Name of test object 1`` share a setup (the same words and numbers: case, punctuation
   and spacing aside). It is named after the test-name prefix (before
   ``_`` or ``-``) all its tests share, when no other setup shares it (R16_001 -> R16), else
   after the fewest leading words (two at least) of its title that tell it apart
   (FULL-FRONTAL).
3. A test with none of these keys whose file names its setup (a CSV's ``# setup:`` line)
   joins that setup; one that names none (a CSV without a header) is grouped by its name
   prefix when the name has one, else it joins setup UNKNOWN. A setup so named is one
   however cased ("SLED" and "sled"), and when a setup of rule 1 or 2 has that name (however
   cased), the test joins it: a CSV that says SLED, or is named SLED_101, is a SLED test
   beside the ``.mme`` ones, and does not push their setup to another name.

A test the metadata puts with tests of another name (R16_005 among SLED_*: a copied ``.mme``)
stays where the metadata says, and its setup names it (``named_elsewhere``) for the report to
ask about it.

Placement: an effect that needs what a rig does not have is impossible there (its ``needs`` in
:mod:`observer_node.model.effects`). Today that is the airbag, impossible where the metadata
(title, type, comments) says hard seat, no interior or no airbag. ``loop --allow-anywhere``
lifts this.
"""

from __future__ import annotations

import fnmatch
import re
from dataclasses import dataclass, field

from ..model.effects import EFFECTS
from .crashtest import CrashDataError, CrashTest

KEYS = ("Type of the test", "Title", "Name of test object 1")


@dataclass
class Setup:
    """Tests that share a rig (see the module's rule), and what their metadata rules out."""

    name: str
    tests: list[str]
    how: str  # "--group PATTERN", "metadata: <key values>", the file's line or "name prefix"
    text: str = ""  # the metadata the placement rules read
    impossible: dict[str, str] = field(default_factory=dict)  # effect -> why not
    # tests the metadata put here though their name is that of another setup's tests (a
    # copied .mme, a mislabelled test): kept where the metadata says, and said
    named_elsewhere: dict[str, str] = field(default_factory=dict)  # test -> the other setup

    def as_dict(self) -> dict:
        return {"name": self.name, "tests": self.tests, "rule": self.how,
                **({"impossible": self.impossible} if self.impossible else {}),
                **({"named_like": self.named_elsewhere} if self.named_elsewhere else {})}


def parse_groups(specs: list[str] | None) -> list[tuple[str, str]]:
    """``NAME=PATTERN`` options -> [(name, pattern)]; one line naming the bad option."""
    out = []
    for spec in specs or []:
        name, sep, pattern = spec.partition("=")
        if not sep or not name.strip() or not pattern.strip():
            raise CrashDataError(f"--group {spec!r}: expected NAME=PATTERN, e.g. R16='R16_*'")
        out.append((name.strip(), pattern.strip()))
    return out


def check_groups(groups: list[tuple[str, str]], names: list[str]) -> None:
    """One line naming a ``--group`` whose pattern matches none of the tests (a typo would
    otherwise leave the tests to their metadata, silently)."""
    for name, pattern in groups:
        if not any(fnmatch.fnmatchcase(n, pattern) for n in names):
            raise CrashDataError(f"--group {name}={pattern}: matches none of the tests "
                                 f"({', '.join(names)})")


def words(text: str) -> list[str]:
    """The words and numbers of ``text`` (any script), a number with the sign that stands
    before it after a space ("-10 DEG" is not "+10 DEG"; "3-POINT" is "3 POINT", "FULL-56"
    is "FULL 56"), its decimal comma a point."""
    return [w.replace(",", ".") for w in
            re.findall(r"(?:(?<!\S)[+-])?\d+(?:[.,]\d+)?(?![^\W_])|[^\W_]+", text)]


def _prefix(name: str) -> str | None:
    parts = re.split(r"[_\-]", name, maxsplit=1)
    return parts[0].upper() if len(parts) == 2 and parts[0] and not parts[0].isdigit() else None


def assign_setups(tests: list[CrashTest], groups: list[tuple[str, str]] | None = None
                  ) -> list[Setup]:
    """Group ``tests`` by the rule above, set each test's ``setup`` to its group's name and
    return the groups in order of first appearance."""
    by_key: dict[tuple, list[CrashTest]] = {}
    how: dict[tuple, str] = {}
    said: list[tuple[tuple, CrashTest]] = []  # rule 3's tests, placed once the others are named
    for t in tests:
        user = next((n for n, pat in groups or [] if fnmatch.fnmatchcase(t.name, pat)), None)
        raw = tuple(t.meta.get(k, "").strip().upper() for k in KEYS)
        # one rig however its title is punctuated ("3-POINT" and "3 POINT": a hostile user's
        # typo had split a rig in two, one half then too small to judge)
        values = tuple(" ".join(words(v)) for v in raw)
        if user is not None:
            key: tuple = ("user", user)
            how[key] = "--group " + next(p for n, p in groups or [] if n == user)
        elif any(values):
            key = ("meta", *values)
            how.setdefault(key, "metadata: " + "; ".join(v for v in raw if v))
        elif t.meta.get("setup", "").strip():  # said by the file, not guessed from the name
            said.append((("file", t.meta["setup"].strip()), t))
            continue
        else:
            said.append((("prefix", _prefix(t.name) or "UNKNOWN"), t))
            continue
        by_key.setdefault(key, []).append(t)
    names = _names(by_key)
    _place_said(said, by_key, how, names)
    pos = {id(t): i for i, t in enumerate(tests)}  # back in the order the tests came
    by_key = {k: sorted(m, key=lambda t: pos[id(t)]) for k, m in
              sorted(by_key.items(), key=lambda km: min(pos[id(t)] for t in km[1]))}
    out = []
    for key, members in by_key.items():
        text = " ".join(" ".join(t.meta.get(k, "") for k in (*KEYS, "Comments"))
                        for t in members)
        # words in the metadata that rule an effect out, and why (its definition's ``needs``)
        impossible = {kind: e.needs[1] for kind, e in EFFECTS.items()
                      if e.needs is not None and e.needs[0].search(text)}
        for t in members:
            t.setup = names[key]
        out.append(Setup(names[key], [t.name for t in members], how[key], text, impossible))
    _name_checks(out, by_key, names)
    return out


def _place_said(said: list[tuple[tuple, CrashTest]], by_key: dict[tuple, list[CrashTest]],
                how: dict[tuple, str], names: dict[tuple, str]) -> None:
    """Rule 3: each test whose setup its file or name says joins the setup of rules 1-2 of
    that name, however cased, else the first-seen spelling's own setup."""
    by_name = {name.casefold(): key for key, name in names.items()}
    for (kind, name), t in said:
        key = by_name.get(name.casefold())
        if key is None:
            key = (kind, name)
            by_name[name.casefold()] = key
            names[key] = name
            how[key] = ("the file's setup line" if kind == "file" else
                        "name prefix" if name != "UNKNOWN" else "no metadata, no name prefix")
        by_key.setdefault(key, []).append(t)


def _name_checks(setups: list[Setup], by_key: dict[tuple, list[CrashTest]],
                 names: dict[tuple, str]) -> None:
    """Fill each metadata setup's ``named_elsewhere``: a test whose name prefix is not its
    own setup's (the prefix most of its tests share) but another setup's."""
    common: dict[str, str | None] = {}
    for key, members in by_key.items():
        prefixes = [_prefix(t.name) for t in members]
        top = max(set(prefixes), key=prefixes.count)
        common[names[key]] = top if prefixes.count(top) * 2 > len(prefixes) else None
    by_prefix = {pre: name for name, pre in common.items() if pre}
    for setup, (key, members) in zip(setups, by_key.items(), strict=True):
        if key[0] != "meta":
            continue
        for t in members:
            pre = _prefix(t.name)
            other = by_prefix.get(pre or "")
            if other is not None and other != setup.name and pre != common[setup.name]:
                setup.named_elsewhere[t.name] = other


def _names(by_key: dict[tuple, list[CrashTest]]) -> dict[tuple, str]:
    names: dict[tuple, str] = {}
    prefixes: dict[tuple, str | None] = {}
    for key, members in by_key.items():
        if key[0] == "user":
            names[key] = key[1]
            continue
        p = {_prefix(t.name) for t in members}
        prefixes[key] = p.pop() if len(p) == 1 else None
    taken = list(names.values())
    for key, pre in prefixes.items():
        shared = [k for k, q in prefixes.items() if q == pre and k != key]
        if pre and not shared and pre not in taken:
            names[key] = pre
    # the rest: the fewest leading title words (else type words) that tell them apart
    rest = [k for k in prefixes if k not in names]
    for key in rest:
        title = words(key[2] or key[1] or "SETUP")
        for n in range(min(2, len(title)), len(title) + 1):
            cand = "-".join(title[:n])
            others = [words(k[2] or k[1] or "SETUP")[:n] for k in rest if k != key]
            if all("-".join(o) != cand for o in others) and cand not in taken:
                break
        while cand in taken:
            cand += "+"
        names[key] = cand
        taken.append(cand)
    return names


def allowed_setups(kind: str, setups: list[Setup], anywhere: bool = False) -> list[str]:
    """The setups where effect ``kind`` is physically possible."""
    return [s.name for s in setups if anywhere or kind not in s.impossible]
