"""The preview's options, declared once (cnlmc.backends.base.Option) and parsed once, and the
tier they choose. AR declares its options on top of these (`preview_option`)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ..base import Option, OptionError, Options
from ..base import parse_options as parse_declared
from ..glsl.options import OPTIONS as GLSL_OPTIONS
from .glass import GLASS_FORMS
from .meshes import MESH_FORMATS, mesh_choices
from .tiers import DEFAULT_TIER, TIERS, Tier, TierError, parse_tier, select_tier

#: the GLSL backend's options the preview passes on (they change the BSDF it renders)
GLSL_PASSED = ("fresnel", "multiscatter")
SIZE_RANGE = (8, 8192)

OPTIONS: tuple[Option, ...] = (
    Option("size", int, 512, doc=f"image size in pixels ({SIZE_RANGE[0]} ... {SIZE_RANGE[1]})"),
    Option("mesh", str, "sphere", doc=f"{mesh_choices()}, or a path to an {MESH_FORMATS} file"),
    Option("tier", str, None, doc=f"quality tier: {', '.join(TIERS)}, mcN or fisN (default {DEFAULT_TIER})"),
    Option(
        "budget_ms",
        float,
        None,
        doc="without a tier: the best tier whose measured frame time fits",
        range=(0.001, 1e6),
    ),
    Option("env", str, "studio", doc="studio, sky, sun, or a path to an .hdr/.exr environment"),
    Option("background", str, "env", choices=("env", "transparent"), doc="the blurred environment, or none"),
    Option("exposure", float, 1.0, doc="linear exposure before the tone curve", range=(0.0, 1e4)),
    Option(
        "msaa",
        int,
        0,
        choices=(0, 1, 2, 4, 8),
        doc="samples per pixel; 0: off, an edge filter in the tone map (2 or 4 cost 3-4x)",
    ),
    Option(
        "glass",
        str,
        "auto",
        choices=GLASS_FORMS,
        doc="how a glass material transmits: a solid (refracted at both interfaces), a thin-walled sheet, "
        "or auto (a closed mesh is a solid, an open one a sheet)",
    ),
    *(option for option in GLSL_OPTIONS if option.name in GLSL_PASSED),
)


def preview_option(name: str, **changes: Any) -> Option:
    """One of the preview's options, with some fields changed (another target's default)."""
    option = next(o for o in OPTIONS if o.name == name)
    return dataclasses.replace(option, **changes)


class PreviewOptionError(OptionError):
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
    glass: str = "auto"


def parse_options(pairs: Mapping[str, object] | None) -> PreviewOptions:
    """Raw `--option` pairs -> PreviewOptions (PreviewOptionError, with did-you-mean, when wrong)."""
    try:
        return preview_options(parse_declared(OPTIONS, pairs, "preview"))
    except OptionError as exc:
        raise PreviewOptionError(str(exc)) from None


def glsl_pairs(options: Options) -> dict[str, str]:
    """The GLSL backend's options among parsed ones, as it reads them."""
    return {name: options[name] for name in GLSL_PASSED}


def checked_tier(name: str | None, error: Callable[[str], Exception] = PreviewOptionError) -> str:
    """The tier option as given ('' when not set), known to parse."""
    if not name:
        return ""
    try:
        parse_tier(name)
    except TierError as exc:
        raise error(str(exc)) from None
    return name


def preview_options(options: Options) -> PreviewOptions:
    """Parsed options -> what the renderer reads, with the checks a declaration cannot say."""
    low, high = SIZE_RANGE
    if not low <= options.size <= high:
        raise PreviewOptionError(f"preview: size {options.size} is out of range ({low} ... {high})")
    return PreviewOptions(
        options.size,
        options.mesh,
        checked_tier(options.tier),
        options.budget_ms,
        options.env,
        options.background,
        options.exposure,
        options.msaa,
        glsl_pairs(options),
        options.glass,
    )


def choose_tier(renderer: Any, scene: Any, material: Any, opts: PreviewOptions) -> tuple[Tier, dict[str, float]]:
    """The tier option, else the best tier within budget_ms, else the default."""
    if opts.tier:
        return parse_tier(opts.tier), {}
    if opts.budget_ms is None:
        return parse_tier(DEFAULT_TIER), {}
    return select_tier(opts.budget_ms, lambda t: renderer.frame_time(scene, material, t, opts.glsl, repeats=3))
