"""Politeness and filler at the edges of a phrase (issue #14): "please", "thanks", "I want",
"make it", "something like" are read past, with a note, as decoration.

A designer who types "brushed steel, please" or "I want matte black plastic" means the material;
rejecting the line over a courtesy teaches nothing useful, and the note still tells them the words
are not part of the language. Only whole phrases listed in stdlib/data/teaching.toml [politeness]
are dropped, and only at the start (`leading`) or the end (`trailing`) of a line, with a mark
beside them (`marks`: "Hi! brushed steel"); inside the line only the single courtesy words listed in
`anywhere` ("no gloss please, matt dark green"), never a phrase. Runs only for a line with an unknown word
(the unknown-word path of cnlmc.document), so ordinary lines pay nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

from .diagnostics import Diagnostic, Severity
from .spans import Span
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged

__all__ = ["is_place", "without_colour_head", "without_politeness"]


def without_politeness(
    diags: list[Diagnostic], words: Sequence[Tagged], tag: Callable[[str], Tagged | None] | None = None
) -> tuple[list[Diagnostic], list[Tagged]]:
    """The line's words without the politeness at its edges, and its diagnostics without the
    unknown-word errors of the dropped words plus one note per dropped phrase. A leading phrase
    listed in `rewrites` ('give it' -> 'with', 'tone down the' -> 'less') leaves its word in its
    place, tagged by `tag` (the lexicon's reading of that word); a pronoun after the first word
    ('polish it') is read as the material above, the verb as its describing word."""
    table = teaching()["politeness"]
    marks = frozenset(table["marks"])
    rewrites: dict[str, str] = table["rewrites"]
    kept = list(words)
    dropped: list[list[Tagged]] = []
    compared: list[Tagged] = []  # the other side of a comparison ('than black')
    put: list[Tagged] = []
    rewritten: list[Tagged] | None = None
    where_said: list[Span] = []  # the trailing phrases read past: every error inside them goes
    for at_start, phrases in ((True, table["leading"]), (False, table["trailing"])):
        while len(kept) > 1:
            if at_start and rewritten is None and tag is not None:  # 'ok, more of a teal': after the politeness
                taken = _edge_phrase(kept, list(rewrites), marks, at_start=True)
                if taken and _edge_phrase(kept, phrases, marks, at_start=True) > taken:
                    taken = 0  # "like it's just been rained on": the longer courtesy phrase wins
                if taken:
                    rewritten, kept = kept[:taken], kept[taken:]
                    said = " ".join(w.text.lower() for w in rewritten if w.text[:1].isalnum())
                    if said in table["towards"]:  # 'more like charcoal than black': what it is not, read past
                        kept, other = _without_other_side(kept)
                        dropped += [other] if other else []
                        compared = other
                    towards_a_material = said in table["towards"] and _ends_in_a_noun(kept)
                    put = _rewritten(rewritten, rewrites[said], tag) if not towards_a_material else []
                    dropped.append(rewritten)
                    break
            taken = _edge_phrase(kept, phrases, marks, at_start)
            if not taken:
                break
            dropped.append(kept[:taken] if at_start else kept[-taken:])
            if not at_start or _set_off(dropped[-1], kept, taken, marks):  # 'oak, nothing else', 'no, keep the colour':
                where_said.append(dropped[-1][0].span.to(dropped[-1][-1].span))  # their own E002 goes too
            kept = kept[taken:] if at_start else kept[:-taken]
    if not compared:  # 'eggshell rather than flat', 'oak instead of walnut': the alternative turned down
        kept, compared = _without_turned_down(kept, table["turned_down"])
        dropped += [compared] if compared else []
    kept, said_last, where = _without_last_words(kept, table)
    dropped += said_last
    kept, inside = _without_courtesy_inside(kept, table["anywhere"])
    dropped += inside
    idiom = _idiom(kept, table["idioms"], tag) if tag is not None and not put else None
    if idiom is not None:
        said_run, put, kept = idiom
        rewritten = said_run
        dropped.append(said_run)
    kept, pronoun, read_as = _without_pronoun(kept, table["pronouns"], tag) if idiom is None else (kept, None, [])
    if pronoun is not None:
        dropped.append([pronoun])
    if not dropped:
        return diags, kept
    spans = [w.span for run in dropped for w in run] + read_as
    out = [d for d in diags if not _inside(d, spans) and not _inside(d, [*where, *where_said], any_code=True)]
    changing = frozenset((*table["changes"], *table["changes_at_end"]))  # 'make it', 'instead': not courtesy
    for run in dropped:
        text = " ".join(w.text for w in run if w.text[:1].isalnum())
        if run is rewritten and put:
            note = f"read '{text}' as '{' '.join(w.text for w in put)}'"
        elif run is compared:
            note = f"read past '{text}': what it is compared with, not what it is"
        elif where and run[0].span.start == where[0].start:
            note = f"read past '{text}': where the material is used, not how it looks"
        elif run[0] is pronoun:
            note = f"read '{text}' as the material above"
        elif text.lower() in changing:
            note = f"read past '{text}': a change phrase (the line's words change the material above, if any)"
        else:
            note = f"read past '{text}': a phrase names the material only, so politeness is left out"
        out.append(Diagnostic(run[0].span.to(run[-1].span), Severity.NOTE, NOTE_CODE, note))
    return out, (kept + put if idiom is not None else put + kept)


def _without_courtesy_inside(kept: list[Tagged], words: Sequence[str]) -> tuple[list[Tagged], list[list[Tagged]]]:
    """The words without a courtesy said inside the line, which never carries meaning ('no gloss
    please, matt dark green': teaching.toml [politeness] anywhere), each one as a run read past."""
    inside = [w for w in kept if w.text.lower() in words]
    if not inside or len(inside) == len(kept):
        return kept, []
    return [w for w in kept if w not in inside], [[w] for w in inside]


def _without_last_words(
    kept: list[Tagged], table: dict[str, Any]
) -> tuple[list[Tagged], list[list[Tagged]], list[Span]]:
    """The words without what ends them and says nothing of the look: 'colour' after a colour ('a
    soft putty colour'), then where the material is used ('tiles in the hallway'); the runs read
    past, and the place's span (all its errors go with it)."""
    runs: list[list[Tagged]] = []
    headless = without_colour_head(kept, table)
    if len(headless) < len(kept):
        runs.append(kept[len(headless) :])
        kept = headless
    place = _place_at_end(kept, table)
    if not place:
        return kept, runs, []
    return kept[:-place], [*runs, kept[-place:]], [kept[-place].span.to(kept[-1].span)]


def without_colour_head(words: list[Tagged], table: Mapping[str, Any]) -> list[Tagged]:
    """The words without a colour's head word after a colour ('a soft putty colour', 'a lighter
    navy shade': teaching.toml [politeness] colour_heads)."""
    if len(words) > 1 and words[-1].text.lower() in table["colour_heads"] and _is_colour(words[-2]):
        return words[:-1]
    return words


def _is_colour(word: Tagged) -> bool:
    return any(c.tag == "COLOR" for c in word.candidates)


def _place_at_end(kept: list[Tagged], table: Mapping[str, Any]) -> int:
    """How many words at the end say where the material is used ('in the hallway', 'for our
    kitchen'): a preposition, an optional article and a listed place; 0 when none, or when
    nothing would be left before them."""
    lowered = [w.text.lower() for w in kept]
    for size in (2, 1):
        at = len(lowered) - size - 1  # the article is needed: 'paint in flat' is not a place
        if at >= 2 and is_place(lowered[at - 1 :], table) and not _substrate(kept[: at - 1], lowered[at - 1]):
            return len(lowered) - at + 1
        at += 1  # no article ('teal tiles in bathroom'): only a place that is no word of the lexicon
        if at >= 2 and all(not w.candidates or w.unknown for w in kept[at:]) and is_place(lowered[at - 1 :], table):
            return len(lowered) - at + 1
    return 0


def _set_off(run: Sequence[Tagged], kept: Sequence[Tagged], taken: int, marks: frozenset[str]) -> bool:
    """Whether the leading phrase `run` (the first `taken` words of `kept`) is set off by a mark
    after it ('no, keep the colour'): an interjection, not a word of the line."""
    return run[-1].text in marks or (taken < len(kept) and kept[taken].text in marks)


def _substrate(before: Sequence[Tagged], preposition: str) -> bool:
    """Whether the thing after 'on' is what the words before lie on ('celadon glaze on a bowl',
    'varnish on a table': a finish or feature with no material of its own, read by cnlmc.on_clause),
    not where a material is used."""
    return preposition == "on" and not any(c.tag == "NOUN" for w in before for c in w.candidates)


def is_place(said: Sequence[str], table: Mapping[str, Any]) -> bool:
    """Whether the (lower-case) words are only where the material is used: a preposition, an
    article (or none, as a phone's terse typing has it) and a listed place ('in the hallway', 'in
    bathroom', 'under the sink': teaching.toml [politeness])."""
    if len(said) < 2 or said[0] not in table["place_prepositions"]:
        return False
    place = said[2:] if said[1] in table["place_articles"] else said[1:]
    return bool(place) and " ".join(place) in table["places"]


def _idiom(
    kept: list[Tagged], idioms: dict[str, str], tag: Callable[[str], Tagged | None]
) -> tuple[list[Tagged], list[Tagged], list[Tagged]] | None:
    """'tone it down', 'warm it up a bit': a listed verb-and-'it' phrase that is the whole line but
    for degree words after it. The phrase's words, the comparative it stands for (tagged, in its
    place), and the degree words (kept, they go before it); None when the line is anything else."""
    lowered = [w.text.lower() for w in kept]
    for n in range(len(kept), 0, -1):
        if " ".join(lowered[:n]) not in idioms:
            continue
        rest = kept[n:]
        if not all(any(c.tag == "ADV" for c in w.candidates) for w in rest):
            return None
        put = _rewritten(kept[:n], idioms[" ".join(lowered[:n])], tag)
        return (kept[:n], put, rest) if put else None
    return None


def _without_other_side(kept: list[Tagged]) -> tuple[list[Tagged], list[Tagged]]:
    """'charcoal than black' after 'more like': the words before 'than', and 'than' with the rest
    (the colour or material it is compared with, which says only what it is not)."""
    at = next((i for i, w in enumerate(kept) if w.text.lower() == "than"), None)
    if at is None or at == 0:
        return kept, []
    return kept[:at], kept[at:]


def _without_turned_down(kept: list[Tagged], markers: Sequence[str]) -> tuple[list[Tagged], list[Tagged]]:
    """'eggshell rather than flat': the words before the first marker phrase ('rather than',
    'instead of'), and the marker with the rest (what the speaker turns down, not what it is);
    the words as they were when no word is said before the marker."""
    lowered = [w.text.lower() for w in kept]
    for at in range(1, len(kept)):
        if any(lowered[at : at + len(m.split())] == m.split() for m in markers):
            before, after = kept[:at], kept[at:]
            if any(w.text[:1].isalnum() for w in before) and not (_ends_in_a_noun(after) and not _names(before)):
                return before, after
            break  # 'matte rather than glossy black plastic': the noun is the phrase's, not the alternative's
    return kept, []


def _names(words: Sequence[Tagged]) -> bool:
    return any(c.tag == "NOUN" for w in words for c in w.candidates)


def _ends_in_a_noun(words: Sequence[Tagged]) -> bool:
    """'more like a dark walnut': the line names a material after its 'towards' phrase, so the
    phrase is a change to it ('make it'), not a comparative ('more of a teal' = more teal)."""
    said = [w for w in words if w.text[:1].isalpha()]
    return bool(said) and any(c.tag == "NOUN" for c in said[-1].candidates)


def _without_pronoun(
    kept: list[Tagged], pronouns: Sequence[str], tag: Callable[[str], Tagged | None] | None
) -> tuple[list[Tagged], Tagged | None, list[Span]]:
    """'polish it', 'sand them': a verb then a pronoun for the material above. The words without
    the pronoun (the verb read as its describing word: 'sand' is sanded, not the material sand),
    the pronoun, and the span whose errors go with the verb's reading."""
    let = _let_pronoun(kept, pronouns)
    if let:  # 'let it age a bit' = 'age it a bit' ('let' read past with the pronoun)
        kept = [kept[2], kept[1], *kept[3:]]
    if len(kept) < 2 or kept[1].text.lower() not in pronouns:
        return kept, None, []
    verb = _participle(kept[0], tag)
    if verb is None and not let and any(c.tag == "NOUN" for c in kept[0].candidates) and _opens_relative(kept[1]):
        return kept, None, []  # 'teak that has silvered': a relative clause, not a verb on 'that'

    rest, past = kept[2:], [verb.span] if verb is not None else []
    if rest and rest[0].text.lower() in teaching()["politeness"]["particles"]:
        rest, past = rest[1:], [*past, rest[0].span]  # 'polish it up': the particle goes with the pronoun
    if let:
        past = [*past, let[0].span]
    said = verb or kept[0]
    rest, reached = _result_words(rest)
    if reached:  # 'polish it up to a mirror' = mirror polished
        past = [*past, *reached]
        return [*rest, said], kept[1], past
    describing = verb is not None or any(c.tag == "ADJ" for c in said.candidates)  # 'matt it a bit'
    if describing and rest and all(any(c.tag == "ADV" for c in w.candidates) for w in rest):
        return [*rest, said], kept[1], past  # 'polish it a bit' = 'a bit polished'
    if describing and len(rest) == 1 and rest[0].text.lower() in teaching()["politeness"]["bare_comparisons"]:
        return [rest[0], said], kept[1], past  # 'polish it more' = 'more polished'
    return [said, *rest], kept[1], past


def _result_words(rest: list[Tagged]) -> tuple[list[Tagged], list[Span]]:
    """'to a mirror finish' after 'polish it': the describing words of the result ('mirror') and the
    spans read past with the verb ('to a', 'finish'); the words as they were and [] otherwise
    (teaching.toml [politeness] result_openers, result_nouns)."""
    table = teaching()["politeness"]
    lowered = [w.text.lower() for w in rest]
    for opener in sorted((tuple(o.split()) for o in table["result_openers"]), key=len, reverse=True):
        n = len(opener)
        if tuple(lowered[:n]) != opener or len(rest) <= n:
            continue
        said = rest[n:]
        tail = [  # 'to a matte finish': the noun after a describing word ('a high shine' keeps it)
            w.span
            for w in said[-1:]
            if w.text.lower() in table["result_nouns"]
            and len(said) > 1
            and any(c.tag == "ADJ" for c in said[-2].candidates)
        ]
        said = [_as_describing(w) for w in said[: len(said) - len(tail)]]
        return said, [w.span for w in rest[:n]] + tail
    return rest, []


def _let_pronoun(kept: list[Tagged], pronouns: Sequence[str]) -> list[Tagged]:
    """['let'] when the words open with 'let it' and a verb ('let it age a bit'), else []."""
    if len(kept) > 2 and kept[0].text.lower() in teaching()["politeness"]["let"] and kept[1].text.lower() in pronouns:
        return [kept[0]]
    return []


def _opens_relative(word: Tagged) -> bool:
    """Whether a pronoun opens a relative clause ('that', 'which': the first words of teaching.toml
    [hedges] relative) rather than stands for the material above."""
    return any(opener.split()[0] == word.text.lower() for opener in teaching()["hedges"]["relative"])


def _as_describing(word: Tagged) -> Tagged:
    """A result word read as a describing word where it may be one ('a mirror': the finish, not the object)."""
    describing = tuple(c for c in word.candidates if c.tag != "NOUN")
    return Tagged(word.text, word.span, describing) if describing and len(describing) < len(word.candidates) else word


def _participle(word: Tagged, tag: Callable[[str], Tagged | None] | None) -> Tagged | None:
    """The describing word a verb before 'it' names ('sand' -> sanded, 'wax' -> waxed, 'age' ->
    aged, 'dye' -> dyed), tagged, in the verb's place; None when no such adjective is known."""
    if tag is None:
        return None
    text = word.text.lower()
    for form in (f"{text}ed", f"{text}d", f"{text[:-1]}ied", f"{text}{text[-1:]}ed"):
        found = tag(form)
        if found is not None and any(c.tag == "ADJ" for c in found.candidates):
            return Tagged(found.text, word.span, tuple(c for c in found.candidates if c.tag == "ADJ"))
    return None


def _rewritten(run: Sequence[Tagged], said: str, tag: Callable[[str], Tagged | None]) -> list[Tagged]:
    """The rewrite's words in place of the phrase ('a bit more of a' -> 'a bit' 'closer'), tagged,
    each inside a word of the phrase from its end (the parser keys words by start, and no written
    word starts there), implied by the phrase; [] when a word is not known or the phrase is shorter."""
    words = [tag(w) for w in _rewrite_words(said, tag)]
    if not words or len(words) > len(run) or any(w is None for w in words):
        return []
    whole = run[0].span.to(run[-1].span)
    out = []
    for word, place in zip(words, run[len(run) - len(words) :]):
        assert word is not None
        s = place.span
        at = min(s.start + 1, s.end)
        out.append(Tagged(word.text, Span(at, s.end, s.line, s.col + at - s.start), word.candidates, implied_by=whole))
    return out


def _rewrite_words(said: str, tag: Callable[[str], Tagged | None]) -> list[str]:
    """The rewrite as the words the lexicon knows: 'a bit closer' is 'a bit' (one adverb) and 'closer'."""
    if tag(said) is not None:
        return [said]
    words = said.split()
    if len(words) > 1 and tag(" ".join(words[:-1])) is not None:
        return [" ".join(words[:-1]), words[-1]]
    return words


def _inside(diag: Diagnostic, spans: Sequence[Span], any_code: bool = False) -> bool:
    """Whether a diagnostic is about dropped words only (its span within one of theirs): a note or an
    unknown word's E001, or any diagnostic with `any_code` (a place's 'says where' E002)."""
    at = diag.span
    if at is None or (diag.is_error and diag.code != "E001" and not any_code):
        return False
    return any(s.start <= at.start and at.end <= s.end for s in spans)


def _part_of_a_word(word: Tagged, words: Sequence[Tagged]) -> bool:
    """A comparative word formation split off a written word ('er' of 'older' = more old: the parts
    touch) is no hesitation ('er, darker')."""
    if not word.candidates or not all(c.tag == "REFINE" for c in word.candidates):
        return False
    s = word.span
    return any(
        o is not word and o.span.line == s.line and (o.span.end == s.start or o.span.start == s.end) for o in words
    )


def _edge_phrase(words: Sequence[Tagged], phrases: Sequence[str], marks: frozenset[str], at_start: bool) -> int:
    """How many words at this edge are a listed phrase (the longest), with the mark beside it. A
    word may hold several ('I'd like' joined by a head-word rule), so the texts are compared joined."""
    lowered = [w.text.lower() for w in words]
    listed = set(phrases)
    taken = 0
    for n in range(1, len(words)):
        edge = lowered[:n] if at_start else lowered[-n:]
        if " ".join(edge) in listed and not _part_of_a_word(words[n - 1] if at_start else words[-n], words):
            taken = n
    if not taken:
        return 0
    beside = lowered[taken] if at_start else lowered[-taken - 1]
    return taken + 1 if beside in marks and taken + 1 < len(words) else taken
