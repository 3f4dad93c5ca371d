"""MaterialX: every stdlib noun and phrase validates and goes through MaterialX's GLSL generator."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.helpers import require

mx = require("MaterialX", "materialx")
pytestmark = pytest.mark.materialx
import MaterialX.PyMaterialXGenGlsl as mxg  # noqa: E402
import MaterialX.PyMaterialXGenShader as mxs  # noqa: E402

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.exchange.conversions import f82_tint, gulbrandsen_edge, openpbr_roughness, standard_roughness  # noqa: E402
from cnlmc.material import Material  # noqa: E402

from .conftest import FAST, all_sources, ir_of, synthetic_ir  # noqa: E402

METALS = Path("/work/shared/data/metals_rgb.json")


@pytest.fixture(scope="module")
def glsl():
    gen = mxg.GlslShaderGenerator.create()
    ctx = mxs.GenContext(gen)
    ctx.registerSourceCodeSearchPath(mx.getDefaultDataSearchPath())
    return gen, ctx


def load(xml: str, library):
    doc = mx.createDocument()
    mx.readFromXmlString(doc, xml)
    doc.setDataLibrary(library)
    return doc


def graph_nodes(doc, category=""):
    """Every node of the document's node graphs (the map nodes live there; the document's own
    top level holds only shaders and materials)."""
    graphs = [c for c in doc.getChildren() if c.getCategory() == "nodegraph"]  # not the data library's
    return [n for g in graphs for n in (g.getNodes(category) if category else g.getNodes())]


def graph_node(doc, name):
    found = [n for n in graph_nodes(doc) if n.getName() == name]
    return found[0] if found else None


def source_node_name(shader_input):
    """The node behind a shader input: through the graph output it connects to."""
    output = shader_input.getConnectedOutput()
    return output.getNodeName() if output is not None else shader_input.getNodeName()


def check_document(ir, options, library, glsl):
    result = emit(ir, "materialx", {**FAST, **options})
    mtlx = result.artifacts[0]
    assert mtlx.name == "materials.mtlx"
    doc = load(mtlx.content, library)
    ok, message = doc.validate()
    assert ok, message
    gen, ctx = glsl
    elements = mxs.findRenderableElements(doc)
    assert len(elements) == len(ir["materials"])
    for element in elements:
        shader = gen.generate(mx.createValidName(element.getNamePath()), element, ctx)
        assert "void main" in shader.getSourceCode(mxs.PIXEL_STAGE)
    files = {a.name for a in result.artifacts[1:]}
    referenced = {i.getValueString() for n in graph_nodes(doc, "image") for i in n.getInputs() if i.getName() == "file"}
    assert referenced == files
    loose = {n.getCategory() for n in doc.getNodes()} - {"surfacematerial", "open_pbr_surface", "standard_surface"}
    assert not loose, f"nodes outside node graphs: {loose}"  # MaterialX's baker needs them in graphs
    return doc, result


@pytest.mark.parametrize("surface", ["open_pbr_surface", "standard_surface"])
@pytest.mark.parametrize("source", all_sources())
def test_validates_and_generates_glsl(source, surface, mx_library, glsl):
    ir = ir_of(source)
    doc, _ = check_document(ir, {"surface": surface}, mx_library, glsl)
    for material in ir["materials"]:
        node = doc.getChild(f"M_{material['name']}")
        assert node.getDocString() == material["phrase"]


@pytest.mark.parametrize("surface", ["open_pbr_surface", "standard_surface"])
def test_synthetic_models(surface, mx_library, glsl):
    doc, result = check_document(synthetic_ir(), {"surface": surface}, mx_library, glsl)
    features = {n.feature for n in result.notes}
    assert {"coat", "coat.color", "distribution.ward"} <= features
    if surface == "open_pbr_surface":  # rotated streaks: a rotated tangent feeds geometry_tangent
        shader = doc.getChild("SR_aniso_plastic")
        assert source_node_name(shader.getInput("geometry_tangent")) == "aniso_plastic_tangent_rotated"


def test_baked_maps_have_colour_spaces(mx_library, glsl):
    doc, result = check_document(ir_of("white varnished oak"), {}, mx_library, glsl)
    colour = graph_node(doc, "white_varnished_oak_base_color_image")
    if colour is None:
        pytest.skip("the wood graph cannot be baked here")
    assert colour.getInput("file").getColorSpace() == "srgb_texture"
    data = graph_node(doc, "white_varnished_oak_roughness_image")
    assert data.getType() == "float" and not data.getInput("file").getColorSpace()
    assert doc.getColorSpace() == "lin_rec709"
    exr = emit(ir_of("white varnished oak"), "materialx", {**FAST, "map_format": "exr-half"}).artifacts[0]
    exr_doc = load(exr.content, mx_library)
    assert graph_node(exr_doc, "white_varnished_oak_base_color_image").getInput("file").getColorSpace() == "lin_rec709"


def test_maps_none_drops_with_a_note():
    result = emit(ir_of("white varnished oak"), "materialx", {"maps": "none"})
    assert len(result.artifacts) == 1
    assert {(n.feature, n.policy) for n in result.notes} >= {("maps.base_color", "drop")}


def test_unknown_option_is_an_error():
    with pytest.raises(ValueError, match="surface"):
        emit(ir_of("polished gold"), "materialx", {"surface": "lambert"})
    with pytest.raises(ValueError, match="unknown option"):
        emit(ir_of("polished gold"), "materialx", {"colour": "red"})


@pytest.mark.skipif(not METALS.exists(), reason="shared metals dataset not present")
def test_conductor_colours_match_the_dataset():
    """f82 / schlick(f0, 1/7) reproduces the dataset's F82_tint_openpbr, and the inverse
    Gulbrandsen edge colour its gulbrandsen_edge_tint_from_fit."""
    metals = {m["name"]: m["primary"] for m in json.loads(METALS.read_text())["metals"]}
    for name in ("silver", "gold", "copper", "aluminum", "iron"):
        ref = metals.get(name) or metals.get("aluminium")
        params = Material.from_ir(ir_of(f"{name}")["materials"][0]).params
        expected = ref["F82_tint_openpbr"]
        if max(ref["F0_srgb_linear"]) > 1.0:  # gold: the lexicon's f0 is its fitted eta/k's (#15), not 1.0376
            f0 = [((n - 1) ** 2 + k**2) / ((n + 1) ** 2 + k**2) for n, k in zip(ref["eta_rgb_fit"], ref["k_rgb_fit"])]
            expected = [b / (a + (1 - a) * (6 / 7) ** 5) for a, b in zip(f0, ref["F82_srgb_linear"])]
        assert f82_tint(params) == pytest.approx([min(v, 1.0) for v in expected], abs=0.02)
        assert gulbrandsen_edge(params) == pytest.approx(ref["gulbrandsen_edge_tint_from_fit"], abs=0.05)


@pytest.mark.parametrize("ax, ay", [(0.1125, 0.072), (0.3, 0.3), (0.5, 0.05), (0.01, 0.002)])
def test_anisotropy_fits_give_back_the_widths(ax, ay):
    r, a = openpbr_roughness(ax, ay)
    at = r * r * math.sqrt(2.0 / (1.0 + (1.0 - a) ** 2))
    assert (at, (1 - a) * at) == pytest.approx((ax, ay), rel=1e-9)
    r, a = standard_roughness(ax, ay)
    assert (r * r / math.sqrt(1 - a), r * r * math.sqrt(1 - a)) == pytest.approx((ax, ay), rel=1e-9)


# ---------------------------------------------------------------- names as written (#13)

UNICODE = "名前 ünïcødé 🔥 Ω"


def test_a_unicode_name_keeps_its_display_name(tmp_path, mx_library):
    from tests.helpers import run_cnlmc

    source = tmp_path / "u.cnl"
    source.write_text(f"{UNICODE}: red plastic\n")
    ir = json.loads(run_cnlmc("compile", str(source)).stdout)
    (material,) = ir["materials"]
    assert material["name"] == "unicode" and material["label"] == UNICODE  # accents folded, the rest kept aside
    done = run_cnlmc("compile", str(source), "-t", "materialx")
    assert done.returncode == 0, done.stderr
    doc = load(done.stdout, mx_library)
    assert doc.validate()[0]
    node = doc.getNode("M_unicode")
    assert node is not None and node.getAttribute("uiname") == UNICODE


def test_names_with_nothing_ascii_left_do_not_collide(tmp_path, mx_library):
    from tests.helpers import run_cnlmc

    source = tmp_path / "cjk.cnl"
    source.write_text('名前: red plastic\n前名: blue plastic\nɸ<&">: gold\n')
    ir = json.loads(run_cnlmc("compile", str(source)).stdout)
    names = [m["name"] for m in ir["materials"]]
    assert len(set(names)) == 3 and all(n.startswith("m_") and n.isascii() for n in names), names
    assert [m["label"] for m in ir["materials"]] == ["名前", "前名", 'ɸ < & " >']
    done = run_cnlmc("compile", str(source), "-t", "materialx")
    assert done.returncode == 0, done.stderr
    doc = load(done.stdout, mx_library)
    assert doc.validate()[0]
    assert sorted(n.getAttribute("uiname") for n in doc.getMaterialNodes()) == sorted(["名前", "前名", 'ɸ < & " >'])
