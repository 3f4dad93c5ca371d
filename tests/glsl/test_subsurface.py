"""The GLSL target carries a translucent body as the preview draws it (docs/glsl.md "Subsurface"):
cnlm_bsdf is the boundary, cnlm_subsurface the body (the same code: snippets/subsurface.glsl), its
uniforms in the header and the sidecar, its table written as a 16-bit PNG. The emitted standalone
pair, given the preview's camera, light and ambient and the object's bounding sphere, draws what
the preview's analytic tier draws (1e-3); every stage and profile passes glslangValidator."""

from __future__ import annotations

import io
import json

import numpy as np
import pytest

from cnlmc.backends import glsl
from cnlmc.material import Material

from .conftest import GLSLANG, material_of, run_glslang

SIZE = 96
TOLERANCE = 1e-3
PHRASES = ("wax", "leaf")


def emitted(phrase: str, **options: str) -> dict[str, str | bytes]:
    """Every file of one material, by name (the texture folder's path left out)."""
    ir = {"ir_version": 1, "materials": [material_of(phrase)], "diagnostics": []}
    result = glsl.emit(ir, {"map_size": "8", **options})
    assert not [n for n in result.notes if n.feature.startswith("subsurface")], result.notes
    return {a.name.rsplit("/", 1)[-1]: a.content for a in result.artifacts}


def read_table(png: bytes) -> np.ndarray:
    from PIL import Image

    with Image.open(io.BytesIO(png)) as image:
        return np.asarray(image, np.float64) / 65535.0


@pytest.mark.parametrize("phrase", PHRASES)
def test_the_header_and_sidecar_carry_the_body(phrase):
    from cnlmc.backends.preview.subsurface import body_uniforms, boundary_material, preintegrated_table

    files = emitted(phrase)
    sidecar = json.loads(files[f"{phrase}.glsl.json"])
    uniforms = {u["name"]: u["value"] for u in sidecar["uniforms"]}
    expected = body_uniforms(boundary_material(Material.from_ir(material_of(phrase))))  # the plan is made from it
    for name, value in expected.items():
        assert np.allclose(uniforms[name], value, rtol=1e-12), name
        assert f" {name} = " in files[f"{phrase}.glsl"]  # listed in the header, with its value
    assert sidecar["subsurface_entry_points"][0].startswith("vec3 cnlm_subsurface(")
    [lut] = [s for s in sidecar["samplers"] if s["name"] == "cnlm_sss_lut"]
    table = read_table(files[lut["file"].rsplit("/", 1)[-1]])  # type: ignore[arg-type]
    assert np.abs(table - preintegrated_table().values).max() <= 0.5 / 65535 + 1e-9


def test_a_material_without_a_body_has_none():
    files = emitted("red plastic")
    assert "cnlm_sss" not in files["red_plastic.glsl"] and "cnlm_subsurface" not in files["red_plastic.frag"]


@pytest.mark.skipif(GLSLANG is None, reason="glslangValidator is not installed")
def test_glslang_accepts_every_stage_and_profile():
    sources = []
    for phrase in PHRASES:
        for profile in ("330", "es300"):
            for specialize in ("on", "off"):
                files = emitted(phrase, profile=profile, specialize=specialize)
                stem = f"{phrase}_{profile}_{specialize}"
                sources += [(f"{stem}.frag", files[f"{phrase}.frag"]), (f"{stem}.vert", files[f"{phrase}.vert"])]
    failures = [(name, out) for name, code, out in run_glslang(sources) if code != 0]
    assert not failures, failures


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


class Standalone:
    """The emitted standalone pair drawing a preview scene into a float framebuffer."""

    def __init__(self, ctx, files: dict, phrase: str):
        self.ctx = ctx
        self.program = ctx.program(vertex_shader=files[f"{phrase}.vert"], fragment_shader=files[f"{phrase}.frag"])
        sidecar = json.loads(files[f"{phrase}.glsl.json"])
        for u in sidecar["uniforms"]:  # as a host of the es300 profile must (330 has them as initialisers)
            value = u["value"]
            self.program[u["name"]].value = tuple(value) if isinstance(value, list) else value
        [lut] = [s for s in sidecar["samplers"] if s["name"] == "cnlm_sss_lut"]
        table = read_table(files[lut["file"].rsplit("/", 1)[-1]]).astype("f4")
        self.lut = ctx.texture((table.shape[1], table.shape[0]), 1, table.tobytes(), dtype="f4")
        self.lut.filter = (ctx.NEAREST, ctx.NEAREST)

    def draw(self, scene, ambient: np.ndarray) -> np.ndarray:
        from cnlmc.backends.preview.glass import bounding_sphere
        from cnlmc.backends.preview.subsurface import metres_per_unit

        ctx, prog, mesh, cam = self.ctx, self.program, scene.mesh, scene.camera
        centre, radius = bounding_sphere(mesh)
        key = scene.env.key
        values = {
            "cnlm_model": tuple(np.eye(4).ravel()),
            "cnlm_normal_matrix": tuple(np.eye(3).ravel()),
            "cnlm_view_projection": tuple(np.asarray(cam.view_projection, np.float64).T.ravel()),
            "cnlm_camera_position": tuple(cam.position),
            "cnlm_light_direction": tuple(key.unit),
            "cnlm_light_radiance": (key.irradiance * scene.env_intensity,) * 3,
            "cnlm_ambient_radiance": tuple(ambient),
            "cnlm_sss_centre": tuple(centre),
            "cnlm_sss_radius": radius,
            "cnlm_sss_closed": int(mesh.closed),
            "cnlm_sss_unit": metres_per_unit(),
        }
        for name, value in values.items():
            if name in prog:
                prog[name].value = value
        self.lut.use(0)
        prog["cnlm_sss_lut"].value = 0
        width, height = SIZE, SIZE
        target = ctx.framebuffer(
            color_attachments=[ctx.texture((width, height), 4, dtype="f4")],
            depth_attachment=ctx.depth_renderbuffer((width, height)),
        )
        vbo = ctx.buffer(mesh.interleaved().tobytes())
        ibo = ctx.buffer(mesh.indices.astype("u4").tobytes())
        names = ["in_position", "in_normal", "in_tangent", "in_uv"]
        layout = " ".join("3f" if n in prog else "12x" for n in names[:3]) + (" 2f" if "in_uv" in prog else " 8x")
        vao = ctx.vertex_array(prog, [(vbo, layout, *[n for n in names if n in prog])], index_buffer=ibo)
        target.use()
        ctx.viewport = (0, 0, width, height)
        target.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(ctx.DEPTH_TEST)
        if mesh.closed:
            ctx.enable(ctx.CULL_FACE)
        vao.render()
        ctx.disable(ctx.CULL_FACE)
        image = np.frombuffer(target.read(components=4, dtype="f4"), np.float32).reshape(height, width, 4)
        for made in (vao, vbo, ibo, target):
            made.release()
        return np.flipud(image)  # top row first, as the preview's frames


@pytest.fixture(scope="module")
def renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SIZE, msaa=0) as made:
        yield made


@pytest.mark.parametrize("phrase", PHRASES)
@pytest.mark.parametrize(("mesh", "behind"), [("sphere", False), ("teapot", False), ("teapot", True)])
def test_the_standalone_draws_what_the_preview_draws(renderer, phrase, mesh, behind):
    """Front-lit and backlit (the light through the body), on a sphere and a teapot (its spout is
    thin): the target's own files (library, standalone pair, sidecar values, the PNG table) against
    the preview's analytic tier, linear, pixel by pixel."""
    from cnlmc.backends.preview.environment import Environment, KeyLight
    from cnlmc.backends.preview.environment_pass import env_resources
    from cnlmc.backends.preview.scene import default_scene
    from cnlmc.material import Material

    scene = renderer.scene(mesh, "studio")
    if behind:
        light = np.subtract(scene.camera.target, scene.camera.eye) + np.array([0.0, 0.3, 0.0])
        env = Environment("behind", scene.env.image, KeyLight(tuple(light), 3.0))
        scene = default_scene(scene.mesh, env, (SIZE, SIZE))
    scene.background = "transparent"
    material = Material.from_ir(material_of(phrase))
    frame = renderer.render(material, scene=scene, tier="analytic", hdr=True)
    ambient = env_resources(renderer.resources, scene.env).mean * scene.env_intensity
    drawn = Standalone(renderer.ctx, emitted(phrase), phrase).draw(scene, np.asarray(ambient, np.float64))
    covered = (drawn[..., 3] > 0.5) & (frame.rgba[..., 3] > 250)
    assert covered.sum() > 0.1 * SIZE * SIZE
    ours = srgb_to_linear(drawn[..., :3].astype(np.float64))[covered]
    preview = frame.hdr[..., :3].astype(np.float64)[covered]
    # the preview's HDR target is half float: within 1e-3 is within one of its steps (measured: at most 1)
    error = np.abs(ours - preview) / np.maximum(np.abs(preview), 0.05)
    assert error.max() <= TOLERANCE, (error.max(), np.unravel_index(error.argmax(), error.shape))
    # the body is what is compared: without it the picture is far off
    assert np.median(preview.max(-1)) > 0.02
