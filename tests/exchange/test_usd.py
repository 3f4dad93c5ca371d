"""USD: every stdlib noun and phrase passes UsdValidation (bar the documented sdrRegistry error
for ND_* ids), reopens with the same values; variants, binary formats and the pipeline API."""

from __future__ import annotations

import zipfile

import pytest

from tests.helpers import require

pxr = require("pxr", "usd")
pytestmark = pytest.mark.usd
from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade, UsdValidation  # noqa: E402

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.exchange import usd as backend  # noqa: E402
from cnlmc.backends.exchange.surface_inputs import surface_inputs  # noqa: E402
from cnlmc.backends.exchange.usd_stage import author_material  # noqa: E402
from cnlmc.material import Material  # noqa: E402

from .conftest import FAST, all_sources, ir_of, synthetic_ir, write_artifacts  # noqa: E402


@pytest.fixture(scope="module")
def validators():
    return UsdValidation.ValidationContext(UsdValidation.ValidationRegistry().GetOrLoadAllValidators())


def problems(stage, validators) -> list[str]:
    """Every error and warning of every UsdValidation validator usd-core ships (the compliance
    checker's rules: usd-core 26 has no UsdUtils.ComplianceChecker)."""
    return [f"{e.GetName()}: {e.GetMessage()}" for e in validators.Validate(stage)]


def select_network(stage, network: str) -> None:
    for prim in stage.GetDefaultPrim().GetChild("Looks").GetChildren():
        prim.GetVariantSets().GetVariantSet(backend.NETWORK_SET).SetVariantSelection(network)


def unexpected_errors(stage, validators) -> list[str]:
    """The stage as written (network=preview) has no error and no warning at all on usd-core;
    with the MaterialX network selected the only errors are its ND_* ids, which need usdMtlx."""
    assert problems(stage, validators) == []
    select_network(stage, "materialx")
    errors = [e for e in validators.Validate(stage) if e.GetType() == UsdValidation.ValidationErrorType.Error]
    return [
        e.GetMessage() for e in errors if not (e.GetName() == "MissingShaderIdInRegistry" and "'ND_" in e.GetMessage())
    ]


def close(a, b) -> bool:
    return all(abs(x - y) < 1e-5 for x, y in zip(a, b)) if hasattr(a, "__len__") else abs(a - b) < 1e-5


def prim_names(ir) -> list[str]:
    """Each IR material's Material prim (one per "or" group, named as the backend names groups)."""
    groups = backend.groups_of([Material.from_ir(m) for m in ir["materials"]])
    names = [""] * len(ir["materials"])
    for name, indices in groups:
        for i in indices:
            names[i] = name
    return names


def check_values(stage, ir, surface="open_pbr_surface"):
    """Each material's PreviewSurface and OpenPBR inputs read back as the backend computed them."""
    looks = stage.GetDefaultPrim().GetChild("Looks")
    select_network(stage, "materialx")
    for material, name in zip(ir["materials"], prim_names(ir)):
        prim = looks.GetChild(name)
        if material.get("variant"):
            prim.GetVariantSets().GetVariantSet(backend.VARIANT_SET).SetVariantSelection(material["variant"]["name"])
        preview = UsdShade.Shader(prim.GetChild("PreviewSurface"))
        for name, (_, value) in backend.preview_inputs(Material.from_ir(material)).items():
            if not preview.GetInput(name).HasConnectedSource():
                assert close(preview.GetInput(name).Get(), value), (material["name"], name)
        mat = UsdShade.Material(prim)
        source = mat.GetSurfaceOutput("mtlx").GetConnectedSources()[0][0].source
        for name, (_, value) in surface_inputs(Material.from_ir(material), surface).items():
            usd_input = UsdShade.Shader(source.GetPrim()).GetInput(name)
            if not usd_input.HasConnectedSource():
                assert close(usd_input.Get(), value), (material["name"], name)


@pytest.mark.parametrize("source", all_sources())
def test_validates_and_reopens(source, tmp_path, validators):
    ir = ir_of(source)
    result = emit(ir, "usd", {**FAST, "mesh": "sphere"})
    write_artifacts(result.artifacts, tmp_path)
    stage = Usd.Stage.Open(str(tmp_path / "materials.usda"))
    assert unexpected_errors(stage, validators) == []
    check_values(stage, ir)
    spheres = stage.GetDefaultPrim().GetChild("Preview").GetChildren()
    assert len(spheres) == len(set(prim_names(ir)))
    for sphere in spheres:
        bound, _ = UsdShade.MaterialBindingAPI(sphere).ComputeBoundMaterial()
        assert bound and bound.GetPrim().GetParent().GetName() == "Looks"


def test_synthetic_and_standard_surface(tmp_path, validators):
    ir = synthetic_ir()
    result = emit(ir, "usd", {**FAST, "surface": "standard_surface"})
    write_artifacts(result.artifacts, tmp_path)
    stage = Usd.Stage.Open(str(tmp_path / "materials.usda"))
    assert unexpected_errors(stage, validators) == []
    check_values(stage, ir, "standard_surface")
    assert {"anisotropic", "coat.color"} <= {n.feature for n in result.notes if n.policy == "drop"}


def test_or_phrase_is_one_prim_with_variants():
    ir = ir_of("blue or red or green plastic")
    stage = Usd.Stage.Open(Sdf.Layer.CreateAnonymous(".usda"))
    stage.GetRootLayer().ImportFromString(emit(ir, "usd", {}).artifacts[0].content)
    (prim,) = stage.GetDefaultPrim().GetChild("Looks").GetChildren()
    vset = prim.GetVariantSets().GetVariantSet(backend.VARIANT_SET)
    assert vset.GetVariantNames() == ["blue", "green", "red"]
    colours = {}
    for name in vset.GetVariantNames():
        vset.SetVariantSelection(name)
        colours[name] = tuple(UsdShade.Shader(prim.GetChild("PreviewSurface")).GetInput("diffuseColor").Get())
    assert len(set(colours.values())) == 3 and colours["red"][0] > colours["red"][2]


@pytest.mark.parametrize("how", [{"format": "usdc"}, {"output": "out/hull.usdc"}])
def test_usdc_is_bytes_and_opens(how, tmp_path):
    ir = ir_of("polished gold")
    (artifact,) = emit(ir, "usd", how).artifacts
    assert artifact.name == "materials.usdc" and isinstance(artifact.content, bytes)
    (tmp_path / artifact.name).write_bytes(artifact.content)
    stage = Usd.Stage.Open(str(tmp_path / artifact.name))
    check_values(stage, ir)


def test_usdz_packages_textures(tmp_path):
    ir = ir_of("white varnished oak")
    (artifact,) = emit(ir, "usd", {**FAST, "format": "usdz"}).artifacts
    (tmp_path / "m.usdz").write_bytes(artifact.content)
    names = zipfile.ZipFile(tmp_path / "m.usdz").namelist()
    assert names[0].endswith(".usdc")
    assert len(names) == 1 + len(ir["materials"][0]["maps"])
    assert Usd.Stage.Open(str(tmp_path / "m.usdz")).GetDefaultPrim()


def test_textures_go_through_uv_texture_and_string_varname(tmp_path):
    ir = ir_of("white varnished oak")
    if not ir["materials"][0]["maps"]:
        pytest.skip("the wood graph cannot be baked here")
    write_artifacts(emit(ir, "usd", FAST).artifacts, tmp_path)
    stage = Usd.Stage.Open(str(tmp_path / "materials.usda"))
    material = stage.GetDefaultPrim().GetChild("Looks").GetChildren()[0]
    reader = UsdShade.Shader(material.GetChild("PrimvarReader_st"))
    assert reader.GetInput("varname").GetTypeName() == Sdf.ValueTypeNames.String
    colour = UsdShade.Shader(material.GetChild("Texture_base_color"))
    assert colour.GetInput("sourceColorSpace").Get() == "sRGB"
    assert UsdShade.Shader(material.GetChild("Texture_roughness")).GetInput("sourceColorSpace").Get() == "raw"
    material.GetVariantSets().GetVariantSet(backend.NETWORK_SET).SetVariantSelection("materialx")
    image = material.GetChild("NG_white_varnished_oak").GetChild("white_varnished_oak_base_color_image")
    assert image.GetAttribute("inputs:file").GetColorSpace() == "srgb_texture"


def test_author_material_into_a_stage_with_binding(tmp_path):
    stage = Usd.Stage.CreateInMemory()
    hull = UsdGeom.Mesh.Define(stage, "/World/Hull")
    mat = author_material(stage, "/Looks/Hull", "lightly brushed, blue anodized aluminum", bind_to=["/World/Hull"])
    assert isinstance(mat, UsdShade.Material) and mat.GetPath() == Sdf.Path("/Looks/Hull")
    bound, _ = UsdShade.MaterialBindingAPI(hull.GetPrim()).ComputeBoundMaterial()
    assert bound.GetPath() == mat.GetPath()
    assert mat.GetPrim().GetCustomDataByKey("cnlmc:phrase") == "lightly brushed, blue anodized aluminum"
    preview = UsdShade.Shader(stage.GetPrimAtPath("/Looks/Hull/PreviewSurface"))
    assert preview.GetInput("metallic").Get() == 1.0
    assert not mat.GetPrim().HasAttribute("outputs:mtlx:surface")  # network=preview: valid on usd-core
    mat.GetPrim().GetVariantSets().GetVariantSet(backend.NETWORK_SET).SetVariantSelection("materialx")
    assert UsdShade.Material(stage.GetPrimAtPath("/Looks/Hull")).GetSurfaceOutput("mtlx").HasConnectedSource()
    glass = author_material(stage, "/Looks/Glass", "red or green glass", texture_dir=tmp_path)
    assert glass.GetPrim().GetVariantSets().GetVariantSet(backend.VARIANT_SET).GetVariantNames() == ["green", "red"]


def test_author_material_with_textures(tmp_path):
    stage = Usd.Stage.CreateNew(str(tmp_path / "shot.usda"))
    UsdGeom.Mesh.Define(stage, "/World/Table")
    author_material(
        stage,
        "/Looks/Table",
        "white varnished oak",
        bind_to=["/World/Table"],
        texture_dir=tmp_path / "tex",
        map_size=16,
    )
    stage.Save()
    files = sorted(p.name for p in (tmp_path / "tex").glob("*")) if (tmp_path / "tex").exists() else []
    if not files:
        pytest.skip("the wood graph cannot be baked here")
    texture = UsdShade.Shader(stage.GetPrimAtPath("/Looks/Table/Texture_base_color"))
    assert texture.GetInput("file").Get().path.startswith("./tex/")


def test_author_material_errors():
    stage = Usd.Stage.CreateInMemory()
    with pytest.raises(ValueError, match="error"):
        author_material(stage, "/Looks/X", "blue anodized unobtanium")
    with pytest.raises(ValueError, match="no prim"):
        author_material(stage, "/Looks/X", "polished gold", bind_to=["/World/Missing"])


def test_preview_is_gf():  # the diffuse preview has no specular lobe
    inputs = backend.preview_inputs(Material.from_ir(ir_of("deep red velvet")["materials"][0]))
    assert inputs["useSpecularWorkflow"][1] == 1 and inputs["specularColor"][1] == [0.0, 0.0, 0.0]
    assert Gf.Vec3f(*inputs["diffuseColor"][1])


# ---------------------------------------------------------------- authoring again (#13)


def preview_of(stage, path):
    return UsdShade.Shader(stage.GetPrimAtPath(f"{path}/PreviewSurface"))


def test_authoring_again_replaces_the_old_network(tmp_path):
    stage = Usd.Stage.CreateNew(str(tmp_path / "shot.usda"))
    author_material(stage, "/Looks/Hull", "steel with a clear coat")
    assert preview_of(stage, "/Looks/Hull").GetInput("clearcoat").Get() == 1.0
    author_material(stage, "/Looks/Hull", "red glass")
    stage.Save()
    reopened = Usd.Stage.Open(str(tmp_path / "shot.usda"))
    preview = preview_of(reopened, "/Looks/Hull")
    assert not preview.GetInput("clearcoat"), "the coat of the old phrase was kept"
    assert preview.GetInput("opacity").Get() == 0.0
    names = {child.GetName() for child in reopened.GetPrimAtPath("/Looks/Hull").GetChildren()}
    assert not any("steel" in name for name in names), names


def test_authoring_again_drops_the_old_variants(tmp_path):
    stage = Usd.Stage.CreateInMemory()
    author_material(stage, "/Looks/Coin", "copper or gold")
    assert stage.GetPrimAtPath("/Looks/Coin").GetVariantSets().HasVariantSet(backend.VARIANT_SET)
    author_material(stage, "/Looks/Coin", "red plastic")
    prim = stage.GetPrimAtPath("/Looks/Coin")
    assert not prim.GetVariantSets().HasVariantSet(backend.VARIANT_SET), "the copper variant still renders"
    assert close(
        preview_of(stage, "/Looks/Coin").GetInput("diffuseColor").Get(), (0.783538, 0.0, 0.0)
    )  # the survey's red #e50000


def test_texture_dir_is_relative_to_the_stage_and_asset_paths_are_relative(tmp_path, monkeypatch):
    shot = tmp_path / "shot"
    shot.mkdir()
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    stage = Usd.Stage.CreateNew(str(shot / "shot.usda"))
    author_material(stage, "/Looks/Table", "white varnished oak", texture_dir="tex", map_size=16)
    stage.Save()
    assert list(elsewhere.iterdir()) == [], "textures were written relative to the current folder"
    reopened = Usd.Stage.Open(str(shot / "shot.usda"))
    texture = UsdShade.Shader(reopened.GetPrimAtPath("/Looks/Table/Texture_base_color"))
    asset = texture.GetInput("file").Get()
    assert asset.path.startswith("./tex/") and not asset.path.startswith("./tex//")
    assert (shot / asset.path).is_file()
    assert (shot / "tex" / "shot.usda_Looks_Table" / "white_varnished_oak_base_color.png").is_file()


def test_authoring_again_removes_its_old_textures_only(tmp_path):
    stage = Usd.Stage.CreateNew(str(tmp_path / "shot.usda"))
    author_material(stage, "/Looks/Table", "white varnished oak", texture_dir="tex", map_size=16)
    author_material(stage, "/Looks/Chair", "walnut", texture_dir="tex", map_size=16)
    table = tmp_path / "tex" / "shot.usda_Looks_Table"
    chair = sorted(p.name for p in (tmp_path / "tex" / "shot.usda_Looks_Chair").iterdir())
    author_material(stage, "/Looks/Table", "heavily rusted iron", texture_dir="tex", map_size=16)
    names = sorted(p.name for p in table.iterdir() if not p.name.startswith("."))
    assert names and all(name.startswith("heavily_rusted_iron") for name in names)
    assert sorted(p.name for p in (tmp_path / "tex" / "shot.usda_Looks_Chair").iterdir()) == chair
    author_material(stage, "/Looks/Table", "red plastic", texture_dir="tex", map_size=16)
    assert not table.exists()


def test_a_unicode_name_is_the_prim_s_display_name(tmp_path):
    from tests.helpers import run_cnlmc

    source = tmp_path / "u.cnl"
    source.write_text("名前 ünïcødé 🔥 Ω: red plastic\n")
    out = tmp_path / "u.usda"
    done = run_cnlmc("compile", str(source), "-t", "usd", "-o", str(out))
    assert done.returncode == 0, done.stderr
    stage = Usd.Stage.Open(str(out))
    prim = stage.GetPrimAtPath("/Root/Looks/unicode")
    assert prim.IsValid() and prim.GetDisplayName() == "名前 ünïcødé 🔥 Ω"
