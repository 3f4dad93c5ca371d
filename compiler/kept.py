"""A change line that keeps the material as it is (issue #14): 'keep the grain', 'keep the same
grey', 'leave the colour as it is though', or an approval alone ('perfect', "that's fine"). Said
in a session such a line changes nothing: it is read as a change line with no change, and a note
says so (stdlib/data/teaching.toml [keeping]). A line that asks for something while it keeps
('keep it matte', 'keep the grain but make it darker') is not one: it reads as before.

Asked only of a line with an unknown word or one that does not parse (cnlmc.document).
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple

from . import ast
from .diagnostics import Diagnostic, Severity
from .phrase_patterns import alternatives
from .spans import Span
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged

if TYPE_CHECKING:
    from .tagger import Tagger

__all__ = ["kept_before_change", "kept_line"]

#: what a kept line may name after its keep phrase, by grammar terminal
NAMED = ("ADJ", "FEATURE", "COAT", "COLOR", "PROP", "NOUN", "SHADE", "ARTICLE")
#: the words of a thing kept ('the grain', 'the varnish'): a describing word after one asks for a change
THINGS = ("FEATURE", "COAT", "PROP", "NOUN")
DESCRIBING = ("ADJ", "COLOR", "SHADE")
#: the marks an approval may carry ('perfect!', 'ok, thanks.')
MARKS = re.compile(r"[,.!?;:…]+")


class Rules(NamedTuple):
    """teaching.toml [keeping], read: the openers, the keep phrases and the trailing words as
    patterns, the approvals, and the pronouns that stand for the material ('keep it matte': not
    'keep this blue', what is kept)."""

    opener: re.Pattern[str]
    keep: re.Pattern[str]
    trailing: re.Pattern[str]
    approvals: frozenset[str]
    pronouns: frozenset[str]


@lru_cache(maxsize=1)
def _rules() -> Rules:
    """teaching.toml [keeping] as Rules, once per process."""
    table: dict[str, Any] = teaching()["keeping"]
    openers = [*teaching()["removal"]["openers"], *table["approvals"], *table["openers"]]
    opener = re.compile(rf"(?:{alternatives(openers)})\s*[,!.:;]?\s+")
    keep = re.compile(rf"(?:{alternatives(table['leading'])})(?=\s|$)")
    trailing = re.compile(rf"(?:[\s,.!?]+(?:{alternatives(table['trailing'])}))*[\s,.!?]*$")
    approvals = frozenset(" ".join(a.split()) for a in table["approvals"])
    return Rules(opener, keep, trailing, approvals, frozenset(table["material_pronouns"]))


def kept_line(text: str, number: int, offset: int, tagger: Tagger) -> tuple[ast.Refinement, Diagnostic] | None:
    """The line as one that keeps the material (a change line with no change, and the note saying
    so), or None."""
    start = len(text) - len(text.lstrip())
    end = len(text.rstrip())
    if start == end:
        return None
    span = Span(offset + start, offset + end, number, start + 1)
    if _approval(text) or _keeps(text, start, number, offset, tagger):
        note = f"read '{text.strip()}' as keeping the material as it is: nothing changes"
        return ast.Refinement(None, (), span, text), Diagnostic(span, Severity.NOTE, NOTE_CODE, note)
    return None


def kept_before_change(text: str, number: int, offset: int, tagger: Tagger) -> tuple[int, Diagnostic] | None:
    """'keep the tiles but make them shinier': where the change after a kept part and its joining
    word ('but': teaching.toml [politeness] remark_breaks) starts, and the note reading the kept
    part past; None when no kept part opens the line."""
    low = text.lower()
    joiners = (*teaching()["politeness"]["remark_breaks"], *teaching()["keeping"]["change_joiners"])
    breaks = (found for joiner in joiners for found in re.finditer(rf"[\s,]+{re.escape(joiner)}\s+", low))
    for found in sorted(
        breaks, key=lambda m: -m.start()
    ):  # the longest kept part first ('keep the grain and colour and make it darker')
        if not text[found.end() :].strip():
            continue
        kept = text[: found.start()]
        start = len(kept) - len(kept.lstrip())
        if _keeps(kept, start, number, offset, tagger):
            span = Span(offset + start, offset + found.end() - 1, number, start + 1)
            said = text[start : found.end()].strip()
            return found.end(), Diagnostic(
                span, Severity.NOTE, NOTE_CODE, f"read past '{said}': what stays, then the change"
            )
    return None


def _approval(text: str) -> bool:
    """Whether the line only approves the material ('perfect!', "ok, that's fine")."""
    approvals = _rules().approvals
    words = " ".join(MARKS.sub(" ", text.lower()).split())
    if words in approvals:
        return True
    parts = [" ".join(p.split()) for p in MARKS.split(text.lower()) if p.strip()]
    return len(parts) > 1 and all(part in approvals for part in parts)


def _keeps(text: str, start: int, number: int, offset: int, tagger: Tagger) -> bool:
    """Whether the line opens with a keep phrase (past its openers) and then names only words of
    the material, with the trailing words read past."""
    opener, keep, trailing, _approvals, pronouns = _rules()
    low = text.lower()
    at = start
    for _ in range(3):
        skipped = opener.match(low, at)
        if skipped is None:
            break
        at = skipped.end()
    found = keep.match(low, at)
    if found is None:
        return False
    lead = found.end()
    said = low[at:lead].split()
    material_named = said[-1] in pronouns or low[lead:].split()[:1] in [[p] for p in pronouns]
    end = lead + len(trailing.sub("", low[lead:]))
    if not low[lead:end].strip():
        return low[at:lead].strip().endswith("same")  # 'keep the same', not 'keep' or 'keep the' alone
    masked = " " * lead + text[lead:end] + " " * (len(text) - end)  # columns stay the user's
    tagged, problems = tagger.tag_line(masked, number, offset)
    return not any(d.is_error for d in problems) and _names_only(tagged, material_named)


def _names_only(words: list[Tagged], material_named: bool) -> bool:
    """Whether every word read names part of the material (a describing word, a feature, a
    colour, a noun...), and none asks for a change (a comparative, 'with', a describing word after
    the thing kept: 'keep the varnish glossy', or after the material named by a pronoun: 'keep it
    matte'; 'keep this blue' keeps what it names)."""
    said = [w for w in words if w.candidates and w.implied_by is None]  # not the words 'varnish' alone implies
    if not said or not all(any(c.tag in NAMED for c in w.candidates) for w in said):
        return False
    thing = next((i for i, w in enumerate(said) if any(c.tag in THINGS for c in w.candidates)), len(said))
    if material_named and thing == len(said):
        return False
    return not any(c.tag in DESCRIBING for w in said[thing + 1 :] for c in w.candidates)  # 'keep the varnish glossy'
