"""glTF: every stdlib noun and the coat / variant / textured / anisotropic phrases pass the Khronos
glTF-Validator (one node process for all files) with 0 errors and 0 warnings; the .glb reopened
with pygltflib gives back the IR's values within 1e-6; two runs give the same bytes; the preview
mesh is sized in metres with tangents; "or" phrases become KHR_materials_variants."""

from __future__ import annotations

import json
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import ROOT, require, run_cnlmc

require("pygltflib", "gltf")
require("OpenImageIO", "maps")
import pygltflib  # noqa: E402

from cnlmc.api import compile_source, emit  # noqa: E402

from .conftest import bakeable, nouns, synthetic_ir  # noqa: E402

VALIDATOR = ROOT / "tools" / "js" / "validate_gltf.js"
VALIDATOR_PACKAGE = ROOT / "tools" / "js" / "node_modules" / "gltf-validator"
FAST = {"map_size": "16"}
#: (file name, phrases, options): coats, variants, textured, anisotropic, on every mesh and both formats
CASES = [
    ("coats.glb", ["white varnished oak", "clear-coated red car paint", "steel with a red lacquer"], {}),
    ("variants.glb", ["red or green glass", "blue or red or green plastic"], {"mesh": "shader_ball"}),
    ("textured.glb", ["heavily rusted iron", "hammered copper", "white marble", "rough stone"], {"mesh": "teapot"}),
    ("anisotropic.glb", ["lightly brushed, blue anodized aluminum", "brushed steel", "brushed plastic"], {}),
    ("glass.glb", ["frosted glass", "tinted glass", "clear glass"], {"size": "0.35"}),
    ("textured.gltf", ["white varnished oak", "heavily rusted iron", "red or blue plastic"], {"mesh": "teapot"}),
    ("paint.glb", ["navy blue velvet", "weathered concrete", "mirror chrome", "polished gold"], {"mesh": "none"}),
    ("real_size.glb", ["hammered copper", "white varnished oak"], {"size": "0.2"}),
]


def compiled(phrases: list[str]) -> dict:
    result = compile_source("".join(f"{p}\n" for p in phrases))
    assert result.ok, [d.message for d in result.diagnostics]
    return bakeable(result.ir)


def write(result, folder: Path) -> Path:
    for artifact in result.artifacts:
        path = folder / artifact.name
        path.parent.mkdir(parents=True, exist_ok=True)
        content = artifact.content
        path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    return folder / result.artifacts[0].name


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> dict[str, tuple[dict, Path]]:
    """name -> (IR, main file): every stdlib noun in one .glb, and each case."""
    out: dict[str, tuple[dict, Path]] = {}
    source = "".join(f"n{i}: {noun}\n" for i, noun in enumerate(nouns()))
    result = compile_source(source)
    assert result.ok
    ir = bakeable(result.ir)
    folder = tmp_path_factory.mktemp("nouns")
    out["nouns.glb"] = ir, write(emit(ir, "gltf", {**FAST, "output": str(folder / "nouns.glb")}), folder)
    out["synthetic.glb"] = synthetic_ir(), write(emit(synthetic_ir(), "gltf", {**FAST, "output": "s.glb"}), folder)
    for name, phrases, options in CASES:
        ir = compiled(phrases)
        folder = tmp_path_factory.mktemp(Path(name).stem)
        out[name] = ir, write(emit(ir, "gltf", {**FAST, **options, "output": name}), folder)
    return out


def load(path: Path) -> dict:
    """The glTF JSON of a .glb or .gltf, read back through pygltflib."""
    document = pygltflib.GLTF2().load(str(path))
    assert document is not None, path
    return json.loads(document.to_json())


# ------------------------------------------------------------------------- validator


def test_khronos_validator_reports_no_error_and_no_warning(written):
    node = shutil.which("node")
    if node is None or not VALIDATOR_PACKAGE.exists():
        pytest.skip("node or gltf-validator missing: run scripts/setup.sh (npm ci in tools/js)")
    files = [str(path) for _, path in written.values()]
    run = subprocess.run([node, str(VALIDATOR), *files], capture_output=True, text=True, timeout=300, check=False)
    reports = json.loads(run.stdout)["reports"]
    assert len(reports) == len(files)
    for report in reports:
        bad = [m for m in report["messages"] if m["severity"] <= 1]
        assert (report["errors"], report["warnings"]) == (0, 0), (report["file"], bad[:5])
    assert run.returncode == 0, run.stderr


# ---------------------------------------------------------------------- IR values back


def expected_base_colour(material: dict) -> list[float]:
    params = material["params"]
    colour = params["base_color"]
    if material["model"]["base"] == "glass":  # its colour is the volume's attenuation
        return [1.0, 1.0, 1.0, 1.0]
    if material["model"]["base"] == "conductor":
        colour = [f * t for f, t in zip(params["f0"], colour)]
    return [min(max(c, 0.0), 1.0) for c in colour] + [1.0]


def check_glass_volume(material: dict, volume: dict) -> None:
    """A glass's colour is the same Beer-Lambert attenuation in glTF: the colour white light turns
    into after attenuationDistance (metres) inside, as the IR's base_color after transmission_depth;
    a colourless or map-coloured glass keeps glTF's default (no attenuation)."""
    colour = [min(max(c, 0.0), 1.0) for c in material["params"]["base_color"]]
    if min(colour) >= 1.0 or "base_color" in material["maps"]:
        assert "attenuationColor" not in volume and "attenuationDistance" not in volume, material["name"]
        return
    darkest = [max(c, 1e-4) for c in colour]  # a viewer takes its log: clamped as Mitsuba's medium is
    assert np.allclose(volume["attenuationColor"], darkest, atol=1e-6, rtol=0), material["name"]
    assert volume["attenuationDistance"] == material["params"].get("transmission_depth", 0.05), material["name"]


def widths(gltf_material: dict) -> tuple[float, float]:
    """(alpha_t, alpha_b) as the glTF spec defines them from roughness and anisotropyStrength."""
    alpha = gltf_material["pbrMetallicRoughness"]["roughnessFactor"] ** 2
    strength = gltf_material.get("extensions", {}).get("KHR_materials_anisotropy", {}).get("anisotropyStrength", 0.0)
    return alpha + (1 - alpha) * strength**2, alpha


def check_material(material: dict, entry: dict) -> None:
    model, params, maps = material["model"], material["params"], material["maps"]
    exts = entry.get("extensions", {})
    pbr = entry["pbrMetallicRoughness"]
    name = material["name"]
    if "base_color" not in maps or model["base"] == "conductor":
        assert np.allclose(pbr["baseColorFactor"], expected_base_colour(material), atol=1e-6, rtol=0), name
    else:
        assert pbr["baseColorFactor"] == [1.0, 1.0, 1.0, 1.0] and "baseColorTexture" in pbr, name
    if "metallic" not in maps:
        assert pbr["metallicFactor"] == (1.0 if model["base"] == "conductor" else 0.0), name
    if params.get("sheen_color") is None:  # a fibre noun's sheen (velvet, cloth), as the IR has it
        assert "KHR_materials_sheen" not in exts, name
    else:
        sheen = exts["KHR_materials_sheen"]
        assert np.allclose(sheen["sheenColorFactor"], params["sheen_color"], atol=1e-6, rtol=0), name
        assert abs(sheen["sheenRoughnessFactor"] - params["sheen_roughness"]) <= 1e-6, name
    if model["base"] == "diffuse":
        assert exts["KHR_materials_specular"]["specularFactor"] == 0.0, name
        return
    if "roughness" not in maps:
        ax, ay = params["alpha"]
        assert np.allclose(widths(entry), (max(ax, ay), min(ax, ay)), atol=1e-6, rtol=0), name
    if model["base"] in ("dielectric", "glass"):
        assert abs(exts["KHR_materials_ior"]["ior"] - params.get("ior", 1.5)) <= 1e-6, name
    assert ("KHR_materials_transmission" in exts) == (model["base"] == "glass"), name
    if model["base"] == "glass":
        assert exts["KHR_materials_transmission"]["transmissionFactor"] == 1.0
        check_glass_volume(material, exts["KHR_materials_volume"])
    if model["anisotropic"]:
        rotation = exts["KHR_materials_anisotropy"]["anisotropyRotation"]
        assert abs(rotation - params.get("anisotropy_rotation", 0.0)) <= 1e-6, name
    if model["coat"]:
        coat = exts["KHR_materials_clearcoat"]
        assert coat["clearcoatFactor"] == 1.0
        assert abs(coat["clearcoatRoughnessFactor"] ** 2 - params["coat"]["alpha"][0]) <= 1e-6, name
    else:
        assert "KHR_materials_clearcoat" not in exts, name


@pytest.mark.parametrize("name", ["nouns.glb", "synthetic.glb", *[c[0] for c in CASES]])
def test_reopened_file_gives_back_the_ir_values(written, name):
    ir, path = written[name]
    document = load(path)
    assert len(document["materials"]) == len(ir["materials"])
    for material, entry in zip(ir["materials"], document["materials"]):
        assert entry["name"] == material["name"]
        check_material(material, entry)
    assert set(document.get("extensionsUsed", [])) <= {
        *(e for m in document["materials"] for e in m.get("extensions", {})),
        "KHR_materials_variants",
        "KHR_texture_transform",
    }


def test_anisotropic_and_coated_features_are_in_the_files(written):
    aniso = load(written["anisotropic.glb"][1])
    assert all("KHR_materials_anisotropy" in m["extensions"] for m in aniso["materials"])
    coats = load(written["coats.glb"][1])
    assert all("KHR_materials_clearcoat" in m["extensions"] for m in coats["materials"])
    glass = load(written["glass.glb"][1])
    assert all(m["extensions"]["KHR_materials_volume"]["thicknessFactor"] == 0.35 for m in glass["materials"])


# ---------------------------------------------------------------------- mesh and maps


def accessor_array(document: pygltflib.GLTF2, index: int) -> np.ndarray:
    accessor = document.accessors[index]
    view = document.bufferViews[accessor.bufferView]
    blob = document.binary_blob()
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[accessor.type]
    dtype = {5126: "<f4", 5123: "<u2", 5125: "<u4"}[accessor.componentType]
    data = np.frombuffer(blob, dtype, accessor.count * width, view.byteOffset + (accessor.byteOffset or 0))
    return data.reshape(accessor.count, width)


def test_preview_mesh_is_sized_in_metres_with_tangents_that_follow_the_normal_map(written):
    document = pygltflib.GLTF2().load(str(written["coats.glb"][1]))
    attributes = document.meshes[0].primitives[0].attributes
    positions = accessor_array(document, attributes.POSITION)
    assert np.allclose(positions.max(0) - positions.min(0), 0.1, atol=1e-4)  # the sphere's own size: 10 cm
    assert abs(positions[:, 1].min()) < 1e-6  # standing on the floor
    normals, tangents = accessor_array(document, attributes.NORMAL), accessor_array(document, attributes.TANGENT)
    assert set(np.unique(tangents[:, 3])) <= {-1.0, 1.0}
    equator = np.abs(normals[:, 1]) < 0.05
    bitangent = np.cross(normals[equator], tangents[equator, :3]) * tangents[equator, 3:]
    assert (bitangent[:, 1] > 0.9).all()  # up the sphere: the way the baked normal map's +Y points
    teapot = pygltflib.GLTF2().load(str(written["textured.glb"][1]))
    extent = accessor_array(teapot, teapot.meshes[0].primitives[0].attributes.POSITION)
    assert 0.25 < (extent.max(0) - extent.min(0)).max() < 0.28  # the teapot's own: 26 cm spout to handle


def test_maps_show_at_their_real_size(written):
    """At its own size a preview mesh's UVs are in the maps' texture unit: no transform. Twice the
    size (a 20 cm sphere), KHR_texture_transform repeats each map twice per UV unit."""
    for name in ("coats.glb", "textured.glb"):
        document = load(written[name][1])
        assert "KHR_texture_transform" not in document.get("extensionsUsed", [])
    document = load(written["real_size.glb"][1])
    copper, oak = document["materials"]
    slots = [copper["normalTexture"], oak["pbrMetallicRoughness"]["baseColorTexture"]]
    slots.append(oak["pbrMetallicRoughness"]["metallicRoughnessTexture"])
    assert all(slot["extensions"]["KHR_texture_transform"]["scale"] == [2.0, 2.0] for slot in slots)
    assert "KHR_texture_transform" in document["extensionsUsed"]


def test_maps_are_png_with_their_colour_spaces(written):
    document = load(written["textured.gltf"][1])
    folder = written["textured.gltf"][1].parent
    uris = [image["uri"] for image in document["images"]]
    assert uris and all(uri.endswith(".png") and (folder / uri).exists() for uri in uris)
    oak = next(m for m in document["materials"] if m["name"] == "white_varnished_oak")
    base = document["textures"][oak["pbrMetallicRoughness"]["baseColorTexture"]["index"]]
    assert document["images"][base["source"]]["uri"].endswith("_base_color.png")
    packed = document["textures"][oak["pbrMetallicRoughness"]["metallicRoughnessTexture"]["index"]]
    assert document["images"][packed["source"]]["uri"].endswith("_metallic_roughness.png")
    import OpenImageIO as oiio

    colour = oiio.ImageInput.open(str(folder / document["images"][base["source"]]["uri"]))
    data = oiio.ImageInput.open(str(folder / document["images"][packed["source"]]["uri"]))
    assert colour.spec().get_string_attribute("oiio:ColorSpace").lower().startswith("srgb")
    assert not data.spec().get_string_attribute("oiio:ColorSpace").lower().startswith("srgb")
    colour.close()
    data.close()


def test_or_phrases_become_material_variants(written):
    ir, path = written["variants.glb"]
    document = load(path)
    names = [v["name"] for v in document["extensions"]["KHR_materials_variants"]["variants"]]
    assert names == list(dict.fromkeys(m["variant"]["name"] for m in ir["materials"]))  # one 'red' switches both
    assert len(document["meshes"]) == 2  # one object per "or" group
    mappings = [
        p["extensions"]["KHR_materials_variants"]["mappings"] for m in document["meshes"] for p in m["primitives"]
    ]
    assert [m["name"] for m in document["meshes"]] == ["red or green glass", "blue or red or green plastic"]
    for group, first in zip(mappings, ("red_glass", "blue_plastic")):
        shown = {names[v]: document["materials"][m["material"]]["name"] for m in group for v in m["variants"]}
        expected = {m["variant"]["name"]: m["name"] for m in ir["materials"] if m["variant"]["group"] == first}
        assert shown == expected and len(shown) == len(group)


def test_capability_notes_for_what_gltf_cannot_express():
    result = emit(compiled(["steel with a red lacquer", "navy blue velvet"]), "gltf", FAST)
    noted = {(n.material, n.feature, n.policy) for n in result.notes}
    steel, velvet = (m["name"] for m in compiled(["steel with a red lacquer", "navy blue velvet"])["materials"])
    assert (steel, "coat.color", "drop") in noted
    assert (velvet, "diffuse.oren_nayar", "approximate") in noted


# ------------------------------------------------------------------- bytes and the CLI


def test_two_runs_give_the_same_bytes():
    ir = compiled(["heavily rusted iron", "red or green glass", "lightly brushed, blue anodized aluminum"])
    first = emit(ir, "gltf", FAST).artifacts[0].content
    assert first == emit(ir, "gltf", FAST).artifacts[0].content and first[:4] == b"glTF"


def test_readme_command_writes_one_phone_ready_glb(tmp_path):
    (tmp_path / "hull.cnl").write_text("hull: lightly brushed, blue anodized aluminum\n", "utf-8")
    run = run_cnlmc("compile", "hull.cnl", "--target", "gltf", "-o", "hull.glb", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hull.cnl", "hull.glb"]
    document = load(tmp_path / "hull.glb")
    assert document["materials"][0]["name"] == "hull" and document["images"]  # the normal map is inside


def test_bad_size_is_a_usage_error_that_says_what_to_do(tmp_path):
    run = run_cnlmc(
        "compile", "-", "-t", "gltf", "--option", "size=-1", "-o", str(tmp_path / "a.glb"), stdin="red plastic\n"
    )
    assert run.returncode == 2 and "size" in run.stderr and "Traceback" not in run.stderr
    assert not any(tmp_path.iterdir())


def test_anisotropy_inversion_is_exact():
    from cnlmc.backends.exchange.gltf_material import anisotropy_of

    for ax, ay in [(0.3, 0.1), (0.09, 0.02), (1.0, 0.5), (0.2, 0.2), (1e-4, 1e-5)]:
        rough, strength = anisotropy_of(ax, ay)
        alpha = rough * rough
        assert math.isclose(alpha + (1 - alpha) * strength**2, ax, abs_tol=1e-12) and math.isclose(alpha, ay)
