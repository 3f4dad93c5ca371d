"""USDZ for AR Quick Look: every package the target writes (every stdlib noun, coats, variants,
textured, anisotropic, glass, on every preview mesh) passes the usdz and ARKit rules of OpenUSD's
compliance checker (restated in cnlmc.backends.exchange.arkit_rules, since usd-core ships none);
the rules catch each kind of fault; two runs give the same bytes; the object is sized in metres."""

from __future__ import annotations

import io
import tempfile
import zipfile
from pathlib import Path

import pytest

from tests.helpers import require, run_cnlmc

require("pxr", "usd")
require("OpenImageIO", "maps")
pytestmark = pytest.mark.usd
from pxr import Sdf, Usd, UsdGeom, UsdShade  # noqa: E402

from cnlmc.api import compile_source, emit  # noqa: E402
from cnlmc.backends.exchange import usd  # noqa: E402
from cnlmc.backends.exchange.arkit_rules import check, check_package  # noqa: E402
from cnlmc.backends.exchange.usdz import package as usdz_bytes  # noqa: E402
from cnlmc.material import Material  # noqa: E402

from .conftest import bakeable, nouns, synthetic_ir  # noqa: E402

FAST = {"map_size": "16"}
CASES = [
    ("coats", ["white varnished oak", "clear-coated red car paint", "steel with a red lacquer"], {}),
    ("variants", ["red or green glass", "blue or red or green plastic"], {"mesh": "shader_ball"}),
    ("textured", ["heavily rusted iron", "hammered copper", "white marble", "rough stone"], {"mesh": "teapot"}),
    ("anisotropic", ["lightly brushed, blue anodized aluminum", "brushed steel", "brushed plastic"], {}),
    ("glass", ["frosted glass", "tinted glass", "clear glass"], {"size": "0.5"}),
    ("real_size", ["hammered copper", "white varnished oak"], {"size": "0.2"}),
]


def compiled(phrases: list[str]) -> dict:
    result = compile_source("".join(f"{p}\n" for p in phrases))
    assert result.ok, [d.message for d in result.diagnostics]
    return bakeable(result.ir)


def package(ir: dict, folder: Path, name: str, **options: str) -> Path:
    (artifact,) = emit(ir, "usdz", {**FAST, **options}).artifacts
    path = folder / f"{name}.usdz"
    path.write_bytes(artifact.content)
    return path


@pytest.fixture(scope="module")
def packages(tmp_path_factory) -> dict[str, tuple[dict, Path]]:
    folder = tmp_path_factory.mktemp("usdz")
    source = "".join(f"n{i}: {noun}\n" for i, noun in enumerate(nouns()))
    result = compile_source(source)
    assert result.ok
    out = {"nouns": (bakeable(result.ir), None), "synthetic": (synthetic_ir(), None)}
    out.update({name: (compiled(phrases), options) for name, phrases, options in CASES})
    return {name: (ir, package(ir, folder, name, **(options or {}))) for name, (ir, options) in out.items()}


@pytest.mark.parametrize("name", ["nouns", "synthetic", *[c[0] for c in CASES]])
def test_every_package_passes_the_arkit_rules(packages, name):
    assert check_package(packages[name][1]) == []


@pytest.mark.parametrize("name", ["nouns", "textured", "variants"])
def test_preview_surface_values_read_back(packages, name):
    ir, path = packages[name]
    stage = Usd.Stage.Open(str(path))
    looks = stage.GetDefaultPrim().GetChild("Looks")
    by_group: dict[str, list[dict]] = {}
    for material in ir["materials"]:
        by_group.setdefault((material.get("variant") or {}).get("group") or material["name"], []).append(material)
    assert len(looks.GetChildren()) == len(by_group)
    for prim, materials in zip(looks.GetChildren(), by_group.values()):
        for material in materials:
            if material.get("variant"):
                variant_set = prim.GetVariantSets().GetVariantSet("material")
                variant_set.SetVariantSelection(material["variant"]["name"])
            surface = UsdShade.Shader(prim.GetChild("PreviewSurface"))
            for key, (_, value) in usd.preview_inputs(Material.from_ir(material)).items():
                if not surface.GetInput(key).HasConnectedSource():
                    got = surface.GetInput(key).Get()
                    assert (
                        list(got) == pytest.approx(value, abs=1e-6)
                        if hasattr(got, "__len__")
                        else got == pytest.approx(value, abs=1e-6)
                    ), (material["name"], key)
    shader_ids = {UsdShade.Shader(p).GetShaderId() for p in stage.Traverse() if p.IsA(UsdShade.Shader)}
    assert shader_ids <= {"UsdPreviewSurface", "UsdUVTexture", "UsdPrimvarReader_float2"}


def test_textures_are_png_inside_the_package_and_resolve(packages):
    path = packages["textured"][1]
    names = zipfile.ZipFile(path).namelist()
    assert names[0] == "materials.usdc" and len(names) > 1
    assert all(n.startswith("textures/") and n.endswith(".png") for n in names[1:])
    stage = Usd.Stage.Open(str(path))
    files = [UsdShade.Shader(p).GetInput("file").Get() for p in stage.Traverse() if p.GetName().startswith("Texture_")]
    assert files and all(f.resolvedPath and f.path.startswith("textures/") for f in files)


def test_object_is_sized_in_metres_and_stands_on_the_floor(packages):
    stage = Usd.Stage.Open(str(packages["coats"][1]))
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0 and UsdGeom.GetStageUpAxis(stage) == "Y"
    meshes = [UsdGeom.Mesh(p) for p in stage.Traverse() if p.IsA(UsdGeom.Mesh)]
    assert len(meshes) == 3
    for mesh in meshes:
        low, high = mesh.GetExtentAttr().Get()
        assert high[1] - low[1] == pytest.approx(0.1, abs=1e-4) and abs(low[1]) < 1e-6  # the sphere's own 10 cm
        bound, _ = UsdShade.MaterialBindingAPI(mesh.GetPrim()).ComputeBoundMaterial()
        assert bound.GetPath().GetParentPath().name == "Looks"
    glass = Usd.Stage.Open(str(packages["glass"][1]))
    low, high = next(UsdGeom.Mesh(p) for p in glass.Traverse() if p.IsA(UsdGeom.Mesh)).GetExtentAttr().Get()
    assert high[0] - low[0] == pytest.approx(0.5, abs=1e-4)


def test_maps_show_at_their_real_size(packages):
    """A 20 cm sphere (twice its own size) gets a UsdTransform2d scaling st by 2 before each texture;
    at its own size there is none."""
    stage = Usd.Stage.Open(str(packages["real_size"][1]))
    textures = [UsdShade.Shader(p) for p in stage.Traverse() if p.GetName().startswith("Texture_")]
    assert len(textures) == 3
    for texture in textures:
        transform = UsdShade.Shader(texture.GetInput("st").GetConnectedSources()[0][0].source.GetPrim())
        assert transform.GetShaderId() == "UsdTransform2d" and tuple(transform.GetInput("scale").Get()) == (2, 2)
    plain = Usd.Stage.Open(str(packages["textured"][1]))
    assert not [p for p in plain.Traverse() if p.GetName().startswith("Transform_")]


def test_or_phrase_is_one_object_named_for_the_phrase_with_a_variant_each(packages):
    stage = Usd.Stage.Open(str(packages["variants"][1]))
    glass = stage.GetPrimAtPath("/Root/Looks/red_or_green_glass")
    variant_set = glass.GetVariantSets().GetVariantSet("material")
    assert variant_set.GetVariantNames() == ["green", "red"] and variant_set.GetVariantSelection() == "red"
    colours = {}
    for name in ("red", "green"):
        variant_set.SetVariantSelection(name)
        colours[name] = tuple(UsdShade.Shader(glass.GetChild("PreviewSurface")).GetInput("diffuseColor").Get())
    assert colours["red"][0] > colours["red"][1] and colours["green"][1] > colours["green"][0]


def test_two_runs_give_the_same_bytes():
    ir = compiled(["heavily rusted iron", "red or green glass", "white varnished oak"])
    first = emit(ir, "usdz", FAST).artifacts[0].content
    assert emit(ir, "usdz", FAST).artifacts[0].content == first


def test_readme_command(tmp_path):
    (tmp_path / "hull.cnl").write_text("hull: lightly brushed, blue anodized aluminum\n", "utf-8")
    run = run_cnlmc("compile", "hull.cnl", "--target", "usdz", "-o", "hull.usdz", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hull.cnl", "hull.usdz"]
    assert check_package(tmp_path / "hull.usdz") == []


# ------------------------------------------------------------- the rules catch faults


def test_rules_reject_the_materialx_network_of_the_usd_target(tmp_path):
    (artifact,) = emit(compiled(["polished gold"]), "usd", {**FAST, "format": "usdz", "mesh": "sphere"}).artifacts
    (tmp_path / "full.usdz").write_bytes(artifact.content)
    failures = check_package(tmp_path / "full.usdz")
    assert any("ND_" in f and "ARKit does not read" in f for f in failures), failures


def layer_text(texture: str = "t.png", colour_space: str = "raw", up: str = "Y") -> bytes:
    """A small stage: a Mesh bound to a Material whose UsdPreviewSurface reads a normal map."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, up)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    root = UsdGeom.Xform.Define(stage, "/Root")
    stage.SetDefaultPrim(root.GetPrim())
    material = UsdShade.Material.Define(stage, "/Root/M")
    surface = UsdShade.Shader.Define(stage, "/Root/M/S")
    surface.CreateIdAttr("UsdPreviewSurface")
    material.CreateSurfaceOutput().ConnectToSource(surface.CreateOutput("surface", Sdf.ValueTypeNames.Token))
    tex = UsdShade.Shader.Define(stage, "/Root/M/T")
    tex.CreateIdAttr("UsdUVTexture")
    tex.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
    tex.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set(colour_space)
    tex.CreateInput("scale", Sdf.ValueTypeNames.Float4).Set((2, 2, 2, 1))
    tex.CreateInput("bias", Sdf.ValueTypeNames.Float4).Set((-1, -1, -1, 0))
    normal = surface.CreateInput("normal", Sdf.ValueTypeNames.Normal3f)
    normal.ConnectToSource(tex.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
    mesh = UsdGeom.Mesh.Define(stage, "/Root/Mesh")
    UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material)
    with tempfile.TemporaryDirectory() as tmp:
        layer = Path(tmp) / "a.usdc"
        stage.GetRootLayer().Export(str(layer))
        return layer.read_bytes()


#: a 1x1 RGB PNG (the rules read a texture's name, not its pixels)
PNG = bytes.fromhex(
    "89504e470d0a1a0a0000000d4948445200000001000000010802000000907753de0000000c4944415408d763f8ffff3f0005fe02fea7d6a4f20000000049454e44ae426082"
)


@pytest.mark.parametrize(
    "fault, files, expected",
    [
        ("good", lambda: [("a.usdc", layer_text()), ("t.png", PNG)], None),
        ("exr texture", lambda: [("a.usdc", layer_text("t.exr")), ("t.exr", b"v/1\x01")], "not PNG or JPEG"),
        ("srgb normal map", lambda: [("a.usdc", layer_text(colour_space="sRGB")), ("t.png", PNG)], "raw"),
        ("z up", lambda: [("a.usdc", layer_text(up="Z")), ("t.png", PNG)], "upAxis"),
        ("missing texture", lambda: [("a.usdc", layer_text("gone.png"))], "gone.png"),
        ("image first", lambda: [("t.png", PNG), ("a.usdc", layer_text())], "not a .usdc layer"),
        ("text file", lambda: [("a.usdc", layer_text()), ("t.png", PNG), ("notes.txt", b"hi")], "extension"),
    ],
)
def test_rules_catch_each_fault(tmp_path, fault, files, expected):
    path = tmp_path / "p.usdz"
    path.write_bytes(usdz_bytes(files()))
    failures = check_package(path)
    if expected is None:
        assert failures == [], failures
    else:
        assert any(expected in f for f in failures), (fault, failures)


def test_rules_catch_compression_and_misalignment(tmp_path):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("a.usdc", layer_text())
        archive.writestr("t.png", PNG)
    (tmp_path / "z.usdz").write_bytes(buffer.getvalue())
    failures = check_package(tmp_path / "z.usdz")
    assert any("compressed" in f for f in failures) and any("multiple of 64" in f for f in failures), failures


def test_base_rules_alone_check_a_usda_as_usdchecker_does_without_arkit(tmp_path):
    stage = Usd.Stage.Open(Sdf.Layer.OpenAsAnonymous(str(write_layer(tmp_path, layer_text(up="Z")))))
    stage.GetRootLayer().Export(str(tmp_path / "shot.usda"))
    (tmp_path / "t.png").write_bytes(PNG)
    assert check(tmp_path / "shot.usda", arkit=False) == []  # Z up and a usda root are fine outside ARKit
    arkit = check(tmp_path / "shot.usda", arkit=True)
    assert any("upAxis" in f for f in arkit) and any("not a .usdc" in f for f in arkit), arkit


def write_layer(folder: Path, data: bytes) -> Path:
    path = folder / "layer.usdc"
    path.write_bytes(data)
    return path
