"""The view's Python side (cnlmc.studio.view_payload): what a compiled material's payload holds,
that its shader is valid GLSL ES 3.00 (glslangValidator), that maps go into the session folder
only, and the named assets (containers of the preview's own environment textures and meshes)."""

from __future__ import annotations

import base64
import json
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from cnlmc.api import compile_source
from tests.helpers import require

require("moderngl", "preview")
from cnlmc.backends.preview.subsurface import preintegrated_table  # noqa: E402
from cnlmc.backends.preview.web import pack, parse_alpha, unpack  # noqa: E402
from cnlmc.studio.view_payload import material_payload, static_asset  # noqa: E402

GLSLANG = shutil.which("glslangValidator")


def payload_of(phrase: str, files: Path) -> dict:
    return material_payload(compile_source(phrase + "\n").ir["materials"][0], files)


def test_a_payload_is_json_with_the_preview_shader_in_glsl_es(tmp_path: Path) -> None:
    payload = payload_of("blue plastic", tmp_path)
    assert json.loads(json.dumps(payload)) == payload
    assert payload["fragment"].startswith("#version 300 es\nprecision highp float;")
    assert "cnlm_bsdf" in payload["fragment"] and "pv_split" in payload["fragment"]
    uniforms = {u["name"]: u for u in payload["uniforms"]}
    assert uniforms["cnlm_base_color"]["value"][2] > uniforms["cnlm_base_color"]["value"][0]
    table = payload["tables"]["pv_black_albedo"]
    assert (table["width"], table["height"]) == (96, 1)  # 3 sections of 32 columns, one row (uniform alpha)
    assert set(payload["prefilter"]) == {"pv_env_material"} and not payload["maps"]
    assert list(tmp_path.iterdir()) == []


def test_a_colour_change_keeps_the_shader_source(tmp_path: Path) -> None:
    """Values are uniforms and comments are stripped: the browser compiles a program once."""
    blue, red = payload_of("blue plastic", tmp_path), payload_of("red plastic", tmp_path)
    assert blue["fragment"] == red["fragment"]
    assert blue["uniforms"] != red["uniforms"]


@pytest.mark.skipif(GLSLANG is None, reason="glslangValidator is not installed (scripts/setup.sh)")
@pytest.mark.parametrize(
    "phrase",
    ["lightly brushed, blue anodized aluminum", "clear glass", "velvet", "oak", "wax", "marble", "metallic car paint"],
)
def test_every_kind_of_shader_compiles_as_glsl_es(tmp_path: Path, phrase: str) -> None:
    payload = payload_of(phrase, tmp_path)
    for stage, source in (("frag", payload["fragment"]), ("vert", payload["vertex"])):
        path = tmp_path / f"shader.{stage}"
        path.write_text(source)
        done = subprocess.run([GLSLANG, "-S", stage, str(path)], capture_output=True, text=True, check=False)
        assert done.returncode == 0, done.stdout[-2000:]


def test_a_translucent_body_is_drawn_as_the_preview_draws_it(tmp_path: Path) -> None:
    """The boundary with a black base under cnlm_bsdf, the body's light from the subsurface term
    (subsurface.boundary_material): its uniforms for a closed and an open mesh."""
    payload = payload_of("wax", tmp_path)
    uniforms = {u["name"]: u["value"] for u in payload["uniforms"]}
    assert uniforms["cnlm_base_color"] == [0.0, 0.0, 0.0]
    assert min(uniforms["cnlm_sss_albedo"]) > 0.3 and min(uniforms["cnlm_sss_mfp"]) > 0
    closed = {u["name"]: u["value"] for u in payload["mesh_uniforms"]["closed"]}
    opened = {u["name"]: u["value"] for u in payload["mesh_uniforms"]["open"]}
    assert set(opened) == set(closed) and (closed["cnlm_sss_closed"], opened["cnlm_sss_closed"]) == (1, 0)
    # the pre-integrated table is a texture (a 561-float uniform array passed WebGL2's 224 vectors)
    table = payload["tables"]["cnlm_sss_lut"]
    values = np.frombuffer(base64.b64decode(table["data"]), np.float32).reshape(table["height"], table["width"], 4)
    assert np.array_equal(values[..., 0], preintegrated_table().values)
    # a volume's base-colour map colours its body (marble's veins): bound, with the boundary still black
    marble = payload_of("marble", tmp_path)
    assert "cnlm_map_base_color" in marble["maps"] and "cnlm_sss_mapped_albedo(uv, p)" in marble["fragment"]
    assert {u["name"]: u["value"] for u in marble["uniforms"]}["cnlm_base_color"] == [0.0, 0.0, 0.0]
    flakes = payload_of("metallic car paint", tmp_path)["mesh_uniforms"]["closed"]
    assert {u["name"] for u in flakes} == {"pv_flake_area", "pv_light_solid_angle"}


#: the uniforms view.js (MaterialView.drawObject) sets itself: the environment, camera, key light, glass
VIEW_SETS = {
    "pv_env",
    "pv_env_prefiltered",
    "pv_env_irradiance",
    "pv_prefilter_levels",
    "pv_env_intensity",
    "pv_env_size",
    "pv_model",
    "pv_normal_matrix",
    "pv_view_projection",
    "pv_camera_position",
    "pv_key_direction",
    "pv_key_irradiance",
    "pv_glass_centre",
    "pv_glass_radius",
    "pv_glass_reference",
    "pv_glass_thin",
}


@pytest.mark.parametrize(
    "phrase", ["clear glass", "velvet", "wax", "marble", "metallic car paint", "oak", "clear-coated red car paint"]
)
def test_every_uniform_of_the_shader_is_given_a_value(tmp_path: Path, phrase: str) -> None:
    """A feature the preview adds (a new uniform its object pass sets) must reach the payload:
    otherwise the browser draws it with zeros."""
    payload = payload_of(phrase, tmp_path)
    declared = set(
        re.findall(
            r"^uniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+(\w+)", payload["fragment"] + payload["vertex"], re.M
        )
    )
    given = {u["name"] for u in payload["uniforms"]} | {u["name"] for u in payload["mesh_uniforms"]["closed"]}
    given |= set(payload["tables"]) | set(payload["prefilter"]) | set(payload["maps"]) | VIEW_SETS
    assert {"pv_key_irradiance", "pv_env_irradiance"} <= declared  # the declarations were found
    assert declared - given == set()


def test_textured_maps_go_into_the_session_folder_once(tmp_path: Path) -> None:
    payload = payload_of("oak", tmp_path)
    files = {m["file"] for m in payload["maps"].values()}
    assert files and {p.name for p in tmp_path.iterdir()} == files
    for m in payload["maps"].values():
        raw = np.frombuffer((tmp_path / m["file"]).read_bytes(), "<f2")
        data = raw.astype(np.float32).reshape(m["height"], m["width"], 4)
        assert np.isfinite(data).all() and data[..., :3].std() > 0.01  # a grain, not a constant
    stamps = {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    payload_of("oak", tmp_path)
    assert {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()} == stamps  # named by content: not rebaked


def test_assets_by_name() -> None:
    mesh, kind = static_asset("mesh/teapot")  # type: ignore[misc]
    assert kind == "application/octet-stream"
    header, arrays = unpack(mesh)
    assert arrays["vertices"].shape[1] == 11 and arrays["indices"].max() < len(arrays["vertices"])
    assert header["radius"] == pytest.approx(1.0, abs=1e-3) and header["lo"][1] == pytest.approx(0.0, abs=1e-6)
    shader = static_asset("shader/tonemap.frag")
    assert shader is not None and shader[0].startswith(b"#version 300 es")
    for unknown in ("mesh/cube", "env/moon", "env/studio@2", "env/studio@x", "shader/../gl.py", "tables/x", ""):
        assert static_asset(unknown) is None, unknown


def test_an_environment_is_the_preview_own_textures() -> None:
    found = static_asset("env/sky")
    assert found is not None
    header, arrays = unpack(found[0])
    assert (header["width"], header["height"]) == (512, 256)
    assert [arrays[f"level{k}"].shape[:2] for k in range(1, 6)] == [(128, 256), (64, 128), (32, 64), (16, 32), (8, 16)]
    sky = arrays["image"].astype(np.float32)
    blurred = arrays["level5"].astype(np.float32)
    assert blurred[..., :3].mean() == pytest.approx(sky[..., :3].mean(), rel=0.25)  # a blur keeps the energy
    exact = static_asset("env/sky@0.25")
    assert exact is not None and unpack(exact[0])[1]["image"].shape == (256, 512, 4)


def test_the_container_round_trips() -> None:
    arrays = {"a": np.arange(6, dtype="<f4").reshape(2, 3), "b": np.arange(3, dtype="<u4")}
    header, back = unpack(pack({"x": 1}, arrays))
    assert header == {"x": 1} and all(np.array_equal(arrays[k], back[k]) for k in arrays)
    with pytest.raises(ValueError):
        unpack(b"nope" + bytes(8))
    assert parse_alpha("0.25") == 0.25 and parse_alpha("0.0001") is None and parse_alpha("nan") is None
