"""The object's contact shadow on the marker's plane: a soft footprint rasterised once per
mesh, drawn as a ground quad before the object (a Renderer overlay)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..preview import gl

SHADOW_EXTENT = 1.6  # half-size of the shadow quad, in units of the fitted object's radius
#: the shadow quad's corners (x, z) in units of SHADOW_EXTENT, in triangle-strip order
QUAD_CORNERS = ((-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0))


def footprint(mesh, extent: float = SHADOW_EXTENT, size: int = 128, height: float = 0.25) -> np.ndarray:
    """Soft contact-shadow opacity on the ground (rows: z from -extent, columns: x), in [0, 1].
    Triangles lower than `height` (fitted units) are rasterised from above and blurred twice."""
    import cv2

    tri = mesh.positions[mesh.indices]
    low = tri[:, :, 1].min(1) < height
    xz = (tri[low][:, :, [0, 2]] / extent * 0.5 + 0.5) * size
    occupancy = np.zeros((size, size), np.uint8)
    cv2.fillPoly(occupancy, list(np.round(xz * 16).astype(np.int32)), 255, cv2.LINE_8, shift=4)
    occ = occupancy.astype(np.float32) / 255.0
    tight = cv2.GaussianBlur(occ, (0, 0), size * 0.02)
    wide = cv2.GaussianBlur(occ, (0, 0), size * 0.08)
    shadow = 0.55 * tight + 0.45 * wide / max(wide.max(), 1e-6)
    return np.clip(shadow / max(shadow.max(), 1e-6), 0, 1).astype(np.float32)


class ShadowOverlay:
    """Draws the shadow quad before the object (a Renderer `overlay` callback)."""

    def __init__(self, mesh, model: np.ndarray, opacity: float):
        self.mesh, self.model, self.opacity = mesh, model, opacity

    def world_points(self) -> np.ndarray:
        """The quad's corners (homogeneous, world): where the overlay draws."""
        e = SHADOW_EXTENT
        corners = np.array([[x * e, 0.0, z * e, 1.0] for x, z in QUAD_CORNERS])
        return corners @ np.asarray(self.model, np.float64).T

    def __call__(self, renderer, scene) -> None:
        import moderngl

        prog, vao = shadow_quad(renderer.resources)
        shadow_texture(renderer.resources, self.mesh).use(0)
        gl.set_uniform(prog, "pv_shadow", 0)
        gl.set_uniform(prog, "pv_opacity", self.opacity)
        gl.set_uniform(prog, "pv_extent", SHADOW_EXTENT)
        gl.set_uniform(prog, "pv_model", self.model)
        gl.set_uniform(prog, "pv_view_projection", scene.camera.view_projection)
        renderer.ctx.disable(moderngl.DEPTH_TEST)
        vao.render(moderngl.TRIANGLE_STRIP)


def shadow_texture(resources, mesh):
    """The mesh's footprint as a texture, made once per mesh content (a video draws it every frame)."""
    return resources.once(
        ("ar shadow", mesh.key),
        lambda: resources.float_texture(footprint(mesh), mipmaps=False, repeat=(False, False)),
    )


def shadow_quad(resources):
    """(program, vertex array) of the ground quad, made once per resources."""

    def make():
        shaders = Path(__file__).parent / "shaders"
        prog = resources.program((shaders / "ground.vert").read_text(), (shaders / "shadow.frag").read_text())
        quad = resources.ctx.buffer(np.array(QUAD_CORNERS, "f4").tobytes())
        return prog, resources.ctx.vertex_array(prog, [(quad, "2f", "in_xz")])

    return resources.once(("ar shadow quad",), make)
