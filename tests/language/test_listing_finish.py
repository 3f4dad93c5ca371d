"""Product-listing finishes and objects named before a material noun (issue #14)."""

import pytest

from .conftest import first


@pytest.mark.parametrize(
    "listed,same_as",
    [
        ("Nickel - Satin Finish", "satin nickel"),
        ("bronze, satin finish", "satin bronze"),
        ("Chrome - Mirror Finish", "mirror chrome"),
    ],
)
def test_a_finish_after_a_listing_dash_is_the_describing_word(compile_text, listed, same_as):
    assert first(compile_text(listed))["params"] == first(compile_text(same_as))["params"]


def test_a_head_word_at_the_end_of_a_plain_phrase_still_names_the_noun(compile_text):
    assert first(compile_text("polished nickel look"))["params"] == first(compile_text("polished nickel"))["params"]


@pytest.mark.parametrize(
    "said,same_as",
    [("gloss door paint", "gloss paint"), ("matt ceiling paint", "matt paint"), ("oak floor tiles", "oak tiles")],
)
def test_an_object_before_a_material_noun_names_where_it_goes(compile_text, said, same_as):
    assert first(compile_text(said))["params"] == first(compile_text(same_as))["params"]


@pytest.mark.parametrize(
    "said,same_as",
    [
        ("sawn Portland stone", "sawn limestone"),
        ("Cotswold stone", "honey limestone"),
        ("York stone", "sandstone"),
        ("silk emulsion", "silk paint"),
        ("slip-matched oak veneer", "oak veneer"),
    ],
)
def test_trade_names_read_as_their_material(compile_text, said, same_as):
    assert first(compile_text(said))["params"] == first(compile_text(same_as))["params"]
