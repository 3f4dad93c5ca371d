"""The sayable forms of a lexicon, by category: what the recogniser's grammar may contain."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from ..lexicon import Entry, Lexicon, normalise
from .settings import SpeechSettings

SPOKEN = re.compile(r"[a-z']+( [a-z']+)*")
SURVEY_FILE = "colour_names.toml"  # stdlib/data: the xkcd survey's everyday colours


@dataclass(frozen=True)
class Vocabulary:
    """category -> its sayable forms (sorted, each a space-joined phrase)."""

    forms: dict[str, tuple[str, ...]]

    def words(self) -> set[str]:
        """Every single word the forms are made of."""
        return {word for forms in self.forms.values() for form in forms for word in form.split()}

    def without(self, unsayable: set[str]) -> Vocabulary:
        """The forms none of whose words is in `unsayable` (words with no pronunciation)."""
        kept = {c: tuple(f for f in forms if not set(f.split()) & unsayable) for c, forms in self.forms.items()}
        return Vocabulary(kept)


def joined_colours(vocabulary: Vocabulary, english: frozenset[str]) -> set[str]:
    """Colour names written as two sayable shade or colour words run together ('darkgreen',
    'lightblue', 'bluegrey': CSS and the survey spell them so) that English does not have as a
    word: said aloud they are the two words, which the grammar says with their own meaning ('dark
    green' is the shade on the colour), so the joined spelling is not sayable. Real compounds
    English has ('aquamarine', 'strawberry') stay."""
    parts = {f for c in ("shades", "colours") for f in vocabulary.forms.get(c, ()) if " " not in f}
    return {
        form
        for form in vocabulary.forms.get("colours", ())
        if " " not in form
        and form not in english
        and any(form[:i] in parts and form[i:] in parts for i in range(1, len(form)))
    }


def sayable_vocabulary(lexicon: Lexicon, settings: SpeechSettings) -> Vocabulary:
    by_category: dict[str, set[str]] = {c: set() for c in settings.categories}
    for category in settings.categories:
        for entry in lexicon.entries.get(category, {}).values():
            by_category[category].update(_spoken_forms(entry, settings))
    return Vocabulary({c: tuple(sorted(forms)) for c, forms in by_category.items()})


def _spoken_forms(entry: Entry, settings: SpeechSettings) -> list[str]:
    """The entry's key and those aliases that spell it another way (aluminium, anodised, gray),
    each if it can be said (letters and spaces, at most max_form_words words)."""
    key = " ".join(normalise(entry.key))
    limit = settings.max_form_words
    if entry.category == "colours" and entry.origin.endswith(SURVEY_FILE):
        limit = settings.survey_colour_max_words
    aliases = [" ".join(normalise(a)) for a in entry.get("aliases", [])]
    forms = [key, *(a for a in aliases if settings.same_spelling(a, key))]
    return [f for f in forms if SPOKEN.fullmatch(f) and len(f.split()) <= limit]


def phrase_words(phrases: Iterable[str]) -> set[str]:
    return {word for phrase in phrases for word in phrase.split()}
