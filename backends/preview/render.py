"""The preview renderer: the GLSL backend's BSDF on a mesh, lit by a key light and an HDR
environment, rendered offscreen, tone mapped to sRGB.

    with Renderer(512) as r:
        frame = r.render(material, mesh="sphere", tier="fis16")   # -> Frame(rgba8, hdr, ms)

A frame is the object pass (object_pass.py) into the targets (targets.py), the background pass
(environment_pass.py) and the tone map (tonemap.py); what they are made from is kept by the
renderer's Resources (resources.py).
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..glsl.options import GlslOptions
from .environment import Environment, environment
from .environment_pass import draw_background, env_resources
from .mesh import Mesh
from .object_pass import draw_object
from .resources import Resources
from .scene import Scene, default_scene, scene_mesh
from .shader import MaterialLike, MaterialShader, as_material, material_shader, shader_key, shader_options
from .subsurface import boundary_material
from .targets import Rect, Targets, grown, read_image, screen_rect, targets
from .tiers import DEFAULT_TIER, Tier, parse_tier
from .tonemap import tonemap

__all__ = ["DEFAULT_MSAA", "Frame", "Renderer", "Scene", "default_scene"]

#: MSAA costs 4x the object pass on llvmpipe (docs/preview.md): off, with the tone map's edge filter.
DEFAULT_MSAA = 0


@dataclass
class Frame:
    rgba: np.ndarray  # (H, W, 4) uint8, sRGB, top row first; alpha = coverage
    hdr: np.ndarray | None  # (H, W, 4) float32 linear radiance before tone mapping (top row first)
    ms: float  # GPU frame time (draw + resolve + tone map, finished), milliseconds
    tier: str = ""
    notes: list = field(default_factory=list)


class Renderer:
    """Offscreen renderer of one size. What it makes (programs, textures, meshes, tables) is
    kept by its `resources`, which renderers may share (`Renderer(w, resources=other.resources)`)
    and which go with `close()` (or the end of a `with` block) when this renderer made them."""

    #: pixels around the projected bounds: the edge filter's 1-pixel reach, and rounding.
    RECT_PAD = 2

    def __init__(
        self,
        width: int = 512,
        height: int | None = None,
        msaa: int = DEFAULT_MSAA,
        edge_aa: bool = True,
        resources: Resources | None = None,
    ):
        self.width, self.height = width, height or width
        self.msaa = msaa
        self.edge_aa = edge_aa  # the tone-map pass's edge filter, used when msaa <= 1
        self._owns_resources = resources is None
        self.resources = resources or Resources()
        self.ctx = self.resources.ctx

    def close(self) -> None:
        """Release the GL context and all it holds, if this renderer made them."""
        if self._owns_resources:
            self.resources.release()

    def __enter__(self) -> Renderer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- what a frame is made from
    def shader(self, material: MaterialLike, glsl_options: Mapping[str, Any] | None = None) -> MaterialShader:
        """The material's shader (GLSL library and plan), made once per content and options; a
        translucent material is given as it is (its boundary is taken here: applied twice, a thin
        sheet's front would be darkened twice)."""
        typed, options = boundary_material(as_material(material)), self.glsl_options(glsl_options)
        key = ("shader", *shader_key(typed, options))
        return self.resources.once(key, lambda: material_shader(typed, options, self.resources.shader_writer))

    def glsl_options(self, pairs: Mapping[str, Any] | None) -> GlslOptions:
        """The GLSL backend's options of a render, parsed once per distinct set of pairs."""
        key = ("glsl options", tuple(sorted((k, str(v)) for k, v in (pairs or {}).items())))
        return self.resources.once(key, lambda: shader_options(pairs))

    def scene(self, mesh: str | Mesh = "sphere", env: str | Environment = "studio") -> Scene:
        """The framed preview scene at this renderer's size (default_scene); a named mesh or
        environment is made once and kept (by name and size), a new Scene around them each call."""
        size = (self.width, self.height)
        if isinstance(mesh, str):
            name = mesh
            mesh = self.resources.once(("scene mesh", name, size), lambda: scene_mesh(name, size))
        if isinstance(env, str):
            env_name = env
            env = self.resources.once(("scene environment", env_name), lambda: environment(env_name))
        return default_scene(mesh, env, size)

    # -- a frame
    def draw(
        self,
        scene: Scene,
        material: MaterialLike,
        tier: Tier | str = DEFAULT_TIER,
        glsl_options: Mapping[str, Any] | None = None,
        model: np.ndarray | None = None,
        overlay: Any = None,
    ) -> Targets:
        """Draw into the targets (no read-back); `overlay(renderer, scene)` draws extra geometry."""
        self.resources.make_current()  # ours must be the current context (another may have been made current)
        tier = parse_tier(tier) if isinstance(tier, str) else tier
        typed = as_material(material)
        shader = self.shader(typed, glsl_options)  # takes a translucent body's boundary itself
        material = boundary_material(typed)  # a translucent body: its boundary (subsurface.py), once
        res = env_resources(self.resources, scene.env)
        t = targets(self.resources, self.width, self.height, self.msaa)
        model = np.eye(4) if model is None else model
        # Only the rectangle around what is drawn is cleared and tone mapped with the object
        # layer (one pixel more is cleared: the edge filter reads its neighbours); without a
        # background only it is read back.
        drawn = self.drawn_rect(scene, model, overlay)
        t.rect = None if scene.background == "env" else drawn
        t.draw_target.use()
        self.ctx.viewport = (0, 0, self.width, self.height)
        t.draw_target.clear(0.0, 0.0, 0.0, 0.0, depth=1.0, viewport=grown(drawn, 1, self.width, self.height))
        if overlay is not None:
            overlay(self, scene)
            t.draw_target.use()
        draw_object(self.resources, scene, material, shader, tier, res, model, self.glsl_options(glsl_options))
        t.resolve(self.ctx)
        if scene.background == "env":
            draw_background(self.resources, t, scene, res)
        tonemap(self.resources, t, scene, scene.background == "env", self.edge_aa, drawn)  # composites the background
        return t

    def drawn_rect(self, scene: Scene, model: np.ndarray, overlay: Any = None) -> Rect | None:
        """The pixel rectangle (x, y, w, h) that holds everything drawn: the object's bounding box
        (and an overlay's `world_points()`, if it has them) projected; None (the whole frame)
        when a corner is behind the camera or an overlay cannot say where it draws."""
        lo, hi = scene.mesh.bounds
        corners = np.array([[x, y, z, 1.0] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
        points = corners @ np.asarray(model, np.float64).T
        if overlay is not None:
            extra = getattr(overlay, "world_points", None)
            if extra is None:
                return None
            points = np.vstack([points, extra()])
        return screen_rect(points, scene.camera.view_projection, self.width, self.height, self.RECT_PAD)

    def render(
        self,
        material: MaterialLike,
        mesh: str | Mesh = "sphere",
        tier: Tier | str = DEFAULT_TIER,
        glsl_options: Mapping[str, Any] | None = None,
        env: str | Environment = "studio",
        scene: Scene | None = None,
        hdr: bool = False,
        **draw_options: Any,
    ) -> Frame:
        """Render one material; returns the sRGB image (top row first) and the frame time."""
        scene = scene or self.scene(mesh, env)
        tier = parse_tier(tier) if isinstance(tier, str) else tier
        material = as_material(material)  # shader() and draw() take a translucent body's boundary, once each
        shader = self.shader(material, glsl_options)
        warm_key = (shader.key, tier.name, scene.mesh.key, scene.env.content_key, self.width, self.height)
        if self.resources.first_use(warm_key):  # the first frame compiles and uploads: drawn once untimed
            self.draw(scene, material, tier, glsl_options, **draw_options)
            self.ctx.finish()
        start = time.perf_counter()
        t = self.draw(scene, material, tier, glsl_options, **draw_options)
        self.ctx.finish()
        ms = (time.perf_counter() - start) * 1000.0
        rgba = read_image(t.ldr, t.rect, (self.width, self.height), "f1")
        linear = read_image(t.resolved, t.rect, (self.width, self.height), "f4") if hdr else None
        return Frame(rgba, linear, ms, tier.name, shader.notes)

    def frame_time(
        self,
        scene: Scene,
        material: MaterialLike,
        tier: Tier | str,
        glsl_options: Mapping[str, Any] | None = None,
        repeats: int = 5,
    ) -> float:
        """Median frame time (ms) over `repeats` frames, after one warm-up frame."""
        material = as_material(material)  # draw() takes a translucent body's boundary, once
        self.draw(scene, material, tier, glsl_options)
        self.ctx.finish()
        times = []
        for _ in range(repeats):
            start = time.perf_counter()
            self.draw(scene, material, tier, glsl_options)
            self.ctx.finish()
            times.append((time.perf_counter() - start) * 1000.0)
        return float(np.median(times))
