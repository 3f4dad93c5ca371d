"""'wood of oak', 'a cloak of moth-eaten grey wool', 'the bottle of green glass': a thing or a kind
named first, then 'of' and the material (issue #14: how many languages say it, and how writers
describe a thing). The line is the material after 'of', with a note; the words before it say what
the thing is, not what it is made of.

Only a line that does not parse comes here (cnlmc.document), so 'veins of gold', 'a hint of blue',
'two coats of varnish' keep their readings; the words before 'of' must be one or two nouns,
objects or unknown words after an optional article or possessive ('a wizard's staff of gnarled
yew'), and what follows 'of' must read as a material.
"""

from __future__ import annotations

from .diagnostics import Diagnostic, Severity
from .joins import of_tag
from .lexicon import Lexicon
from .tagged import NOTE_CODE, Tagged

__all__ = ["made_of"]

#: the tags a word naming the thing or the kind may have ('wood', 'floor', an unknown 'staff')
_THING_TAGS = ("NOUN", "OBJECT")
#: the most words naming the thing ('steering wheel of', 'kitchen floor of')
_THING_WORDS = 2


def made_of(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """The words after the line's first 'of' and the note that reads the line as them, when the
    words before it name a thing or a kind (see the module doc; `text`: the line); None otherwise."""
    at = next((i for i, w in enumerate(words) if of_tag(w, "OF")), None)
    if at is None or at + 1 == len(words):
        return None
    start = _after_determiners(words, at)
    thing = [w.text for w in words[start:at]]
    if not thing:  # 'the floor of tiles': the tagger read 'floor' past as saying where
        before = text[: words[at].span.col - 1].split()
        thing = before[len(before) - len(before[start:]) :] if start < len(before) else []
        thing = [w for w in thing if w.isalpha()]
    elif not all(_names_a_thing(w) for w in words[start:at]):
        return None
    if not thing or len(thing) > _THING_WORDS or _a_material_of_a_thing(words[start:at], words[at + 1 :], lexicon):
        return None
    said = " ".join((*thing, words[at].text))
    material = " ".join(text[words[at].span.col - 1 + len(words[at].text) :].split())
    span = words[0].span.to(words[at].span)
    note = f"read '{said} {material}' as '{material}' (the material of the {' '.join(thing)})"
    return words[at + 1 :], Diagnostic(span, Severity.NOTE, NOTE_CODE, note)


def _after_determiners(words: list[Tagged], end: int) -> int:
    """Where the words after the line's articles start, before `end` (a possessive was read past by
    the tagger: 'a wizard's staff of yew')."""
    i = 0
    while i < end and of_tag(words[i], "ARTICLE"):
        i += 1
    return i


def _names_a_thing(word: Tagged) -> bool:
    return word.unknown or any(of_tag(word, tag) for tag in _THING_TAGS)


def _a_material_of_a_thing(before: list[Tagged], after: list[Tagged], lexicon: Lexicon) -> bool:
    """'the satin nickel of an old tap': a material noun (no thing) before 'of' and a thing after it
    (an object, read as its usual material by the tagger): the material is the one before; the
    rest says where it is."""
    said = [w for w in after if w.text[:1].isalpha() and not of_tag(w, "ARTICLE")]
    last_before = before[-1] if before else None
    if not said or last_before is None or not of_tag(last_before, "NOUN"):
        return False
    if any(e.category == "objects" for e in lexicon.lookup((last_before.text.lower(),))):
        return False
    return any(e.category == "objects" for e in lexicon.lookup((said[-1].text.lower(),)))
