"""'rust on steel', 'a clear lacquer over oak', 'green patina on old copper': a clause said on the
material it lies on is that material with the clause ('steel with rust'). The joining words are
data (teaching.toml [hedges] `on`); runs only for a line that does not parse (they are not words of
the language, so the tagger leaves them out)."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from . import ast
from .diagnostics import Diagnostic, Severity
from .joins import DESCRIBING
from .lexicon import Lexicon
from .parser import parsed_item, parsed_material
from .phrase_patterns import alternatives
from .spans import Span
from .suggest import everyday_noun, teaching
from .tagged import NOTE_CODE, Candidate, Tagged, written_span, written_text

__all__ = ["context_dropped", "implied_with", "likeness_dropped", "on_material"]


def on_material(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """The material after the joining word with the clause before it, and the note; None when the
    line has no joining word, or its two sides are not a clause and a material."""
    joining = _joining(text)
    if joining is None or not words:
        return None
    start, end = joining
    line_start = words[0].span.line_start
    known = [w for w in words if not (w.unknown and start <= w.span.start - line_start < end)]
    before = [w for w in known if w.span.start - line_start < start]
    after = [w for w in known if w.span.start - line_start >= end]
    if not before or not after or any(w.unknown for w in known):
        return None
    material = parsed_material(after, text, lexicon.caches.shapes)
    clause = parsed_item([implied_with(before[0]), *before], text, lexicon.caches.shapes)
    if material is not None and not isinstance(clause, ast.Refinement):
        return _treatment_on(before, after, words, text, lexicon, (start, end))
    if material is None or not isinstance(clause, ast.Refinement) or not (clause.coat or clause.features):
        return None
    if material.coat is not None and clause.coat is not None:
        return None  # two coats: the error says so
    joined = ast.Material(
        material.name,
        material.groups,
        material.nouns,
        material.coat or clause.coat,
        written_span(words),
        text,
        material.refinements,
        (*material.features, *clause.features),
    )
    said = " ".join(text[start:end].split())
    clause_said = " ".join(w.text for w in before if w.text[:1].isalnum())
    material_said = " ".join(w.text for w in after if w.text[:1].isalnum())
    message = f"read '{clause_said} {said} {material_said}' as '{material_said} with {clause_said}'"
    return joined, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, message)


def _treatment_on(
    before: list[Tagged],
    after: list[Tagged],
    words: Sequence[Tagged],
    text: str,
    lexicon: Lexicon,
    joining: tuple[int, int],
) -> tuple[ast.Material, Diagnostic] | None:
    """'oil on maple', 'a hand-rubbed oil finish on maple': describing words on a material that name
    no clause (a treatment read as its adjective, 'oiled') are those words before it ('oiled
    maple'), with a note; None when they do not read so."""
    said_before = [w for w in before if w.text[:1].isalnum() and not any(c.tag == "ARTICLE" for c in w.candidates)]
    if not said_before or not all(any(c.tag in DESCRIBING for c in w.candidates) for w in said_before):
        return None
    material = parsed_material([*said_before, *after], text, lexicon.caches.shapes)
    if material is None:
        return None
    said = " ".join(text[joining[0] : joining[1]].split())
    clause_said = " ".join(w.text for w in said_before)
    read = " ".join(_as_describing(w) for w in said_before)  # 'oil' as 'oiled'
    material_said = " ".join(w.text for w in after if w.text[:1].isalnum())
    message = f"read '{clause_said} {said} {material_said}' as '{read} {material_said}'"
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, message)


def _as_describing(word: Tagged) -> str:
    """The word as the describing word it is read as ('oil': 'oiled'), else as said."""
    keys = {c.key for c in word.candidates if c.tag == "ADJ"}
    return keys.pop() if len(keys) == 1 and len(word.candidates) == 1 else word.text


def _joining(text: str) -> tuple[int, int] | None:
    """Where the first joining word stands in the line ('on', 'over', 'on top of'), or None."""
    words = teaching()["hedges"]["on"]
    pattern = r"\b(?:" + alternatives(words) + r")\b"
    found = re.search(pattern, text.lower())
    return (found.start(), found.end()) if found is not None else None


def implied_with(first: Tagged) -> Tagged:
    """An implied 'with' before the clause's first word (inside it: the parser keys words by start)."""
    s = first.span
    at = min(s.start + 1, s.end)
    return Tagged("with", Span(at, s.end, s.line, s.col + 1), (Candidate("WITH", "with", "keywords"),), implied_by=s)


def likeness_dropped(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'chrome, like a bathroom tap', 'brass, as on an old ship': a comparison with a thing after
    the material, set off by a comma, is read past (teaching.toml [hedges] `likeness`); None when
    the words before it are not a material."""
    found = re.search(r",\s*(?:" + alternatives(teaching()["hedges"]["likeness"]) + r")\b", text.lower())
    bare = re.search(r",\s*like\b", text.lower()) if found is None else None
    if bare is not None and _possessive_after(text, bare.end()):
        found = bare  # 'dark brown, like grandad's wireless': a thing, as after 'like a'
    elif bare is not None:
        # 'something light, like birch': a bare 'like' names the material only after describing words
        if not words:
            return None
        line_start = words[0].span.line_start
        before = [w for w in words if w.span.start - line_start < bare.start()]
        if not before:
            return None
        end = line_start + bare.end()
        return _described_likeness(words, before, end, text, lexicon) or _restated_colour(
            words, before, end, text, lexicon
        )
    if found is None:
        return None
    if not words:
        return None
    line_start = words[0].span.line_start
    before = [w for w in words if w.span.start - line_start < found.start()]
    if not before or any(w.unknown for w in before):
        return None
    material = parsed_material(before, text, lexicon.caches.shapes)
    if material is None:
        return _described_likeness(words, before, line_start + found.end(), text, lexicon) or _likeness_of_a_colour(
            words, before, text[found.start() + 1 :].strip(), text, lexicon
        )
    said = text[found.start() + 1 :].strip()
    note = f"read past '{said}': a likeness to a thing, after the material it names"
    start = line_start + found.start() + 1 + (len(text[found.start() + 1 :]) - len(text[found.start() + 1 :].lstrip()))
    span = Span(start, line_start + len(text.rstrip()), words[0].span.line, start - line_start + 1)
    return material, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)


def _possessive_after(text: str, at: int) -> bool:
    """Whether the word after offset `at` says whose a thing is ('like grandad's wireless')."""
    from .tagger import possessive

    rest = text[at:].split()
    return len(rest) > 1 and possessive(rest[0])


def _restated_colour(
    words: Sequence[Tagged], before: Sequence[Tagged], end: int, text: str, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """'greyish green, like sage', 'slime green, like really really green': colours alone, then a
    bare 'like' and colours alone: the person says the colour again, as they mean it; the words
    after 'like' on the everyday noun (paint), with a note. None when either side is not describing
    words alone."""
    after = [w for w in words if w.span.start >= end and w.text[:1].isalnum()]
    said = [w for w in before if w.text[:1].isalnum()]
    if not said or not all(w.candidates and all(c.tag in DESCRIBING for c in w.candidates) for w in said):
        return None  # 'paint, like navy': a material before the likeness keeps its error
    material = _on_everyday_noun(after, text, lexicon)
    if material is None:
        return None
    note = (
        f"read '{written_text(after)}' as the colour '{written_text(said)}' said again, as meant; "
        f"no material named: on {everyday_noun()}"
    )
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def _likeness_of_a_colour(
    words: Sequence[Tagged], before: Sequence[Tagged], likeness: str, text: str, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """'warm greige, like a mushroom': describing words alone, then a likeness that names no
    material: the describing words on the everyday noun colours go on (paint, as for describing
    words alone: cnlmc.implied), the likeness read past; None when they do not parse so."""
    said = [w for w in before if w.text[:1].isalnum()]
    material = _on_everyday_noun(said, text, lexicon)
    if material is None:
        return None
    noun = everyday_noun()
    note = (
        f"no material named: read '{written_text(said)}' as '{written_text(said)} {noun}', "
        f"and read past '{likeness}': a likeness to a thing"
    )
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def _class_of_the_likeness(word: Tagged, after: Sequence[Tagged], lexicon: Lexicon) -> bool:
    """Whether a noun before the likeness is the class of the material the likeness names ('wood
    very light, like maple': maple is a wood): said as 'something', it goes."""
    own = [w for w in after if not _only_a_thing(w, lexicon)]  # 'like window' names a thing, not a wood
    classes = {
        entry.get("class")
        for w in own
        for c in w.candidates
        if c.tag == "NOUN" and (entry := lexicon.entry("nouns", c.key)) is not None
    }
    return any(c.tag == "NOUN" and c.key in classes for c in word.candidates)


def _described_likeness(
    words: Sequence[Tagged], before: Sequence[Tagged], end: int, text: str, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """'something warm, like a honey-coloured oak': describing words, then the likeness names the
    material: the material with the describing words before it ('warm honey-coloured oak')."""
    after = [w for w in words if w.span.start >= end and w.text[:1].isalnum()]
    said = [w for w in before if w.text[:1].isalnum() and not _class_of_the_likeness(w, after, lexicon)]
    if (
        not after
        or any(w.unknown for w in after)
        or not all(any(c.tag in DESCRIBING for c in w.candidates) for w in said)
    ):
        return None  # an unknown word in the likeness ('like a holly leaf'): a thing, not the material
    material = parsed_material([*said, *after], text, lexicon.caches.shapes)
    if material is None:
        return None
    reading = " ".join(part for part in (written_text(said), written_text(after)) if part)
    note = f"read '{text.strip()}' as '{reading}': the likeness names the material, the words before it describe it"
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def context_dropped(
    words: Sequence[Tagged],
    text: str,
    lexicon: Lexicon,
    read: Callable[[list[Tagged]], ast.Item | None] | None = None,
) -> tuple[ast.Item, Diagnostic] | None:
    """'sage green for the kitchen cabinets', 'rusty corrugated iron on the shed roof', 'gold like a
    wedding ring', 'white marble, the kind you see in hotels': where the material is, what it is for,
    where it came from or what it is like, said after the words of the look (teaching.toml [hedges]
    `context`), is read past: the line is the words before it (colours alone on the everyday noun, as
    for describing words alone); None when no such words come after a material, a change or colours.
    Tried last, after the readings of a clause on its material ('rust on steel') and of a likeness.
    `read`: another reading of the words before it ('Eiche hell wie unser Esstisch': the describing
    word after the noun), tried when they do not parse as they stand."""
    if not words:
        return None
    low = text.lower()
    line_start = words[0].span.line_start
    table = teaching()["hedges"]
    pointed = rf"(?:{alternatives(table['context_pointing'])})\s+(?:{alternatives(table['pointing_words'])})"
    bare = alternatives(table["context_unknown"])
    pattern = rf"(?:^|(?<=[\s,;.]))(?:{alternatives(table['context'])}|{pointed}|(?P<bare>{bare}))(?=[\s,.!?]|$)"
    likeness = tuple(w for w in table["context_pointing"] if w.split()[-1] == "like")
    after_noun = frozenset(table["context_after_noun"])
    for found in re.finditer(pattern, low):
        if found.group("bare") and not _unknown_after(words, line_start + found.end(), lexicon):
            continue  # 'oak, like walnut': a material after the likeness word
        if not found.group(0).startswith(likeness) and _names_a_material(words, line_start + found.start(), lexicon):
            continue  # 'steel on the oak', 'brass inlay on the walnut': a second material, not a place
        before = [w for w in words if _said_before(w, line_start + found.start())]
        if found.group("bare"):  # 'oak like soot': 'oak like' was joined as a likeness; the words as said alone
            before = _tagged_alone(text[: found.start()], words[0].span.line, line_start, lexicon)
        while before and not before[-1].text[:1].isalnum():  # 'white marble, the kind ...': the comma goes too
            before.pop()
        said = [w for w in before if w.text[:1].isalnum()]
        if not said or any(w.unknown for w in said):
            continue
        if found.group(0).split()[0] in after_noun and not any(c.tag == "NOUN" for c in said[-1].candidates):
            continue  # 'the aluminium of a laptop lid', not 'more of a sage'
        unarticled = [w for w in said if not all(c.tag == "ARTICLE" for c in w.candidates)]  # 'a really glossy ...'
        reading = parsed_item(before, text, lexicon.caches.shapes) or _on_everyday_noun(unarticled, text, lexicon)
        if reading is None and read is not None:
            reading = read(before)
        if reading is None:
            continue
        dropped = text[found.start() :].strip()
        span = Span(line_start + found.start(), line_start + len(text.rstrip()), words[0].span.line, found.start() + 1)
        note = f"read past '{dropped}': where it is, what it is for or what it is like, not how it looks"
        return reading, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)
    return None


def _tagged_alone(text: str, line: int, line_start: int, lexicon: Lexicon) -> list[Tagged]:
    """The words of `text` (the start of a line) tagged as a line of their own; [] on an error."""
    from .tagger import Tagger

    words, problems = Tagger.of(lexicon).tag_line(text, line, line_start)
    return [] if any(d.is_error for d in problems) else words


def _unknown_after(words: Sequence[Tagged], at: int, lexicon: Lexicon) -> bool:
    """Whether the last word said from offset `at` on is one the lexicon does not know or knows only
    as a thing, and no word there is a material's own name ('like old buildings', 'like soot', 'like
    window'; not 'like walnut')."""
    said = [w for w in words if w.implied_by is None and w.span.start >= at and w.text[:1].isalpha()]
    if not said or not (said[-1].unknown or _only_a_thing(said[-1], lexicon)):
        return False
    return not any(
        not w.unknown and not _only_a_thing(w, lexicon) and any(c.tag == "NOUN" for c in w.candidates) for w in said
    )


def _categories(word: Tagged, lexicon: Lexicon) -> set[str]:
    """The lexicon categories that know the word as written."""
    return {e.category for e in lexicon.lookup(tuple(word.text.lower().split()))}


def _only_a_thing(word: Tagged, lexicon: Lexicon) -> bool:
    """Whether the lexicon knows the word only as an object ('window', 'phone'; not 'glass')."""
    return _categories(word, lexicon) == {"objects"}


def _names_a_material(words: Sequence[Tagged], at: int, lexicon: Lexicon) -> bool:
    """Whether a word said from offset `at` on is a material's own name ('oak'; not 'roof', an
    object whose usual material the joins put in its place)."""
    for word in words:
        if word.implied_by is not None or word.span.start < at or not word.text[:1].isalpha():
            continue
        categories = _categories(word, lexicon)
        if "nouns" in categories and "objects" not in categories:
            return True
    return False


def _said_before(word: Tagged, at: int) -> bool:
    """Whether a word stands before offset `at`, or is implied by one that does ('with grout' of
    'tiles behind the hob': laid tiles)."""
    said = word.implied_by or word.span
    return said.start < at


def _on_everyday_noun(said: Sequence[Tagged], text: str, lexicon: Lexicon) -> ast.Material | None:
    """Describing words alone on the everyday noun ('sage green' = sage green paint: cnlmc.implied);
    None when a word is no describing word, or they do not parse so."""
    from .implied import implied_noun

    if not said or not all(any(c.tag in DESCRIBING for c in w.candidates) for w in said):
        return None
    return parsed_material([*said, implied_noun(everyday_noun(), said[-1])], text, lexicon.caches.shapes)
