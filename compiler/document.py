"""A material file: one material or refinement per line, '#' comments, optional 'name:'.

Lines end as cnlmc.lines says (CRLF, LF or a lone CR); `iter_lines` is re-exported from there."""

from __future__ import annotations

import functools
import re
from collections.abc import Iterator, Sequence
from contextvars import ContextVar
from dataclasses import replace

from . import ast
from .degree_after import degrees_after, simile, simile_word
from .diagnostics import Diagnostic, Severity, error
from .joins import of_tag
from .lexicon import Lexicon
from .line_parts import PART_MARKS, Reader, by_parts, material_then_comparatives, part_cuts
from .lines import iter_lines
from .noun_first import noun_first_note, noun_first_readings
from .on_clause import context_dropped, likeness_dropped, on_material
from .parser import ParseFailure, describe_expected, parse_line_shape, parsed_item
from .phrase_patterns import alternatives
from .relative_clause import (
    clause_after,
    described_colour_after,
    describing_after,
    participle_after,
    relative_material,
)
from .removal import removal_line
from .shape_store import save_shapes
from .spans import Span, blanked
from .suggest import teaching
from .syntax import Shape
from .tagged import NOTE_CODE, Candidate, Tagged, only_tag, written_span, written_text
from .tagger import Tagger

__all__ = ["iter_items", "iter_lines", "parse_document", "parse_line"]

#: whether describing words after the noun may be read as after a comma (off while the parts of a
#: line so read are read, so the reading never nests)
_NOUN_FIRST: ContextVar[bool] = ContextVar("noun_first", default=True)
#: the most words a line read so may have (listings are short; each place for the comma is a parse)
NOUN_FIRST_WORDS = 12

MAX_LINE_CHARS = 2000
MAX_LINE_WORDS = 64


def parse_document(source: str, lexicon: Lexicon, filename: str = "<input>") -> ast.Document:
    """Parse every line; problems become diagnostics and the next line is parsed anyway."""
    doc = ast.Document(filename, source)
    tagger = Tagger.of(lexicon)
    for number, offset, text in iter_lines(source):
        node = parse_line(text, number, offset, tagger, doc.diagnostics)
        if node is not None:
            doc.items.append(node)
    save_shapes(lexicon.caches.shapes)  # the shapes read here, for the next run (nothing new: no write)
    return doc


def iter_items(source: str, lexicon: Lexicon, diags: list[Diagnostic]) -> Iterator[tuple[ast.Item, bool]]:
    """Each line's node in document order, parsed as it is asked for, and whether its line has an
    error; the problems go to `diags` as each line is parsed (what parse_document collects)."""
    tagger = Tagger.of(lexicon)
    for number, offset, text in iter_lines(source):
        before = len(diags)
        node = parse_line(text, number, offset, tagger, diags)
        if node is not None:
            yield node, len(diags) > before and any(d.is_error for d in diags[before:])
    save_shapes(lexicon.caches.shapes)  # the shapes read here, for the next run (nothing new: no write)


def parse_line(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Item | None:
    stripped = text.lstrip()
    if not stripped or stripped[0] == "#":  # blank, or a comment
        return None
    if len(text) > MAX_LINE_CHARS:
        diags.append(
            error(
                Span(offset, offset + len(text), number, 1),
                "E004",
                f"line is too long ({len(text)} characters; at most {MAX_LINE_CHARS})",
            )
        )
        return None
    mark = len(diags)
    node = _parsed_line(text, number, offset, tagger, diags)
    if not any(d.is_error for d in diags[mark:]):
        return node
    for reread in WHOLE_LINE_REREADINGS:
        found = reread(text, number, offset, tagger)
        if found is not None:
            diags[mark:] = found[1]
            return found[0]
    if passed := _english_read_past(text, number, offset, tagger, diags[mark:]):
        diags[mark:] = passed[1]
        return passed[0]
    return node


def _corrected(text: str, number: int, offset: int, tagger: Tagger) -> tuple[ast.Item, list[Diagnostic]] | None:
    """The line read with its mid-line correction (cnlmc.corrections), with a note; None when it
    has none or does not read so."""
    from .corrections import correction

    lexicon = tagger.lexicon
    found = correction(text, lambda word: {entry.tag for entry in lexicon.lookup((word,))})
    if found is None:
        return None
    said: list[Diagnostic] = []
    node = _parsed_line(found.text, number, offset, tagger, said)  # one correction a line: no nesting
    if node is None or any(d.is_error for d in said):
        return None
    span = Span(offset + found.start, offset + found.end, number, found.start + 1)
    note = f"read past '{found.dropped} {found.marker}': a correction, the word after it said instead"
    if not found.dropped:  # 'no actually a lot lighter'
        note = f"read past '{found.marker}': a correction, what follows said instead"
    return replace(node, text=text), [*said, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)]


def _fillers_after_comma(
    words: list[Tagged], text: str, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic, int] | None:
    """'not glossy, just a flat grey paint', 'matte, a grey paint': after a comma, filler words
    (teaching.toml [politeness] after_comma) and an article before the rest are read past, with a
    note and where they start; None when the line has none, or does not read as a material then."""
    fillers = frozenset(teaching()["politeness"]["after_comma"])
    for at, word in enumerate(words[:-2]):
        if not only_tag(word, "COMMA"):
            continue
        end = at + 1
        while end < len(words) - 1 and (words[end].text.lower() in fillers or only_tag(words[end], "ARTICLE")):
            end += 1
        if end == at + 1:
            continue
        node = _parsed([*words[: at + 1], *words[end:]], text, lexicon)
        if not isinstance(node, ast.Material):
            return None
        run = words[at + 1 : end]
        said = " ".join(w.text for w in run)
        note = Diagnostic(
            run[0].span.to(run[-1].span), Severity.NOTE, NOTE_CODE, f"read past '{said}': filler after the comma"
        )
        return node, note, run[0].span.start
    return None


def _read_blanked(
    text: str, start: int, number: int, offset: int, tagger: Tagger, message: str
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """The line read again with its text from `start` to the end blanked (columns stay), its notes
    and a note of `message` over the words read past; None when it does not then read cleanly. A
    refinement keeps the text it was read from (a first line's comparison re-reads it)."""
    said: list[Diagnostic] = []
    node = _parsed_line(blanked(text, [(start, len(text))]), number, offset, tagger, said)
    if node is None or any(d.is_error for d in said):
        return None
    span = Span(offset + start + 1, offset + len(text.rstrip()), number, start + 2)
    note = Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read past '{text[start:].strip()}': {message}")
    return (node if isinstance(node, ast.Refinement) else replace(node, text=text)), [*said, note]


def _not_another_material(
    text: str, number: int, offset: int, tagger: Tagger
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'a brushed nickel tap, not chrome', 'walnut, not oak': a material the line ends by saying it
    is not (after a comma: teaching.toml [hedges] `not_another`) is read past with a note, the line
    read without it; None when the words after it name no material, or the rest does not read as a
    material cleanly."""
    found = _not_another_pattern().search(text)
    if found is None:
        return None
    other, problems = tagger.tag_line(found.group("other"), number, 0)
    if not other or any(d.is_error for d in problems) or not any(c.tag == "NOUN" for c in other[-1].candidates):
        return None
    read = _read_blanked(text, found.start(), number, offset, tagger, "what it is not, named only to rule it out")
    return read if read is not None and isinstance(read[0], ast.Material) else None


@functools.cache
def _not_another_pattern() -> re.Pattern[str]:
    table = teaching()["hedges"]
    articles = alternatives(table["pointing_words"])
    lead = rf",\s*(?:(?:{alternatives(table['not_another_before'])})\s+)?(?:{alternatives(table['not_another'])})"
    return re.compile(rf"{lead}\s+(?:(?:{articles})\s+)?(?P<other>[^,]+?)\s*[.!]?\s*$", re.IGNORECASE)


def _without_place(text: str, number: int, offset: int, tagger: Tagger) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'a glossier black for the bonnet': where it goes or what it is for (cnlmc.place_words) read
    past and the whole line read again (so a comparison as the first line still lands on paint),
    with a note; None when the line has none or does not then read cleanly."""
    from .place_words import place_at

    start = place_at(text, tagger.lexicon)
    if start is None:
        return None
    return _read_blanked(text, start, number, offset, tagger, "where it goes or what it is for, not how it looks")


def _without_fillers(text: str, number: int, offset: int, tagger: Tagger) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'um so like brushed copper you know', 'red, um, dark red velvet': the fillers of speech
    anywhere in a line that does not read (teaching.toml [politeness] fillers_anywhere) blanked, a
    comma left doubled by one blanked too, and the line read again, with a note; None when it has
    none or still does not read cleanly."""
    found = [(m.start(), m.end()) for m in _fillers_pattern().finditer(text)]
    if not found:
        return None
    plain = blanked(text, found)
    doubled = [(m.start(), m.start() + 1) for m in re.finditer(r",(?=\s*,)", plain)]
    plain = blanked(plain, doubled).rstrip()
    if not plain.strip():
        return None
    said: list[Diagnostic] = []
    node = _parsed_line(plain + " " * (len(text) - len(plain)), number, offset, tagger, said)
    if node is None or any(d.is_error for d in said):
        return None
    listed = ", ".join(dict.fromkeys(f"'{text[a:b]}'" for a, b in found))
    span = Span(offset + found[0][0], offset + found[-1][1], number, found[0][0] + 1)
    note = Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read past {listed}: words of speech, not of the look")
    return replace(node, text=text), [*said, note]


@functools.cache
def _fillers_pattern() -> re.Pattern[str]:
    fillers = teaching()["politeness"]["fillers_anywhere"]
    return re.compile(rf"(?<![\w'])(?:{alternatives(fillers)})(?![\w'])", re.IGNORECASE)


def _without_after_material(
    text: str, number: int, offset: int, tagger: Tagger
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'mirror polished steel without any scratches', 'oak with no knots': a material, then what it is
    without, said with no comma (teaching.toml [removal] inline), read as after a comma ('steel,
    without any scratches': cnlmc.line_parts takes the words off, or says the material has none),
    with a note; None for any other line."""
    low = text.lower()
    for phrase, reading in teaching()["removal"]["inline"].items():
        start = low.find(f" {phrase} ")
        if start <= 0 or not low[:start].strip() or len(reading) > len(phrase):
            continue
        end = start + 1 + len(phrase)  # the phrase said as its reading, right-aligned: columns stay
        listed = f"{text[:start]},{' ' * (len(phrase) - len(reading))}{reading}{text[end:]}"
        lexicon = tagger.lexicon
        found = material_then_comparatives(
            listed, number, offset, _part_reader(listed, number, offset, lexicon), lexicon
        )
        if found is None:
            return None
        said = f"{text[:start].strip()}, {text[start + 1 :].strip()}"
        span = Span(offset + start + 1, offset + len(text.rstrip()), number, start + 2)
        note = f"read '{text.strip()}' as '{said}' (what it is without, after the material)"
        return replace(found[0], text=text), [*found[1], Diagnostic(span, Severity.NOTE, NOTE_CODE, note)]
    return None


#: readings of a whole line that does not read, tried in turn (each a note of what it read past)
WHOLE_LINE_REREADINGS = (
    _corrected,  # 'oak matt no wait satin': the correction's word
    _not_another_material,  # 'a brushed nickel tap, not chrome'
    _without_place,  # 'a glossier black for the bonnet'
    _without_fillers,  # 'um so like brushed copper you know'
    _without_after_material,  # 'steel without any scratches'
)


def _english_read_past(
    text: str, number: int, offset: int, tagger: Tagger, said: list[Diagnostic]
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """The line read without its unknown words of English that say nothing cnlmc can show, each
    with its warning (cnlmc.read_past: 'gnarled yew'); None when it may not be or does not read."""
    from .read_past import passable_words, warning

    formation = tagger.formation()
    slips = formation.slips_index()
    if slips is None:  # a language that reads no slips has no word list either (German)
        return None

    def word_of(diag: Diagnostic) -> str:
        span = diag.span
        return text[span.col - 1 : span.col - 1 + span.end - span.start] if span and span.line == number else ""

    def near(word: str) -> bool:
        return any(edits == 1 for edits, _form in slips.index.typos(word))

    passed = passable_words([d for d in said if d.is_error], word_of, near)
    if not passed:
        return None
    columns = [(d.span.col - 1, d.span.col - 1 + d.span.end - d.span.start) for d in passed if d.span is not None]
    again: list[Diagnostic] = []
    node = _parsed_line(blanked(text, columns), number, offset, tagger, again)
    if not isinstance(node, ast.Material) or not _noun_said(node, text) or any(d.is_error for d in again):
        return None  # 'glossy guitar' is not glossy paint: the material must be named, not implied
    return replace(node, text=text), [*again, *(warning(d, word_of(d)) for d in passed)]


def _noun_said(node: ast.Material, text: str) -> bool:
    """Whether one of the material's nouns is written on the line where it stands (not implied by
    describing words: 'glossy' read as glossy paint)."""
    start = node.span.start - (node.span.col - 1)
    written = (text[n.span.start - start : n.span.end - start].strip().lower() for n in node.nouns)
    return any(said and said in noun.text.lower() for said, noun in zip(written, node.nouns))


def _removal(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Refinement | None:
    """The line as one that takes words off the material above (cnlmc.removal: 'lose the brushed
    look', 'no rust'), with the line's plain reading as its comparatives ('lose the shine' = less
    shine) for a material that has none of them (cnlmc.passes.refine); None for any other line.
    Asked only of a line with an unknown or rule-read word or one that does not parse."""
    removal = removal_line(text, number, offset, tagger)
    if removal is None:
        return None
    refinement, note = removal
    plain_diags: list[Diagnostic] = []
    plain = _parsed_line(text, number, offset, tagger, plain_diags, removals=False)
    if isinstance(plain, ast.Refinement) and plain.items and not any(d.is_error for d in plain_diags):
        refinement = replace(refinement, items=plain.items)
    diags.append(note)
    return refinement


def read_without_removal(line: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, list[Diagnostic]] | None:
    """A removal line with no material above ('no sheen', 'no gloss at all') read as the words say
    alone (word formation's negation: 'no sheen' = matte, on the everyday noun), with its notes;
    None when that reading names no material or has an error."""
    span = line.span
    offset = span.start - (span.col - 1)
    diags: list[Diagnostic] = []
    node = _parsed_line(line.text, span.line, offset, Tagger.of(lexicon), diags, removals=False)
    if any(d.is_error for d in diags):
        return None
    if (node is None or _changes_nothing(node)) and diags:  # 'not metallic': no word left, on the everyday noun
        from .suggest import everyday_noun

        noun = everyday_noun()
        said = line.text.strip()
        note = Diagnostic(
            span,
            Severity.NOTE,
            NOTE_CODE,
            f"no material named: read '{said}' as plain {noun} (the words only say what it is not)",
        )
        return ast.Material(None, (), (ast.Word(noun, noun, "nouns", span),), None, span, line.text), [*diags, note]
    return (node, diags) if isinstance(node, ast.Material) else None


def read_change_alone(line: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, list[Diagnostic]] | None:
    """A change line of describing words with no material above ('make it navy blue', 'hey can you
    make it pillar box red please') read as its words alone, the material they describe implied,
    with a note; None when they do not read so."""
    if not line.groups or line.items:
        return None
    span = line.span
    offset = span.start - (span.col - 1)
    first, last = line.groups[0].span, line.groups[-1].span
    alone = " " * (first.start - offset) + line.text[first.start - offset : last.end - offset]
    diags: list[Diagnostic] = []
    node = _parsed_line(alone, span.line, offset, Tagger.of(lexicon), diags, removals=False)
    if not isinstance(node, ast.Material) or any(d.is_error for d in diags):
        return None
    said = alone.strip()
    note = f"no material above: read '{line.text.strip()}' as its words alone, '{said}'"
    return replace(node, text=line.text), [*diags, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)]


def _changes_nothing(node: ast.Item) -> bool:
    return isinstance(node, ast.Refinement) and node.keeps_only


def _kept(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Refinement | None:
    """The line as one that keeps the material as it is ('keep the grain', 'perfect': cnlmc.kept),
    a change line with no change, with its note; None for any other line."""
    from .kept import kept_line

    kept = kept_line(text, number, offset, tagger)
    if kept is None:
        return None
    diags.append(kept[1])
    return kept[0]


def _said_line(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Refinement | None:
    """The line as a comparative said as a removal ('less of the orange, please'), a removal or one
    that keeps the material; None for any other line."""
    return (
        _comparative_reading(text, number, offset, tagger, diags)
        or _removal(text, number, offset, tagger, diags)
        or _kept(text, number, offset, tagger, diags)
        or _change_after_kept(text, number, offset, tagger, diags)
        or _going_back(text, number, offset, tagger, diags)
        or _degree_after(text, number, offset, tagger, diags)
    )


def _degree_after(
    text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]
) -> ast.Refinement | None:
    """'rougher, a little', 'darker, but only slightly', 'lighter a bit': a degree said after the
    comparatives is their degree (each one said without its own), with a note; None for any other
    line. Each place the degree may start is tried, the last word first ('bit', then 'a bit')."""
    low = text.lower()
    cuts = [end for end in range(len(low.rstrip(" .!?")), 0, -1) if low[end - 1] in " ,"][:_DEGREE_WORDS]
    for end in cuts:
        reading = _degree_from(text, low, end, number, offset, tagger)
        if reading is not None:
            diags.extend(reading[1])
            return reading[0]
    return None


_DEGREE_WORDS = 3  # a degree is at most three words ('a little bit'): the places it may start


def _degree_from(
    text: str, low: str, at: int, number: int, offset: int, tagger: Tagger
) -> tuple[ast.Refinement, list[Diagnostic]] | None:
    """The line read with the degree starting at `at` (after a space or comma), or None."""
    from .suggest import teaching

    degree = low[at:].rstrip(" .!?")
    head = low[:at].rstrip(" ,")
    between = teaching()["going_back"]["before_degree"]  # 'darker, but only slightly'
    while head.rsplit(" ", 1)[-1] in between and " " in head:
        head = head.rsplit(" ", 1)[0].rstrip(" ,")
    if not degree or not head:
        return None
    entries = tagger.lexicon.lookup(tuple(degree.split()))
    if not any(e.category == "adverbs" for e in entries):
        return None
    said: list[Diagnostic] = []
    node = _parsed_line(text[: len(head)], number, offset, tagger, said, removals=False)
    if not isinstance(node, ast.Refinement) or not node.items or any(d.is_error for d in said):
        return None
    span = Span(offset + at, offset + at + len(degree), number, at + 1)
    key = next(e.key for e in entries if e.category == "adverbs")
    adverb = ast.Word(text[at : at + len(degree)], key, "adverbs", span)
    items = tuple(item if item.adverbs else replace(item, adverbs=(adverb,)) for item in node.items)
    note = Diagnostic(
        span, Severity.NOTE, NOTE_CODE, f"read '{text[at : at + len(degree)]}' as the degree of the change before it"
    )
    line = replace(node, items=items, span=_line_span(text, number, offset), text=text)
    return line, [*said, note]


def _going_back(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Refinement | None:
    """'go back a bit' (cnlmc.back: reversed where the change above is known), or 'too blue, back a
    bit': the change before the back part, which is read past with a note; None for any other line."""
    from .back import back_after_change, back_line, change_after_back

    found = back_line(text, number, offset, tagger)
    if found is not None:
        return found
    tail = back_after_change(text, tagger)
    head = change_after_back(text) if tail is None else None
    if tail is None and head is None:
        return None
    change: list[Diagnostic] = []
    if tail is not None:  # 'too blue, back a bit'
        end, said = tail
        node = _parsed_line(text[:end], number, offset, tagger, change, removals=False)
        start = text.index(said, end)
    else:  # 'no, go back a bit darker'
        assert head is not None
        node = _parsed_line(" " * head + text[head:], number, offset, tagger, change, removals=False)
        said, start = text[:head].strip(" ,"), len(text) - len(text.lstrip())
    if not isinstance(node, ast.Refinement) or not node.items or any(d.is_error for d in change):
        return None
    span = Span(offset + start, offset + start + len(said), number, start + 1)
    note = f"read past '{said}': the change said with it says which way"
    diags.extend([*change, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)])
    return replace(node, span=_line_span(text, number, offset), text=text)


def _line_span(text: str, number: int, offset: int) -> Span:
    """The span of the whole line, its trailing blanks left out (a line read another way)."""
    return Span(offset, offset + len(text.rstrip()), number, 1)


def parse_change_line(text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]) -> ast.Item | None:
    """A line built by the compiler (a reversal: cnlmc.back) parsed as a line of the source is."""
    return _parsed_line(text, number, offset, tagger, diags, removals=False)


def _change_after_kept(
    text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]
) -> ast.Refinement | None:
    """'keep the tiles but make them shinier': the change after what stays (cnlmc.kept), read as a
    line of its own where it stands, with a note for the part read past; None for any other line."""
    from .kept import kept_before_change

    found = kept_before_change(text, number, offset, tagger)
    if found is None:
        return None
    start, note = found
    said: list[Diagnostic] = []
    node = _parsed_line(" " * start + text[start:], number, offset, tagger, said)
    if not isinstance(node, ast.Refinement) or any(d.is_error for d in said):
        return None
    diags.extend([note, *said])
    return replace(node, span=_line_span(text, number, offset), text=text)


def _comparative_reading(
    text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]
) -> ast.Refinement | None:
    """'less of the rust', 'a bit less of the orange': the comparative the phrase also is ('less
    rust': less of it, not none; teaching.toml [removal] comparative), with a note; None when the
    line does not open with one or does not read so."""
    from .suggest import teaching

    low = text.lower()
    start = len(low) - len(low.lstrip())
    table = teaching()["removal"]["comparative"]
    phrase = next((p for p in sorted(table, key=len, reverse=True) if low[start:].startswith(p + " ")), None)
    if phrase is None:
        return None
    end = start + len(phrase)
    said: list[Diagnostic] = []
    rewritten = text[:start] + table[phrase] + " " * (end - start - len(table[phrase])) + text[end:]
    plain = _parsed_line(rewritten, number, offset, tagger, said, removals=False)
    if not isinstance(plain, ast.Refinement) or not plain.items or any(d.is_error for d in said):
        return None
    span = Span(offset + start, offset + end, number, start + 1)
    note = f"read '{text[start:end]}' as '{table[phrase]}': less of it, not none"
    diags.extend([*said, Diagnostic(span, Severity.NOTE, NOTE_CODE, note)])
    return plain


def _parsed_line(
    text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic], removals: bool = True
) -> ast.Item | None:
    words, tag_diags = tagger.tag_line(text, number, offset)
    if tag_diags and removals and (removal := _said_line(text, number, offset, tagger, diags)) is not None:
        return removal
    mark = len(diags)
    if tag_diags:  # only unknown words and characters may lack candidates
        from .teach import fit_unknown_words  # the teaching modules load only for a line with a problem

        fitted, words = fit_unknown_words(tag_diags, words, tagger.lexicon)
        diags.extend(fitted)
        words = [t for t in words if t.candidates]
    if not words:  # every word read past ('not too yellow', 'not at all rusty'): a line that changes nothing
        spans = [d.span for d in diags[mark:] if d.span is not None and d.span.line == number]
        if not spans or any(d.is_error for d in diags[mark:]):
            return None
        return ast.Refinement(None, (), spans[0].to(spans[-1]), text)
    if len(words) > MAX_LINE_WORDS:
        diags.append(
            error(
                words[0].span.to(words[-1].span),
                "E004",
                f"phrase is too long ({len(words)} words; at most {MAX_LINE_WORDS})",
            )
        )
        return None
    words, after = degrees_after(words)  # 'shiny af': very shiny
    diags.extend(after)
    if tag_diags and any(w.unknown and w.text.lower() == simile_word() for w in words):
        likened = _simile_reading(words, text, tagger.lexicon, diags)  # 'concrete smooth as glass'
        if likened is not None:
            return likened
    try:
        shape, picks = parse_line_shape(words, tagger.lexicon.caches.shapes)
    except ParseFailure as failure:
        if removals and (removal := _said_line(text, number, offset, tagger, diags)) is not None:
            return removal
        return _failed_line(failure, words, text, tagger.lexicon, diags)
    node = shape.build(words, picks, text)
    if isinstance(node, ast.Material) and node.refinements and (toward := _toward_colour_noun(node, words)):
        return toward  # 'more charcoal', 'a bit more terracotta': the colour, not a new material
    if tag_diags and any(d.is_error for d in diags[mark:]) and (whole := _whole_line(words, text, tagger.lexicon)):
        diags[mark:] = whole[1]  # 'rust on steel', 'deeper, closer to burgundy': the unknown word read
        return whole[0]
    if tag_diags and any(d.is_error for d in diags[mark:]):  # "it's brushed steel": guesses parsed it
        stated = _statement_reading(words, text, tagger.lexicon, diags)
        if stated is not None:
            return stated
    if tag_diags and isinstance(node, ast.Material):  # a change phrase read past: 'make it walnut'
        from .implied import material_change

        change = material_change(node, words, text, tagger.lexicon)
        if change is not None:
            diags.append(change[1])
            return change[0]
    return node


def _toward_colour_noun(node: ast.Material, words: list[Tagged]) -> ast.Refinement | None:
    """'more charcoal', 'lighter, more terracotta': 'more' or 'less' with nothing after it but a noun
    that is also a colour is a change of the colour above toward (or away from) that colour, not a
    new material with a comparative of nothing; None for any other material."""
    if len(node.nouns) != 1 or node.groups or node.coat or node.features:
        return None
    item, noun = node.refinements[-1], node.nouns[0]  # 'lighter, more charcoal': the last compares
    from .suggest import teaching

    if item.target is not None or item.word.key not in teaching()["politeness"]["bare_comparisons"]:
        return None
    said = next((w for w in words if w.span.start == noun.span.start), None)
    colour = next((c for c in said.candidates if c.tag == "COLOR"), None) if said is not None else None
    if colour is None:
        return None
    named = ast.Colour((), ast.Word(noun.text, colour.key, colour.category, noun.span), noun.span)
    toward = ast.RefineItem(item.word, named, item.span.to(noun.span), item.adverbs)
    return ast.Refinement(None, (*node.refinements[:-1], toward), node.span, node.text)


def _failed_line(
    failure: ParseFailure, words: list[Tagged], text: str, lexicon: Lexicon, diags: list[Diagnostic]
) -> ast.Item | None:
    """The taught error of a line that does not parse, or the line read with its implied material
    when it only describes one ('matte black'), or as a change of the material above when it
    starts with a change phrase ('make it blue'): cnlmc.implied."""
    from .hedges import (
        but_after_noun,
        comparison_shared,
        finish_dropped,
        inside_a_note,
        named_then_compared,
        postfix_finish,
        read_past,
        reread,
        with_after_comma,
        with_implied,
    )
    from .sense_said import kind_said, sense_said

    named = _material_named_first(words, text, lexicon)  # 'marble: white, honed'
    if named is not None:
        diags.append(named[1])
        return named[0]
    filled = _fillers_after_comma(words, text, lexicon)  # 'not glossy, just a flat grey paint'
    if filled is not None:
        diags[:] = [d for d in diags if not (d.is_error and d.span is not None and d.span.start >= filled[2])]
        diags.append(filled[1])
        return filled[0]
    sensed = sense_said(words, text, lexicon) or kind_said(words, text, lexicon)  # 'teak, the colour not the wood'
    if sensed is not None:
        diags[:] = [d for d in diags if not (d.is_error and d.span is not None and d.span.start >= sensed[2])]
        diags.append(sensed[1])
        return sensed[0]
    made = _made_of_reading(words, text, lexicon, diags)  # 'wood of oak', 'a cloak of grey wool'
    if made is not None:
        return made
    likened = _simile_reading(words, text, lexicon, diags)  # 'rough as sandpaper': very rough
    if likened is not None:
        return likened
    compared = _compared_after_noun(words, text, lexicon)  # 'copper darker than a penny'
    if compared is not None:
        diags[:] = [
            d for d in diags if not (d.span and d.span.start >= compared[2])
        ]  # its notes and errors: this one says it
        diags.append(compared[1])
        return compared[0]
    listed = _slashes_listing(words)  # 'matte/black/rubber': a list, not alternatives
    if listed is not None and (node := _parsed(listed, text, lexicon)) is not None:
        whole_line = words[0].span.to(words[-1].span)
        note = f"read '{written_text(words)}' as a list: a slash between words of different kinds is a comma"
        diags.append(Diagnostic(whole_line, Severity.NOTE, NOTE_CODE, note))
        return node
    polite = _politely(words, lexicon)  # 'more of a teal', 'ok, a bit darker': known words, a rewrite
    if polite is not None and (node := _parsed(polite[1], text, lexicon)) is not None:
        diags.extend(polite[0])
        return _as_change(node, polite[1], text, lexicon, diags)
    bare = _without_article(words)  # 'a darker, moodier green': a line of comparatives
    if bare is not None and isinstance(node := _parsed(bare, text, lexicon), ast.Refinement):
        return node
    hedged, notes = reread(words, lexicon)  # 'a touch of sheen' = 'slightly sheen'
    bare = _without_article(hedged) if notes else None  # 'a paler shade of brown' = 'paler brown'
    if bare is not None and isinstance(node := _parsed(bare, text, lexicon), ast.Refinement):
        diags[:] = [d for d in diags if not read_past(d, notes)]
        diags.extend(notes)
        return node
    clause = (
        postfix_finish(hedged, lexicon)
        or with_implied(hedged)
        or finish_dropped(hedged, lexicon)
        or comparison_shared(hedged)  # 'more worn and weathered'
        or named_then_compared(hedged)  # 'grain more visible', 'stain darker'
    )
    said_with_errors = _said_with_errors(words, diags)  # 'oak, no grain' is a removal; 'floor but not orange' too
    comma_clause = None if said_with_errors else with_after_comma(hedged)
    but_clause = None if said_with_errors else but_after_noun(hedged)  # 'grey paint but not too shiny'
    for attempt in _rereadings(hedged, notes, (comma_clause, clause, but_clause)):
        node = _parsed(attempt[0], text, lexicon)
        if node is not None:
            diags[:] = [d for d in diags if not read_past(d, attempt[1])]  # 'loads' of 'loads of'
            diags.extend(attempt[1])
            return node
    whole = (
        _whole_line(hedged, text, lexicon)
        or _but_then_comparatives(hedged, text, lexicon)
        or _clause_first(hedged, notes, text, lexicon)
    )
    if whole is not None:
        taken = _removal_part(
            text, _but_at(words)
        )  # 'no' of 'oak, no grain': read as the removal, and no other note of it
        passed = [n for n in whole[1] if n.message.startswith("read past ")]  # a part read past: all its errors go
        diags[:] = [
            d
            for d in diags
            if not read_past(d, whole[1], taken)
            and not read_past(d, passed, misplaced=True)
            and not (taken and _said_again(d, whole[1]))
            and not (d.severity is Severity.NOTE and inside_a_note(d, passed))  # and its words' notes
        ]
        diags.extend(whole[1])
        return whole[0]
    if notes:  # still no parse: the rest reads the words as reread, and says so
        words, failure = hedged, _failure_of(hedged, lexicon) or failure
        diags[:] = [d for d in diags if not read_past(d, notes)]
        diags.extend(notes)
    implied, said = _implied_reading(failure, words, text, lexicon)
    if implied is None and polite is not None and (again := _failure_of(polite[1], lexicon)) is not None:
        implied, polite_said = _implied_reading(again, polite[1], text, lexicon)  # 'a soft putty colour'
        if implied is not None:
            diags.extend(polite[0])
            said = polite_said
    if implied is None and (first := _noun_first(words, text, lexicon)) is not None:
        diags.extend(
            d for d in first[1] if d not in diags
        )  # 'steel brushed', 'oak a bit darker': when nothing else reads the line
        return first[0]
    if implied is None and (stated := _statement_reading(words, text, lexicon, diags)) is not None:
        return stated  # 'the table is oak', 'the throne was hewn from black basalt': when nothing else reads it
    diags.append(said)
    return implied


#: the readings of the words before a statement's copula: a thing ('the table', 'the oak floor')
_SUBJECT_TAGS = frozenset(
    ("ARTICLE", "NOUN", "OBJECT", "NAME", "COLON", "ADJ", "COLOR", "SHADE", "ADV")
)  # "the old radio"


def _statement_reading(words: list[Tagged], text: str, lexicon: Lexicon, diags: list[Diagnostic]) -> ast.Item | None:
    """The line said as a statement about the thing, read as what it says of the material
    (cnlmc.statements), the errors of the words read past gone; None when it is no statement."""
    from .statements import read_statement, statement

    found = statement(text) if words else None
    if found is None:
        return None
    at = words[0].span
    line_start = at.start - (at.col - 1)
    subject = [w for w in words if w.implied_by is None and w.span.start - line_start < found.copula[0]]
    if not all(w.unknown or any(c.tag in _SUBJECT_TAGS for c in w.candidates) for w in subject):
        return None  # 'darker, it's sitting in a damp alley', 'duller like its old': no thing before it
    names_material = any(
        "nouns" in {e.category for e in lexicon.lookup((part,))} for w in subject for part in w.text.lower().split()
    )

    def parse(alone: str, said: list[Diagnostic]) -> ast.Item | None:
        return parse_line(alone, at.line, line_start, Tagger.of(lexicon), said)

    reading = read_statement(text, found, at.line, line_start, parse, names_material)
    colours = [w for w in subject if not names_material and any(c.tag in ("COLOR", "SHADE") for c in w.candidates)]
    if reading is not None and colours:  # 'the red chair is plastic': the thing's colour is the material's
        kept = [(w.span.start - line_start, w.span.end - line_start) for w in colours]
        coloured = read_statement(text, found, at.line, line_start, parse, names_material, kept)
        reading = coloured if coloured is not None and _only_coloured(reading[0], coloured[0]) else reading
    if reading is None:
        return None
    # the line's first reading failed: what it said goes, the statement's reading says it again
    diags[:] = [d for d in diags if not (d.span is not None and d.span.line == at.line)]
    diags.extend(reading[1])
    return replace(reading[0], text=text)


def _only_coloured(plain: ast.Material, coloured: ast.Material) -> bool:
    """Whether the subject's colour only colours the material the statement names: the same nouns
    (not a species the colour names with it: 'the black chair is oak' is not black oak) and no
    colour of its own said after the copula ('the green door is painted red')."""
    same = [n.key for n in plain.nouns] == [n.key for n in coloured.nouns]
    return same and not any(g.colours for g in plain.groups)


def _made_of_reading(words: list[Tagged], text: str, lexicon: Lexicon, diags: list[Diagnostic]) -> ast.Item | None:
    """The line as the material after its 'of' when the words before name a thing or a kind
    (cnlmc.made_of), the errors of those words read past; None when the rest is no material."""
    from .hedges import read_past
    from .made_of import made_of

    found = made_of(words, text, lexicon)
    if found is None:
        return None
    rest, note = found
    said: list[Diagnostic] = []
    node = _parsed(rest, text, lexicon)
    if node is None and (failure := _failure_of(rest, lexicon)) is not None:
        node = _failed_line(failure, rest, text, lexicon, said)
    if not isinstance(node, ast.Material) or any(d.is_error for d in said):
        return None
    diags[:] = [d for d in diags if not read_past(d, [note])]
    diags.extend([note, *said])
    return node


def _material_named_first(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Item, Diagnostic] | None:
    """'marble: white, honed', 'concrete: raw, grey': a name that is a material noun, and after its
    colon only describing words, is the material they describe (the words, then the noun), with a
    note; None for any other line."""
    if len(words) < 3 or not only_tag(words[0], "NAME") or not only_tag(words[1], "COLON"):
        return None
    head = words[0]
    offset = head.span.start - head.span.col + 1
    named, _notes = Tagger.of(lexicon).tag_line(head.text, head.span.line, head.span.start)
    known = len(named) == 1 and not named[0].unknown
    nouns = tuple(c for c in named[0].candidates if c.tag == "NOUN" and c.category == "nouns") if known else ()
    if not nouns:
        return None
    from .implied import implied_noun

    end = words[-1].span.end
    rest = words[2:]
    at = next((i for i, w in enumerate(rest) if i and only_tag(w, "WITH")), len(rest))  # 'white w/ grey chips'
    placed = implied_noun(nouns[0].key, rest[at - 1])  # inside the word's span before it, where no word starts
    noun = Tagged(head.text, placed.span, nouns, implied_by=head.span)
    node = _parsed([*rest[:at], noun, *rest[at:]], text, lexicon)
    if not isinstance(node, ast.Material):
        return None
    said = f"{text[rest[0].span.start - offset : rest[at - 1].span.end - offset]} {head.text.lower()}"
    if at < len(rest):
        said += f" {text[rest[at].span.start - offset : end - offset]}"
    note = f"read '{head.text}:' as the material the words after it describe: '{said}'"
    return node, Diagnostic(head.span, Severity.NOTE, NOTE_CODE, note)


def _as_change(node: ast.Item, words: list[Tagged], text: str, lexicon: Lexicon, diags: list[Diagnostic]) -> ast.Item:
    """A material read past its change phrase ('more of a cream' under marble) as the change of the
    material above it names (cnlmc.implied.material_change), with its note; any other node as it is."""
    from .implied import material_change

    change = material_change(node, words, text, lexicon) if isinstance(node, ast.Material) else None
    if change is None:
        return node
    diags.append(change[1])
    return change[0]


def _implied_reading(
    failure: ParseFailure, words: list[Tagged], text: str, lexicon: Lexicon
) -> tuple[ast.Item | None, Diagnostic]:
    """The line read with its implied material ('matte black' = matte black paint; a change of the
    material above when it starts with a change phrase: 'make it blue'), and its note; or None and
    the taught error (cnlmc.implied, cnlmc.teach)."""
    from .implied import as_change, implied_material, starts_with_change
    from .teach import teach_syntax_error

    taught = teach_syntax_error(_syntax_error(failure, words, lexicon), words, lexicon)
    implied = implied_material(taught, words, lexicon, text) or _implied_before_comma(words, lexicon, text)
    if implied is None:
        return None, taught
    with_noun, note = implied
    try:
        shape, picks = parse_line_shape(with_noun, lexicon.caches.shapes)
    except ParseFailure:
        clause = _comma_clause_after_implied(with_noun, note, lexicon)  # 'white, a touch of sheen'
        if clause is None:
            return None, taught
        (shape, picks), with_noun, note = clause
    material = shape.build(with_noun, picks, text)
    if isinstance(material, ast.Material) and starts_with_change(text):
        return as_change(material, words)
    return material, note


def _implied_before_comma(words: list[Tagged], lexicon: Lexicon, text: str) -> tuple[list[Tagged], Diagnostic] | None:
    """'white, a touch of sheen': the describing words before the first comma with their implied
    material (cnlmc.implied), the rest of the line after them; None when the part before the comma
    is not read so or the rest names no feature."""
    from .implied import implied_material
    from .teach import teach_syntax_error

    comma = _first_comma(words) or 0
    rest = words[comma + 1 :]
    if not comma or not any(c.tag == "FEATURE" for w in rest for c in w.candidates):
        return None
    failure = _failure_of(words[:comma], lexicon)
    if failure is None:
        return None
    taught = teach_syntax_error(_syntax_error(failure, words[:comma], lexicon), words[:comma], lexicon)
    implied = implied_material(taught, words[:comma], lexicon, text)
    return None if implied is None else ([*implied[0], *words[comma:]], implied[1])


def _clause_first(
    words: list[Tagged], notes: list[Diagnostic], text: str, lexicon: Lexicon
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'a touch of sheen, off white', 'some sheen, otherwise matt': a feature clause said first and
    the material (or its colour, a material implied) after the comma, read as that material with the
    clause; the notes of the reread words and one saying so. None for any other line."""
    from .hedges import with_after_comma

    comma = _first_comma(words)
    if not comma or comma + 1 == len(words):
        return None
    first, rest = words[:comma], words[comma + 1 :]
    if not any(c.tag == "FEATURE" for w in first for c in w.candidates):
        return None
    if any(c.tag in ("NOUN", "COMMA", "WITH") for w in first for c in w.candidates):
        return None
    reordered = [*rest, words[comma], *first]
    implied = _implied_before_comma(reordered, lexicon, text)  # 'off white, a touch of sheen'
    with_implied = _comma_clause_after_implied(*implied, lexicon) if implied is not None else None
    readings = [with_after_comma(reordered), with_implied[1:] if with_implied is not None else None]
    for tokens, note in (r for r in readings if r is not None):
        node = _parsed(tokens, text, lexicon)
        if isinstance(node, ast.Material):
            moved = f"read '{written_text(words)}' as '{written_text(rest)}, {written_text(first)}' (the clause after its material)"
            return node, [*notes, note, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, moved)]
    return None


def _first_comma(words: list[Tagged]) -> int | None:
    """Where the line's first comma (or mark read as one) stands, or None."""
    return next((i for i, w in enumerate(words) if any(c.tag == "COMMA" for c in w.candidates)), None)


def _comma_clause_after_implied(
    words: list[Tagged], note: Diagnostic, lexicon: Lexicon
) -> tuple[tuple[Shape, list[Candidate]], list[Tagged], Diagnostic] | None:
    """The implied material's line read with its feature after the comma as its clause ('white,
    a touch of sheen' = 'white paint with a touch of sheen'): the parse, the words and one note
    saying both readings; None when it does not parse so either."""
    from .hedges import with_after_comma

    clause = with_after_comma(words)
    if clause is None:
        return None
    try:
        parsed = parse_line_shape(clause[0], lexicon.caches.shapes)
    except ParseFailure:
        return None
    both = Diagnostic(note.span, note.severity, note.code, f"{note.message}; {clause[1].message}")
    return parsed, clause[0], both


def _whole_line(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Item, list[Diagnostic]] | None:
    """The line read whole another way, with its notes: a clause on its material ('rust on steel':
    cnlmc.on_clause), or a refinement of comma parts ('deeper, more of a burgundy'); a material
    with a part that takes words off ('white paint, no texture') by its parts first, so that the
    removal is not read as a describing word after the material."""
    removal = _removal_part(text)
    if removal and (parts := _by_parts(words, text, lexicon)) is not None:
        return parts
    placed = (
        on_material(words, text, lexicon)
        or likeness_dropped(words, text, lexicon)
        or relative_material(words, text, lexicon)
        or participle_after(words, text, lexicon)
        or (None if removal else describing_after(words, text, lexicon))  # 'no texture' is no describing word
        or clause_after(words, text, lexicon)
        or described_colour_after(words, text, lexicon)
        or context_dropped(words, text, lexicon, lambda before: _noun_first_item(before, text, lexicon))
    )
    if placed is not None:
        return placed[0], [placed[1]]
    return _by_parts(words, text, lexicon)


def _removal_part(text: str, but: int | None = None) -> bool:
    """Whether a part after the first (a comma apart, or after the line's 'but' at `but`) opens with
    a removal phrase ('oak, no grain', 'wood floor but not orange')."""
    from .removal import opens_removal

    points = part_cuts(text)
    if but is not None and opens_removal(text[but:].split(None, 1)[-1]):
        return True
    return any(opens_removal(text[a + 1 : b]) for a, b in list(zip(points, points[1:]))[1:])


def _but_word(words: list[Tagged]) -> Tagged | None:
    """The line's one 'but' (teaching.toml [politeness] remark_breaks), or None."""
    from .suggest import teaching

    breaks = teaching()["politeness"]["remark_breaks"]
    joiners = [w for w in words if w.text.lower() in breaks and w.implied_by is None]
    return joiners[0] if len(joiners) == 1 else None


def _but_at(words: list[Tagged]) -> int | None:
    """Where in the line (its column from 0) its one 'but' stands, or None."""
    but = _but_word(words)
    return None if but is None else but.span.start - words[0].span.line_start


def _said_again(diag: Diagnostic, notes: list[Diagnostic]) -> bool:
    """A note of a failed reading inside a note of the one taken ('no grain' read as no effect
    beside 'no grain' read as a removal): said again, and otherwise."""
    from .hedges import inside_a_note

    return diag.severity == Severity.NOTE and diag not in notes and inside_a_note(diag, notes)


def _by_parts(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Item, list[Diagnostic]] | None:
    """The line read by its comma-separated parts, each read as a line of its own where it stands
    (cnlmc.line_parts; the other parts blanked, so columns stay the line's): one refinement of its
    parts ('deeper, more of a burgundy'), else a material moved by the comparative parts after it
    ('walnut, a bit darker')."""
    if not any(w.text in PART_MARKS for w in words) or words[0].implied_by is not None:
        return None
    at = words[0].span
    number, offset = at.line, at.start - (at.col - 1)
    read = _part_reader(text, number, offset, lexicon)
    return by_parts(text, number, offset, read) or material_then_comparatives(text, number, offset, read, lexicon)


def _part_reader(text: str, number: int, offset: int, lexicon: Lexicon) -> Reader:
    """Reads the text from start to end as a line of its own, the rest blanked (columns stay the line's)."""

    def read(start: int, end: int, said: list[Diagnostic]) -> ast.Item | None:
        alone = " " * start + text[start:end] + " " * (len(text) - end)
        return parse_line(alone, number, offset, Tagger.of(lexicon), said)

    return read


def _but_then_comparatives(
    words: list[Tagged], text: str, lexicon: Lexicon
) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'navy but a bit brighter', 'concrete but lighter grey': a material (or colours), 'but', then
    comparatives: the material moved by them, as 'navy, a bit brighter' is, with a note."""
    joiner = _but_word(words)
    if joiner is None or words[0].implied_by is not None:
        return None
    start = joiner.span.start - words[0].span.line_start
    found = _comparatives_after_comma(words[0], text, start, len(joiner.text), lexicon)
    if found is None:
        return None
    said = f"{text[:start].strip()}, {text[start + len(joiner.text) :].strip()}"
    note = f"read '{text.strip()}' as '{said}' (the comparatives after '{joiner.text}')"
    return found[0], [*found[1], Diagnostic(joiner.span, Severity.NOTE, NOTE_CODE, note)]


def _noun_first_item(words: list[Tagged], text: str, lexicon: Lexicon) -> ast.Item | None:
    """The words read noun first ('Eiche hell'), without the note: for a part of a line whose own
    note says how the line was read."""
    found = _noun_first(words, text, lexicon)
    return found[0] if found is not None else None


def _noun_first(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Item, list[Diagnostic]] | None:
    """'steel brushed', 'plastic charcoal grey', 'oak a bit darker': describing words (or
    comparatives) after the noun with no comma, read as after a comma (cnlmc.noun_first), with a
    note; None when no place for the comma reads the line."""
    from .hedges import with_after_comma

    said = [w for w in words if w.text[:1].isalnum()]
    if not _NOUN_FIRST.get() or len(said) > NOUN_FIRST_WORDS:
        return None  # a part of a line read by it ('oak, a bit darker'), or a long line: no second try
    for listed, k in noun_first_readings(words):
        node = _parsed(listed, text, lexicon)
        if isinstance(node, ast.Material):
            return node, [noun_first_note(words, k)]
        clause = with_after_comma(listed)  # 'paint mostly matte, a little sheen'
        if clause is not None and isinstance(node := _parsed(clause[0], text, lexicon), ast.Material):
            return node, [noun_first_note(words, k), clause[1]]
        start = listed[k].span.start - words[0].span.line_start  # the implied comma, on the space before word k
        if text[start : start + 1] != " ":
            continue
        token = _NOUN_FIRST.set(False)
        try:
            found = _comparatives_after_comma(words[0], text, start, 1, lexicon)
        finally:
            _NOUN_FIRST.reset(token)
        if found is not None:
            return found[0], [*found[1], noun_first_note(words, k, comparatives=True)]
    return None


def _comparatives_after_comma(
    first: Tagged, text: str, start: int, width: int, lexicon: Lexicon
) -> tuple[ast.Material, list[Diagnostic]] | None:
    """The line with its `width` characters at `start` read as a comma (the rest blank, so every
    word keeps its place): a material, then comparatives (cnlmc.line_parts), or None."""
    number, offset = first.span.line, first.span.line_start
    listed = text[:start] + "," + " " * (width - 1) + text[start + width :]
    return material_then_comparatives(listed, number, offset, _part_reader(listed, number, offset, lexicon), lexicon)


def _without_article(words: list[Tagged]) -> list[Tagged] | None:
    """'a darker, moodier green', 'a slightly darker grey': the comparatives (and their degree
    words) without the article before them, or None."""
    main = [w for w in words if w.text[:1].isalpha()]
    if len(main) < 2 or not any(c.tag == "ARTICLE" for c in main[0].candidates):
        return None
    after = next((w for w in main[1:] if not all(c.tag == "ADV" for c in w.candidates)), None)
    if after is None or not any(c.tag == "REFINE" for c in after.candidates):
        return None
    return [w for w in words if w is not main[0]]


def _politely(words: list[Tagged], lexicon: Lexicon) -> tuple[list[Diagnostic], list[Tagged]] | None:
    """The line read without its politeness and with its rewrites (cnlmc.politeness), as a line
    with an unknown word is: its notes and words; None when nothing is read past or rewritten."""
    from .politeness import without_politeness
    from .teach import tagged_word

    notes, kept = without_politeness([], words, lambda word: tagged_word(word, lexicon))
    return (notes, kept) if notes else None


def _said_with_errors(words: list[Tagged], diags: list[Diagnostic]) -> bool:
    """Whether the tagger already found an error on the line of these words (a word it left out)."""
    line = words[0].span.line if words else None
    return any(d.is_error and d.span is not None and d.span.line == line for d in diags)


def _rereadings(
    hedged: list[Tagged], notes: list[Diagnostic], clauses: Sequence[tuple[list[Tagged], Diagnostic] | None]
) -> Iterator[tuple[list[Tagged], list[Diagnostic]]]:
    """The line read with its quantity phrases as degrees (when it had any), then as a clause with
    an implied 'with' ('a subtle sheen', 'pale ash, faint grain') or as the comparatives of a finish
    ('a glossier finish'): each with its notes (cnlmc.hedges)."""
    if notes:
        yield hedged, notes
    for clause in clauses:
        if clause is not None:
            yield clause[0], [*notes, clause[1]]


def _simile_reading(words: list[Tagged], text: str, lexicon: Lexicon, diags: list[Diagnostic]) -> ast.Item | None:
    """The line read with its simile ('concrete smooth as glass' = very smooth concrete: cnlmc.
    degree_after.simile), the errors inside the simile replaced by a note; None when it has none or
    does not read so."""
    likened = simile(words)
    if likened is None:
        return None
    node = _parsed(likened[0], text, lexicon) or _noun_first_item(likened[0], text, lexicon)
    implied = None
    if node is None and all(w.implied_by is not None or of_tag(w, "ADJ") or of_tag(w, "ADV") for w in likened[0]):
        from .implied import implied_noun
        from .suggest import everyday_noun

        implied = everyday_noun()  # 'as shiny as a mirror': the describing words alone, on paint
        node = _parsed([*likened[0], implied_noun(implied, likened[0][-1])], text, lexicon)
    if node is None:
        return None
    _, left, word, degree = likened
    diags[:] = [d for d in diags if not (d.span and left.start <= d.span.start < left.end)]
    said = text[left.start - words[0].span.line_start : left.end - words[0].span.line_start]
    said_words = said.lower().split()
    if len(said_words) < 2 or said_words[1] != word.lower():  # 'smooth as glass' (not 'as smooth as glass')
        said = f"{word} {said}"
    note = f"read '{said}' as '{degree} {word}': a likeness says it strongly"
    if implied is not None:
        note += f", on {implied} (no material named)"
    diags.append(Diagnostic(left, Severity.NOTE, NOTE_CODE, note))
    return node


def _compared_after_noun(words: list[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Item, Diagnostic, int] | None:
    """'copper darker than a penny', 'brushed nickel less shiny than a faucet': a material, a
    comparative (with its degree words; 'more'/'less' with the word it compares) and 'than' + what
    it is compared with: the material one step that way, as the inline comparative ('darker
    copper'), what it is compared with read past; the reading, its note and where the comparative
    starts (the notes from there on are replaced by this one). None for any other line."""
    than_words = Tagger.of(lexicon).formation().rules.comparison
    line_start = words[0].span.line_start if words else 0
    at = next((i for i, w in enumerate(words) if _next_word(text, w.span.end - line_start) in than_words), None)
    if at is None or at + 1 >= len(words):  # the tagger drops 'than' (and 'a'): 'darker', 'penny'
        return None
    start = at if of_tag(words[at], "REFINE") else at - 1  # 'less shiny than': 'less' compares 'shiny'
    if start < 1 or not of_tag(words[start], "REFINE"):
        return None
    while start > 1 and of_tag(words[start - 1], "ADV"):  # 'a bit darker than'
        start -= 1
    node = _parsed([*words[start : at + 1], *words[:start]], text, lexicon)
    if not isinstance(node, ast.Material):
        return None
    thing = words[at + 1].span.to(words[-1].span)
    comparative, material = written_text(words[start : at + 1]), written_text(words[:start])
    other = text[words[at].span.end - line_start :].split(None, 1)[1].strip()  # after 'than': 'a penny'
    note = (
        f"read '{text.strip()}' as '{comparative} {material}': one step {comparative}, not measured against '{other}'"
    )
    return node, Diagnostic(words[0].span.to(thing), Severity.NOTE, NOTE_CODE, note), words[start].span.start


def _next_word(text: str, at: int) -> str:
    """The lower-case word of the line's text that follows column `at` ('' at its end)."""
    rest = text[at:].split(None, 1)
    return rest[0].lower() if rest else ""


def _slashes_listing(words: list[Tagged]) -> list[Tagged] | None:
    """'matte/black/rubber': a slash between words of different kinds lists them, as a comma does
    (between words of one kind it offers alternatives: 'copper/brass'); None when no slash does."""
    from .joins import implied_comma

    out = list(words)
    for i in range(1, len(words) - 1):
        if words[i].text != "/" or _tags(words[i - 1]) & _tags(words[i + 1]):
            continue
        out[i] = implied_comma(words[i + 1])
    return out if out != words else None


def _tags(word: Tagged) -> set[str]:
    return {c.tag for c in word.candidates}


def _parsed(words: list[Tagged], text: str, lexicon: Lexicon) -> ast.Item | None:
    return parsed_item(words, text, lexicon.caches.shapes)


def _failure_of(words: list[Tagged], lexicon: Lexicon) -> ParseFailure | None:
    try:
        parse_line_shape(words, lexicon.caches.shapes)
    except ParseFailure as failure:
        return failure
    return None


def _syntax_error(failure: ParseFailure, words: list[Tagged], lexicon: Lexicon) -> Diagnostic:
    """E002 for a word in the wrong place; E003 for a phrase that never names its material."""
    has_noun = any(c.tag == "NOUN" for t in words for c in t.candidates)
    is_refinement = any(c.tag == "REFINE" for c in words[0].candidates)
    at = failure.tagged or words[-1]
    span = at.span if failure.tagged else words[0].span.to(words[-1].span)
    from .mistakes import known_mistake

    mistake = known_mistake(lexicon, failure)
    if mistake is not None:
        return error(span if failure.tagged else at.span, "E002", mistake.message.format(word=at.text), (mistake.hint,))
    if failure.tagged is None and not has_noun and not is_refinement:
        return error(
            span,
            "E003",
            "this phrase names no material: end it with a noun",
            ("for example 'brushed aluminum' or 'white varnished oak'",),
        )
    if failure.tagged is None:
        in_coat = any(c.tag == "WITH" for t in words for c in t.candidates)
        return _early_end(at, failure.expected, in_coat)
    return error(
        at.span, "E002", f"'{at.text}' cannot stand here", (f"expected {describe_expected(failure.expected)}",)
    )


def _early_end(last: Tagged, expected: set[str], in_coat: bool) -> Diagnostic:
    """The line stopped before the grammar was done: say what is missing."""
    if "COAT" in expected and (in_coat or "NOUN" not in expected):
        return error(
            last.span,
            "E002",
            f"the coat clause ends at '{last.text}' without naming the coat",
            ("end it with a coat word, e.g. 'oak with a glossy varnish'",),
        )
    if "NOUN" in expected:
        return error(
            last.span,
            "E002",
            f"the phrase ends at '{last.text}' without naming the material",
            ("end it with a material noun, e.g. 'brushed aluminum'",),
        )
    return error(
        last.span, "E002", f"the phrase cannot end after '{last.text}'", (f"expected {describe_expected(expected)}",)
    )
