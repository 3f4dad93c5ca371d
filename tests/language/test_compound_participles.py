"""Compound participles and adjectives (issue #14, category 1): a manner, a degree or a qualifier
joined to a participle or adjective (hand-forged, kiln-dried, close-grained, heavy-rusted), read by the
[compound_first] rules of stdlib/lexicon/word_formation.toml, each reading a note.

No phrase here is in tests/language/everyday.toml: the rules must be general. Each is compared with
the phrase it should mean through the real compiler (model, parameters, maps).
"""

import pytest

from cnlmc.api import compile_source
from cnlmc.diagnostics import Severity
from cnlmc.lexicon import load_lexicon


@pytest.fixture(scope="module")
def lexicon():
    return load_lexicon()


def compiled(lexicon, text):
    result = compile_source(text, "cp.cnl", lexicon)
    assert result.ok, (text, [d.message for d in result.diagnostics])
    warnings = [d.message for d in result.diagnostics if d.severity is Severity.WARNING]
    assert not warnings, (text, warnings)
    (material,) = result.ir["materials"]
    return result, {k: material[k] for k in ("model", "params", "maps")}


def notes(result):
    return [d.message for d in result.diagnostics if d.severity is Severity.NOTE]


@pytest.mark.parametrize(
    ("text", "meaning", "note_has"),
    [
        # a manner first: dropped, the participle read (hyphenated, glued, spaced)
        ("hand-rubbed cherry", "rubbed cherry", "'hand' says how"),
        ("handrubbed maple", "rubbed maple", "'hand' says how"),
        ("hand rubbed teak", "rubbed teak", "'hand' says how"),
        ("machine-polished brass", "polished brass", "'machine' says how"),
        ("salt-glazed ceramic", "glazed ceramic", "'salt' says how"),
        ("stone-ground terrazzo", "ground terrazzo", "'stone' says how"),
        ("water-worn copper", "worn copper", "'water' says how"),
        ("kiln-glazed porcelain", "glazed porcelain", "'kiln' says how"),
        ("factory-painted steel", "painted steel", "'factory' says how"),
        ("hand-oiled walnut", "oiled walnut", "'hand' says how"),
        ("hand waxed pine", "waxed pine", "'hand' says how"),
        ("flame-polished acrylic", "polished acrylic", "'flame' says how"),
        ("steam-bent ash", "ash", "how it was made"),
        ("hand-thrown stoneware", "stoneware", "how it was made"),
        ("handmade paper", "paper", "how it was made"),
        ("factory-finished maple", "maple", "how it was made"),
        # a participle of the lexicon that shapes, not finishes: the material as it is
        ("hand-forged steel", "steel", "'hand' says how"),
        ("laser-cut aluminium", "aluminium", "'laser' says how"),
        ("mouth-blown glass", "glass", ""),
        ("machine-turned brass", "brass", "'machine' says how"),
        ("kiln-dried ash", "ash", ""),
        ("vat-dyed linen", "linen", ""),
        # a synonym of a first part: that part's compound, with its own meaning
        ("close-grained birch", "fine-grained birch", "'close' means 'fine'"),
        ("tight-grained cherry", "fine-grained cherry", "'tight' means 'fine'"),
        ("open-grained ash", "coarse-grained ash", "'open' means 'coarse'"),
        ("wide-grained pine", "coarse-grained pine", "'wide' means 'coarse'"),
        # a degree first: that adverb on the rest
        ("heavy-rusted iron", "strongly rusted iron", "is a degree"),
        ("lightly-brushed steel", "lightly brushed steel", "is a degree"),
        ("deep-etched glass", "strong etched glass", "is a degree"),
        ("loose-woven hemp", "slightly woven hemp", "is a degree"),
        ("tightly-woven wool", "strongly woven wool", "is a degree"),
        ("sand-cast brass", "brass", "how it was made"),
        ("drop forged iron", "forged iron", "'drop' says how"),
        ("hand-finished oak", "oak", "how it was made"),
    ],
)
def test_compound_first_part(lexicon, text, meaning, note_has):
    result, look = compiled(lexicon, text)
    _plain, expected = compiled(lexicon, meaning)
    assert look == expected, (text, meaning)
    said = notes(result)
    assert said, f"{text!r} was read without a note"
    assert any(note_has in n for n in said), said


def wood_params(lexicon, text):
    _result, look = compiled(lexicon, text)
    return look["maps"]["base_color"]["params"]


def test_grain_size_is_the_wood_graphs_density(lexicon):
    """fine-grained: denser fibres and rings than the wood's own; coarse-grained: fewer, bolder."""
    fine = wood_params(lexicon, "fine-grained oak")
    coarse = wood_params(lexicon, "coarse-grained oak")
    assert fine["scale"] > 1.0 > coarse["scale"]
    assert fine["ring_scale"] > 1.0 > coarse["ring_scale"]
    assert wood_params(lexicon, "close grained oak") == fine  # spaced: the lexicon's alias


def test_a_manner_is_never_a_colour_or_a_second_material(lexicon):
    """'salt', 'stone', 'water' are nouns (and colours): first in a compound they say how it was made."""
    for text in ("salt-glazed stoneware", "stone-ground concrete", "water-worn granite"):
        result, _look = compiled(lexicon, text)
        assert not [d for d in result.diagnostics if d.code == "N122"], text  # not 'the colour of salt'


def test_a_manner_before_nothing_it_can_read_is_still_unknown(lexicon):
    """The rules never eat a typo: 'hand' before a word that is neither a describing word nor a participle."""
    result = compile_source("hand-xqzt oak", "cp.cnl", lexicon)
    assert not result.ok
    assert any(d.code == "E001" for d in result.diagnostics)


def test_a_suffix_of_the_rules_is_not_a_participle(lexicon):
    """'sand-coloured' is the colour of sand (resemblance), not 'made with sand': the manner rule
    comes after the suffix rules and never reads 'coloured' as a participle."""
    result, look = compiled(lexicon, "sand-coloured plaster")
    _plain, expected = compiled(lexicon, "sand plaster")
    assert look == expected
    assert not [n for n in notes(result) if "how it was made" in n]
