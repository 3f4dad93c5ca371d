"""A finish, then a negated finish it already is not ('glossy paint but not mirror', 'satin, not
glossy', 'matte but not chalky'; issue #14): the negation says what the finish said is not, so it is
read past with a note instead of being read as its declared opposite ('not mirror' = rough), which
contradicted the finish (W101) and moved it. A negated finish the one said already is would be a
contradiction ('glossy but not shiny': shiny lies between glossy and the middle of the finishes) and
keeps its reading and warning.

The finishes are on settings.toml `finish_ladder` (the roughness each sets); the middle is the rung
nearest roughness 0.5 (satin). The finish said excludes the negated one when that one lies past it,
away from the middle, or on the other side of it."""

from __future__ import annotations

from .. import ast
from ..diagnostics import Diagnostic, Severity
from ..lexicon import Entry
from ..state import Context, MaterialState
from ..tagged import NOTE_CODE
from .finish_ladder import finish_roughness, finishes

MIDDLE = 0.5  # the rung nearest this roughness is the middle finish


def already_not(state: MaterialState, ctx: Context, word: ast.Word) -> bool:
    """Whether `word` is a negated finish that another finish said on its line already excludes; if
    so a note says it is read past (see the module doc)."""
    said = word.text.lower().split()
    negated_entry = _negated(ctx, word.key, said)
    negated = finish_roughness(negated_entry)
    if negated is None:
        return False
    middle = _middle(ctx)
    for other in _finish_words(state, word):
        level = finish_roughness(ctx.lexicon.entry("adjectives", other.key))
        if level is not None and _excludes(level, negated, middle):
            note = f"read past '{word.text}': '{other.text}' is not {' '.join(said[1:])} already"
            state.diagnostics.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))
            return True
    return False


def _finish_words(state: MaterialState, word: ast.Word) -> list[ast.Word]:
    """The other describing words of the material's line, said before or after `word` (the finish
    stage may apply the negated one first: 'satin paint but not glossy')."""
    groups = getattr(state.selection, "groups", ())
    return [w for g in groups for w in g.adjectives if w is not word and w.span.line == word.span.line]


def _excludes(level: float, negated: float, middle: float) -> bool:
    """A finish at `level` is not one at `negated` when that lies past it away from the middle, at the
    middle, or on the middle's other side; one between it and the middle it partly is."""
    if abs(level - negated) < 1e-9:
        return False
    low, high = sorted((level, middle))
    return not (low < negated < high)


def _negated(ctx: Context, key: str, said: list[str]) -> Entry | None:
    """The adjective a word said as 'not X' negates: X, when the word was read as X's declared
    opposite ('not mirror' read as rough); None for any other word."""
    if len(said) < 2:
        return None
    found = [e for e in ctx.lexicon.lookup(tuple(said[1:])) if e.category == "adjectives"]
    return found[0] if found and found[0].get("opposite") == key else None


def _middle(ctx: Context) -> float:
    ladder = finishes(ctx)
    return min(ladder, key=lambda v: abs(v - MIDDLE)) if ladder else MIDDLE
