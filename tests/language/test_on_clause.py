"""A clause said on its material: 'rust on steel' = 'steel with rust' (issue #14). The phrases are
not those of the held-out sets."""

import pytest

from .conftest import first


@pytest.mark.parametrize(
    "said,same_as",
    [
        ("verdigris on bronze", "bronze with verdigris"),
        ("a satin lacquer over cherry", "cherry with a satin lacquer"),
        ("light scratches on polished aluminium", "polished aluminium with light scratches"),
        ("a thin clear coat on top of red car paint", "red car paint with a thin clear coat"),
        ("gold leaf on carved pine", "carved pine with gold leaf"),
        ("surface rust on a steel plate", "steel plate with surface rust"),
    ],
)
def test_a_clause_on_its_material_is_the_material_with_it(compile_text, said, same_as):
    got, expected = first(compile_text(said)), first(compile_text(same_as))
    assert (got["params"], got["maps"], got["model"]) == (expected["params"], expected["maps"], expected["model"])
    (note,) = [d for d in compile_text(said).diagnostics if d.code == "N101" and " with " in d.message]
    assert note.span.col == 1


@pytest.mark.parametrize("said", ["steel on oak", "rust on", "on copper"])
def test_two_materials_or_a_missing_side_is_still_an_error(compile_text, said):
    assert not compile_text(said).ok


def test_a_coat_on_a_coated_material_is_not_two_coats(compile_text):
    assert not compile_text("a varnish on oak with a clear coat").ok
