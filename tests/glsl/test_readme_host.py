"""The README's GLSL drop-in works for a mapped material: its fragment shader (with the emitted
library pasted in for the #include) and its Python host snippet (bind_maps) render the README's
hull ('lightly brushed, blue anodized aluminum': a normal map) and deck (white varnished oak:
colour and roughness maps) on llvmpipe: not black, with a highlight. Left unbound, the samplers
fall back to the uniform values and the highlight stays."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import require, run_cnlmc

moderngl = require("moderngl", "glsl")
require("PIL", "glsl")


README = Path(__file__).resolve().parents[2] / "README.md"
SIZE = 96
VERTEX = """#version 330 core
in vec3 in_position; in vec3 in_tangent; in vec2 in_uv;
uniform mat4 view_projection;
out vec3 N, T, P; out vec2 UV;
void main() {
    N = in_position; T = in_tangent; P = in_position; UV = in_uv;
    gl_Position = view_projection * vec4(in_position, 1.0);
}
"""


def readme_blocks() -> tuple[str, str]:
    """The README's GLSL drop-in shader and its Python host snippet."""
    text = README.read_text(encoding="utf-8")
    glsl = [b for b in re.findall(r"```glsl\n(.*?)```", text, re.S) if '#include "hull.glsl"' in b]
    python = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if "def bind_maps" in b]
    assert len(glsl) == 1 and len(python) == 1, "the README's GLSL drop-in or its host snippet is missing"
    return glsl[0], python[0]


def unit_sphere(rings: int = 32, segments: int = 64) -> np.ndarray:
    """Interleaved position, tangent (d/du), uv of a unit sphere's triangles."""
    rows = []
    for i in range(rings + 1):
        v, theta = i / rings, np.pi * i / rings
        for j in range(segments + 1):
            u, phi = j / segments, 2 * np.pi * j / segments
            p = [np.sin(theta) * np.cos(phi), np.cos(theta), -np.sin(theta) * np.sin(phi)]
            t = [-np.sin(phi), 0.0, -np.cos(phi)]
            rows.append(p + t + [u, 1.0 - v])
    grid = np.array(rows, "f4")
    width = segments + 1
    quads = [(i * width + j, (i + 1) * width + j) for i in range(rings) for j in range(segments)]
    index = [k for a, b in quads for k in (a, b, b + 1, a, b + 1, a + 1)]
    return grid[np.array(index)]


def look_at_projection() -> np.ndarray:
    eye, f = np.array([0.0, 0.0, 3.2]), 3.2
    near, far, fov = 0.1, 10.0, np.radians(40)
    scale = 1 / np.tan(fov / 2)
    projection = np.array(
        [
            [scale, 0, 0, 0],
            [0, scale, 0, 0],
            [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
            [0, 0, -1, 0],
        ]
    )
    view = np.eye(4)
    view[2, 3] = -f
    return (projection @ view).astype("f4"), eye


def render(library: str, folder: Path, sidecar: str | None) -> np.ndarray:
    """The README shader around `library`; maps bound with the README's bind_maps (None: unbound)."""
    fragment, host = readme_blocks()
    fragment = fragment.replace('#include "hull.glsl"', library)
    ctx = moderngl.create_context(standalone=True, backend="egl")
    try:
        program = ctx.program(vertex_shader=VERTEX, fragment_shader=fragment)
        if sidecar is not None:
            namespace: dict = {}
            exec(compile(host.split("\nbind_maps(ctx")[0], str(README), "exec"), namespace)  # the definition
            namespace["bind_maps"](ctx, program, sidecar, str(folder))
        matrix, eye = look_at_projection()
        program["view_projection"].write(matrix.T.copy().tobytes())
        program["eye"].value = tuple(eye)
        program["light_dir"].value = (0.4, 0.5, 0.77)
        program["light_rgb"].value = (3.0, 3.0, 3.0)
        mesh = ctx.buffer(unit_sphere().tobytes())
        layout = (mesh, "3f 3f 2f", "in_position", "in_tangent", "in_uv")
        if "in_tangent" not in program:  # a model without tangents: the linker dropped it
            layout = (mesh, "3f 12x 2f", "in_position", "in_uv")
        vao = ctx.vertex_array(program, [layout])
        target = ctx.framebuffer(
            color_attachments=[ctx.texture((SIZE, SIZE), 4, dtype="f4")],
            depth_attachment=ctx.depth_renderbuffer((SIZE, SIZE)),
        )
        target.use()
        target.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(moderngl.DEPTH_TEST)
        vao.render()
        pixels = np.frombuffer(target.read(components=4, dtype="f4"), "f4").reshape(SIZE, SIZE, 4)
    finally:
        ctx.release()
    return pixels[::-1, :, :3]


@pytest.fixture(scope="module")
def compiled(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("readme")
    source = Path(__file__).resolve().parents[2] / "examples" / "anodized.cnl"
    done = run_cnlmc("compile", str(source), "--target", "glsl", "--option", "map_size=64", "-o", str(out) + "/")
    assert done.returncode == 0, done.stderr
    return out


def luminance(image: np.ndarray) -> np.ndarray:
    return image @ np.array([0.2126, 0.7152, 0.0722])


def assert_lit_with_highlight(image: np.ndarray, what: str) -> None:
    sphere = luminance(image)[luminance(image) > 0]
    assert sphere.size > 0.3 * SIZE * SIZE * 0.4, f"{what}: the sphere is black"
    assert np.isfinite(image).all(), what
    assert sphere.max() > 0.2 and sphere.max() > 4 * np.median(sphere), (what, sphere.max(), np.median(sphere))


@pytest.mark.parametrize("name", ["hull", "deck"])
def test_the_readme_drop_in_renders_a_mapped_material(name, compiled):
    meta = json.loads((compiled / f"{name}.glsl.json").read_text())
    assert meta["samplers"], f"{name} has no maps"
    for sampler in meta["samplers"]:
        assert (compiled / sampler["file"]).is_file(), sampler
    image = render((compiled / f"{name}.glsl").read_text(), compiled, f"{name}.glsl.json")
    assert_lit_with_highlight(image, f"{name}, maps bound")


@pytest.mark.parametrize("name", ["hull", "deck"])
def test_unbound_samplers_keep_the_highlight(name, compiled):
    image = render((compiled / f"{name}.glsl").read_text(), compiled, None)
    assert_lit_with_highlight(image, f"{name}, no maps bound")
