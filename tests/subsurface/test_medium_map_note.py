"""Issue #19 review 1: Mitsuba's homogeneous medium cannot be textured. A translucent volume with a
base-colour map (marble's veins) exported natively says so in a note (W203, not a W202 "baked" note
for an image nothing reads), and writes no image for it; an opaque textured material is unchanged."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source
from cnlmc.backends.exchange import mitsuba


def exported(phrase: str, tmp_path, **options: str):
    ir = compile_source(phrase + "\n").ir
    return mitsuba.TARGET.emit_ir(ir, {"output": str(tmp_path / "scene.xml"), "map_size": "8", **options})


@pytest.mark.parametrize("phrase", ["marble", "black marble with white veins", "jade"])
def test_a_textured_medium_says_its_map_is_not_drawn(tmp_path, phrase):
    result = exported(phrase, tmp_path)
    notes = {n.feature: n for n in result.notes}
    note = notes["maps.base_color"]
    assert note.code == "W203" and "homogeneous medium cannot be textured" in note.message
    scene = next(a.content for a in result.artifacts if a.name.endswith(".xml"))
    assert 'type="homogeneous"' in scene and "bitmap" not in scene  # true: the medium has one colour
    assert not [a.name for a in result.artifacts if a.name.endswith(".png")]


def test_an_opaque_textured_material_still_bakes_its_map(tmp_path):
    result = exported("oak", tmp_path)
    assert {n.feature: n.code for n in result.notes}["maps.base_color"] == "W202"
    assert [a.name for a in result.artifacts if a.name.endswith("_base_color.png")]
