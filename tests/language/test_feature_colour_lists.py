"""Feature clauses with a list of colours (issue #14, category 5): 'flecks of red and green',
'with red and black speckles', 'veins of gold and grey'. A feature's graph draws one colour, so the
first is the feature's and the rest are left out with a note (never a warning, never an error).
No phrase here is in tests/language/everyday.toml.
"""

import pytest

from cnlmc.diagnostics import Severity
from cnlmc.lexicon import load_lexicon

from .conftest import look


@pytest.fixture(scope="module")
def lexicon():
    return load_lexicon()


@pytest.mark.parametrize(
    ("text", "meaning", "left_out"),
    [
        ("granite with specks of white and grey", "granite with specks of white", "grey"),
        ("granite with flecks of pink and black", "granite with flecks of pink", "black"),
        ("quartzite with flecks of silver and gold", "quartzite with flecks of silver", "gold"),
        ("terrazzo with chips of red, blue and yellow", "terrazzo with chips of red", "blue, yellow"),
        ("terrazzo with specks of green and white", "terrazzo with specks of green", "white"),
        ("marble with veins of grey and gold", "marble with veins of grey", "gold"),
        ("marble with veining of black and white", "marble with veining of black", "white"),
        ("onyx with veins of amber and cream", "onyx with veins of amber", "cream"),
        ("marble with veins of dark green and white", "marble with veins of dark green", "white"),
        ("copper with a patina of green and blue", "copper with a patina of green", "blue"),
        ("bronze with a patina of turquoise and brown", "bronze with a patina of turquoise", "brown"),
        ("granite with spots of ochre and black", "granite with spots of ochre", "black"),
        ("marble with veins of gold and grey and a polished finish", "polished marble with veins of gold", "grey"),
        ("granite with flecks of red and green, with a matte finish", "matte granite with flecks of red", "green"),
        ("white marble with veins of light grey and taupe", "white marble with veins of light grey", "taupe"),
    ],
)
def test_the_first_colour_is_the_features(lexicon, text, meaning, left_out):
    result, got = look(lexicon, text)
    _plain, expected = look(lexicon, meaning)
    assert got == expected, (text, meaning)
    notes = [d.message for d in result.diagnostics if d.severity is Severity.NOTE and "left out" in d.message]
    assert notes and f"'{left_out}' left out" in notes[0], notes


@pytest.mark.parametrize(
    "text",
    [
        "granite with red and black speckles",
        "marble with grey and gold veins",
        "terrazzo with white, grey and black flecks",
        "granite with flecks of black and a glossy finish",
    ],
)
def test_colours_before_a_feature_and_an_and_after_it_compile(lexicon, text):
    look(lexicon, text)


@pytest.mark.parametrize(
    ("text", "meaning", "left_out"),
    [
        ("granite with red and black speckles", "granite with red speckles", "black"),
        ("marble with grey and white veining", "marble with grey veining", "white"),
        ("terrazzo with white, grey and black flecks", "terrazzo with white flecks", "grey, black"),
        ("bronze with a green and brown patina", "bronze with a green patina", "brown"),
    ],
)
def test_colours_before_a_feature_the_first_is_drawn(lexicon, text, meaning, left_out):
    result, got = look(lexicon, text)
    _plain, expected = look(lexicon, meaning)
    assert got == expected
    assert any(f"'{left_out}' left out" in d.message for d in result.diagnostics if d.severity is Severity.NOTE)


def test_multicoloured_flecks_are_flecks(lexicon):
    assert look(lexicon, "terrazzo with multicoloured flecks")[1] == look(lexicon, "terrazzo with flecks")[1]


def test_an_and_before_another_clause_is_not_a_colour_list(lexicon):
    result, _got = look(lexicon, "granite with flecks of black and a glossy finish")
    assert not [d for d in result.diagnostics if "left out" in d.message]


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("fine grain walnut", "walnut with fine grain"),
        ("heavy grain oak", "oak with heavy grain"),
        ("gold vein marble", "marble with gold veins"),
        ("black speckle granite", "granite with black speckles"),
        ("subtle sheen plastic", "plastic with a subtle sheen"),
        ("speckled granite", "granite with speckles"),
        ("flecked terrazzo", "terrazzo with flecks"),
        ("veiny marble", "marble with veins"),
        ("speckled white ceramic", "white ceramic with speckles"),
        ("speckled granite with a polished finish", "granite with speckles and a polished finish"),
        ("dotted blue ceramic", "blue ceramic with dots"),
    ],
)
def test_a_feature_named_before_the_material_is_its_clause(lexicon, text, meaning):
    result, got = look(lexicon, text)
    _plain, expected = look(lexicon, meaning)
    assert got == expected, (text, meaning)
    assert any("a feature named before the material" in d.message for d in result.diagnostics)
