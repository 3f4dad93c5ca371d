"""The body term's pre-integrated table is a texture (cnlm_sss_lut, snippets/subsurface.glsl), not a
uniform array: OpenGL ES 3.0 (WebGL2) guarantees only 224 fragment uniform vectors, and the table's
561 floats were 561 of them. The shader's look-up reads the texture exactly as
PreintegratedTable.lookup reads the table, and every program the preview links for a material stays
within ES 3.0's fragment limits (224 uniform vectors, 16 texture units)."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.material import Material

#: OpenGL ES 3.0's guaranteed minimums (GL_MAX_FRAGMENT_UNIFORM_VECTORS, GL_MAX_TEXTURE_IMAGE_UNITS)
ES3_FRAGMENT_UNIFORM_VECTORS = 224
ES3_TEXTURE_UNITS = 16
#: phrases that between them select every branch of the preview's fragment shader: a thick body, a
#: thin sheet, sheen, flakes under a coat, rough glass, anisotropy, maps, a plain metal
PHRASES = (
    "wax",
    "leaf",
    "navy blue velvet",
    "metallic car paint",
    "frosted glass",
    "brushed aluminum",
    "oak wood",
    "gold",
)
IBL_KINDS = ("ambient", "splitsum", "sampled")
#: GL matrix types -> the vectors (columns) one takes; every other non-sampler type takes one
MATRIX_COLUMNS = {0x8B5A: 2, 0x8B5B: 3, 0x8B5C: 4, 0x8B65: 2, 0x8B66: 2, 0x8B67: 3, 0x8B68: 3, 0x8B69: 4, 0x8B6A: 4}
SAMPLER_TYPES = range(0x8B5D, 0x8B64 + 1)  # sampler1D .. sampler2DRectShadow (sampler2D = 0x8B5E)
SAMPLER_TYPES_ES3 = (0x8DC1, 0x8DC4, 0x8DC5, 0x8DCA, 0x8DCC, 0x8DCF, 0x8DD2, 0x8DD4, 0x8DD7)
#: a vertex stage that feeds the preview's fragment inputs and has no uniforms of its own
PASS_THROUGH = """#version 330 core
in vec3 in_position;
out vec3 v_position; out vec3 v_normal; out vec3 v_tangent; out vec2 v_uv;
void main() {
    v_position = in_position; v_normal = in_position; v_tangent = in_position; v_uv = in_position.xy;
    gl_Position = vec4(in_position, 1.0);
}
"""
LOOKUP_MAIN = """
uniform sampler2D probe;
out vec4 probe_out;
void main() {
    vec2 at = texelFetch(probe, ivec2(gl_FragCoord.xy), 0).xy;
    probe_out = vec4(cnlm_sss_preintegrated(at.x, at.y), 0.0, 0.0, 1.0);
}
"""


@pytest.fixture(scope="module")
def renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(16) as made:
        yield made


def material_of(phrase: str) -> Material:
    """The phrase's material as the renderer takes it (Renderer.shader takes a body's boundary)."""
    return Material.from_ir(compile_source(phrase + "\n").ir["materials"][0])


def fragment_limits(program) -> tuple[int, int]:
    """(uniform vectors, samplers) of a linked program's active uniforms, without packing (each
    scalar, vector or array element one vector; a matrix one per column): an upper bound of what an
    ES 3.0 implementation counts."""
    import moderngl

    vectors = samplers = 0
    for name in program:
        member = program[name]
        if not isinstance(member, moderngl.Uniform):
            continue
        if member.gl_type in SAMPLER_TYPES or member.gl_type in SAMPLER_TYPES_ES3:
            samplers += member.array_length
        else:
            vectors += member.array_length * MATRIX_COLUMNS.get(member.gl_type, 1)
    return vectors, samplers


def test_the_count_sees_an_array_element_by_element(renderer):
    """The counter is not blind to arrays: the table as the uniform array it was is 561 vectors."""
    source = "#version 330 core\nuniform float lut[561];\nuniform mat3 m;\nuniform sampler2D s;\nout vec4 o;\n"
    source += "void main() { int i = int(gl_FragCoord.x); o = vec4(lut[i] + m[i % 3].x) + texture(s, vec2(0.5)); }\n"
    program = renderer.ctx.program(vertex_shader=PASS_THROUGH, fragment_shader=source)
    assert fragment_limits(program) == (561 + 3, 1)


@pytest.mark.parametrize("phrase", PHRASES)
def test_every_preview_program_fits_opengl_es_3(renderer, phrase):
    from cnlmc.backends.preview import gl

    shader = renderer.shader(material_of(phrase), None)
    for ibl in IBL_KINDS:
        fragment = gl.preview_fragment(shader.name, shader.library, shader.plan, ibl)
        program = renderer.ctx.program(vertex_shader=PASS_THROUGH, fragment_shader=fragment)
        vectors, samplers = fragment_limits(program)
        assert vectors <= ES3_FRAGMENT_UNIFORM_VECTORS, (phrase, ibl, vectors)
        assert samplers <= ES3_TEXTURE_UNITS, (phrase, ibl, samplers)
        if shader.plan.subsurface:
            assert "cnlm_sss_lut" in program  # the table is read, as a sampler
        program.release()


def test_the_texture_look_up_is_the_table_look_up(renderer):
    """cnlm_sss_preintegrated (texelFetch + bilinear in the shader) against the table's own bilinear
    look-up: the grid's corners and edges, between cells, past both ends of the curvature axis."""
    from cnlmc.backends.preview.object_pass import subsurface_table
    from cnlmc.backends.preview.subsurface import preintegrated_table

    table = preintegrated_table()
    cosines = np.concatenate([np.linspace(-1.0, 1.0, 33), np.linspace(-1.0, 1.0, 31) + 0.013, [-1.5, 1.5]])
    rhos = np.concatenate([[0.0, 1e-4, 0.05, 0.3, 1.0, 2.5, 7.0, 19.0, 40.0, 1e4], np.geomspace(1e-3, 50.0, 22)])
    grid = np.stack(np.meshgrid(np.clip(cosines, -1.5, 1.5), rhos, indexing="ij"), -1).astype(np.float32)
    height, width = grid.shape[:2]
    ctx = renderer.ctx
    library = renderer.shader(material_of("wax"), None).library
    program = ctx.program(vertex_shader=PASS_THROUGH, fragment_shader="#version 330 core\n" + library + LOOKUP_MAIN)
    probe = ctx.texture((width, height), 4, np.concatenate([grid, np.zeros_like(grid)], -1).tobytes(), dtype="f4")
    subsurface_table(renderer.resources).use(0)
    probe.use(1)
    program["cnlm_sss_lut"].value, program["probe"].value = 0, 1
    target = ctx.framebuffer(color_attachments=[ctx.texture((width, height), 4, dtype="f4")])
    quad = ctx.buffer(np.array([-1, -1, 0, 3, -1, 0, -1, 3, 0], "f4").tobytes())
    vao = ctx.vertex_array(program, [(quad, "3f", "in_position")])
    target.use()
    vao.render(vertices=3)
    got = np.frombuffer(target.read(components=4, dtype="f4"), np.float32).reshape(height, width, 4)[..., 0]
    want = np.array([[table.lookup(float(c), float(r)) for c, r in row] for row in grid.astype(np.float64)])
    assert np.abs(got - want).max() < 2e-6, np.abs(got - want).max()
    assert want.std() > 0.1  # the grid spans the table, not one value
    for made in (vao, quad, target, probe, program):
        made.release()


#: session 9's form of the look-up: the table as a uniform array (desktop GL allows it; ES 3.0 does not)
ARRAY_LOOK_UP = """uniform float pv_sss_lut[LUT_SIZE];
float cnlm_sss_preintegrated(float nl, float rho) {
    float row = (clamp(nl, -1.0, 1.0) + 1.0) * 0.5 * float(COS_STEPS - 1);
    float col = clamp(rho / (1.0 + rho) / cnlm_sss_lut_u_max, 0.0, 1.0) * float(RHO_STEPS - 1);
    int r0 = min(int(row), COS_STEPS - 2);
    int c0 = min(int(col), RHO_STEPS - 2);
    float fr = row - float(r0), fc = col - float(c0);
    float top = mix(pv_sss_lut[r0 * RHO_STEPS + c0], pv_sss_lut[r0 * RHO_STEPS + c0 + 1], fc);
    float bottom = mix(pv_sss_lut[(r0 + 1) * RHO_STEPS + c0], pv_sss_lut[(r0 + 1) * RHO_STEPS + c0 + 1], fc);
    return mix(top, bottom, fr);
}
"""


def with_array_look_up(source: str) -> str:
    """The fragment with cnlm_sss_preintegrated read from a uniform array instead of the texture."""
    from cnlmc.backends.preview.subsurface import settings

    start = source.index("float cnlm_sss_preintegrated(")
    depth, end = 0, source.index("{", start)
    for at in range(end, len(source)):
        depth += {"{": 1, "}": -1}.get(source[at], 0)
        if depth == 0:
            end = at
            break
    cos_steps, rho_steps = settings().profile_cos_steps, settings().profile_rho_steps
    old = ARRAY_LOOK_UP.replace("LUT_SIZE", str(cos_steps * rho_steps))
    old = old.replace("COS_STEPS", str(cos_steps)).replace("RHO_STEPS", str(rho_steps))
    return source[:start] + old + source[end + 1 :]


@pytest.mark.parametrize("phrase", ["wax", "milk"])
def test_the_picture_is_the_one_the_uniform_array_drew(gl_available, monkeypatch, phrase):
    """Before/after: the teapot (curvature from thin spout to thick belly) drawn with the table as a
    texture and with session 9's uniform array, in one process: the same image (measured: identical)."""
    from cnlmc.backends.preview import gl, object_pass
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.subsurface import preintegrated_table

    material = material_of(phrase)
    with Renderer(64) as texture:
        now = texture.render(material, mesh="teapot", tier="splitsum", hdr=True).hdr
    fragment, uniforms = gl.preview_fragment, object_pass.subsurface_uniforms
    monkeypatch.setattr(gl, "preview_fragment", lambda *args: with_array_look_up(fragment(*args)))
    monkeypatch.setattr(
        object_pass,
        "subsurface_uniforms",
        lambda *args: {**uniforms(*args), "pv_sss_lut": preintegrated_table().values.ravel()},
    )
    with Renderer(64) as array:
        before = array.render(material, mesh="teapot", tier="splitsum", hdr=True).hdr
    assert before[..., :3].max() > 0.1  # the body is drawn
    assert np.abs(now - before).max() <= 1e-3 * np.abs(before).max()
