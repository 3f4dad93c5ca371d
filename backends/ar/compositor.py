"""The material's object rendered on the marker and composited over the photo."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..preview.camera import Camera
from ..preview.environment import environment
from ..preview.meshes import fit, mesh_by_name
from ..preview.render import Renderer, Scene
from ..preview.resources import Resources
from ..preview.shader import MaterialLike
from .options import AROptions, camera_matrix, parse_options
from .pose import Pose, estimate_pose, find_marker, gl_projection, gl_view
from .shadow import ShadowOverlay


@dataclass
class ARFrame:
    image: np.ndarray  # BGR uint8, the photo with the object
    pose: Pose
    rgba: np.ndarray  # the rendered layer (RGBA, sRGB), top row first
    model: np.ndarray  # object (fitted, y-up) -> world scale matrix
    view_projection: np.ndarray


class Compositor:
    """The material's object on the marker, photo after photo, for one set of options. It keeps
    what every frame reuses: the renderer's resources (programs, textures, the shadow's
    footprint), the fitted mesh and the environment; `close()` releases them."""

    def __init__(self, options: Mapping[str, object] | AROptions | None = None, resources: Resources | None = None):
        self.opts = options if isinstance(options, AROptions) else parse_options(options)
        self.mesh = fit(mesh_by_name(self.opts.mesh), stand=True)  # a bad mesh or environment fails
        self.env = environment(self.opts.env)  # before a GL context is made
        self._owns_resources = resources is None
        self.resources = resources or Resources()

    def close(self) -> None:
        """Release the GL context and all it holds, if this compositor made them."""
        if self._owns_resources:
            self.resources.release()

    def __enter__(self) -> Compositor:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def composite(self, photo: np.ndarray, material: MaterialLike, source: str = "the image") -> ARFrame:
        """Detect the marker, estimate the pose, render the object on it and composite (BGR in, BGR out)."""
        opts = self.opts
        height, width = photo.shape[:2]
        K = camera_matrix(opts, width, height)
        pose = estimate_pose(find_marker(photo, opts.marker_id, source), opts.marker_length, K, opts.dist)
        rgba, model, view_projection = self.render_layer(pose, width, height, material)
        return ARFrame(over_photo(rgba, photo), pose, rgba, model, view_projection)

    def render_layer(self, pose: Pose, width: int, height: int, material: MaterialLike):
        """The object (and its shadow) as an RGBA layer for a camera at `pose`:
        (rgba top row first, model matrix, view-projection matrix)."""

        opts = self.opts
        distance = float(np.linalg.norm(pose.tvec))
        s = opts.marker_length * opts.scale / 2
        model = np.diag([s, s, s, 1.0])
        camera = Camera(
            (0, 0, 0),
            (0, 0, -1),
            view_override=gl_view(pose),
            projection_override=gl_projection(pose.K, width, height, distance * 0.01, distance * 10 + 10 * s),
        )
        scene = Scene(self.mesh, camera, self.env, background="transparent", exposure=opts.exposure)
        overlay = ShadowOverlay(self.mesh, model, opts.shadow) if opts.shadow > 0 else None
        renderer = Renderer(width, height, msaa=opts.msaa, resources=self.resources)
        frame = renderer.render(
            material, tier=opts.tier, glsl_options=opts.glsl, scene=scene, model=model, overlay=overlay
        )
        return frame.rgba, model, camera.view_projection


def composite(
    photo: np.ndarray, material: MaterialLike, options: dict | AROptions | None = None, source: str = "the image"
) -> ARFrame:
    """One photo composited (Compositor.composite, its resources released afterwards)."""
    with Compositor(options) as compositor:
        return compositor.composite(photo, material, source)


def render_layer(pose: Pose, width: int, height: int, material: MaterialLike, opts: AROptions):
    """One layer rendered (Compositor.render_layer, its resources released afterwards)."""
    with Compositor(opts) as compositor:
        return compositor.render_layer(pose, width, height, material)


def over_photo(rgba: np.ndarray, photo_bgr: np.ndarray) -> np.ndarray:
    """The layer (straight alpha, RGB) over the photo (BGR), rounded to 8 bits; only the rows and
    columns the layer covers are blended, the rest of the photo is copied."""
    out = photo_bgr.copy()
    rows, cols = np.nonzero(rgba[..., 3].max(1))[0], np.nonzero(rgba[..., 3].max(0))[0]
    if not len(rows):
        return out
    box = (slice(rows[0], rows[-1] + 1), slice(cols[0], cols[-1] + 1))
    a = rgba[box][..., 3:4].astype(np.float32) / 255.0
    layer = rgba[box][..., 2::-1].astype(np.float32)  # RGB -> BGR
    out[box] = np.round(layer * a + photo_bgr[box].astype(np.float32) * (1 - a)).astype(np.uint8)
    return out
