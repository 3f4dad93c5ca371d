"""Which sense of a word is meant, said after a comma (issue #14, held-out sets 53 and 56): 'teak,
the colour not the wood', 'emerald, the gem not just the colour'. A noun that is both a colour and a
thing is read in the sense named: its colour (on the everyday noun, as 'teak colour' reads) or the
thing itself ('emerald gem', or the noun alone when the sense word names nothing more). The words
for the senses are teaching data (teaching.toml [senses]); tried on a line that fails to parse."""

from __future__ import annotations

import re
from collections.abc import Sequence

from . import ast
from .diagnostics import Diagnostic, Severity
from .lexicon import Lexicon
from .parser import parsed_material
from .phrase_patterns import alternatives
from .suggest import everyday_noun, teaching
from .tagged import NOTE_CODE, Tagged, written_span


def sense_said(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic, int] | None:
    """The material of the sense named after the comma, a note, and where the words naming the sense
    start (what they are read as is said by the note); None when the line is not a noun, a comma,
    'the' and a sense word (then, optionally, 'not [just] the' and another)."""
    table = teaching()["senses"]
    colour, things = table["colour"], table["thing"]
    pattern = (
        rf"^(?P<head>[^,]+),\s*the\s+(?P<sense>{alternatives([*colour, *things])})"
        rf"(?:\s*,?\s*(?:{alternatives(table['not'])})\s+the\s+\w+)?\s*[.!]?\s*$"
    )
    found = re.match(pattern, text.lower())
    if found is None or not words:
        return None
    line_start = words[0].span.line_start
    head = [w for w in words if w.span.start - line_start < found.end("head") and w.text[:1].isalnum()]
    sense = next((w for w in words if w.span.start - line_start == found.start("sense")), None)
    if not head or sense is None or any(w.unknown for w in head):
        return None
    material = _in_sense(head, sense, found.group("sense") in colour, text, lexicon)
    if material is None:
        return None
    meaning = "its colour" if found.group("sense") in colour else f"the {found.group('sense')} itself"
    note = f"read '{' '.join(w.text for w in head)}' as {meaning}, as the line says"
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note), line_start + found.end("head")


def _in_sense(head: list[Tagged], sense: Tagged, colour: bool, text: str, lexicon: Lexicon) -> ast.Material | None:
    """The head read with the sense word after it ('teak colour', 'emerald gem'), joined as a line
    would be; for a thing, the head alone when the sense word adds nothing that parses."""
    from .implied import implied_noun
    from .tagger import Tagger

    joined = Tagger.of(lexicon).joiner.joined([*head, sense], [])
    if colour:
        if len(joined) != len(head) or not any(c.tag == "COLOR" for c in joined[-1].candidates):
            return None
        joined = [
            *joined[:-1],
            Tagged(joined[-1].text, joined[-1].span, tuple(c for c in joined[-1].candidates if c.tag == "COLOR")),
        ]
        return parsed_material([*joined, implied_noun(everyday_noun(), joined[-1])], text, lexicon.caches.shapes)
    return parsed_material(joined, text, lexicon.caches.shapes) or parsed_material(head, text, lexicon.caches.shapes)


def kind_said(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic, int] | None:
    """'white marble tabletop, carrara type', 'marble, carrara': a material, a comma, then a noun
    whose entry is a kind of it (its key ends in the material's: 'carrara marble' of 'marble'),
    optionally with a word saying so ('type', 'kind', 'style': teaching.toml [senses] kind_words):
    the kind in the material's place, its describing words kept, a note; where the kind starts. None
    for any other line."""
    table = teaching()["senses"]
    found = re.match(
        rf"^(?P<head>[^,]+),\s*(?P<kind>[^,]+?)(?:\s+(?:{alternatives(table['kind_words'])}))?\s*[.!]?\s*$",
        text.lower(),
    )
    if found is None or not words:
        return None
    line_start = words[0].span.line_start
    head = [w for w in words if w.span.start - line_start < found.end("head") and w.text[:1].isalnum()]
    kind = [w for w in words if found.start("kind") <= w.span.start - line_start < found.end("kind")]
    if not head or len(kind) != 1 or kind[0].unknown or head[-1].unknown:
        return None
    material = next((c for c in head[-1].candidates if c.tag == "NOUN"), None)
    specific = next((c for c in kind[0].candidates if c.tag == "NOUN"), None)
    if material is None or specific is None or specific.key == material.key:
        return None
    if specific.key.split()[-1] != material.key.split()[-1] or len(specific.key.split()) < 2:
        return None  # 'carrara marble' is a marble; 'oak' is not a kind of 'marble'
    said = [*head[:-1], Tagged(kind[0].text, kind[0].span, (specific,))]
    parsed = parsed_material(said, text, lexicon.caches.shapes)
    if parsed is None:
        return None
    note = f"read '{head[-1].text}, {kind[0].text}' as '{specific.key}' (the kind named after the comma)"
    return parsed, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note), line_start + found.end("head")
