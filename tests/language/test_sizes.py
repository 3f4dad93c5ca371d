"""The size of the pieces ('wide oak floorboards', 'large white tiles') is read past with a note:
sizes are not drawn at the scale a material is drawn (stdlib word_formation.toml qualifiers.sizes)."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source

from .conftest import look


@pytest.mark.parametrize(
    ("said", "meant"),
    [("wide oak floorboards", "oak floorboards"), ("large white tiles", "white tiles"), ("narrow planks", "planks")],
)
def test_a_size_is_read_past_with_a_note(stdlib, said, meant):
    result, meaning = look(stdlib, said)
    assert meaning == look(stdlib, meant)[1]
    assert any("size of the pieces" in d.message for d in result.diagnostics)


def test_a_size_alone_is_no_material(stdlib):
    assert [d.code for d in compile_source("wide\n", "s.cnl", stdlib).diagnostics] == ["E001"]


@pytest.mark.parametrize(
    ("said", "meant"),
    [("plain white paint", "white paint"), ("standard oak", "oak"), ("simple black plastic", "black plastic")],
)
def test_the_ordinary_kind_is_read_past_with_a_note(stdlib, said, meant):
    """'plain', 'standard', 'simple' before a material: the material without more (qualifiers.ordinary)."""
    result, meaning = look(stdlib, said)
    assert meaning == look(stdlib, meant)[1]
    assert any("the ordinary kind" in d.message for d in result.diagnostics)
