"""German word order (issue #14, category 4): a participle after the noun without a comma ('Eiche
geölt' = 'Eiche, geölt') and 'X aus Y' ('Dielen aus Eiche' = Eichendielen = oak), from the German
overlay's word formation rules ([compounds] postfix, made_of). Each reading is a note. No phrase here
is in tests/language/everyday.toml.
"""

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.diagnostics import Severity

from .conftest import look


@pytest.fixture(scope="module")
def de():
    return lexicon_for(["de"])


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("Nussbaum geölt", "Nussbaum, geölt"),
        ("Kiefer gewachst", "Kiefer, gewachst"),
        ("Aluminium gebürstet", "Aluminium, gebürstet"),
        ("Messing poliert", "Messing, poliert"),
        ("Edelstahl matt", "Edelstahl, matt"),
        ("Marmor geschliffen", "Marmor, geschliffen"),
        ("Kupfer leicht gebürstet", "Kupfer, leicht gebürstet"),
        ("Buche geölt und gewachst", "Buche, geölt und gewachst"),
        ("Granit poliert", "Granit, poliert"),
        ("Stahl sandgestrahlt", "Stahl, sandgestrahlt"),
        ("Marmor poliert mit grauen Adern", "Marmor, poliert, mit grauen Adern"),
    ],
)
def test_a_participle_after_the_noun_needs_no_comma(de, text, meaning):
    result, got = look(de, text)
    _plain, expected = look(de, meaning)
    assert got == expected, (text, meaning)
    assert any("after the noun" in d.message for d in result.diagnostics if d.severity is Severity.NOTE)


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("Bretter aus Kiefer", "Kiefer"),
        ("Platten aus Granit", "Granit"),
        ("Rohre aus Messing", "Messing"),
        ("Fliesen aus Schiefer", "Schiefer"),
        ("Dielen aus Nussbaum", "Nussbaum"),
        ("Rohre aus verzinktem Stahl", "verzinkter Stahl"),
        ("Knöpfe aus Messing", "Messing"),
        ("Dachrinne aus Zink", "Zink"),
        ("Ohrringe aus Silber", "Silber"),
    ],
)
def test_object_aus_material_is_the_material(de, text, meaning):
    result, got = look(de, text)
    _plain, expected = look(de, meaning)
    assert got == expected, (text, meaning)
    assert any("the material of" in d.message for d in result.diagnostics if d.severity is Severity.NOTE)


def test_english_reads_describing_words_after_the_noun_only_when_nothing_else_does():
    """English has no postfix rule in its tagger: 'oak oiled' is read as 'oiled oak' only after every
    other reading failed (cnlmc.noun_first), and says so in English."""
    result = compile_source("oak oiled", "en.cnl", lexicon_for([]))
    assert result.ok
    assert any("as 'oiled oak' (describing words go before the noun)" in d.message for d in result.diagnostics)


def test_aus_before_a_word_that_is_no_material_stays_an_error(de):
    assert not compile_source("Dielen aus xqzt", "de.cnl", de).ok
