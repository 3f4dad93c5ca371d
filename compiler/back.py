"""Going back a bit (issue #14): 'go back a bit', 'hmm, back a little', 'take it back a touch'.

Such a line reverses the change of the change line above it: each of that line's comparatives is
said again by its refinement's `opposite` (refinements.toml: 'darker' -> 'lighter', 'less' ->
'more', 'grainier' -> 'less grain'), at the line's own degree ('a bit' = slightly; without one the
opposite as said, which the bracket rule takes halfway back: docs/refinement.md). 'go back a bit'
twice goes back twice from the same change. Said after a change on the same line ('hmm too dark,
go back a bit') it is read past: the change already says which way (stdlib/data/teaching.toml
[going_back]).

`back_line`, `back_after_change` and `change_after_back` read a line (asked by cnlmc.document only
for a line with an unknown word or one that does not parse; `goes_back` by a session for every
line, so that a complaint is not read into it); `reversed_change` builds the reversed line where the
change above is known (cnlmc.analyze). Openers are stripped one at a time, so no pattern backtracks
over a run of them.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import fields, is_dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple

from . import ast
from .diagnostics import Diagnostic, Severity
from .phrase_patterns import alternatives
from .spans import Span
from .suggest import teaching
from .tagged import NOTE_CODE

if TYPE_CHECKING:
    from .lexicon import Lexicon
    from .tagger import Tagger

__all__ = [
    "WHOLE",
    "LineParser",
    "back_after_change",
    "back_line",
    "change_after_back",
    "goes_back",
    "reversed_change",
    "taken_back",
]

#: the degree of a line that takes the whole change above back ('undo', 'scrap that': [going_back] whole)
WHOLE = "*whole*"
#: reads a line of text as the source's lines are read (text, line number, offset, tagger, diagnostics)
LineParser = Callable[[str, int, int, "Tagger", list[Diagnostic]], "ast.Item | None"]


class Rules(NamedTuple):
    """teaching.toml [going_back] as patterns: one opener, the back phrase with its degree and the
    trailing words to the line's end, and the back phrase before a change ('go back a bit darker')."""

    opener: re.Pattern[str]
    back: re.Pattern[str]
    head: re.Pattern[str]


@lru_cache(maxsize=1)
def _rules() -> Rules:
    table: dict[str, Any] = teaching()["going_back"]
    openers = [*teaching()["removal"]["openers"], *teaching()["keeping"]["openers"], *table["openers"]]
    opener = re.compile(rf"(?:{alternatives(openers)})\s*[,!.:;]?\s+")
    phrases = alternatives([*table["phrases"], *table["whole"]])
    trailing = rf"(?:[\s,.!?]+(?:{alternatives(table['trailing'])}))*[\s,.!?]*$"
    back = re.compile(rf"(?:{phrases})(?P<degree>(?:\s+[a-z]+){{0,3}}?){trailing}")
    head = re.compile(rf"(?:{phrases})[\s,]+(?=\S)")
    return Rules(opener, back, head)


def _past_openers(low: str, at: int) -> int:
    """Where the words start after up to three openers ('ok,', 'ooh', 'no wait'), one at a time."""
    at = len(low) - len(low[at:].lstrip())
    for _ in range(3):
        found = _rules().opener.match(low, at)
        if found is None:
            break
        at = found.end()
    return at


def _back_at(low: str, at: int) -> re.Match[str] | None:
    """The back phrase (with its degree and trailing words) filling the line from `at`, past openers."""
    return _rules().back.match(low, _past_openers(low, at))


def _degree(found: re.Match[str], tagger: Tagger) -> str | None:
    """The degree said after the back phrase ('a bit'), '' for none; None when the words there are
    no adverb of the lexicon (the line is then something else)."""
    words = tuple(found["degree"].split())
    if not words:
        return ""
    if any(e.category == "adverbs" for e in tagger.lexicon.lookup(words)):
        return " ".join(words)
    return None


def goes_back(text: str) -> bool:
    """Whether the whole line only goes back ('ooh too far, go back a little'): no complaint to read."""
    return _back_at(text.lower(), 0) is not None


def back_line(text: str, number: int, offset: int, tagger: Tagger) -> ast.Refinement | None:
    """The line as one that goes back on the change above (its degree in `back`), or None."""
    found = _back_at(text.lower(), 0)
    if found is None:
        return None
    degree = _degree(found, tagger)
    if degree is None:
        return None
    phrase = text.lower()[found.start() : found.start("degree")].strip()
    if not degree and phrase in teaching()["going_back"]["whole"]:
        degree = WHOLE
    start = len(text) - len(text.lstrip())
    span = Span(offset + start, offset + len(text.rstrip()), number, start + 1)
    return ast.Refinement(None, (), span, text, back=degree)


def back_after_change(text: str, tagger: Tagger) -> tuple[int, str] | None:
    """'too blue, back a bit': where the change before the back part ends, and the back part
    (read past); None for any other line."""
    low = text.lower()
    mark = max(low.rfind(","), low.rfind(";"))
    found = _back_at(low, mark + 1) if mark > 0 else None
    if found is None or _degree(found, tagger) is None or not low[:mark].strip():
        return None
    end = len(low[:mark].rstrip())
    return end, text[end:].strip(" ,;")


def change_after_back(text: str) -> int | None:
    """'no, go back a bit darker': where the change after the back phrase starts (the back phrase
    is read past: the change says which way); None when the line does not open so."""
    low = text.lower()
    found = _rules().head.match(low, _past_openers(low, 0))
    return None if found is None else found.end()


def taken_back(back: ast.Refinement, above: ast.Refinement | None) -> Diagnostic:
    """The note of a line that takes the line above back whole ('undo'), or says there is none."""
    said = back.text.strip()
    if above is None:
        return Diagnostic(back.span, Severity.NOTE, NOTE_CODE, f"'{said}': nothing to take back (no change above)")
    note = f"read '{said}' as taking back the line above ('{above.text.strip()}')"
    return Diagnostic(back.span, Severity.NOTE, NOTE_CODE, note)


def reversed_change(
    back: ast.Refinement, above: ast.Refinement | None, lexicon: Lexicon, parse: LineParser
) -> tuple[ast.Refinement | None, Diagnostic]:
    """The change line `above` reversed at `back`'s degree, on `back`'s span, with the note that
    says how it was read; None (and a note saying why) where nothing above can be reversed.
    `parse` reads a line of text (cnlmc.document.parse_change_line)."""
    said = back.text.strip()
    reversal = _reversal_text(back.back or "", above, lexicon) if above is not None else ""
    line = _parsed_reversal(reversal, back, lexicon, parse) if reversal else None
    if line is None:
        why = "only comparatives ('darker', 'less glossy') are reversed" if above is not None else "no change above"
        return None, Diagnostic(back.span, Severity.NOTE, NOTE_CODE, f"'{said}': nothing to go back from ({why})")
    note = f"read '{said}' as '{reversal}': the change above, reversed"
    return line, Diagnostic(back.span, Severity.NOTE, NOTE_CODE, note)


def _reversal_text(degree: str, above: ast.Refinement, lexicon: Lexicon) -> str:
    """'a bit lighter, a bit more orange' for 'darker, less orange' at 'a bit': each comparative by
    its opposite, its target as said; '' when none has an opposite."""
    line_start = above.span.start - above.span.col + 1
    parts = []
    for item in above.items:
        opposite = lexicon.require("refinements", item.word.key).get("opposite")
        if opposite is None:
            continue
        target = item.target
        said = "" if target is None else above.text[target.span.start - line_start : target.span.end - line_start]
        parts.append(" ".join(w for w in (degree, str(opposite), said) if w))
    return ", ".join(parts)


def _parsed_reversal(text: str, back: ast.Refinement, lexicon: Lexicon, parse: LineParser) -> ast.Refinement | None:
    """The reversal text parsed as a change line, every span on the back line's; None when it is
    not one (or has an error)."""
    from .tagger import Tagger

    diags: list[Diagnostic] = []
    span = back.span
    node = parse(text, span.line, span.start - span.col + 1, Tagger.of(lexicon), diags)
    if not isinstance(node, ast.Refinement) or not node.items or any(d.is_error for d in diags):
        return None
    items = tuple(_respanned(item, span) for item in node.items)
    return ast.Refinement(back.name, items, span, back.text, back=back.back)


def _respanned(node: Any, span: Span) -> Any:
    """`node` (an AST word, colour or comparative, or a tuple of them) with every span `span`: the
    reversal's words stand where the back line does."""
    if isinstance(node, Span):
        return span
    if isinstance(node, tuple):
        return tuple(_respanned(n, span) for n in node)
    if is_dataclass(node) and not isinstance(node, type):
        return replace(node, **{f.name: _respanned(getattr(node, f.name), span) for f in fields(node)})
    return node
