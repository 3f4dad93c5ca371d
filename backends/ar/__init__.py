"""AR: the previewed material on an object standing on an ArUco marker in a photo (or video).

    write_marker(path, marker_id=0, pixels=480) -> Path
    ar_command(photo_path, ir, out_path, options) -> ARReport
    ar_video(video_path, ir, out_path, options) -> ARReport
    composite(photo_bgr, material, options) -> (image_bgr, Pose)

Options (strings): marker_length (0.1; any unit, the scene is relative to it), marker_id (any),
scale (1.0: the object's bounding-sphere diameter in marker lengths), intrinsics ("fx,fy,cx,cy";
default from the image size and fov), fov (60 degrees, horizontal), dist (k1,k2,p1,p2,k3),
mesh (teapot), tier (splitsum), env (studio), shadow (0.65 opacity, 0 = none), material (name or
index of the IR material, default the first), exposure (1.0), msaa (4 for a photo; 0 for a
video: the tone map's edge filter instead, about 3x less time per frame), fresnel, multiscatter.
Errors are ARError subclasses with an `exit_code` (NoMarkerFound 65, PhotoUnreadable 66,
AROptionError 2).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import ARError, AROptionError, NoMarkerFound, PhotoUnreadable
from .marker import write_marker
from .pose import Pose, default_intrinsics, estimate_pose, find_marker, gl_projection, gl_view

NAME = "ar"
DEFAULTS = {
    "marker_length": "0.1",
    "marker_id": "",
    "scale": "1.0",
    "intrinsics": "",
    "fov": "60",
    "dist": "",
    "mesh": "teapot",
    "tier": "splitsum",
    "env": "studio",
    "shadow": "0.65",
    "material": "",
    "exposure": "1.0",
    "msaa": "4",
    "fresnel": "exact",
    "multiscatter": "off",
}
#: video frames: no multisampling (bench/ar_frames.py: msaa 4 costs about 3x per frame on llvmpipe).
VIDEO_MSAA = "0"
SHADOW_EXTENT = 1.6  # half-size of the shadow quad, in units of the fitted object's radius
#: the shadow quad's corners (x, z) in units of SHADOW_EXTENT, in triangle-strip order
QUAD_CORNERS = ((-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0))


@dataclass
class AROptions:
    marker_length: float = 0.1
    marker_id: int | None = None
    scale: float = 1.0
    intrinsics: tuple | None = None
    fov: float = 60.0
    dist: tuple | None = None
    mesh: str = "teapot"
    tier: str = "splitsum"
    env: str = "studio"
    shadow: float = 0.65
    material: str = ""
    exposure: float = 1.0
    msaa: int = 4
    glsl: dict = field(default_factory=dict)


def _floats(text: str, count: tuple, what: str) -> tuple | None:
    if not text:
        return None
    try:
        values = tuple(float(x) for x in text.replace(";", ",").split(","))
    except ValueError:
        raise AROptionError(f"ar: {what} must be comma-separated numbers, got {text!r}") from None
    if len(values) not in count:
        raise AROptionError(f"ar: {what} takes {' or '.join(map(str, count))} numbers, got {len(values)}")
    return values


def parse_options(options: dict | None) -> AROptions:
    from ..capabilities import COMPILER_OPTIONS

    options = {k: str(v) for k, v in (options or {}).items() if k not in COMPILER_OPTIONS}
    unknown = sorted(set(options) - set(DEFAULTS))
    if unknown:
        raise AROptionError(f"ar: unknown option(s) {', '.join(unknown)}; known: {', '.join(DEFAULTS)}")
    o = {**DEFAULTS, **options}
    try:
        length, scale, fov = float(o["marker_length"]), float(o["scale"]), float(o["fov"])
        shadow, exposure, msaa = float(o["shadow"]), float(o["exposure"]), int(o["msaa"])
        marker_id = int(o["marker_id"]) if o["marker_id"] else None
    except ValueError as exc:
        raise AROptionError(f"ar: {exc}") from None
    if length <= 0 or scale <= 0 or not 1 < fov < 179:
        raise AROptionError("ar: marker_length and scale must be positive and fov within (1, 179) degrees")
    return AROptions(
        length,
        marker_id,
        scale,
        _floats(o["intrinsics"], (4,), "intrinsics"),
        fov,
        _floats(o["dist"], (4, 5, 8), "dist"),
        o["mesh"],
        o["tier"],
        o["env"],
        shadow,
        o["material"],
        exposure,
        msaa,
        {"fresnel": o["fresnel"], "multiscatter": o["multiscatter"]},
    )


def camera_matrix(opts: AROptions, width: int, height: int) -> np.ndarray:
    if opts.intrinsics:
        fx, fy, cx, cy = opts.intrinsics
        return np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]], np.float64)
    return default_intrinsics(width, height, opts.fov)


def pick_material(ir: dict, which: str) -> dict:
    materials = ir["materials"]
    if not materials:
        raise AROptionError("ar: the IR has no material")
    if not which:
        return materials[0]
    if which.isdigit() and int(which) < len(materials):
        return materials[int(which)]
    for m in materials:
        if m["name"] == which:
            return m
    raise AROptionError(f"ar: no material {which!r} (have: {', '.join(m['name'] for m in materials)})")


# -------------------------------------------------------------------- shadow


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

        from cnlmc.backends.preview import gl

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


# ----------------------------------------------------------------- compositing


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

    def __init__(self, options: dict | AROptions | None = None, resources=None):
        from cnlmc.backends.preview.environment import environment
        from cnlmc.backends.preview.meshes import fit, mesh_by_name
        from cnlmc.backends.preview.resources import Resources

        self.opts = options if isinstance(options, AROptions) else parse_options(options)
        self._owns_resources = resources is None
        self.resources = resources or Resources()
        self.mesh = fit(mesh_by_name(self.opts.mesh), stand=True)
        self.env = environment(self.opts.env)

    def close(self) -> None:
        if self._owns_resources:
            self.resources.release()

    def __enter__(self) -> Compositor:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def composite(self, photo: np.ndarray, material: dict, source: str = "the image") -> ARFrame:
        """Detect the marker, estimate the pose, render the object on it and composite (BGR in, BGR out)."""
        opts = self.opts
        height, width = photo.shape[:2]
        K = camera_matrix(opts, width, height)
        pose = estimate_pose(find_marker(photo, opts.marker_id, source), opts.marker_length, K, opts.dist)
        rgba, model, view_projection = self.render_layer(pose, width, height, material)
        return ARFrame(over_photo(rgba, photo), pose, rgba, model, view_projection)

    def render_layer(self, pose: Pose, width: int, height: int, material: dict):
        """The object (and its shadow) as an RGBA layer for a camera at `pose`:
        (rgba top row first, model matrix, view-projection matrix)."""
        from cnlmc.backends.preview.camera import Camera
        from cnlmc.backends.preview.render import Renderer, Scene

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
    photo: np.ndarray, material: dict, options: dict | AROptions | None = None, source: str = "the image"
) -> ARFrame:
    """One photo composited (Compositor.composite, its resources released afterwards)."""
    with Compositor(options) as compositor:
        return compositor.composite(photo, material, source)


def render_layer(pose: Pose, width: int, height: int, material: dict, opts: AROptions):
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


def read_photo(path) -> np.ndarray:
    import cv2

    path = Path(path)
    if not path.exists():
        raise PhotoUnreadable(f"photo {path} does not exist")
    image = cv2.imread(str(path), cv2.IMREAD_COLOR)
    if image is None:
        raise PhotoUnreadable(f"cannot read {path} as an image")
    return image


@dataclass
class ARReport:
    path: Path
    frames: int
    poses: list
    missed: int = 0
    notes: list = field(default_factory=list)


def ar_command(photo_path, ir: dict, out_path, options: dict | None = None) -> ARReport:
    """Photo with a printed marker -> the same photo with the material's object standing on it.
    Raises NoMarkerFound ("no marker found in photo.jpg ..."), PhotoUnreadable, AROptionError."""
    opts = parse_options(options)
    material = pick_material(ir, opts.material)
    photo = read_photo(photo_path)
    result = composite(photo, material, opts, source=Path(photo_path).name)
    out_path = Path(out_path)
    write_image_atomic(out_path, result.image)
    return ARReport(out_path, 1, [result.pose])


def write_image_atomic(path: Path, image) -> None:
    """Encode by the file's extension and write it whole or not at all."""
    import cv2

    from cnlmc.output import write_atomic

    ok, data = cv2.imencode(path.suffix or ".png", image)
    if not ok:
        raise AROptionError(f"cannot encode an image as '{path.suffix}': use .png or .jpg")
    write_atomic(path, data.tobytes())


def ar_video(video_path, ir: dict, out_path, options: dict | None = None, max_frames: int | None = None) -> ARReport:
    """Frames in, frames out (OpenCV VideoCapture / VideoWriter, mp4v). Frames without a marker
    pass through unchanged and are counted in `missed`; none found at all raises NoMarkerFound."""
    import cv2

    opts = parse_options({"msaa": VIDEO_MSAA, **(options or {})})
    material = pick_material(ir, opts.material)
    with Compositor(opts) as compositor:
        capture = cv2.VideoCapture(str(video_path))
        if not capture.isOpened():
            raise PhotoUnreadable(f"cannot open video {video_path}")
        return _composite_frames(compositor, capture, video_path, material, Path(out_path), max_frames)


def _composite_frames(compositor, capture, video_path, material, out_path: Path, max_frames) -> ARReport:
    import cv2

    fps = capture.get(cv2.CAP_PROP_FPS) or 25.0
    writer, poses, missed, count = None, [], 0, 0
    partial = out_path.with_name(f".{out_path.name}.partial{out_path.suffix}")
    try:
        while max_frames is None or count < max_frames:
            ok, frame = capture.read()
            if not ok:
                break
            count += 1
            try:
                result = compositor.composite(frame, material, source=f"{Path(video_path).name} frame {count}")
                frame, pose = result.image, result.pose
                poses.append(pose)
            except NoMarkerFound:
                missed += 1
            if writer is None:
                out_path.parent.mkdir(parents=True, exist_ok=True)
                writer = cv2.VideoWriter(
                    str(partial), cv2.VideoWriter_fourcc(*"mp4v"), fps, (frame.shape[1], frame.shape[0])
                )
            writer.write(frame)
    finally:
        capture.release()
        if writer is not None:
            writer.release()
    if count == 0 or not poses:
        partial.unlink(missing_ok=True)
    if count == 0:
        raise PhotoUnreadable(f"no frames could be read from {video_path}")
    if not poses:
        raise NoMarkerFound(f"no marker found in any of the {count} frames of {Path(video_path).name}")
    os.replace(partial, out_path)
    return ARReport(out_path, count, poses, missed)


__all__ = [
    "write_marker",
    "ar_command",
    "ar_video",
    "composite",
    "parse_options",
    "ARError",
    "NoMarkerFound",
    "PhotoUnreadable",
    "AROptionError",
    "ARReport",
    "ARFrame",
]
