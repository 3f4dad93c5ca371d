"""A material implied by describing words alone ('matte black', 'slate blue', 'a little rusty').

A line of describing words that names no material is not an error a person made: it describes a
surface and leaves the material to the compiler. Its material is the first phrase the teaching
offers for it that only adds a noun after the words as written (cnlmc.teach: a colour's WordNet
kind, 'khaki' -> khaki fabric; else the everyday nouns every word applies to, paint first; for a
describing word its own example's noun first, 'very hammered' -> copper); every offer compiles
without a warning. An offer that puts a noun in place of a known colour ('teak' for 'teal') is not
taken: the colour is what was said, and the offer stays in the note as another choice. The noun is
added as an implied word (the span of the word that implies it), and a note says what was read
and how to choose another material.

A line with a comparison ('lighter than'), a refinement word or an unknown word keeps its error:
there the missing noun is a mistake, not a choice left to us. Runs only for a line that failed to
parse (the hot path never reaches it)."""

from __future__ import annotations

import math
from collections.abc import Sequence

from . import ast
from .colour import linear_to_oklab
from .diagnostics import Diagnostic, Severity
from .lexicon import Lexicon
from .spans import Span
from .suggest import everyday_noun, teaching
from .tagged import NOTE_CODE, Candidate, Tagged, written_span, written_text

__all__ = [
    "as_change",
    "first_line_comparison",
    "implied_material",
    "implied_noun",
    "material_change",
    "starts_with_change",
]

#: the readings of a noun that a change to another kind of material takes instead ("make it cream"
#: under red plastic: the colour; "make it satin" under tile: the finish)
CHANGE_READINGS = ("COLOR", "ADJ")

NOT_DESCRIBING = frozenset({"NAME", "OF", "NOUN", "OBJECT"})  # a line with one of these keeps its error


def implied_material(
    taught: Diagnostic, words: Sequence[Tagged], lexicon: Lexicon, text: str
) -> tuple[list[Tagged], Diagnostic] | None:
    """The line's words with the implied noun added, and the note saying so; None to keep `taught`.
    An inline comparative may stand first ('a slightly lighter grey' = one step lighter than grey
    paint), but not a comparison ('lighter than red': what is compared is missing)."""
    if taught.code not in ("E002", "E003") or not taught.suggestions or not words:
        return None
    if any(w.unknown for w in words):
        return None
    plating = _plating_alone(words, lexicon) or _metal_ish_alone(words, lexicon)
    if plating is not None:
        return plating
    main = [w for w in words if w.text[:1].isalpha()]
    with_at = next((i for i, w in enumerate(main) if any(c.tag == "WITH" for c in w.candidates)), len(main))
    said, tail = main[:with_at], main[with_at:]  # a 'with' clause may name a colour by a noun ('gold flakes')
    if said and not tail and _describes_after_a_noun(said):
        return _as_described(words, said, lexicon)
    if said and not tail and _colour_named_after_a_noun(said):  # 'plaster pink', 'sea glass green'
        return _on_everyday_noun(words, said, lexicon)
    if not said or any(c.tag in NOT_DESCRIBING for w in said for c in w.candidates):
        return None
    if any(c.tag == "REFINE" for w in said for c in w.candidates) and _compares(text, lexicon):
        return None
    chosen = _first_added_noun(taught.suggestions, said, tail, lexicon)
    if chosen is None:
        return None
    offer, key, written = chosen
    last = said[-1]
    at = words.index(last) + 1
    implied = [*words[:at], implied_noun(key, last), *words[at:]]
    return implied, _note(said, written, [o for o in taught.suggestions if o != offer])


DESCRIBING = ("ADJ", "COLOR", "SHADE", "ADV")


def _describes_after_a_noun(said: Sequence[Tagged]) -> bool:
    """'satin black', 'terracotta orange', 'matte, silver grey': words each of which describes (a
    finish, a colour), one of them a noun too, ending in a colour: read as describing words all."""
    return (
        len(said) > 1
        and any(c.tag == "NOUN" for w in said[:-1] for c in w.candidates)
        and all(any(c.tag in DESCRIBING for c in w.candidates) for w in said)
        and all(c.tag in (*DESCRIBING, "NOUN") for w in said for c in w.candidates)
        and any(c.tag == "COLOR" for c in said[-1].candidates)  # it ends in a colour: 'satin black'
    )


def _colour_named_after_a_noun(said: Sequence[Tagged]) -> bool:
    """'soft plaster pink', 'sea glass green': describing words, then a noun (the thing the colour
    is seen on), then a basic colour term at the end (colour_compounds.toml: 'tin periwinkle' is a
    misplaced colour, not a name): a colour named after the noun, with no material named."""
    from .passes.colour_compounds import rules

    basic = rules()["basic_terms"]
    if len(said) < 2 or not any(c.tag == "COLOR" and c.key in basic for c in said[-1].candidates):
        return False
    nouns = [k for k, w in enumerate(said) if any(c.tag == "NOUN" and c.key == w.text.lower() for c in w.candidates)]
    return (
        bool(nouns)
        and nouns[-1] == len(said) - 2
        and all(any(c.tag in DESCRIBING for c in w.candidates) for w in said[: nouns[0]])
    )


def _on_everyday_noun(
    words: Sequence[Tagged], said: Sequence[Tagged], lexicon: Lexicon
) -> tuple[list[Tagged], Diagnostic] | None:
    """The words with the everyday noun after them when that parses ('plaster pink paint': the
    colour named after plaster, N122), and the note; None otherwise. The grammar takes a colour
    named after a noun first only, so describing words before it go after it ('soft plaster pink' =
    'plaster pink soft paint': the order of describing words does not change what they do)."""
    from .parser import ParseFailure, parse_line_shape

    noun = everyday_noun()
    at = words.index(said[-2])
    for order in (list(words), [*words[: at - len(said) + 2], *words[at:], *words[at - len(said) + 2 : at]]):
        with_noun = [*order, implied_noun(noun, said[-1])]
        try:
            parse_line_shape(with_noun, lexicon.caches.shapes)
        except ParseFailure:
            continue
        return with_noun, _note(said, noun, [])
    return None


def _as_described(
    words: Sequence[Tagged], said: Sequence[Tagged], lexicon: Lexicon
) -> tuple[list[Tagged], Diagnostic] | None:
    """The words with their noun readings left out and the first everyday noun after them
    ('satin black' = satin black paint), when that parses; None otherwise."""
    from .parser import ParseFailure, parse_line_shape

    everyday = [str(n) for n in teaching()["completions"]["nouns"]]
    noun = everyday[0]
    described = [
        Tagged(w.text, w.span, tuple(c for c in w.candidates if c.tag != "NOUN"), w.unknown, w.implied_by)
        if any(w is s for s in said)
        else w
        for w in words
    ]
    with_noun = [*described, implied_noun(noun, said[-1])]
    try:
        parse_line_shape(with_noun, lexicon.caches.shapes)
    except ParseFailure:
        return None
    written = written_text(said)
    return with_noun, _note(said, noun, [f"{written} {other}" for other in everyday[1:3]])


def _plating_alone(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """'chrome-plated', 'gold plated': a metal and a describing word that puts it on the surface
    (colour_target = 'material'), with nothing under it: the surface its example names ('gold
    plated steel': steel), with a note."""
    main = [w for w in words if w.text[:1].isalpha()]
    if len(main) < 2 or main[-1] is not words[-1]:
        return None
    metals = [c for c in main[-2].candidates if c.tag == "NOUN"]
    entries = [lexicon.entry("adjectives", c.key) for c in main[-1].candidates if c.tag == "ADJ"]
    plating = next((e for e in entries if e is not None and e.get("colour_target") == "material"), None)
    metal = lexicon.entry("nouns", metals[0].key) if metals else None
    if plating is None or metal is None or metal.get("model") != "conductor":
        return None
    example = str(plating.get("example", "")).split()
    under = lexicon.entry("nouns", example[-1]) if example else None
    if under is None:
        return None
    hint = "name the surface under the plating to choose another, e.g. 'gold plated brass'"
    return [*words, implied_noun(under.key, words[-1])], _note(main, under.key, [], hint=hint)


def _metal_ish_alone(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """'brass-ish', 'matte copperish': a metal's name hedged with '-ish' last, no material named, is
    that metal (what the words are like), with a note; not a paint of the metal's colour."""
    main = [w for w in words if w.text[:1].isalpha()]
    if not main or main[-1] is not words[-1]:
        return None
    from .passes.colour_compounds import rules
    from .passes.metal_tone import metal_named

    last = main[-1]
    hedges = [suffix for suffix in rules()["hedged"]["suffixes"] if last.text.lower().endswith(suffix)]
    if not hedges or not any(c.tag == "COLOR" for c in last.candidates):
        return None
    metal = metal_named(last.text.lower(), [f"-{hedges[0]}", hedges[0]], lexicon)
    if metal is None:
        return None
    noun = Tagged(last.text, last.span, (Candidate("NOUN", metal.key, "nouns"),))
    note = Diagnostic(
        last.span,
        Severity.NOTE,
        NOTE_CODE,
        f"read '{last.text}' as {metal.key} (a metal's name with '-ish': the metal, as near as named)",
    )
    return [*words[:-1], noun], note


def _apply_to_anything(said: Sequence[Tagged], lexicon: Lexicon) -> bool:
    """Whether the words are describing words none of which is limited to some materials (gloss,
    roughness, degree and colour words: no `applies_to`; 'white semi-gloss' is paint, not its
    example's nickel)."""
    readings = [c for w in said for c in w.candidates]
    adjectives = [lexicon.entry("adjectives", c.key) for c in readings if c.tag == "ADJ"]
    return bool(adjectives) and not any(a is None or a.get("applies_to") for a in adjectives)


def _compares(text: str, lexicon: Lexicon) -> bool:
    """Whether the line has a comparison word ('than', 'als': the word formation rules), which the
    tagger read into its comparative and dropped."""
    formation = lexicon.caches.word_formation
    comparison = formation.rules.comparison if formation is not None else ()
    return any(word.lower() in comparison for word in text.split())


def _first_added_noun(
    offers: Sequence[str], said: Sequence[Tagged], tail: Sequence[Tagged], lexicon: Lexicon
) -> tuple[str, str, str] | None:
    """The noun of the first offer that only adds one (an offer that puts a noun in place of a known
    colour, 'teak' for 'teal', stays in the note as another choice: the colour is what was said);
    None when the first offer is a noun one edit from the colour and of its colour ('terracota', a
    spelling the colour survey kept, is terracotta misspelt: the error offers it). Describing
    words that apply to any material take an everyday noun first ('not glossy' = not glossy paint,
    where the teaching offers the word's own example first: 'dull steel'); a word for some
    materials keeps its example's ('very hammered' = very hammered copper, 'lightly brushed' =
    lightly brushed aluminum)."""
    if offers and _misspelt_noun_of_that_colour(offers[0], said, lexicon):
        return None
    if _apply_to_anything(said, lexicon):
        everyday = {noun: k for k, noun in enumerate(teaching()["completions"]["nouns"])}  # most common first
        offers = sorted(offers, key=lambda o: everyday.get(o.split()[-1], len(everyday)))
    for offer in offers:
        added = _added_noun(offer, said, tail, lexicon)
        if added is not None and _every_word_applies(said, added[0], lexicon):
            return (offer, *added)
    return None


def _every_word_applies(said: Sequence[Tagged], noun: str, lexicon: Lexicon) -> bool:
    """Whether every describing word said applies to the noun ('white glaze shiny': a glaze is for
    ceramics, so not the copper that 'shiny' offers first)."""
    from .passes.base import applies_to

    entry = lexicon.entry("nouns", noun)
    adjectives = [lexicon.entry("adjectives", c.key) for w in said for c in w.candidates if c.tag == "ADJ"]
    return entry is None or all(a is None or applies_to(entry, a) for a in adjectives)


SAME_COLOUR = 0.1  # OKLab distance under which a colour and a noun's own colour are the same family


def _misspelt_noun_of_that_colour(offer: str, said: Sequence[Tagged], lexicon: Lexicon) -> bool:
    from .read_past import english_noun

    written = [w.text for w in said]
    if english_noun(said[-1].text):  # 'blush' is a word (not a misspelt 'plush'); 'terracota' is not
        return False
    words = offer.split()
    if len(words) != sum(len(t.split()) for t in written) or offer.lower() == " ".join(written).lower():
        return False
    colours = [c for c in said[-1].candidates if c.tag == "COLOR"]
    nouns = [e for e in lexicon.lookup((words[-1].lower(),)) if e.category == "nouns"]
    colour = lexicon.entry("colours", colours[0].key) if colours else None
    own = (nouns[0].get("base_color") or nouns[0].get("f0")) if nouns else None
    if colour is None or colour.get("rgb") is None or not isinstance(own, list):
        return False
    return math.dist(linear_to_oklab(colour.get("rgb")), linear_to_oklab(own)) < SAME_COLOUR


def _added_noun(offer: str, said: Sequence[Tagged], tail: Sequence[Tagged], lexicon: Lexicon) -> tuple[str, str] | None:
    """The noun (key, as written) the offer adds after the words as written (None: it changes them)."""
    head = written_text(said) + " "
    end = "".join(f" {w.text}" for w in tail)
    if not offer.startswith(head) or not offer.endswith(end):
        return None
    added = offer[len(head) : len(offer) - len(end)].strip().rstrip(",;").strip()  # 'almost black paint, with ...'
    nouns = [e for e in lexicon.lookup(tuple(added.lower().split())) if e.category == "nouns"]
    return (nouns[0].key, added) if nouns and added else None


def implied_noun(noun: str, last: Tagged) -> Tagged:
    """The noun as a word inside the last written word's span (the parser keys words by start,
    and no written word starts there), implied by it."""
    s = last.span
    at = min(s.start + 1, s.end)
    return Tagged(
        noun, Span(at, s.end, s.line, s.col + at - s.start), (Candidate("NOUN", noun, "nouns"),), implied_by=s
    )


def _note(said: Sequence[Tagged], noun: str, others: Sequence[str], why: str = "", hint: str = "") -> Diagnostic:
    """N101 'no material named: read X as X NOUN', with the other offers (or `hint`) to choose from."""
    written = written_text(said)
    choose = f": {', '.join(repr(o) for o in others[:2])}" if others else ""
    message = f"no material named: read '{written}' as '{written} {noun}'{why}"
    return Diagnostic(
        written_span(said),
        Severity.NOTE,
        NOTE_CODE,
        message,
        (hint or f"name the material to choose another{choose}",),
    )


def starts_with_change(text: str) -> bool:
    """Whether the line starts with a change phrase ('make it', 'turn it': teaching.toml
    [politeness] changes), then a space or a mark, after any other politeness ('now make it'), or
    ends with one ('matte instead': `changes_at_end`)."""
    table = teaching()["politeness"]
    said = " ".join(text.lower().split())
    if said.rstrip(" " + "".join(table["marks"])).endswith(tuple(f" {p}" for p in table["changes_at_end"])):
        return True
    while True:
        if _starts_with_one_of(said, table["changes"]) or _second_word_is_a_pronoun(said, table["pronouns"]):
            return True
        polite = _starts_with_one_of(said, table["leading"])
        if not polite:
            return False
        said = said[len(polite) :].lstrip(" " + "".join(table["marks"]))


def _second_word_is_a_pronoun(said: str, pronouns: Sequence[str]) -> bool:
    """'polish it', 'frost them a little': a pronoun for the material above after the first word."""
    words = said.split()
    return len(words) > 1 and words[1].strip("".join(teaching()["politeness"]["marks"])) in pronouns


def _starts_with_one_of(said: str, phrases: Sequence[str]) -> str:
    """The longest of the phrases the text starts with (then a space, a mark or its end), or ''."""
    ends = ("", " ", *teaching()["politeness"]["marks"])
    found = [p for p in phrases if said.startswith(p) and said[len(p) : len(p) + 1] in ends]
    return max(found, key=len, default="")


def as_change(material: ast.Material, words: Sequence[Tagged]) -> tuple[ast.Refinement, Diagnostic]:
    """'make it blue': the described words as a change line of the material above (its groups,
    'with' clauses and inline comparatives: 'a slightly darker grey'; the implied noun is dropped),
    and the note saying so."""
    typed = [w for w in words if w.text[:1].isalpha() and w.implied_by is None]
    said = typed or [w for w in words if w.text[:1].isalpha()]  # 'between beige and grey': one implied colour
    change = ast.Refinement(
        None, material.refinements, material.span, material.text, material.coat, material.features, material.groups
    )
    written = written_text(said)
    message = f"read '{written}' as a change of the material above: its words apply to it"
    return change, Diagnostic(written_span(said), Severity.NOTE, NOTE_CODE, message)


def material_change(
    node: ast.Material, words: Sequence[Tagged], text: str, lexicon: Lexicon
) -> tuple[ast.Refinement, Diagnostic] | None:
    """'make it walnut', 'switch to brass', 'can you make it gold instead': a change line that names
    a material. The change carries the material (cnlmc.analyze.changed_material: a material of the
    same kind as the one above takes its place, its describing words kept; another kind replaces
    it) and, for a noun that is also a colour or a describing word ('make it cream' under red
    plastic, 'make it satin' under tile), that reading, used when the kinds differ. None for any
    other line."""
    if node.name is not None or len(node.nouns) != 1 or node.nouns[0].unknown or not starts_with_change(text):
        return None
    noun = node.nouns[0]
    entry = lexicon.entry("nouns", noun.key)
    if entry is None:
        return None
    said = next((w for w in words if w.span.start == noun.span.start), None)
    colours = tuple(c for c in said.candidates if c.tag in CHANGE_READINGS) if said is not None else ()
    as_colour = _colour_change(words, said, colours, text, lexicon) if said is not None and colours else None
    kind = entry.get("class", noun.key)
    if as_colour is not None:
        change = ast.Refinement(
            None, (), node.span, node.text, as_colour.coat, as_colour.features, as_colour.groups, material=node
        )
        message = (
            f"read '{noun.text}' as a change of the material above: {noun.key} if it is {kind} too, else the colour"
        )
    else:
        change = ast.Refinement(None, (), node.span, node.text, material=node)
        message = f"read '{noun.text}' as a change of the material above: now {noun.key} (its describing words kept if it is {kind} too)"
    return change, Diagnostic(noun.span, Severity.NOTE, NOTE_CODE, message)


def _colour_change(
    words: Sequence[Tagged], said: Tagged, colours: tuple[Candidate, ...], text: str, lexicon: Lexicon
) -> ast.Refinement | None:
    """The change line with its noun read as the colour it also is."""
    from .parser import parsed_material

    as_colour = [Tagged(w.text, w.span, colours) if w is said else w for w in words]
    noun = everyday_noun()
    with_noun = [*as_colour, implied_noun(noun, as_colour[-1])]
    material = parsed_material(with_noun, text, lexicon.caches.shapes)
    return as_change(material, with_noun)[0] if material is not None else None


def _compared_list(item: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'darker, moodier green' first: paint with every comparative as an inline one, the one that
    names the colour first (the colour is the material's, the others then move it)."""
    from .parser import parsed_material

    noun = everyday_noun()
    last = item.items[-1]
    implied = Tagged(noun, last.span, (Candidate("NOUN", noun, "nouns"),), implied_by=item.span)
    bare = parsed_material([implied], item.text, lexicon.caches.shapes)
    if bare is None:
        return None
    ordered = (*[i for i in item.items if i.target is not None], *[i for i in item.items if i.target is None])
    material = ast.Material(None, (), bare.nouns, None, item.span, item.text, ordered)
    said = " ".join(i.word.text for i in item.items)
    message = f"no material named: read '{item.text.strip()}' as {noun}, then '{said}' (comparisons as the first line)"
    hint = "name the material to choose another, or write the material first and these lines below it"
    return material, Diagnostic(item.span, Severity.NOTE, NOTE_CODE, message, (hint,))


def _closer_alone(item: ast.Refinement, colour: ast.Colour) -> tuple[ast.Material, Diagnostic]:
    """'more like a burnt orange' first: nothing to come closer from, so the colour itself, on the
    everyday noun colours go on."""
    noun = everyday_noun()
    group = ast.Group("colour", (), (colour,), (), colour.span)
    implied = ast.Word(noun, noun, "nouns", item.span)
    material = ast.Material(None, (group,), (implied,), None, item.span, item.text)
    said = " ".join(w.text for w in colour.words)
    message = f"no material named: read '{item.text.strip()}' as '{said} {noun}' (nothing above to come closer from)"
    hint = "name the material to choose another, or write the material first and this line below it"
    return material, Diagnostic(item.span, Severity.NOTE, NOTE_CODE, message, (hint,))


def _colour_said_plainly(words: list[Tagged], lexicon: Lexicon) -> list[Tagged]:
    """The words with 'a shade of navy' read as 'navy' (cnlmc.hedges.colour_of) and a colour's head
    word after it left out ('a lighter navy shade', 'a warmer grey tone': teaching.toml
    [politeness] colour_heads), as the line's own reading did, so a noun can follow the colour."""
    from .hedges import colour_of
    from .politeness import without_colour_head

    rewritten = colour_of(words, lexicon)
    return without_colour_head(rewritten[0] if rewritten is not None else words, teaching()["politeness"])


def first_line_comparison(item: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'paler blue', 'a bit warmer grey' with no material above: a comparison as the first line
    describes a material one step from its colour on the everyday noun colours go on ('paler blue'
    = one step paler than blue paint), with a note; None for any other refinement (it keeps W104)."""
    if not item.items or item.coat is not None or item.features or item.groups:
        return None
    if not isinstance(item.items[-1].target, ast.Colour):
        return None
    if len(item.items) > 1:
        return _compared_list(item, lexicon)
    target = item.items[0].target
    if (
        isinstance(target, ast.Colour)
        and lexicon.require("refinements", item.items[0].word.key).get("towards") is not None
    ):
        return _closer_alone(item, target)
    from .parser import parsed_material
    from .place_words import place_at
    from .spans import blanked
    from .tagger import Tagger

    start = item.span.start - (item.span.col - 1)  # the line's offset: its text is the whole line
    place = place_at(item.text, lexicon)  # 'a shinier red for the door': the place read past
    said_text = item.text if place is None else blanked(item.text, [(place, len(item.text))])
    tagged, diags = Tagger.of(lexicon).tag_line(said_text, item.span.line, start)
    words = _colour_said_plainly(tagged, lexicon)
    dropped = {w.span.start for w in tagged if not any(w is kept for kept in words)}
    errors = [d for d in diags if d.is_error and (d.span is None or d.span.start not in dropped)]
    if errors or not words:  # a note ('darker than navy' read as 'darker navy') is fine
        return None
    noun = everyday_noun()
    with_noun = [*words, implied_noun(noun, words[-1])]
    material = parsed_material(with_noun, said_text, lexicon.caches.shapes)
    if material is None:
        return None
    said = [w for w in words if w.text[:1].isalpha()]
    hint = "name the material to choose another, or write the material first and this line below it"
    return material, _note(said, noun, [], why=" (a comparison as the first line)", hint=hint)
