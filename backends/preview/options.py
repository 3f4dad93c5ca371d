"""The preview's options (`--option key=value` strings), parsed once, and the tier they choose."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..capabilities import COMPILER_OPTIONS
from .tiers import DEFAULT_TIER, parse_tier, select_tier

OPTIONS = {
    "size": "512",
    "mesh": "sphere",
    "tier": "",
    "budget_ms": "",
    "env": "studio",
    "background": "env",
    "exposure": "1.0",
    "msaa": "0",
    "fresnel": "exact",
    "multiscatter": "off",
    "seed": "0",
}


class PreviewOptionError(ValueError):
    """An unknown option or a value that cannot be used."""


@dataclass
class PreviewOptions:
    size: int = 512
    mesh: str = "sphere"
    tier: str = ""
    budget_ms: float | None = None
    env: str = "studio"
    background: str = "env"
    exposure: float = 1.0
    msaa: int = 0
    glsl: dict = field(default_factory=dict)


def parse_options(options: dict | None) -> PreviewOptions:
    options = {k: str(v) for k, v in (options or {}).items() if k in OPTIONS or k not in COMPILER_OPTIONS}
    unknown = sorted(set(options) - set(OPTIONS))
    if unknown:
        raise PreviewOptionError(f"preview: unknown option(s) {', '.join(unknown)}; known: {', '.join(OPTIONS)}")
    o = {**OPTIONS, **options}
    try:
        size, msaa, exposure = int(o["size"]), int(o["msaa"]), float(o["exposure"])
        budget = float(o["budget_ms"]) if o["budget_ms"] else None
    except ValueError as exc:
        raise PreviewOptionError(f"preview: {exc}") from None
    if not 8 <= size <= 8192:
        raise PreviewOptionError(f"preview: size {size} is out of range (8 ... 8192)")
    if o["background"] not in ("env", "transparent"):
        raise PreviewOptionError("preview: background must be env or transparent")
    if o["tier"]:
        try:
            parse_tier(o["tier"])
        except ValueError as exc:
            raise PreviewOptionError(str(exc)) from None
    return PreviewOptions(
        size,
        o["mesh"],
        o["tier"],
        budget,
        o["env"],
        o["background"],
        exposure,
        msaa,
        {"fresnel": o["fresnel"], "multiscatter": o["multiscatter"]},
    )


def choose_tier(renderer, scene, material: dict, opts: PreviewOptions):
    """The tier option, else the best tier within budget_ms, else the default."""
    if opts.tier:
        return parse_tier(opts.tier), {}
    if opts.budget_ms is None:
        return parse_tier(DEFAULT_TIER), {}
    return select_tier(opts.budget_ms, lambda t: renderer.frame_time(scene, material, t, opts.glsl, repeats=3))
