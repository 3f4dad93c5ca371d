"""Errors that teach: a 'did you mean' that fits the word's slot, and a known word in the wrong
role said as such, with a phrase that works ("'burgundy' is a colour here — did you mean
'burgundy plastic'?").

The slot of a word comes from where it stands in its clause (stdlib/data/teaching.toml, [slots]):
the last word of the phrase is the noun slot, a word before a known noun a modifier slot, the
last word after 'with' the coat slot. A phrase offered is checked: it must tag and parse.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from functools import lru_cache
from types import MappingProxyType

from .diagnostics import Diagnostic, did_you_mean
from .hedges import colour_between
from .lexicon import CATEGORY_TAGS, Lexicon
from .measures import without_measures
from .package_data import package_folder
from .politeness import without_politeness
from .suggest import allowed_edits, teaching
from .tagged import Candidate, Tagged, written_text

__all__ = ["fit_unknown_words", "teach_syntax_error", "wordnet_kinds"]

CLAUSE_BREAKS = frozenset({"WITH", "COMMA", "AND", "OR", "COLON"})
FINISHED_BY_A_NOUN = frozenset({"colours", "adjectives", "shades"})  # offered everyday nouns when alone
ROLE_ORDER = {tag: i for i, tag in enumerate(("COAT", "COLOR", "ADJ", "SHADE", "PROP", "ADV", "REFINE"))}  # said first


# ---------------------------------------------------------------- did you mean, by slot


def fit_unknown_words(
    diags: list[Diagnostic], words: Sequence[Tagged], lexicon: Lexicon
) -> tuple[list[Diagnostic], list[Tagged]]:
    """The tagger's diagnostics and words, each unknown word's suggestions redrawn from the
    categories of its slot, and its guessed readings those of the slot (so the parser does not
    report a second error for a guess that does not fit: 'tinn glass' is not 'tin glass')."""
    diags, words = without_measures(diags, words)
    diags, words = colour_between(diags, words, lexicon)
    diags, words = without_politeness(diags, words, lambda word: tagged_word(word, lexicon))
    out, fitted = [], list(words)
    for diag in diags:
        index = _unknown_index(diag, words)
        if index is None:
            out.append(diag)
            continue
        categories = teaching()["slots"][slot_of(words, index)]
        suggestions = _form_typos(words, index, lexicon) + lexicon.suggest(words[index].text, categories)
        out.append(replace(diag, hints=did_you_mean(suggestions), suggestions=tuple(suggestions)))
        fitted[index] = _guessed(words[index], categories)
    return out, fitted


def tagged_word(word: str, lexicon: Lexicon) -> Tagged | None:
    """One word as the lexicon tags it alone (a politeness rewrite's 'with', 'less')."""
    from .tagger import Tagger

    tagged, diags = Tagger.of(lexicon).tag_line(word, 1, 0)
    return tagged[0] if len(tagged) == 1 and not diags else None


def _form_typos(words: Sequence[Tagged], index: int, lexicon: Lexicon) -> list[str]:
    """'stainles steel' -> 'stainless steel': two-word forms whose second word follows the unknown
    word and whose first word it is a typo of."""
    if index + 1 >= len(words) or words[index + 1].unknown:
        return []
    from rapidfuzz.distance import OSA

    low, following = words[index].text.lower(), words[index + 1].text.lower()
    budget = allowed_edits(low)
    return [
        " ".join(form)
        for form in lexicon.forms
        if len(form) == 2 and form[1] == following and OSA.distance(low, form[0], score_cutoff=budget) <= budget
    ][:1]


def _guessed(tagged: Tagged, categories: Sequence[str]) -> Tagged:
    tags = [CATEGORY_TAGS[c] for c in categories if c in CATEGORY_TAGS]
    return Tagged(tagged.text, tagged.span, tuple(Candidate(t, "", "unknown") for t in tags), unknown=True)


def _unknown_index(diag: Diagnostic, words: Sequence[Tagged]) -> int | None:
    if diag.code != "E001" or diag.span is None:
        return None
    for i, tagged in enumerate(words):
        if tagged.unknown and tagged.span == diag.span and tagged.text[:1].isalpha():
            return i
    return None


def slot_of(words: Sequence[Tagged], index: int) -> str:
    """'noun', 'modifier', 'coat' or 'open': what the word at `index` stands for in its clause."""
    in_coat = any(_is_tag(w, "WITH") for w in words[:index])
    after = _rest_of_clause(words, index)
    if not after:
        return "coat" if in_coat else "noun"
    if any(not w.unknown and _is_tag(w, "COAT" if in_coat else "NOUN") for w in after):
        return "modifier"
    return "open"


def _rest_of_clause(words: Sequence[Tagged], index: int) -> list[Tagged]:
    rest = []
    for tagged in words[index + 1 :]:
        if not tagged.unknown and any(c.tag in CLAUSE_BREAKS for c in tagged.candidates):
            break
        if tagged.text[:1].isalpha():
            rest.append(tagged)
    return rest


def _only_noun(tagged: Tagged) -> bool:
    return all(c.tag == "NOUN" for c in tagged.candidates)


def _is_tag(tagged: Tagged, tag: str) -> bool:
    return any(c.tag == tag for c in tagged.candidates)


# ---------------------------------------------------------------- a known word in another role


def teach_syntax_error(diag: Diagnostic, words: Sequence[Tagged], lexicon: Lexicon) -> Diagnostic:
    """E002/E003 of a line whose words are all known: say the role of the word that cannot stand
    where it is, and offer phrases that work (each one parses)."""
    if any(w.unknown for w in words) or diag.code not in ("E002", "E003"):
        return diag
    main = _main_clause(words)
    if diag.code == "E003" or not any(_is_tag(w, "NOUN") for w in main):
        return _no_noun(diag, words, main, lexicon) or diag
    return _after_noun(diag, main, lexicon) or diag


def _main_clause(words: Sequence[Tagged]) -> list[Tagged]:
    start = next((i + 1 for i, w in enumerate(words) if _is_tag(w, "COLON")), 0)
    end = next((i for i, w in enumerate(words) if i >= start and _is_tag(w, "WITH")), len(words))
    return [w for w in words[start:end] if w.text[:1].isalpha()]


def _no_noun(diag: Diagnostic, words: Sequence[Tagged], main: list[Tagged], lexicon: Lexicon) -> Diagnostic | None:
    """'burgundy' alone: a colour here — did you mean 'burgundy plastic'? (its entry's example; for
    a colour, its WordNet kind first). A 'with' clause after it stays in the offer."""
    if not main:
        return None
    last, written = main[-1], written_text(main)
    tail = "".join(f" {w.text}" for w in words[words.index(main[-1]) + 1 :])
    for reading in sorted(last.candidates, key=lambda c: ROLE_ORDER.get(c.tag, len(ROLE_ORDER))):
        role = teaching()["roles"].get(reading.category)
        if role is None:
            continue
        colour = reading.category == "colours"  # a colour alone may be a noun misspelt ('terracota')
        kinds = _kind_phrases(written, last.text, lexicon) if colour else []
        typos = [" ".join([*written.split()[:-1], noun]) for noun in _misspelt_nouns(last.text, lexicon, colour)]
        example = _example_phrases(written, last.text, reading, lexicon)
        everyday = _everyday_phrases(written, main, lexicon) if reading.category in FINISHED_BY_A_NOUN else []
        ordered = (*typos, *kinds, *everyday, *example) if colour else (*example, *everyday)
        offered = [p + tail for p in ordered]
        phrases = _working(offered, lexicon)
        hint = f"'{last.text}' is {role} here" + (f" — {did_you_mean(phrases)[0]}" if phrases else "")
        return replace(diag, hints=(hint, *diag.hints[len(phrases) > 0 :]), suggestions=tuple(phrases))
    return None


def _misspelt_nouns(word: str, lexicon: Lexicon, colour: bool) -> list[str]:
    """The nouns a colour alone may be a typo of ('terracota' -> 'terracotta'); not a longer noun
    that starts with the very word ('black' is not a typo of 'black ash', nor 'dark brown' of 'dark brown skin')."""
    if not colour:
        return []
    said = word.lower()
    return [
        n
        for n in lexicon.suggest(word, ("nouns",))
        if n.lower().split()[0] != said and not n.lower().startswith(f"{said} ")
    ]


def _everyday_phrases(written: str, main: Sequence[Tagged], lexicon: Lexicon) -> list[str]:
    """'matte black' -> 'matte black paint', 'matte black plastic': the everyday nouns
    (teaching.toml [completions], most common first) that every describing word applies to."""
    table = teaching()["completions"]
    fitting = (f"{written} {noun}" for noun in table["nouns"] if _applies_to_all(noun, main, lexicon))
    clean = [phrase for phrase in fitting if _compiles_cleanly(phrase, lexicon)]
    return clean[: table["offered"]]


def _compiles_cleanly(phrase: str, lexicon: Lexicon) -> bool:
    """Whether the phrase compiles with no error and no warning (a word that does not apply to
    the noun warns: W102), so an offer is one the compiler itself accepts as it is. Two of the
    words said that contradict each other ('glossy matte') warn whatever the noun (W101): that
    warning is the words', and stays with the offer."""
    from .api import compile_source  # the teaching runs inside a compilation: imported when needed

    return not any(
        d.severity.value == "error" or (d.severity.value == "warning" and d.code not in WORDS_OWN_WARNINGS)
        for d in compile_source(phrase, "<offer>", lexicon).diagnostics
    )


WORDS_OWN_WARNINGS = frozenset({"W101"})  # a contradiction between the words said (passes/words.py)


def _applies_to_all(noun: str, main: Sequence[Tagged], lexicon: Lexicon) -> bool:
    """Whether each word that is only a describing word allows the noun (its `applies_to`: the
    noun's class or key); colours and shades allow any noun."""
    entry = lexicon.entry("nouns", noun)
    if entry is None:
        return False
    allowed_by = {noun, str(entry.get("class", ""))}
    for word in main:
        if word.candidates and all(c.tag == "ADJ" for c in word.candidates):
            adjectives = [lexicon.entry("adjectives", c.key) for c in word.candidates]
            limits = [set(a.get("applies_to") or ()) for a in adjectives if a is not None]
            if limits and all(limit and not limit & allowed_by for limit in limits):
                return False
    return True


def _kind_phrases(written: str, word: str, lexicon: Lexicon) -> list[str]:
    """'khaki' -> 'khaki fabric': the nearest WordNet kind of the word that is a lexicon noun."""
    for kind in wordnet_kinds().get(word.lower(), ()):
        if any(e.category == "nouns" for e in lexicon.lookup(tuple(kind.split()))):
            return [f"{written} {kind}"]
    return []


def _example_phrases(written: str, word: str, reading: Candidate, lexicon: Lexicon) -> list[str]:
    """The written words finished as the word's own entry's example finishes it ('lightly' with
    'lightly brushed brass' -> 'lightly brushed brass'; 'dark glossy' with 'glossy red plastic' ->
    'dark glossy red plastic'); a coat goes on its example's material ('oak with a varnish')."""
    entry = lexicon.entry(reading.category, reading.key)
    example = str(entry.get("example", "")) if entry is not None else ""
    if not example:
        return []
    if reading.category == "coats":
        return [f"{example.split(' with ', 1)[0]} with a {written}"]
    example_words = example.split()
    lowered = [w.lower() for w in example_words]
    spellings = (word.lower().split()[-1], reading.key.lower().split()[-1])  # 'gently' is written 'lightly' there
    own = next((s for s in spellings if s in lowered), None)
    rest = example_words[lowered.index(own) + 1 :] if own is not None else []
    return [f"{written} {' '.join(rest)}"] if rest else []


def _after_noun(diag: Diagnostic, main: list[Tagged], lexicon: Lexicon) -> Diagnostic | None:
    """'steel teal': the colour comes before the noun — did you mean 'teal steel'?"""
    only_nouns = [i for i, w in enumerate(main) if _only_noun(w)]  # 'satin nickel brushed': 'nickel'
    first_noun = only_nouns[-1] if only_nouns else next(i for i, w in enumerate(main) if _is_tag(w, "NOUN"))
    tail = main[first_noun + 1 :]
    if not tail or any(_only_noun(w) for w in tail):
        return None
    moved = [*main[:first_noun], *tail, main[first_noun]]
    phrases = _working([" ".join(w.text for w in moved)], lexicon)
    if not phrases:
        return None
    reading = next(c for c in tail[0].candidates if c.tag != "NOUN")
    role = teaching()["roles"].get(reading.category, "a describing word")
    if any(phrases[0] in hint for hint in diag.hints):  # the learned hint shows this very phrase
        return replace(diag, suggestions=tuple(phrases))
    hint = f"'{tail[0].text}' is {role}: it comes before the noun — {did_you_mean(phrases)[0]}"
    return replace(diag, hints=(hint,), suggestions=tuple(phrases))


def _working(phrases: list[str], lexicon: Lexicon) -> list[str]:
    """The phrases (each once) that this lexicon tags and parses without an error (tagged and
    parsed directly, not through document.parse_line, so no offer is itself taught)."""
    from .parser import ParseFailure, parse_line_shape
    from .tagger import Tagger

    tagger = Tagger.of(lexicon)
    out: list[str] = []
    for phrase in phrases:
        words, diags = tagger.tag_line(phrase, 1, 0)
        if phrase in out or any(d.is_error for d in diags) or not words:
            continue
        try:
            parse_line_shape(words, lexicon.caches.shapes)
        except ParseFailure:
            continue
        out.append(phrase)
    return out


@lru_cache(maxsize=1)
def wordnet_kinds() -> Mapping[str, tuple[str, ...]]:
    """WordNet noun -> its kinds, nearest first (stdlib/data/wordnet_aliases.toml; English only)."""
    import tomllib

    text = (package_folder("cnlmc.stdlib") / "data" / "wordnet_aliases.toml").read_text("utf-8")
    nouns = tomllib.loads(text).get("nouns", {})
    return MappingProxyType({word: tuple(row.get("kind_of", ())) for word, row in nouns.items()})
