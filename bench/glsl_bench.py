"""GLSL backend benchmark: phrase -> GLSL latency next to MaterialX's own GLSL generator,
emitted size, and the frame-time payoff of specialization on llvmpipe.

    .venv/bin/python bench/glsl_bench.py [--runs 200] [--frames 30]

Prints one table. Columns:
  ours ms      median / p99 of compile_source(phrase) + glsl.emit (fragment, vertex, library, sidecar)
  mtlx ms      median / p99 of building an open_pbr_surface document with the same parameters and
               generating its GLSL with MaterialX's GlslShaderGenerator (generator and context reused)
  ratio        ours / MaterialX (goal <= 0.5)
  lines        our standalone .frag vs MaterialX's pixel stage
  frame ms     llvmpipe, 512x512 sphere, one directional light: our specialized shader vs our
               all-features shader (specialize=off, the same material) -- the payoff of specializing
"""

from __future__ import annotations

import argparse
import json
import statistics
import time

import numpy as np

from cnlmc.api import compile_source
from cnlmc.backends import glsl

PHRASES = (
    "glossy red plastic",
    "polished gold",
    "lightly brushed, blue anodized aluminum",
    "red varnished oak",
    "velvet",
)
SIZE = 512


def percentile(samples, q):
    return float(np.percentile(np.asarray(samples), q))


def time_runs(fn, runs):
    fn()  # warm caches (lexicon, templates, tables) once, as a long-running tool would
    samples = []
    for _ in range(runs):
        start = time.perf_counter()
        fn()
        samples.append((time.perf_counter() - start) * 1e3)
    return statistics.median(samples), percentile(samples, 99)


def ours(phrase):
    ir = compile_source(phrase + "\n").ir
    return glsl.emit(ir, {})


# ---- MaterialX ----


class MaterialX:
    def __init__(self):
        import MaterialX as mx
        import MaterialX.PyMaterialXGenGlsl as mxg
        import MaterialX.PyMaterialXGenShader as mxs

        self.mx, self.mxs = mx, mxs
        self.lib = mx.createDocument()
        mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), self.lib)
        self.gen = mxg.GlslShaderGenerator.create()
        self.ctx = mxs.GenContext(self.gen)
        self.ctx.registerSourceCodeSearchPath(mx.getDefaultDataSearchPath())

    def document(self, material):
        mx = self.mx
        doc = mx.createDocument()
        doc.setDataLibrary(self.lib)
        shader = doc.addNode("open_pbr_surface", "SR_" + material["name"], "surfaceshader")
        for name, kind, value in open_pbr_inputs(material):
            shader.setInputValue(name, mx.Color3(*value) if kind == "color3" else float(value), kind)
        doc.addMaterialNode("M_" + material["name"], shader)
        return doc

    def generate(self, material):
        doc = self.document(material)
        element = self.mxs.findRenderableElements(doc)[0]
        shader = self.gen.generate(self.mx.createValidName(element.getNamePath()), element, self.ctx)
        return shader.getSourceCode(self.mxs.PIXEL_STAGE)


def open_pbr_inputs(material):
    """The IR parameters as OpenPBR inputs (the comparable shader, not an exact mapping)."""
    model, params = material["model"], material["params"]
    inputs = [
        ("base_color", "color3", params.get("base_color", [0.8] * 3)),
        ("specular_roughness", "float", params.get("roughness", 0.5)),
    ]
    if model["base"] == "conductor":
        inputs += [("base_metalness", "float", 1.0), ("specular_color", "color3", params["f82"])]
    if model["anisotropic"]:
        inputs.append(("specular_roughness_anisotropy", "float", params.get("anisotropy", 0.0)))
    if model["coat"] and params.get("coat"):
        inputs += [
            ("coat_weight", "float", 1.0),
            ("coat_ior", "float", params["coat"]["ior"]),
            ("coat_roughness", "float", params["coat"].get("roughness", 0.0)),
        ]
    if model["base"] in ("dielectric", "glass"):
        inputs.append(("specular_ior", "float", params.get("ior", 1.5)))
    return inputs


# ---- frame time on llvmpipe ----


def sphere(rings=64, segments=128):
    v, u = np.meshgrid(np.linspace(0, np.pi, rings + 1), np.linspace(0, 2 * np.pi, segments + 1), indexing="ij")
    pos = np.stack([np.sin(v) * np.cos(u), np.cos(v), np.sin(v) * np.sin(u)], -1)
    tangent = np.stack([-np.sin(u), np.zeros_like(u), np.cos(u)], -1)
    uv = np.stack([u / (2 * np.pi), v / np.pi], -1)
    verts = np.concatenate([pos, pos, tangent, uv], -1).reshape(-1, 11).astype("f4")
    idx = []
    w = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b = r * w + s, (r + 1) * w + s
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return verts, np.asarray(idx, "i4")


def perspective(fov_y, aspect, near, far):
    f = 1 / np.tan(fov_y / 2)
    return np.array(
        [
            [f / aspect, 0, 0, 0],
            [0, f, 0, 0],
            [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
            [0, 0, -1, 0],
        ]
    )


class FrameTimer:
    def __init__(self):
        import moderngl

        self.ctx = moderngl.create_context(standalone=True, backend="egl")
        self.fbo = self.ctx.simple_framebuffer((SIZE, SIZE))
        verts, idx = sphere()
        self.vbo, self.ibo = self.ctx.buffer(verts.tobytes()), self.ctx.buffer(idx.tobytes())
        self.ctx.enable(moderngl.DEPTH_TEST)
        eye = np.array([0.0, 0.0, 3.0])
        view = np.eye(4)
        view[2, 3] = -3.0
        self.uniforms = {
            "cnlm_model": np.eye(4),
            "cnlm_normal_matrix": np.eye(3),
            "cnlm_view_projection": perspective(0.8, 1.0, 0.1, 10.0) @ view,
            "cnlm_camera_position": eye,
            "cnlm_light_direction": (0.4, 0.6, 0.7),
            "cnlm_light_radiance": (3.0, 3.0, 3.0),
            "cnlm_ambient_radiance": (0.05, 0.05, 0.05),
        }

    def frame_ms(self, files, frames):
        prog = self.ctx.program(vertex_shader=files["vert"], fragment_shader=files["frag"])
        values = {u["name"]: u["value"] for u in json.loads(files["glsl.json"])["uniforms"]}
        values.update({k: np.asarray(v, "f8").T.ravel() if np.ndim(v) == 2 else v for k, v in self.uniforms.items()})
        for name, value in values.items():
            if name in prog:
                prog[name].value = tuple(np.ravel(value)) if np.ndim(value) else value
        attrs = [a for a in ("in_position", "in_normal", "in_tangent", "in_uv") if a in prog]
        layout = " ".join(
            {"in_position": "3f", "in_normal": "3f", "in_tangent": "3f", "in_uv": "2f"}[a]
            if a in attrs
            else {"in_position": "3x4", "in_normal": "3x4", "in_tangent": "3x4", "in_uv": "2x4"}[a]
            for a in ("in_position", "in_normal", "in_tangent", "in_uv")
        )
        vao = self.ctx.vertex_array(prog, [(self.vbo, layout, *attrs)], self.ibo)
        self.fbo.use()
        self.fbo.clear()
        vao.render()
        self.ctx.finish()  # compile/warm
        samples = []
        for _ in range(frames):
            start = time.perf_counter()
            self.fbo.clear()
            vao.render()
            self.ctx.finish()
            samples.append((time.perf_counter() - start) * 1e3)
        vao.release()
        prog.release()
        return statistics.median(samples)


def emitted(material, **options):
    ir = {"materials": [material]}
    return {
        a.name.split(".", 1)[1]: a.content for a in glsl.emit(ir, {k: str(v) for k, v in options.items()}).artifacts
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--frames", type=int, default=30)
    args = parser.parse_args()
    mtlx = MaterialX()
    timer = FrameTimer()
    header = (
        f"{'phrase':42} {'ours ms med/p99':>16} {'mtlx ms med/p99':>16} {'ratio':>6} "
        f"{'lines ours/mtlx':>16} {'frame ms spec/uber':>19} {'speed-up':>8}"
    )
    print(header)
    print("-" * len(header))
    for phrase in PHRASES:
        material = compile_source(phrase + "\n").ir["materials"][0]
        ours_med, ours_p99 = time_runs(lambda: ours(phrase), args.runs)
        mtlx_med, mtlx_p99 = time_runs(lambda: mtlx.generate(material), args.runs)
        specialized, uber = emitted(material), emitted(material, specialize="off")
        lines_ours = len(specialized["frag"].splitlines())
        lines_mtlx = len(mtlx.generate(material).splitlines())
        spec_ms = timer.frame_ms(specialized, args.frames)
        uber_ms = timer.frame_ms(uber, args.frames)
        print(
            f"{phrase:42} {ours_med:7.2f} /{ours_p99:7.2f} {mtlx_med:7.2f} /{mtlx_p99:7.2f} "
            f"{ours_med / mtlx_med:6.2f} {lines_ours:7d} /{lines_mtlx:7d} {spec_ms:8.2f} /{uber_ms:8.2f} "
            f"{uber_ms / spec_ms:7.2f}x"
        )


if __name__ == "__main__":
    main()
