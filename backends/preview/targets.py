"""Where a frame is drawn and read: the framebuffers of one size (Targets), the pixel
rectangles a frame is limited to, and reading an image back."""

from __future__ import annotations

from typing import Any

import numpy as np

from .resources import Resources

#: the background (the environment blurred at mip 3) is drawn at 1/4 resolution and upsampled.
BACKGROUND_SCALE = 4

Rect = tuple[int, int, int, int]  # x, y, w, h in OpenGL window coordinates (y up)


class Targets:
    """The HDR target (half float) with depth, and the 8-bit output, for one size.

    With MSAA (msaa > 1) the scene is drawn into a multisampled renderbuffer and resolved
    into `resolved_tex`; without it, straight into `resolved_tex` (no resolve pass)."""

    HDR_DTYPE = "f2"

    def __init__(self, ctx, width: int, height: int, msaa: int):
        self.size = (width, height)
        self.rect: Rect | None = None  # what the last draw() cleared, tone mapped and will read (None: all)
        self.samples = msaa if msaa > 1 else 0
        self.resolved_tex = ctx.texture(self.size, 4, dtype=self.HDR_DTYPE)
        if self.samples:
            self.msaa = ctx.framebuffer(
                [ctx.renderbuffer(self.size, 4, samples=msaa, dtype=self.HDR_DTYPE)],
                ctx.depth_renderbuffer(self.size, samples=msaa),
            )
            self.resolved = ctx.framebuffer([self.resolved_tex])
        else:
            self.msaa = self.resolved = ctx.framebuffer([self.resolved_tex], ctx.depth_renderbuffer(self.size))
        self.ldr = ctx.framebuffer([ctx.renderbuffer(self.size, 4)])
        self.background_size = (max(width // BACKGROUND_SCALE, 1), max(height // BACKGROUND_SCALE, 1))
        self.background_tex = ctx.texture(self.background_size, 4, dtype=self.HDR_DTYPE)
        self.background_tex.repeat_x = self.background_tex.repeat_y = False
        self.background = ctx.framebuffer([self.background_tex])

    @property
    def draw_target(self):
        return self.msaa

    def resolve(self, ctx) -> None:
        if self.samples:
            ctx.copy_framebuffer(self.resolved, self.msaa)


def targets(resources: Resources, width: int, height: int, msaa: int) -> Targets:
    """The framebuffers of one size and sample count in `resources`' context, made once."""
    return resources.once(("targets", width, height, msaa), lambda: Targets(resources.ctx, width, height, msaa))


def screen_rect(points: np.ndarray, view_projection: np.ndarray, width: int, height: int, pad: int = 0) -> Rect | None:
    """Pixel rectangle (x, y, w, h; OpenGL window coordinates) covering homogeneous world
    points (N, 4) after projection, padded and clipped to the frame; None if a point is at or
    behind the camera plane (its projection is unbounded)."""
    clip = np.asarray(points, np.float64) @ np.asarray(view_projection, np.float64).T
    w = clip[:, 3]
    if not np.all(w > 1e-9):
        return None
    ndc = clip[:, :2] / w[:, None]
    x = (ndc[:, 0] * 0.5 + 0.5) * width
    y = (ndc[:, 1] * 0.5 + 0.5) * height
    x0, y0 = int(np.floor(x.min())), int(np.floor(y.min()))
    return grown((x0, y0, int(np.ceil(x.max())) - x0, int(np.ceil(y.max())) - y0), pad, width, height)


def grown(rect: Rect | None, pixels: int, width: int, height: int) -> Rect | None:
    """`rect` grown by `pixels` on every side, clipped to the frame (None stays None)."""
    if rect is None:
        return None
    x0, y0 = max(rect[0] - pixels, 0), max(rect[1] - pixels, 0)
    x1, y1 = min(rect[0] + rect[2] + pixels, width), min(rect[1] + rect[3] + pixels, height)
    return (x0, y0, max(x1 - x0, 0), max(y1 - y0, 0))


def strips_around(rect: Rect, width: int, height: int) -> list[Rect]:
    """The frame outside `rect` as up to four non-empty rectangles: below, above, left, right."""
    x, y, w, h = rect
    strips = [(0, 0, width, y), (0, y + h, width, height - y - h), (0, y, x, h), (x + w, y, width - x - w, h)]
    return [s for s in strips if s[2] > 0 and s[3] > 0]


def read_image(fbo: Any, rect: Rect | None, size: tuple[int, int], dtype: str) -> np.ndarray:
    """RGBA of the framebuffer, top row first; with `rect` only that rectangle is read, the rest
    is zero (transparent black, what the frame holds there)."""
    width, height = size
    numpy_type = np.uint8 if dtype == "f1" else np.float32
    if rect is None:
        data = np.frombuffer(fbo.read(components=4, dtype=dtype), numpy_type)
        return data.reshape(height, width, 4)[::-1].copy()
    image = np.zeros((height, width, 4), numpy_type)
    x, y, w, h = rect
    if w and h:
        data = np.frombuffer(fbo.read(viewport=rect, components=4, dtype=dtype), numpy_type).reshape(h, w, 4)
        image[height - y - h : height - y, x : x + w] = data[::-1]
    return image
