"""Hedged and clipped speech (issue #14): 'a touch of sheen', 'a bit of rust', 'loads of patina',
'a subtle sheen' said without its 'with'.

A quantity said before a feature or a describing word is that word's degree (stdlib/data/
teaching.toml [hedges] quantities: 'a touch of' = 'slightly', 'just a hint of' = 'barely', 'a lot
of' = 'many'), read with a note. Before a colour alone the phrase is kept ('a hint of blue' is the
hint feature: a slight tint). A clause said without 'with' ('a subtle sheen', 'some patina',
'fine scratches') is read with an implied 'with': under a material it adds the clause to it; as a
first line its material is the one the feature's example names ('some patina' = copper with some
patina), or paint for a feature of any surface (teaching.toml [hedges] any_surface).

Runs only for a line that failed to parse (cnlmc.document): the hot path never reaches it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from . import ast
from .diagnostics import Diagnostic, Severity
from .joins import DESCRIBING
from .lexicon import Lexicon
from .spans import Span
from .suggest import everyday_noun, teaching
from .tagged import NOTE_CODE, Candidate, Tagged, written_span

__all__ = [
    "colour_between",
    "colour_of",
    "inside_a_note",
    "finish_dropped",
    "first_line_clause",
    "first_line_finish",
    "read_past",
    "reread",
    "with_implied",
]

DEGREE_TARGETS = frozenset({"FEATURE", "COAT", "ADJ", "PROP", "REFINE", "SHADE"})
NOT_A_CLAUSE = frozenset({"WITH", "NAME", "OBJECT", "REFINE"})  # a line with one of these is not a bare clause


def reread(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], list[Diagnostic]]:
    """The words with each quantity phrase before a feature or describing word read as its degree
    word, and a note for each; the words as they were (and no note) when there is none."""
    table: dict[str, str] = teaching()["hedges"]["quantities"]
    out: list[Tagged] = []
    notes: list[Diagnostic] = []
    i = 0
    while i < len(words):
        n = _quantity_at(words, i, table)
        if n and i and _is_article(words[i - 1]):
            n = 0  # 'a hint of green' is the feature 'hint' (with its article), not 'hint of' said bare
        if n and _degree_target(words, i + n, _names_a_feature(words[i : i + n])):
            said = _joined(words[i : i + n])
            word = _degree_word(table[said], words[i : i + n], lexicon)
            if word is not None:
                out.append(word)
                notes.append(_read_as(words[i : i + n], word.text))
                i += n
                continue
        out.append(words[i])
        i += 1
    said_of = colour_of(out, lexicon)
    if said_of is not None:
        out, note = said_of
        notes.append(note)
    kind = the_kind(out)
    if kind is not None:
        out, note = kind
        notes.append(note)
    return out, notes


def the_kind(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """'cherry wood, the reddish kind, satin varnish': 'the' + describing words + a kind word
    (teaching.toml [hedges] `kinds`), set off as a list item, is those describing words, with a
    note; None when the line has no such part."""
    table = teaching()["hedges"]
    kinds, articles = table["kinds"], table["kind_articles"]
    texts = [w.text.lower() for w in words]
    for at, text in enumerate(texts):
        if text not in articles:
            continue
        end = next((k for k in range(at + 1, len(words)) if texts[k] in kinds), None)
        if end is None or end == at + 1 or end - at > 4:
            continue
        said = words[at + 1 : end]
        if not all(any(c.tag in DESCRIBING for c in w.candidates) for w in said):
            continue
        if end + 1 < len(words) and words[end + 1].text[:1].isalnum():
            continue  # 'the reddish kind of oak': the kind names the material after it
        return [*words[:at], *said, *words[end + 1 :]], _read_as(words[at : end + 1], _joined(said))
    return None


def colour_of(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """'the colour of wet sand', 'a shade of moss': the words after 'of' read as 'X colour' (the
    colour of X: cnlmc.joins, the named colour nearest its own), in the place of the phrase, with a
    note; None when the line has no such phrase or X is not a colour or a thing with one."""
    table = teaching()["hedges"]
    texts = [w.text.lower() for w in words]
    at = next((k for k in range(len(texts) - 2) if texts[k] in table["colour_of"] and texts[k + 1] == "of"), None)
    if at is None:
        return None
    start = at - 1 if at and texts[at - 1] in table["colour_of_lead"] else at
    end = next((k for k in range(at + 2, len(words)) if not words[k].text[:1].isalnum()), len(words))
    tagged = None
    if end - at > 3 and any(c.tag == "NOUN" for c in words[end - 1].candidates):
        tagged = _coloured(words[at + 2 : end - 1], texts[at], lexicon)  # 'the colour of sand paint':
        end -= tagged is not None  # the paint is what has the colour
    tagged = tagged or _coloured(words[at + 2 : end], texts[at], lexicon)
    if tagged is None:
        return _shade_of_a_material(words, at, end)
    said = " ".join(w.text for w in words[at + 2 : end])
    run = words[start:end]
    whole = run[0].span.to(run[-1].span)
    read = [
        Tagged(t.text, _implied(t.text, t.candidates[0], run[-1], step).span, t.candidates, implied_by=whole)
        for step, t in enumerate(tagged)
    ]
    return [*words[:start], *read, *words[end:]], _read_as(run, f"{said} {texts[at]}")


def _shade_of_a_material(words: Sequence[Tagged], at: int, end: int) -> tuple[list[Tagged], Diagnostic] | None:
    """'a slightly darker shade of oak': after a comparative, 'a shade of' before a material noun is
    read past: the comparative of the material ('slightly darker oak'), with a note; None otherwise."""
    if at == 0 or not any(c.tag == "REFINE" for c in words[at - 1].candidates):
        return None
    if end - at < 3 or not any(c.tag == "NOUN" for c in words[end - 1].candidates):
        return None
    run = words[at : at + 2]
    said = " ".join(w.text for w in run)
    note = Diagnostic(
        run[0].span.to(run[-1].span),
        Severity.NOTE,
        NOTE_CODE,
        f"read past '{said}': the comparative is of the material",
    )
    return [*words[:at], *words[at + 2 :]], note


def _coloured(said: Sequence[Tagged], head: str, lexicon: Lexicon) -> list[Tagged] | None:
    """The words 'X colour' as the tagger reads them (the colour of the thing X), or X alone when
    X is a colour ('butter'); None when neither ends in a colour."""
    from .tagger import Tagger

    text = " ".join(w.text for w in said)
    for line in (f"{text} {head}", text):
        tagged, problems = Tagger.of(lexicon).tag_line(line, 1, 0)
        if tagged and not any(d.is_error for d in problems) and any(c.tag == "COLOR" for c in tagged[-1].candidates):
            return tagged
    return None


def colour_between(
    diags: list[Diagnostic], words: Sequence[Tagged], lexicon: Lexicon
) -> tuple[list[Diagnostic], list[Tagged]]:
    """'somewhere between beige and grey': the colour 'beige-grey' in the words' place, the unknown
    words of the phrase read past and a note; all as they were when the compound is not a colour.
    Runs on the unknown-word path ('between' is not a word of the language)."""
    kept, notes = _between(words, lexicon)
    if not notes:
        return diags, list(words)
    return [d for d in diags if not read_past(d, notes)] + notes, kept


def _between(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], list[Diagnostic]]:
    """'somewhere between beige and grey' -> the colour 'beige-grey' (a note says so); the words as
    they were when the compound is not a colour."""
    table = teaching()["hedges"]
    texts = [w.text.lower() for w in words]
    if table["between"] not in texts:
        return list(words), []
    at = texts.index(table["between"])
    if at + 3 >= len(words) or texts[at + 2] != "and":
        return list(words), []
    first, second = words[at + 1], words[at + 3]
    start = at - 1 if at and _joined(words[:at]).endswith(tuple(table["between_lead"])) else at
    while start > 0 and _joined(words[start - 1 : at]) in table["between_lead"]:
        start -= 1
    if start < at and _joined(words[start:at]) not in table["between_lead"]:
        start = at
    from .tagger import Tagger

    tagged, unknown = Tagger.of(lexicon).tag_line(f"{first.text.lower()}-{second.text.lower()}", 1, 0)
    compound = tagged[0] if len(tagged) == 1 and not unknown else None
    run = words[start : at + 4]
    if (metals := _metal_pair(first, second, lexicon)) is not None:
        return [*words[:start], *metals, *words[at + 4 :]], [_read_as(run, f"{first.text}-ish {second.text}")]
    if compound is None and (pair := _colour_pair(run, first, second)) is not None:
        return [*words[:start], *pair, *words[at + 4 :]], [_read_as(run, f"{first.text}-ish {second.text}")]
    if compound is None or not any(c.tag == "COLOR" for c in compound.candidates):
        return _finish_between(words, run, first, second, lexicon)
    word = _implied(compound.text, next(c for c in compound.candidates if c.tag == "COLOR"), run[-1], 1)
    word = Tagged(word.text, word.span, word.candidates, implied_by=run[0].span.to(run[-1].span))
    return [*words[:start], word, *words[at + 4 :]], [_read_as(run, compound.text)]


def _metal_pair(first: Tagged, second: Tagged, lexicon: Lexicon) -> list[Tagged] | None:
    """'somewhere between brass and copper', two metals: the second metal, the first's '-ish' colour
    word before it (passes/metal_tone.py mixes their optics half way); None unless both are metals."""
    if not all(_names_metal(w, lexicon) for w in (first, second)):
        return None
    from .tagger import Tagger

    tagged, diags = Tagger.of(lexicon).tag_line(f"{first.text.lower()}-ish", 1, 0)
    fits = len(tagged) == 1 and not any(d.is_error for d in diags)
    colours = tuple(c for c in tagged[0].candidates if c.tag == "COLOR") if fits else ()
    if not colours:
        return None
    nouns = tuple(c for c in second.candidates if c.tag == "NOUN")
    return [Tagged(f"{first.text}-ish", first.span, colours), Tagged(second.text, second.span, nouns)]


def _names_metal(word: Tagged, lexicon: Lexicon) -> bool:
    for candidate in word.candidates:
        entry = lexicon.entry("nouns", candidate.key) if candidate.tag == "NOUN" else None
        if entry is not None and entry.get("model") == "conductor":
            return True
    return False


def _colour_pair(run: Sequence[Tagged], first: Tagged, second: Tagged) -> list[Tagged] | None:
    """'between navy and charcoal', two colours with no compound of their own: the first hedged
    before the second ('navy-ish charcoal': colour_compounds.toml [hedged], half way between them),
    the colours read as colours only ('charcoal' is also a material); None when either is no colour."""
    colours = [tuple(c for c in w.candidates if c.tag == "COLOR") for w in (first, second)]
    if not all(colours) or first.unknown or second.unknown:
        return None
    from .passes.colour_compounds import rules

    adverb = str(rules()["hedged"]["adverb"])
    whole = run[0].span.to(run[-1].span)
    s = first.span
    return [
        _implied(adverb, Candidate("ADV", adverb, "adverbs"), run[0], 0, whole),
        Tagged(first.text, first.span, colours[0]),
        # right after the first colour, as a hedged pair stands (its span takes in the "and")
        Tagged(second.text, Span(s.end + 1, second.span.end, s.line, s.col + s.end + 1 - s.start), colours[1]),
    ]


def _finish_between(
    words: Sequence[Tagged], run: Sequence[Tagged], first: Tagged, second: Tagged, lexicon: Lexicon
) -> tuple[list[Tagged], list[Diagnostic]]:
    """'somewhere between satin and gloss': two finishes that each set the roughness are the first,
    one step toward the second ('glossier satin'; teaching.toml [hedges] between_steps names the
    comparative each way), with a note; the words as they were for any other pair."""
    said, other = _roughness_set(first, lexicon), _roughness_set(second, lexicon)
    if said is None or other is None or said[1] == other[1]:
        return list(words), []
    (key, rough), toward = said, other[1]
    steps = teaching()["hedges"]["between_steps"]
    step = steps["smoother"] if toward < rough else steps["rougher"]
    comparative = _implied(step, Candidate("REFINE", step, "refinements"), run[-1], 1, run[0].span.to(run[-1].span))
    finish = _implied(first.text, Candidate("ADJ", key, "adjectives"), run[-1], 2, run[0].span.to(run[-1].span))
    at = list(words).index(run[0])
    return [*words[:at], comparative, finish, *words[at + len(run) :]], [_read_as(run, f"{step} {first.text}")]


def _roughness_set(word: Tagged, lexicon: Lexicon) -> tuple[str, float] | None:
    """The finish adjective a word names and the roughness it sets ('satin': 0.35), or None."""
    from .passes.finish_ladder import finish_roughness

    for candidate in word.candidates:
        value = finish_roughness(lexicon.entry("adjectives", candidate.key)) if candidate.tag == "ADJ" else None
        if value is not None:
            return candidate.key, value
    return None


def with_implied(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """A clause said without 'with' ('a subtle sheen', 'slightly sheen' after reread): the words
    after an implied 'with', and the note; None for any other line."""
    main = [w for w in words if w.text[:1].isalpha()]
    if not main or not any(c.tag == "FEATURE" for w in main for c in w.candidates):
        return None  # a coat alone has its own reading ('varnish' = wood with varnish: cnlmc.implied)
    if any(c.tag in NOT_A_CLAUSE for w in main for c in w.candidates):
        return None
    if any(all(c.tag == "NOUN" for c in w.candidates) or any(c.tag == "OBJECT" for c in w.candidates) for w in main):
        return None  # a material is named (or a thing that has one): its error is a mistake, not a clause
    clause = next(w for w in main if any(c.tag == "FEATURE" for c in w.candidates))
    if any(any(c.tag == "COMMA" for c in w.candidates) for w in words[: words.index(clause)]):
        return None  # 'white, a touch of sheen': the white thing (a material implied) with its clause
    written = " ".join(w.text for w in main)
    note = Diagnostic(written_span(main), Severity.NOTE, NOTE_CODE, f"read '{written}' as 'with {written}'")
    return [_implied("with", Candidate("WITH", "with", "keywords"), clause, 1), *words], note


def with_after_comma(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """'pale ash, faint grain', 'white paint, a touch of sheen' ('slightly sheen' after reread): a
    feature after the material's last comma is its clause, the comma read as 'with'; the words and
    the note; None for any other line."""
    commas = [i for i, w in enumerate(words) if any(c.tag == "COMMA" for c in w.candidates)]
    if not commas or any(c.tag == "WITH" for w in words for c in w.candidates):
        return None
    words = _feature_part_last(words, commas)  # 'oak, visible grain, matt' = 'oak, matt, visible grain'
    commas = [i for i, w in enumerate(words) if any(c.tag == "COMMA" for c in w.candidates)]
    at = commas[-1]
    rest = [w for w in words[at + 1 :] if w.text[:1].isalpha()]
    if not rest or not any(c.tag == "FEATURE" for w in rest for c in w.candidates):
        return None
    if any(all(c.tag == "NOUN" for c in w.candidates) for w in rest):
        return None  # a second material after the comma: its own error
    comma = words[at]
    said = " ".join(w.text for w in rest)
    note = Diagnostic(written_span(rest), Severity.NOTE, NOTE_CODE, f"read ', {said}' as 'with {said}'")
    with_ = Tagged("with", comma.span, (Candidate("WITH", "with", "keywords"),), implied_by=comma.span)
    return [*words[:at], with_, *words[at + 1 :]], note


def _feature_part_last(words: Sequence[Tagged], commas: list[int]) -> list[Tagged]:
    """The words with a middle part that names a feature and no material ('visible grain' of 'oak,
    visible grain, matt') moved after the last part, where a clause stands; as they were otherwise."""
    cuts = [*commas, len(words)]
    parts = [list(words[a:b]) for a, b in zip(cuts, cuts[1:])]  # each with its leading comma
    middle = [p for p in parts[:-1] if _names_feature_only(p[1:])]
    if len(middle) != 1 or _names_feature_only(parts[-1][1:]):
        return list(words)
    moved = [w for p in parts if p is not middle[0] for w in p]
    return [*words[: commas[0]], *moved, *middle[0]]


def _names_feature_only(part: Sequence[Tagged]) -> bool:
    said = [w for w in part if w.text[:1].isalpha()]
    return (
        bool(said)
        and any(c.tag == "FEATURE" for w in said for c in w.candidates)
        and not any(all(c.tag == "NOUN" for c in w.candidates) for w in said)
    )


def finish_dropped(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """'a glossier finish', 'a smoother, glossier finish': comparatives said of the finish are the
    comparatives (a change line); the words without the article and the finish word, and the note."""
    main = [w for w in words if w.text[:1].isalpha()]
    if len(main) < 2 or not any(c.tag == "REFINE" for w in main for c in w.candidates):
        return None
    last = main[-1]
    finish = next((c for c in last.candidates if c.tag == "FEATURE"), None)
    entry = lexicon.entry("features", finish.key) if finish is not None else None
    if entry is None or not entry.get("finish"):
        return None
    lead = _leading_with(words)  # 'with a glossier finish', 'give it a glossier finish' ('give it' = 'with')
    kept = [w for w in words[lead:] if w is not last and not (w is words[lead] and _is_article(w))]
    said = " ".join(w.text for w in main)
    read = " ".join(w.text for w in kept if w.text[:1].isalpha())
    return kept, Diagnostic(main[0].span.to(last.span), Severity.NOTE, NOTE_CODE, f"read '{said}' as '{read}'")


def _leading_with(words: Sequence[Tagged]) -> int:
    """1 when the words open with 'with' (the clause's own word, said of the finish), else 0."""
    return 1 if len(words) > 1 and any(c.tag == "WITH" for c in words[0].candidates) else 0


def postfix_finish(words: Sequence[Tagged], lexicon: Lexicon) -> tuple[list[Tagged], Diagnostic] | None:
    """'oak, matte finish', 'Oak - Natural Finish': describing words after the noun and a comma,
    ending in a finish word, are those describing words ('oak, matte'); the note says so."""
    main = [w for w in words if w.text[:1].isalpha()]
    if len(main) < 3 or not any(c.tag == "COMMA" for w in words for c in w.candidates):
        return None
    if any(c.tag == "REFINE" for w in main for c in w.candidates):
        return None  # 'a smoother, shinier finish': comparatives of the finish (finish_dropped)
    last = main[-1]
    finish = next((c for c in last.candidates if c.tag == "FEATURE"), None)
    entry = lexicon.entry("features", finish.key) if finish is not None else None
    if entry is None or not entry.get("finish") or any(c.tag == "WITH" for w in words for c in w.candidates):
        return None
    kept = [w for w in words if w is not last]
    said = " ".join(w.text for w in main)
    read = " ".join(w.text for w in kept if w.text[:1].isalpha())
    return kept, Diagnostic(written_span(main), Severity.NOTE, NOTE_CODE, f"read '{said}' as '{read}'")


def _is_article(word: Tagged) -> bool:
    return any(c.tag == "ARTICLE" for c in word.candidates)


def first_line_clause(item: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """A clause line with no material above ('with a subtle sheen', 'some patina'): the material
    the feature's example names, or paint for a feature of any surface, with the clause; a note."""
    if item.items or item.groups or not (item.features or item.coat):
        return None
    from .parser import parsed_material
    from .tagger import Tagger

    start = item.span.start - (item.span.col - 1)  # the line's offset: its text is the whole line
    words, diags = Tagger.of(lexicon).tag_line(item.text, item.span.line, start)
    words, notes = reread([w for w in words if w.candidates], lexicon)
    if not words or any(not read_past(d, notes) for d in diags):
        return None
    if not any(c.tag == "WITH" for w in words for c in w.candidates):
        implied = with_implied(words)
        if implied is None:
            return None
        words = implied[0]
    head = item.coat.coat if item.coat is not None else item.features[0].word
    noun = _noun_for(head, lexicon)
    clause = next(w for w in words if w.span.start == head.span.start)
    with_noun = [_implied(noun, Candidate("NOUN", noun, "nouns"), clause, 2), *words]
    material = parsed_material(with_noun, item.text, lexicon.caches.shapes)
    if material is None:
        return None
    said = [w for w in words if w.text[:1].isalpha() and w.implied_by is None]
    written = " ".join(w.text for w in said)
    joined = written if any(c.tag == "WITH" for w in said for c in w.candidates) else f"with {written}"
    message = f"no material named: read '{written}' as '{noun} {joined}'"
    hint = f"name the material first to choose another, e.g. 'oak {written}'"
    return material, Diagnostic(written_span(said), Severity.NOTE, NOTE_CODE, message, (hint,))


def read_past(diag: Diagnostic, notes: Sequence[Diagnostic], misplaced: bool = False) -> bool:
    """Whether `diag` is an unknown word inside a phrase a note read as something else ('loads' of
    'loads of'); with `misplaced`, a misplaced one too ('no' of 'oak, no grain')."""
    return diag.code in (("E001", "E002") if misplaced else ("E001",)) and inside_a_note(diag, notes)


def inside_a_note(diag: Diagnostic, notes: Sequence[Diagnostic]) -> bool:
    """Whether `diag`'s span lies inside one of the notes' spans."""
    at = diag.span
    return at is not None and any(
        n.span is not None and n.span.start <= at.start and at.end <= n.span.end for n in notes
    )


def first_line_finish(item: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'a glossier finish' with no material above: the comparatives on paint, one step from it (as
    'glossier paint'), with a note; None for any other line."""
    if not item.items or item.features or item.coat is not None:
        return None
    from .parser import parsed_material
    from .tagger import Tagger

    start = item.span.start - (item.span.col - 1)
    words, diags = Tagger.of(lexicon).tag_line(item.text, item.span.line, start)
    dropped = finish_dropped(words, lexicon) if not diags else None
    if dropped is None:
        return None
    kept = [w for w in dropped[0] if w.text[:1].isalnum()]
    paint = everyday_noun()
    with_noun = [*kept, _implied(paint, Candidate("NOUN", paint, "nouns"), kept[-1], 1)]
    material = parsed_material(with_noun, item.text, lexicon.caches.shapes)
    if material is None:
        return None
    said = " ".join(w.text for w in words if w.text[:1].isalpha())
    read = " ".join(w.text for w in kept)
    message = f"no material named: read '{said}' as '{read} {paint}'"
    hint = "name the material to choose another, or write the material first and this line below it"
    typed = [w for w in words if w.text[:1].isalpha()]
    return material, Diagnostic(written_span(typed), Severity.NOTE, NOTE_CODE, message, (hint,))


def first_line_described(item: ast.Refinement, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'glossier satin' (as 'somewhere between satin and gloss' reads) with no material above: the
    describing word on paint, then the comparative (as 'glossier satin paint'), with a note; None
    for any other line, or a describing word of some materials only."""
    if len(item.items) != 1 or item.coat is not None or item.features or item.groups:
        return None
    said = item.items[0]
    target = said.target
    if not isinstance(target, ast.Word) or target.category != "adjectives":
        return None
    entry = lexicon.entry("adjectives", target.key)
    if entry is None or entry.get("applies_to"):
        return None
    paint = everyday_noun()
    noun = ast.Word(paint, paint, "nouns", target.span)
    group = ast.Group("adjective", (), (), (target,), target.span)
    step = ast.RefineItem(said.word, None, said.span, said.adverbs)
    material = ast.Material(None, (group,), (noun,), None, item.span, item.text, (step,))
    message = f"no material named: read '{said.word.text} {target.text}' as '{said.word.text} {target.text} {paint}'"
    return material, Diagnostic(item.span, Severity.NOTE, NOTE_CODE, message)


def _noun_for(head: ast.Word, lexicon: Lexicon) -> str:
    """The noun of the feature's (or coat's) example, or paint for a feature of any surface."""
    paint = everyday_noun()
    if head.category == "features" and head.key in teaching()["hedges"]["any_surface"]:
        return paint
    entry = lexicon.entry(head.category, head.key)
    example = str(entry.get("example") or "") if entry is not None else ""
    before = example.split(" with ")[0].split()
    nouns = [e for e in lexicon.lookup((before[-1].lower(),)) if e.category == "nouns"] if before else []
    return nouns[0].key if nouns else paint


def _quantity_at(words: Sequence[Tagged], i: int, table: dict[str, str]) -> int:
    """How many words from i make a listed quantity phrase (the longest), or 0."""
    found = 0
    for n in range(1, min(5, len(words) - i) + 1):
        if _joined(words[i : i + n]) in table:
            found = n
    return found


def _degree_target(words: Sequence[Tagged], j: int, feature_said: bool) -> bool:
    """Whether what follows a quantity phrase takes a degree: the first word after any further
    degree words and colours is a feature, coat, describing word or property; or a colour ends
    the line and the phrase has no feature of its own ('a bit of blue' = slightly blue, but 'a
    hint of blue' keeps its hint feature: a slight tint)."""
    for word in words[j:]:
        tags = {c.tag for c in word.candidates}
        if tags & DEGREE_TARGETS:
            return True
        if not tags & {"ADV", "COLOR", "ARTICLE"}:
            return False
    return not feature_said and j < len(words)


def _names_a_feature(run: Sequence[Tagged]) -> bool:
    """Whether the phrase is an article, a feature word and 'of' ('a hint of', 'a touch of')."""
    return len(run) == 3 and any(c.tag == "FEATURE" for c in run[1].candidates)


def _degree_word(key: str, run: Sequence[Tagged], lexicon: Lexicon) -> Tagged | None:
    """The degree word `key` (an adverb) in the phrase's place: inside its last word's span (the
    parser keys words by start, and no written word starts there), implied by the phrase."""
    entry = lexicon.entry("adverbs", key)
    if entry is None:
        return None
    return _implied(key, Candidate("ADV", key, "adverbs"), run[-1], 1, whole=run[0].span.to(run[-1].span))


def but_after_noun(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """'grey paint but not too shiny', 'glass but not frosted': 'but' right after the material and
    before its describing words sets them off as a comma would ('grey paint, but not too shiny');
    the words with that comma and the note, None for any other line."""
    from .joins import implied_comma

    breaks = teaching()["politeness"]["describing_breaks"]
    for k in range(1, len(words) - 1):
        word, before = words[k], words[k - 1]
        after = next((w for w in words[k + 1 :] if not all(c.tag == "ADV" for c in w.candidates)), words[k + 1])
        if word.text.lower() not in breaks or not any(c.tag == "AND" for c in word.candidates):
            continue
        if not any(c.tag == "NOUN" for c in before.candidates) or before.unknown or not _describes(after):
            return None
        comma = implied_comma(word)
        said = " ".join(w.text for w in words)
        note = f"read '{said}' as '{' '.join(w.text for w in words[:k])}, {' '.join(w.text for w in words[k:])}'"
        return [*words[:k], comma, *words[k:]], Diagnostic(
            before.span.to(words[-1].span), Severity.NOTE, NOTE_CODE, note
        )
    return None


def named_then_compared(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """'grain more visible', 'stain darker', 'veins stronger', 'the brushing less obvious': a feature
    or property named, then its comparative (and perhaps a word of how visible, read past): the
    comparative before it ('more grain', 'darker stain'), with a note; None for any other line."""
    said = [w for w in words if w.text[:1].isalpha()]
    if said and any(c.tag == "ARTICLE" for c in said[0].candidates):
        said = said[1:]
    if len(said) not in (2, 3):
        return None
    named, compared, rest = said[0], said[1], said[2:]
    if named.unknown or not any(c.tag in ("PROP", "FEATURE") for c in named.candidates):
        return None
    if not any(c.tag == "REFINE" for c in compared.candidates):
        return None
    if rest and not all(c.tag == "ADV" for c in rest[0].candidates):
        return None
    read = f"{compared.text} {named.text}"
    note = f"read '{' '.join(w.text for w in said)}' as '{read}'"
    return [compared, named], Diagnostic(named.span.to(said[-1].span), Severity.NOTE, NOTE_CODE, note)


def comparison_shared(words: Sequence[Tagged]) -> tuple[list[Tagged], Diagnostic] | None:
    """'more worn and weathered', 'less shiny and less yellow': a comparison word ('more', 'less')
    before describing words joined by 'and' compares each of them ('more worn, more weathered'); the
    words so read and the note, None for any other line."""
    from .joins import implied_comma

    first = words[0] if words else None
    refine = next((c for c in first.candidates if c.tag == "REFINE"), None) if first is not None else None
    if first is None or refine is None or first.text.lower() not in teaching()["politeness"]["bare_comparisons"]:
        return None
    out: list[Tagged] = [first]
    for k, word in enumerate(words[1:], start=1):
        after = words[k + 1] if k + 1 < len(words) else None
        if any(c.tag == "AND" for c in word.candidates) and after is not None and _describes(after):
            out += [replace(implied_comma(word), span=word.span), _implied(first.text, refine, word, 1)]
        else:
            out.append(word)
    if len(out) == len(words):
        return None
    said = " ".join(w.text for w in words)
    read = " ".join(w.text for w in out).replace(" ,", ",")
    return out, Diagnostic(first.span.to(words[-1].span), Severity.NOTE, NOTE_CODE, f"read '{said}' as '{read}'")


def _describes(word: Tagged) -> bool:
    return any(c.tag in ("ADJ", "COLOR", "SHADE", "PROP") for c in word.candidates) and not any(
        c.tag == "REFINE" for c in word.candidates
    )


def _implied(text: str, candidate: Candidate, inside: Tagged, step: int, whole: Span | None = None) -> Tagged:
    """A word no one typed, placed `step` characters into `inside`'s span (each implied word of a
    line at its own step, so each keeps its own start), implied by `whole` (default: that word)."""
    s = inside.span
    at = min(s.start + step, s.end)
    return Tagged(text, Span(at, s.end, s.line, s.col + at - s.start), (candidate,), implied_by=whole or s)


def _joined(words: Sequence[Tagged]) -> str:
    return " ".join(w.text.lower() for w in words)


def _read_as(run: Sequence[Tagged], word: str) -> Diagnostic:
    said = " ".join(w.text for w in run)
    return Diagnostic(run[0].span.to(run[-1].span), Severity.NOTE, NOTE_CODE, f"read '{said}' as '{word}'")
