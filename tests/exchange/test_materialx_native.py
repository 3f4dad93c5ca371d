"""MaterialX maps=native: procedural maps with a recipe become MaterialX nodes, the rest are baked."""

from __future__ import annotations

import pytest

from tests.helpers import require, run_cnlmc

mx = require("MaterialX", "materialx")
pytestmark = pytest.mark.materialx

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.exchange import materialx_native as native  # noqa: E402

from .conftest import FAST, ir_of  # noqa: E402
from .test_materialx import check_document, glsl, graph_node, graph_nodes, source_node_name  # noqa: E402,F401

# phrase -> (native node categories expected, roles native, roles baked)
CASES = {
    "sandblasted aluminum": ({"noise2d", "heighttonormal", "texcoord"}, {"normal"}, set()),
    "polished white marble": ({"fractal2d", "sin", "mix", "texcoord"}, {"base_color"}, set()),
    "polished granite": ({"cellnoise2d", "worleynoise2d", "mix"}, {"base_color"}, set()),
    "heavily rusted iron": (
        {"fractal2d", "worleynoise2d", "smoothstep", "mix"},
        {"base_color", "roughness", "mask"},
        set(),
    ),
    "white varnished oak": (set(), set(), {"base_color", "roughness"}),
}


@pytest.mark.parametrize("surface", ["open_pbr_surface", "standard_surface"])
@pytest.mark.parametrize("phrase", sorted(CASES))
def test_native_maps(phrase, surface, mx_library, glsl):  # noqa: F811
    categories, native_roles, baked_roles = CASES[phrase]
    ir = ir_of(phrase)
    material = ir["materials"][0]
    assert set(material["maps"]) == native_roles | baked_roles  # the phrase still has these maps
    doc, result = check_document(ir, {"surface": surface, "maps": "native"}, mx_library, glsl)
    present = {n.getCategory() for n in graph_nodes(doc)}
    assert categories <= present
    images = {n.getName() for n in graph_nodes(doc, "image")}
    assert images == {f"{material['name']}_{role}_image" for role in baked_roles}
    assert {a.name for a in result.artifacts[1:]} == {
        f"textures/materials.mtlx/{material['name']}_{role}.png" for role in baked_roles
    }
    policies = {n.feature: (n.policy, n.message) for n in result.notes if n.feature.startswith("maps.")}
    assert set(policies) == {f"maps.{role}" for role in native_roles | baked_roles}
    for role in native_roles:
        assert policies[f"maps.{role}"] == native.NATIVE
    for role in baked_roles:
        assert policies[f"maps.{role}"][0] == "bake"


def test_rust_mask_drives_metalness(mx_library, glsl):  # noqa: F811
    doc, _ = check_document(ir_of("heavily rusted iron"), {"maps": "native"}, mx_library, glsl)
    shader = doc.getChild("SR_heavily_rusted_iron")
    metalness = shader.getInput("base_metalness")
    assert source_node_name(metalness) == "heavily_rusted_iron_rust_metallic"
    assert graph_node(doc, "heavily_rusted_iron_rust_metallic").getCategory() == "subtract"
    # colour, roughness and metalness share one mask
    assert len([n for n in graph_nodes(doc) if n.getCategory() == "smoothstep"]) == 1


def test_roughness_recipe_follows_the_material(mx_library, glsl):  # noqa: F811
    ir = ir_of("sandblasted aluminum")
    material = ir["materials"][0]
    material["maps"]["roughness"] = {
        "graph": "sandblasted",
        "output": "roughness",
        "params": {"contrast": 2.0},
        "seed": 0,
    }
    doc, result = check_document(ir, {"maps": "native"}, mx_library, glsl)
    remap = graph_node(doc, f"{material['name']}_sandblasted_roughness")
    r = material["params"]["roughness"]
    assert remap.getInputValue("outlow") == pytest.approx(r - 0.1)
    assert remap.getInputValue("outhigh") == pytest.approx(r + 0.1)
    assert any(n.getCategory() == "fractal2d" for n in graph_nodes(doc))
    assert not graph_nodes(doc, "image")


def test_bake_stays_the_default(mx_library, glsl):  # noqa: F811
    doc, result = check_document(ir_of("polished granite"), {}, mx_library, glsl)
    assert graph_nodes(doc, "image")
    assert not any(n.getCategory() in ("cellnoise2d", "worleynoise2d") for n in graph_nodes(doc))


def test_maps_none_still_drops(mx_library, glsl):  # noqa: F811
    doc, result = check_document(ir_of("polished granite"), {"maps": "none"}, mx_library, glsl)
    assert not graph_nodes(doc, "image") and not graph_nodes(doc, "cellnoise2d")
    assert {n.policy for n in result.notes if n.feature.startswith("maps.")} == {"drop"}


def test_bogus_map_mode_is_an_error():
    with pytest.raises(ValueError, match=r"maps='bogus'.*native"):
        emit(ir_of("polished granite"), "materialx", {**FAST, "maps": "bogus"})


def test_native_from_the_command_line(tmp_path):
    out = tmp_path / "out.mtlx"
    source = "stone: polished white marble\nhull: heavily rusted iron\n"
    r = run_cnlmc(
        "compile", "-", "-t", "materialx", "--option", "maps=native", "-o", str(out), stdin=source, cwd=tmp_path
    )
    assert r.returncode == 0, r.stderr
    written = list(tmp_path.rglob("*.mtlx"))
    assert written, "nothing written"
    text = written[0].read_text()
    assert "fractal2d" in text and "<image" not in text
