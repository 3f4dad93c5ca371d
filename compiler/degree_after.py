"""A degree said after its describing word (issue #14, texting and speech): 'shiny af', 'rough as
hell', 'matte to the max'. The adverb (an alias of a degree word, stdlib/lexicon/adverbs.toml) is
read before the word it follows, with a note; stdlib/data/teaching.toml [hedges] `after_the_word`
lists the forms said after. Without this the grammar would give the adverb to the next describing
word ('shiny af matte leather': very matte) or warn that it modifies nothing."""

from __future__ import annotations

from collections.abc import Sequence

from .diagnostics import Diagnostic, Severity
from .spans import Span
from .tagged import NOTE_CODE, Candidate, Tagged

#: tags of the words a degree word can qualify (the describing words)
QUALIFIED = frozenset({"ADJ", "SHADE", "PROP", "REFINE", "COAT", "FEATURE"})


def degrees_after(words: Sequence[Tagged]) -> tuple[list[Tagged], list[Diagnostic]]:
    """The words with each after-the-word degree moved before the describing word it follows, and a
    note for each; the words as they were when there is none (the common case: no table read)."""
    out: list[Tagged] = []
    notes: list[Diagnostic] = []
    for k, word in enumerate(words):
        degree = _after(word, words, k + 1) if out and _qualified(out[-1]) else None
        if degree is None:
            out.append(word)
            continue
        before, moved = placed_before(out[-1], degree, word.span)
        out[-1:] = [before, moved]
        note = f"read '{out[-1].text} {word.text}' as '{degree} {moved.text}'"
        notes.append(
            Diagnostic(
                moved.implied_by.to(word.span) if moved.implied_by else word.span, Severity.NOTE, NOTE_CODE, note
            )
        )
    return out, notes


def _qualified(word: Tagged) -> bool:
    return any(c.tag in QUALIFIED for c in word.candidates) and len(word.text) > 1


def _after(word: Tagged, words: Sequence[Tagged], next_at: int) -> str | None:
    """The degree word a word said after its describing word stands for, or None: a form only said
    after ('af'), or a degree adverb of several words with nothing after it to qualify ('aged a
    bit', 'rough a little, oiled': the line or its part ends there)."""
    adverb = next((c for c in word.candidates if c.tag == "ADV"), None)
    if adverb is None:
        return None
    from .suggest import teaching  # read only for an adverb after a describing word

    table: dict[str, str] = teaching()["hedges"]["after_the_word"]
    said = table.get(word.text.lower())
    ends = next_at == len(words) or any(c.tag == "COMMA" for c in words[next_at].candidates)
    if said is None and " " in word.text.strip() and ends:
        return adverb.key  # a degree said as a noun phrase ('a bit', 'a little') follows its word; 'very' does not
    return said


def placed_before(word: Tagged, degree: str, said: Span) -> tuple[Tagged, Tagged]:
    """The degree word at the describing word's start, and that word one character in (the parser
    keys words by start), both implied by what was said."""
    s = word.span
    before = Tagged(
        degree, Span(s.start, s.end, s.line, s.col), (Candidate("ADV", degree, "adverbs"),), implied_by=said
    )
    moved = Tagged(word.text, Span(s.start + 1, s.end, s.line, s.col + 1), word.candidates, implied_by=s)
    return before, moved


def simile_word() -> str:
    """The word of a simile ('as': teaching.toml [hedges] simile)."""
    from .suggest import teaching

    return str(teaching()["hedges"]["simile"]["word"])


def simile(words: Sequence[Tagged]) -> tuple[list[Tagged], Span, str, str] | None:
    """'rough as sandpaper', 'smooth as a mirror metal', 'shiny as glass': a describing word, then
    the simile's word and a thing (up to a comma or the end): the describing word at the simile's
    degree (teaching.toml [hedges] simile: 'very', a simile says it strongly), the thing left out;
    the words, the span left out, the word's text and the degree. None when no simile follows a
    describing word."""
    from .suggest import teaching

    said, degree = simile_word(), str(teaching()["hedges"]["simile"]["degree"])
    for i in range(1, len(words) - 1):
        if words[i].text.lower() != said or not _qualified(words[i - 1]):
            continue
        end = next((k for k in range(i + 1, len(words)) if not words[k].text[:1].isalnum()), len(words))
        nouns = [k for k in range(i + 1, end) if any(c.tag == "NOUN" for c in words[k].candidates)]
        named_before = any(c.tag == "NOUN" for w in words[: i - 1] for c in w.candidates)
        opened = i >= 2 and words[i - 2].text.lower() == said  # 'as shiny as a mirror': its first 'as' too
        if end == len(words) and len(nouns) > 1 and not named_before and not opened:
            end = nouns[-1]  # 'smooth as a mirror metal': the last noun is the material
        if end <= i + 1:
            continue
        start = i - 2 if opened else i - 1
        left = words[start if opened else i].span.to(words[end - 1].span)
        before, moved = placed_before(words[i - 1], degree, left)
        return [*words[:start], before, moved, *words[end:]], left, words[i - 1].text, degree
    return None
