"""The node-type registry: type name -> function and its input table.

Input kinds: 'map' (another node's output, a number or an RGB triple), 'int', 'float',
'color' (RGB triple), 'colors' (list of RGB triples), 'floats' (list of numbers),
'enum' (one of `choices`), 'bool'.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from . import filters, noise, normals, patterns
from .worley import FEATURES

REQUIRED = object()


@dataclass(frozen=True)
class Input:
    kind: str
    default: Any = REQUIRED
    doc: str = ""
    choices: tuple = ()


@dataclass(frozen=True)
class NodeType:
    function: Callable
    inputs: dict[str, Input] = field(default_factory=dict)
    category: str = "filter"

    @property
    def doc(self) -> str:
        return (self.function.__doc__ or "").strip().split("\n")[0]


def noise_inputs(**extra) -> dict[str, Input]:
    table = {
        "scale": Input("int", 8, "lattice cells across the tile (higher = finer)"),
        "stretch": Input("int", 1, "features this many times longer along u than v"),
    }
    table.update(extra)
    return table


def fractal_inputs() -> dict[str, Input]:
    return noise_inputs(
        basis=Input("enum", "perlin", "octave noise", tuple(noise.BASES)),
        scale=Input("int", 4, "cells across the tile in the first octave"),
        octaves=Input("int", 5, "number of octaves (capped where cells reach 2 px)"),
        gain=Input("float", 0.5, "amplitude ratio between successive octaves"),
    )


MAP, ZERO, ONE = "map", 0.0, 1.0

GENERATORS = {
    "value": NodeType(noise.single("value"), noise_inputs(), "generator"),
    "perlin": NodeType(noise.single("perlin"), noise_inputs(), "generator"),
    "simplex": NodeType(noise.single("simplex"), noise_inputs(), "generator"),
    "fbm": NodeType(noise.fbm, fractal_inputs(), "generator"),
    "turbulence": NodeType(noise.turbulence, fractal_inputs(), "generator"),
    "worley": NodeType(
        noise.worley,
        noise_inputs(
            feature=Input("enum", "f1", "f1, f2, edge (f2 - f1) or cell (random per cell)", FEATURES),
            jitter=Input("float", 1.0, "how far feature points stray from cell centres (0..1)"),
        ),
        "generator",
    ),
    "wave": NodeType(
        patterns.wave,
        {
            "shape": Input("enum", "sine", "wave shape", patterns.WAVE_SHAPES),
            "frequency": Input("int", 1, "cycles across the tile"),
            "direction": Input("float", 0.0, "degrees, 0 = along u, 90 = along v (snapped to tile)"),
            "phase": Input(MAP, ZERO, "phase offset map in cycles"),
            "distortion": Input("float", 1.0, "multiplier on the phase map"),
        },
        "generator",
    ),
    "linear_gradient": NodeType(
        patterns.linear_gradient,
        {
            "direction": Input("float", 0.0, "degrees"),
            "repeat": Input("int", 1, "ramps across the tile"),
            "mirror": Input("bool", True, "triangle ramp (seamless) instead of saw"),
        },
        "generator",
    ),
    "radial_gradient": NodeType(
        patterns.radial_gradient,
        {"centre_u": Input("float", 0.5), "centre_v": Input("float", 0.5), "radius": Input("float", 0.5, "tile units")},
        "generator",
    ),
    "checkerboard": NodeType(
        patterns.checkerboard, {"count": Input("int", 8, "cells per side (made even)")}, "generator"
    ),
    "tiles": NodeType(
        patterns.tiles,
        {
            "count": Input("int", 4, "tiles per side"),
            "gap": Input("float", 0.05, "grout width, tile units"),
            "bevel": Input("float", 0.05, "bevel width, tile units"),
            "feature": Input("enum", "height", "height or cell", ("height", "cell")),
        },
        "generator",
    ),
    "bricks": NodeType(
        patterns.bricks,
        {
            "rows": Input("int", 8, "brick rows (made even)"),
            "per_row": Input("int", 4, "bricks per row"),
            "gap": Input("float", 0.06, "mortar width in brick heights"),
            "bevel": Input("float", 0.04, "bevel width in brick heights"),
            "feature": Input("enum", "height", "height or cell", ("height", "cell")),
        },
        "generator",
    ),
}

FILTERS = {
    "blend": NodeType(
        filters.blend,
        {
            "a": Input(MAP, ZERO, "bottom layer"),
            "b": Input(MAP, ONE, "top layer"),
            "mode": Input("enum", "mix", "blend mode", filters.BLEND_MODES),
            "amount": Input(MAP, ONE, "opacity of the top layer (map or number)"),
            "clamp": Input("bool", True, "clamp to [0, 1]"),
        },
    ),
    "blur": NodeType(filters.blur, {"input": Input(MAP), "radius": Input("float", 0.01, "Gaussian sigma, tile units")}),
    "directional_blur": NodeType(
        filters.directional_blur,
        {
            "input": Input(MAP),
            "length": Input("float", 0.1, "streak length, tile units"),
            "direction": Input("float", 0.0, "degrees"),
        },
    ),
    "levels": NodeType(
        filters.levels,
        {
            "input": Input(MAP),
            "in_low": Input("float", 0.0),
            "in_high": Input("float", 1.0),
            "gamma": Input("float", 1.0),
            "out_low": Input("float", 0.0),
            "out_high": Input("float", 1.0),
        },
    ),
    "contrast": NodeType(
        filters.contrast,
        {
            "input": Input(MAP),
            "amount": Input("float", 1.0, "0 flat, 1 unchanged, >1 more"),
            "pivot": Input("float", 0.5),
        },
    ),
    "invert": NodeType(filters.invert, {"input": Input(MAP)}),
    "colorize": NodeType(
        filters.colorize,
        {
            "input": Input(MAP),
            "colors": Input("colors", ((0, 0, 0), (1, 1, 1)), "gradient stops"),
            "positions": Input("floats", None, "stop positions (default: even)"),
        },
    ),
    "hsv_adjust": NodeType(
        filters.hsv_adjust,
        {
            "input": Input(MAP),
            "hue": Input("float", 0.0, "turns"),
            "saturation": Input("float", 1.0),
            "value": Input("float", 1.0),
        },
    ),
    "threshold": NodeType(
        filters.threshold, {"input": Input(MAP), "low": Input("float", 0.45), "high": Input("float", 0.55)}
    ),
    "warp": NodeType(
        filters.warp,
        {
            "input": Input(MAP),
            "by": Input(MAP, 0.5, "u displacement map (0.5 = none)"),
            "by_v": Input(MAP, None, "v displacement map (default: `by` shifted half a tile)"),
            "amount": Input("float", 0.1, "displacement at by = 1, tile units"),
        },
    ),
    "transform": NodeType(
        filters.transform,
        {
            "input": Input(MAP),
            "scale": Input("int", 1, "repeats (integer keeps tiling)"),
            "rotate": Input("float", 0.0, "degrees (snapped to the lattice)"),
            "offset_u": Input("float", 0.0),
            "offset_v": Input("float", 0.0),
        },
    ),
    "normalize": NodeType(
        filters.normalize, {"input": Input(MAP), "spread": Input("float", 0.18, "standard deviation after")}
    ),
    "coverage_mask": NodeType(
        filters.coverage_mask,
        {
            "input": Input(MAP),
            "coverage": Input("float", 0.5, "fraction of the tile covered (0..1)"),
            "softness": Input("float", 0.05, "edge width in quantile units"),
        },
    ),
    "height_to_normal": NodeType(
        normals.height_to_normal,
        {"input": Input(MAP, doc="height map"), "strength": Input("float", 1.0, "bump strength")},
    ),
}

NODE_TYPES: dict[str, NodeType] = {**GENERATORS, **FILTERS}
