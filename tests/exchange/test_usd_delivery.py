"""USD a pipeline can trust (#16): every format passes all of usd-core's validators as written
(the MaterialX network waits in the `network` variant `materialx` for a USD build with usdMtlx),
usdz packages are byte-identical between runs and keep the layer's texture paths, preview spheres
have a real-world size, a variant group's prim is named for its phrase, and maps=native reaches
the MaterialX network."""

from __future__ import annotations

import zipfile

import pytest

from tests.helpers import require, run_cnlmc

pxr = require("pxr", "usd")
pytestmark = pytest.mark.usd
from pxr import Sdf, Usd, UsdGeom, UsdShade, UsdValidation  # noqa: E402

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.exchange import usd as backend  # noqa: E402

from .conftest import FAST, ir_of, write_artifacts  # noqa: E402

TEXTURED = "heavily rusted iron\nwhite varnished oak\nred or green glass\n"


@pytest.fixture(scope="module")
def validators():
    return UsdValidation.ValidationContext(UsdValidation.ValidationRegistry().GetOrLoadAllValidators())


def problems(stage, validators) -> list[str]:
    return [f"{e.GetName()}: {e.GetMessage()}" for e in validators.Validate(stage)]


def compile_usd(tmp_path, name: str, *options: str, source: str = TEXTURED):
    """Compile through the API as the CLI does (-o tmp_path/name); returns the main file's path."""
    ir = {**ir_of(source.splitlines()[0])}
    ir["materials"] = [m for line in source.splitlines() for m in ir_of(line)["materials"]]
    pairs = dict(option.split("=", 1) for option in options)
    result = emit(ir, "usd", {**FAST, "output": str(tmp_path / name), **pairs})
    tmp_path.mkdir(parents=True, exist_ok=True)
    main, *rest = result.artifacts
    write_artifacts(rest, tmp_path)
    out = tmp_path / name
    out.write_bytes(main.content if isinstance(main.content, bytes) else main.content.encode())
    return out


@pytest.mark.parametrize("name", ["hull.usda", "hull.usdc", "hull.usdz"])
def test_every_format_passes_every_usd_core_validator(name, tmp_path, validators, capfd):
    out = compile_usd(tmp_path, name, "mesh=sphere")
    assert "Warning" not in capfd.readouterr().err  # USD's own warnings (e.g. "Failed to resolve reference")
    stage = Usd.Stage.Open(str(out))
    assert problems(stage, validators) == []


def test_usdz_is_byte_identical_and_keeps_its_texture_paths(tmp_path, validators):
    first = compile_usd(tmp_path / "a", "hull.usdz")
    second = compile_usd(tmp_path / "b", "hull.usdz")
    assert first.read_bytes() == second.read_bytes()
    package = zipfile.ZipFile(first)
    names = package.namelist()
    assert names[0].endswith(".usdc") and len(names) > 1
    assert not any(n.startswith("0/") for n in names), names
    for info in package.infolist():
        assert info.compress_type == zipfile.ZIP_STORED and info.date_time == (1980, 1, 1, 0, 0, 0)
        data_start = info.header_offset + 30 + len(info.filename) + len(info.extra)
        assert data_start % 64 == 0, info.filename
    stage = Usd.Stage.Open(str(first))
    files = set()
    for prim in stage.Traverse():
        shader = UsdShade.Shader(prim)
        if shader and shader.GetIdAttr().Get() == "UsdUVTexture":
            files.add(shader.GetInput("file").Get().path)
    assert files and files <= set(names), (files, names)


def test_preview_spheres_have_a_real_world_size(tmp_path):
    out = compile_usd(tmp_path, "hull.usda", "mesh=sphere")
    stage = Usd.Stage.Open(str(out))
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    spheres = stage.GetDefaultPrim().GetChild("Preview").GetChildren()
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
    sizes = [cache.ComputeWorldBound(s).ComputeAlignedRange().GetSize() for s in spheres]
    assert len(sizes) == 3 and all(abs(size[0] - 0.10) < 1e-4 for size in sizes)  # 10 cm balls
    whole = cache.ComputeWorldBound(stage.GetDefaultPrim()).ComputeAlignedRange()
    assert whole.GetSize()[0] < 0.5 and whole.GetMin()[1] >= -1e-6  # side by side on the ground


def preview_colour(stage, prim, variant):
    prim.GetVariantSets().GetVariantSet(backend.VARIANT_SET).SetVariantSelection(variant)
    return tuple(UsdShade.Shader(prim.GetChild("PreviewSurface")).GetInput("diffuseColor").Get())


@pytest.mark.parametrize(
    "source, prim_name", [("red or green glass", "red_or_green_glass"), ("hull: red or green glass", "hull")]
)
def test_a_variant_group_is_named_for_what_it_holds(source, prim_name):
    stage = Usd.Stage.Open(Sdf.Layer.CreateAnonymous(".usda"))
    stage.GetRootLayer().ImportFromString(emit(ir_of(source), "usd", {}).artifacts[0].content)
    (prim,) = stage.GetDefaultPrim().GetChild("Looks").GetChildren()
    assert prim.GetName() == prim_name
    red, green = preview_colour(stage, prim, "red"), preview_colour(stage, prim, "green")
    assert red[0] > red[1] and green[1] > green[0]


def test_maps_native_reaches_the_materialx_network(tmp_path, validators):
    out = compile_usd(tmp_path, "stone.usda", "maps=native", source="polished white marble\n")
    stage = Usd.Stage.Open(str(out))
    assert problems(stage, validators) == []
    (prim,) = stage.GetDefaultPrim().GetChild("Looks").GetChildren()
    assert UsdShade.Shader(prim.GetChild("Texture_base_color"))  # the preview still reads a baked map
    prim.GetVariantSets().GetVariantSet(backend.NETWORK_SET).SetVariantSelection("materialx")
    ids = {UsdShade.Shader(p).GetIdAttr().Get() for p in Usd.PrimRange(prim) if p.IsA(UsdShade.Shader)}
    assert "ND_fractal2d_float" in ids and "ND_image_color3" not in ids, ids  # the colour is native
    errors = {e.GetName() for e in validators.Validate(stage)}
    assert errors <= {"MissingShaderIdInRegistry"}  # only the ND_* ids a USD without usdMtlx lacks


def test_a_usdz_from_the_command_line_says_nothing_but_what_it_wrote(tmp_path, validators):
    out = tmp_path / "hull.usdz"
    done = run_cnlmc("compile", "-", "-t", "usd", "--option", "map_size=16", "-o", str(out), stdin=TEXTURED)
    assert done.returncode == 0, done.stderr
    assert "Warning" not in done.stderr and "Failed to resolve" not in done.stderr, done.stderr
    assert problems(Usd.Stage.Open(str(out)), validators) == []


def test_the_network_option_selects_materialx(tmp_path):
    out = compile_usd(tmp_path, "gold.usda", "network=materialx", source="polished gold\n")
    stage = Usd.Stage.Open(str(out))
    (prim,) = stage.GetDefaultPrim().GetChild("Looks").GetChildren()
    assert UsdShade.Material(prim).GetSurfaceOutput("mtlx").HasConnectedSource()
