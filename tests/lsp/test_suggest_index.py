"""'Did you mean' through the lexicon's index gives exactly what measuring every form gives (#13:
an unknown word cost ~2 ms of scanning, 3.7 s for a 300-line document of unknown words in the
server). The index only narrows the candidates; the answer must not change by one form."""

from __future__ import annotations

import random
import string

import pytest

from cnlmc.api import lexicon_for
from cnlmc.lexicon import CATEGORY_TAGS
from cnlmc.suggest import FormIndex, teaching

LEXICON = lexicon_for()
CATEGORY_SETS = [tuple(CATEGORY_TAGS), *(tuple(c) for c in teaching()["slots"].values()), ("nouns",)]


@pytest.fixture(scope="module")
def index() -> FormIndex:
    LEXICON.suggest("zorblat")
    found = LEXICON.caches.suggestion_index
    assert found is not None
    return found


def typo(rng: random.Random, word: str) -> str:
    """One to three edits of optimal string alignment (insert, delete, substitute, swap), some of
    them spaces and hyphens."""
    letters = list(word)
    for _ in range(rng.randint(1, 3)):
        at, letter, edit = rng.randrange(len(letters) + 1), rng.choice(string.ascii_lowercase + " -"), rng.randrange(4)
        if edit == 0:
            letters.insert(at, letter)
        elif edit == 1 and len(letters) > 1 and at < len(letters):
            del letters[at]
        elif edit == 2 and at < len(letters):
            letters[at] = letter
        elif at + 1 < len(letters):
            letters[at], letters[at + 1] = letters[at + 1], letters[at]
    return "".join(letters)


def words(index: FormIndex, seed: int) -> list[str]:
    rng = random.Random(seed)
    forms = rng.sample(index.forms, 300)
    made_up = ["".join(rng.choice(string.ascii_lowercase) for _ in range(rng.randint(1, 16))) for _ in range(200)]
    return forms[:50] + [typo(rng, f) for f in forms] + made_up


@pytest.mark.parametrize("categories", CATEGORY_SETS[:2], ids=["every category", "noun slot"])
def test_the_index_finds_what_measuring_every_form_finds(index, categories):
    for word in words(index, seed=len(categories)):
        assert index.closest(word, categories, 50) == index.closest(word, categories, 50, scan=True), word


def test_long_words_and_many_edits_are_found(index):
    """Words of 8+ letters (two edits) and 12+ letters (three) go through the letter-pair filter."""
    rng = random.Random(12)
    long_forms = [f for f in index.forms if len(f) >= 8]
    for form in rng.sample(long_forms, 150):
        word = typo(rng, form)
        for categories in CATEGORY_SETS[2:]:
            assert index.closest(word, categories, 50) == index.closest(word, categories, 50, scan=True), word


def test_known_typos_keep_their_suggestions():
    assert LEXICON.suggest("coper")[0] == "copper"
    assert LEXICON.suggest("alumnum")[0] == "aluminum"
    assert "mahogany" in LEXICON.suggest("mahagony")
    assert LEXICON.suggest("stainless", ("nouns",))[0] == "stainless steel"
    assert "wood" in LEXICON.suggest("rubberwood", ("nouns",))


def test_the_index_is_made_once_per_lexicon(index):
    LEXICON.suggest("blorptastic")
    LEXICON.suggest("qwertyuiopasdf", ("nouns",))
    assert LEXICON.caches.suggestion_index is index
