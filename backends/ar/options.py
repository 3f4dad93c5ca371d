"""The AR command's options, declared once on top of the preview's (cnlmc.backends.base.Option)
and parsed once, and what they choose: the camera matrix and the IR material to place."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from cnlmc.material import Document, Material

from ..base import Option, OptionError, as_document
from ..base import parse_options as parse_declared
from ..preview.options import GLSL_PASSED, checked_tier, glsl_pairs, preview_option
from .errors import AROptionError
from .marker import MARKER_IDS
from .pose import default_intrinsics

NAME = "ar"
#: AR's own options, then the preview's it renders with (AR's defaults: the teapot, msaa 4)
OPTIONS: tuple[Option, ...] = (
    Option(
        "marker_length",
        float,
        0.1,
        doc="the printed marker's side (any unit: the scene is relative to it)",
        range=(1e-6, 1e6),
    ),
    Option("marker_id", int, None, doc="the marker to use (default: the largest found)", range=(0, MARKER_IDS - 1)),
    Option("scale", float, 1.0, doc="the object's bounding-sphere diameter in marker lengths", range=(1e-3, 1e3)),
    Option("intrinsics", str, None, doc="fx,fy,cx,cy in pixels (default: from the image size and fov)"),
    Option("fov", float, 60.0, doc="horizontal field of view in degrees, without intrinsics", range=(1.0, 179.0)),
    Option("dist", str, None, doc="lens distortion k1,k2,p1,p2[,k3[,k4,k5,k6]]"),
    Option("shadow", float, 0.65, doc="contact shadow opacity (0: none)", range=(0.0, 1.0)),
    Option("material", str, None, doc="the IR material to place: its name or index (default the first)"),
    preview_option("mesh", default="teapot"),
    preview_option("tier", default="splitsum"),
    preview_option("env"),
    preview_option("exposure"),
    preview_option("msaa", default=4, doc="samples per pixel (4 for a photo; a video's default 0: the edge filter)"),
    *(preview_option(name) for name in GLSL_PASSED),
)


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


def _floats(text: str | None, count: tuple[int, ...], what: str) -> tuple[float, ...] | None:
    if not text:
        return None
    try:
        values = tuple(float(x) for x in text.replace(";", ",").split(","))
    except ValueError:
        raise AROptionError(f"ar: {what} must be comma-separated numbers, got {text!r}") from None
    if len(values) not in count:
        raise AROptionError(f"ar: {what} takes {' or '.join(map(str, count))} numbers, got {len(values)}")
    if not all(math.isfinite(v) for v in values):
        raise AROptionError(f"ar: {what} must be finite numbers, got {text!r}")
    return values


def _intrinsics(text: str | None) -> tuple[float, ...] | None:
    """fx,fy,cx,cy: focal lengths in pixels (positive), the principal point (finite)."""
    values = _floats(text, (4,), "intrinsics")
    if values is not None and not (values[0] > 0 and values[1] > 0):
        raise AROptionError(f"ar: intrinsics fx and fy must be positive (pixels), got {text!r}")
    return values


def parse_options(pairs: Mapping[str, object] | None) -> AROptions:
    """Raw `--option` pairs -> AROptions (AROptionError, with did-you-mean, when wrong)."""
    try:
        o = parse_declared(OPTIONS, pairs, NAME)
    except OptionError as exc:
        raise AROptionError(str(exc)) from None
    return AROptions(
        o.marker_length,
        o.marker_id,
        o.scale,
        _intrinsics(o.intrinsics),
        o.fov,
        _floats(o.dist, (4, 5, 8), "dist"),
        o.mesh,
        checked_tier(o.tier, AROptionError),
        o.env,
        o.shadow,
        o.material or "",
        o.exposure,
        o.msaa,
        glsl_pairs(o),
    )


def camera_matrix(opts: AROptions, width: int, height: int) -> np.ndarray:
    if opts.intrinsics:
        fx, fy, cx, cy = opts.intrinsics
        return np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]], np.float64)
    return default_intrinsics(width, height, opts.fov)


IR = Document | Mapping[str, Any]  # the typed document, or its JSON form


def pick_material(ir: IR, which: str) -> Material:
    """The IR material the `material` option names (its name or index; default the first)."""
    materials = as_document(ir).materials
    if not materials:
        raise AROptionError("ar: the IR has no material")
    if not which:
        return materials[0]
    if which.isdigit() and int(which) < len(materials):
        return materials[int(which)]
    for m in materials:
        if m.name == which:
            return m
    raise AROptionError(f"ar: no material {which!r} (have: {', '.join(m.name for m in materials)})")
