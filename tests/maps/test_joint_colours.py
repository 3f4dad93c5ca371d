"""A clause names the colour of the joints between bricks or tiles ("red brick with white mortar",
"white tiles with black grout"): the graph's joints take the named colour, the faces keep theirs.
Measured on the baked colour map, the joints found by the graph's own mask output."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc import api
from cnlmc.backends.maps.bake import bake
from cnlmc.material import params_to_ir

SIZE = 256


def _faces_and_joints(phrase: str) -> tuple[np.ndarray, np.ndarray]:
    """Mean linear colour of the faces (mask 1) and of the joints (mask 0) of the phrase's colour map."""
    result = api.compile_source(phrase, "<phrase>")
    assert not [d for d in result.diagnostics if d.is_error or d.severity.name == "WARNING"], result.diagnostics
    material = result.document.materials[0]
    ref = material.maps["base_color"].to_ir()
    baked = bake({"color": ref, "mask": {**ref, "output": "mask"}}, params_to_ir(material.params), SIZE, 0)
    colour, mask = baked["color"], baked["mask"]
    return colour[mask > 0.99].mean(axis=0), colour[mask < 0.01].mean(axis=0)


@pytest.mark.parametrize(
    "phrase, joints_lighter",
    [
        ("white tiles with black grout", False),
        ("black tiles with white grout", True),
        ("brick with white mortar", True),
        ("red brick with black mortar", False),
    ],
)
def test_the_joints_take_the_named_colour_and_the_faces_keep_theirs(phrase, joints_lighter):
    faces, joints = _faces_and_joints(phrase)
    assert (joints.mean() > 2 * faces.mean()) if joints_lighter else (joints.mean() < 0.5 * faces.mean())


def test_a_coloured_grout_is_that_colour_and_the_default_grout_a_light_grey():
    _faces, blue = _faces_and_joints("white tiles with blue grout")
    assert blue[2] > 1.5 * blue[0]
    _faces, own = _faces_and_joints("white tiles with grout")
    assert np.ptp(own) < 0.05 and 0.3 < own.mean() < 0.7


def test_brick_without_a_mortar_clause_keeps_its_grey_mortar():
    _faces, plain = _faces_and_joints("brick")
    _faces, said = _faces_and_joints("brick with mortar")
    assert np.allclose(plain, said) and np.ptp(plain) < 0.06


@pytest.mark.parametrize("phrase", ["a backsplash with white grout", "subway tile with dark grout"])
def test_an_object_before_a_clause_is_the_material_not_a_qualifier(phrase):
    material = api.compile_source(phrase, "<phrase>").document.materials[0]
    assert material.maps["base_color"].graph == "tiles"
