"""The tone-map pass: the HDR frame to 8-bit sRGB, with the edge filter (without MSAA) and the
environment background composited where the object does not cover the pixel."""

from __future__ import annotations

from typing import Any

from . import gl
from .resources import Resources
from .scene import Scene
from .targets import Rect, Targets, strips_around


def tonemap(
    resources: Resources,
    t: Targets,
    scene: Scene,
    background: bool,
    edge_aa: bool,
    rect: Rect | None = None,
) -> None:
    """Edge filter (without MSAA), the environment background (where the object does not
    cover the pixel), exposure, ACES, sRGB, in one pass over `rect` (x, y, w, h), where
    something was drawn, or over the whole frame when rect is None. Outside `rect`: the
    background alone (a variant without the object layer's five reads), or nothing
    (read_image() reads `rect` back; the rest is transparent black, what the pass writes)."""
    import moderngl

    ctx = resources.ctx
    ctx.disable(moderngl.DEPTH_TEST)
    t.ldr.use()
    vao = tonemap_variant(resources, t, scene, background, edge_aa)
    ctx.scissor = rect
    vao.render(moderngl.TRIANGLES, vertices=3)
    if rect is not None and background:
        vao = tonemap_variant(resources, t, scene, background, edge_aa, "PV_BACKGROUND_ONLY")
        for strip in strips_around(rect, *t.size):
            ctx.scissor = strip
            vao.render(moderngl.TRIANGLES, vertices=3)
    ctx.scissor = None


def tonemap_variant(
    resources: Resources, t: Targets, scene: Scene, background: bool, edge_aa: bool, define: str = ""
) -> Any:
    """The tone-map variant's vertex array, its textures bound and uniforms set."""
    prog, vao = resources.fullscreen("tonemap.frag", define)
    t.resolved_tex.use(0)
    gl.set_uniform(prog, "pv_hdr", 0)
    gl.set_uniform(prog, "pv_exposure", scene.exposure)
    gl.set_uniform(prog, "pv_curve", 0)
    gl.set_uniform(prog, "pv_edge_aa", int(edge_aa and not t.samples))
    gl.set_uniform(prog, "pv_background", int(background))
    if background:
        t.background_tex.use(1)
        gl.set_uniform(prog, "pv_background_image", 1)
    return vao
