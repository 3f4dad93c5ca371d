"""The AR command's options (`--option key=value` strings), parsed once, and what they choose:
the camera matrix and the IR material to place."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..capabilities import COMPILER_OPTIONS
from .errors import AROptionError
from .pose import default_intrinsics

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
