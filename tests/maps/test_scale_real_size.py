"""Textures at real scale (issue #15 item 4): every stdlib graph states its size in metres, and the
feature size measured from its baked map (the spectrum's peak, not the parameter) on the 10 cm
preview sphere is within a factor 1.5 of that size; `finer` / `coarser` scale from there."""

from __future__ import annotations

import math

import numpy as np
import pytest

from cnlmc import api
from cnlmc.backends.maps.evaluate import evaluate
from cnlmc.backends.maps.feature_size import dominant_period
from cnlmc.backends.maps.library import graph_names, load_graph
from cnlmc.backends.maps.service import bake_arrays
from cnlmc.backends.preview import meshes

SIZE = 512


def sphere_metres_per_uv() -> tuple[float, float]:
    """Metres one UV unit spans on the 10 cm sphere, measured from the mesh: round its equator (u)
    and from pole to pole (v)."""
    mesh = meshes.sphere(32, 64)
    radius = meshes.SPHERE_DIAMETER_M / 2
    u, v = mesh.uvs[:, 0], mesh.uvs[:, 1]
    return 2 * math.pi * radius / float(u.max() - u.min()), math.pi * radius / float(v.max() - v.min())


def test_the_sphere_is_10_cm_with_isotropic_uvs_in_the_maps_texture_unit():
    along_u, along_v = sphere_metres_per_uv()
    assert along_u == pytest.approx(along_v, rel=1e-3)  # a map's features keep their shape
    assert meshes.sphere().metres_per_uv == pytest.approx(along_u, rel=1e-3)
    for name in graph_names():  # every map's stated texture unit is what the sphere's UVs measure
        assert load_graph(name).scale.metres_per_unit == pytest.approx(along_u, rel=1e-3), name


@pytest.mark.parametrize("name", graph_names())
def test_feature_size_on_the_sphere_is_the_stated_real_size(name):
    graph = load_graph(name)
    scale = graph.scale
    assert scale is not None, f"{name} states no real size ([scale] table)"
    baked = evaluate(graph, SIZE, 0, {}, {}, [scale.measure])[scale.measure]
    along_u, along_v = sphere_metres_per_uv()
    metres = dominant_period(baked, scale.axis) * (along_v if scale.axis == "v" else along_u)
    ratio = metres / scale.feature
    assert 1 / 1.5 <= ratio <= 1.5, f"{name}: {metres * 1000:.1f} mm measured, {scale.feature * 1000:.1f} mm stated"


def _measured(phrase: str, role: str, axis: str = "any") -> float:
    material = api.compile_source(phrase, "<phrase>").document.materials[0]
    return dominant_period(bake_arrays(material, SIZE, 0, roles=[role])[role], axis)


@pytest.mark.parametrize(
    "phrase, role, axis, refinements",
    [("hammered copper", "normal", "any", ("finer", "coarser")), ("brick", "base_color", "v", ("finer",))],
)
def test_finer_and_coarser_scale_from_the_real_size(phrase, role, axis, refinements):
    """A refinement line multiplies the density from the real size. Brick has no 'coarser': a tile
    holds two courses at real size, and a running bond needs an even number of them."""
    plain = _measured(phrase, role, axis)
    if "finer" in refinements:
        assert _measured(f"{phrase}\nfiner", role, axis) < plain / 1.3
    if "coarser" in refinements:
        assert _measured(f"{phrase}\ncoarser", role, axis) > plain * 1.3


def test_concrete_is_grey_at_its_measured_albedo():
    """physicallybased.info 'Concrete' albedo 0.51 (../shared/data/dielectrics.json): the baked map's
    mean stays near it (it was near-white in the preview: mean 208/255)."""
    material = api.compile_source("concrete", "<phrase>").document.materials[0]
    mean = bake_arrays(material, 128, 0, roles=["base_color"])["base_color"][..., :3].mean()
    assert 0.51 / 1.15 < mean < 0.51 * 1.15
    assert np.isfinite(mean)


SCALE = """
doc = "test"
[params.scale]
default = 1.0
range = [0.5, 2.0]
doc = "density"
[nodes.noise]
type = "perlin"
[scale]
metres_per_unit = 0.157
feature = 0.02
what = "blobs"
measure = "mask"
axis = "any"
source = "our choice"
[palette]
max_chroma = 0.1
dark_params = { scale = 1.5 }
[outputs]
mask = "noise"
"""


@pytest.mark.parametrize(
    "change, key, words",
    [
        (("feature = 0.02", "feature = -1"), "scale.feature", "above 0"),
        (('measure = "mask"', 'measure = "colour"'), "scale.measure", "not an output"),
        (('axis = "any"', 'axis = "w"'), "scale.axis", "one of u, v, any"),
        (("max_chroma = 0.1", "max_chroma = 3"), "palette.max_chroma", "[0, 0.4]"),
        (("max_chroma = 0.1", "max_chroma = 0.1\nlightness_curve = 9"), "palette.lightness_curve", "[0.25, 4]"),
        (("max_chroma = 0.1", "max_chroma = 0.1\nhue_range = [30, 80]"), "palette.hue_range", "together"),
        (
            ("max_chroma = 0.1", "max_chroma = 0.1\nhue_range = [30, 400]\nhue_reach = 9\noff_hue_max_chroma = 0.1"),
            "palette.hue_range",
            "[0, 360)",
        ),
        (("dark_params = { scale = 1.5 }", "dark_params = { scale = 9 }"), "palette.dark_params.scale", "outside"),
        (("dark_params = { scale = 1.5 }", "dark_params = { scal = 1 }"), "palette.dark_params.scal", "did you mean"),
    ],
)
def test_scale_and_palette_tables_are_checked(tmp_path, change, key, words):
    from cnlmc.backends.maps import GraphSchemaError, load_graph_file

    path = tmp_path / "g.toml"
    path.write_text(SCALE)
    assert load_graph_file(path).scale.feature == 0.02
    path.write_text(SCALE.replace(*change))
    with pytest.raises(GraphSchemaError) as caught:
        load_graph_file(path)
    assert "g.toml" in str(caught.value) and key in str(caught.value) and words in str(caught.value)
