"""Native MaterialX recipes for cnlmc procedural maps (`--option maps=native`).

RECIPES: (graph, output) -> recipe(ctx) -> the MaterialX node whose output stands for the
map (the same thing a baked `image` node would give: a colour, a float in [0,1], or an
encoded tangent-space normal). The caller connects it through the same path as images
(conductor tint, sqrt for linear roughness, normalmap). The patterns are driven by
`texcoord`, scaled like the cnlmc graph (params scale, contrast, strength, coverage), and
are similar to, not the same pixels as, the baked maps. Maps without a recipe are baked.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Collection, Iterable, Mapping
from importlib import resources
from typing import Any

import MaterialX as mx
import numpy as np

from cnlmc.material import MapRef, Material, Params

from ..maps.service import bake_arrays

NATIVE = ("approximate", "expressed with MaterialX nodes: similar pattern, not the same pixels as cnlmc's baked map")

_TYPES = {"color3": mx.Color3, "vector2": mx.Vector2, "vector3": mx.Vector3}


# The size cnlmc's own map is baked at to learn its mean colour (our choice: the mean at 128 is
# within 1 % of the mean at 256 for marble and granite, 2 % for rust, in a tenth of the time).
MEAN_BAKE_SIZE = 256
GAIN_RANGE = (0.0, 4.0)


def load_stats() -> dict[str, Any]:
    """The measured means of the recipes' patterns (materialx_native_stats.json, with its source)."""
    text = resources.files("cnlmc.backends.exchange").joinpath("materialx_native_stats.json").read_text()
    return dict(json.loads(text))


class Ctx:
    """What a recipe needs: the document, a name prefix, the map's graph params, the material, and
    the measured pattern means (`stats`)."""

    def __init__(self, doc: Any, ident: str, ref: MapRef, material: Material, stats: Mapping[str, Any]):
        self.doc, self.prefix, self.graph_params = doc, f"{ident}_{ref.graph}", ref.params
        self.material: Params = material.params
        self.source, self.ref, self.stats = material, ref, stats

    def baked_mean(self) -> np.ndarray:
        """The mean linear colour of cnlmc's own baked map for this ref (the one maps=bake writes)."""
        material = Material.from_ir({**self.source.to_ir(), "maps": {"base_color": self.ref.to_ir()}})
        colour = bake_arrays(material, MEAN_BAKE_SIZE, 0, roles=("base_color",))["base_color"]
        return np.asarray(colour, dtype=np.float64).reshape(-1, 3).mean(axis=0)

    def mean_matched(self, colour: Any, expected: Iterable[float]) -> Any:
        """colour x (cnlmc's baked mean / the recipe's expected mean), per channel: the native
        pattern keeps the mean colour of the baked map."""
        expected_mean = np.maximum(np.asarray(list(expected), dtype=np.float64), 1e-6)
        gain = np.clip(self.baked_mean() / expected_mean, *GAIN_RANGE)
        return self.node("multiply", "color_mean", "color3", in1=colour, in2=_colour(gain))

    def param(self, name: str, default: float) -> float:
        """A graph parameter; `default`: the recipe's value where the IR leaves it to the graph."""
        return float(self.graph_params.get(name, default))

    def node(self, category: str, name: str, mx_type: str, **inputs: Any) -> Any:
        """Add a node (or reuse one of that name: maps of one graph share their pattern)."""
        full = f"{self.prefix}_{name}"
        existing = self.doc.getNode(full)
        if existing is not None:
            return existing
        node = self.doc.addNode(category, full, mx_type)
        for key, value in inputs.items():
            if isinstance(value, mx.Node):
                node.setConnectedNode(key, value)
            elif isinstance(value, tuple):  # (type, value)
                kind, raw = value
                node.setInputValue(key, _TYPES[kind](*raw) if kind in _TYPES else raw, kind)
            elif isinstance(value, int) and not isinstance(value, bool):
                node.setInputValue(key, value, "integer")
            else:
                node.setInputValue(key, float(value), "float")
        return node

    def uv(self, name: str, frequency: float, offset: tuple[float, float] = (0.0, 0.0)) -> Any:
        """texcoord * frequency (+ offset, so patterns of one graph decorrelate)."""
        tex = self.node("texcoord", "texcoord", "vector2")
        scaled = self.node("multiply", f"{name}_uv", "vector2", in1=tex, in2=round(frequency, 6))
        if offset == (0.0, 0.0):
            return scaled
        return self.node("add", f"{name}_uv_offset", "vector2", in1=scaled, in2=("vector2", offset))

    def unit(self, name: str, noise: Any) -> Any:
        """A noise in about [-1, 1] -> [0, 1], clamped."""
        remap = self.node("remap", f"{name}_01", "float", **{"in": noise}, inlow=-1.0, inhigh=1.0)
        return self.node("clamp", f"{name}_clamp", "float", **{"in": remap})


def _colour(values: Iterable[float]) -> tuple[str, tuple[float, ...]]:
    return ("color3", tuple(round(float(v), 6) for v in values))


def _scaled(colour: Iterable[float], factor: float) -> tuple[str, tuple[float, ...]]:
    return _colour(min(max(c * factor, 0.0), 1.0) for c in colour)


# ---------------------------------------------------------------------------- sandblasted


def sandblasted_roughness(ctx: Ctx) -> Any:
    """Low-frequency fractal2d blotches: roughness +-0.05*contrast around the material's."""
    r, contrast = float(ctx.material.roughness), ctx.param("contrast", 1.0)
    blotches = ctx.node("fractal2d", "blotches", "float", octaves=3, texcoord=ctx.uv("blotches", 4.0))
    spread = 0.05 * contrast
    remap = ctx.node(
        "remap", "roughness", "float", **{"in": blotches}, inlow=-1.0, inhigh=1.0, outlow=r - spread, outhigh=r + spread
    )
    return ctx.node("clamp", "roughness_clamp", "float", **{"in": remap})


def sandblasted_normal(ctx: Ctx) -> Any:
    """Dense fine noise2d pits -> heighttonormal (an encoded tangent-space normal)."""
    scale, strength = ctx.param("scale", 1.0), ctx.param("strength", 1.0)
    pits = ctx.node("noise2d", "pits", "float", amplitude=0.5, pivot=0.5, texcoord=ctx.uv("pits", 96.0 * scale))
    return ctx.node("heighttonormal", "normal", "vector3", **{"in": pits}, scale=round(0.08 * strength, 6))


# --------------------------------------------------------------------------------- marble


def marble_veins(ctx: Ctx) -> Any:
    """Vein darkness in [0,1]: 1 - |sin(bands + turbulence)|^0.3 (thin dark lines)."""
    scale, grain = ctx.param("scale", 1.0), ctx.param("grain", 1.0)
    angle = math.radians(ctx.param("direction", 30.0))
    turbulence = ctx.node(
        "fractal2d", "turbulence", "float", octaves=6, diminish=0.55, texcoord=ctx.uv("turbulence", 3.0)
    )
    across = ctx.node(
        "dotproduct",
        "across",
        "float",
        in1=ctx.uv("bands", 1.0),
        in2=("vector2", (round(math.cos(angle), 6), round(math.sin(angle), 6))),
    )
    bands = ctx.node("multiply", "bands", "float", in1=across, in2=round(math.pi * 3.0 * scale, 6))
    bend = ctx.node("multiply", "bend", "float", in1=turbulence, in2=round(1.4 * grain * math.pi, 6))
    phase = ctx.node("add", "phase", "float", in1=bands, in2=bend)
    wave = ctx.node("absval", "wave", "float", **{"in": ctx.node("sin", "sin", "float", **{"in": phase})})
    lines = ctx.node("power", "lines", "float", in1=wave, in2=0.3)
    return ctx.node("subtract", "veins", "float", in1=1.0, in2=lines)


def marble_color(ctx: Ctx) -> Any:
    """mix(base_color, darker vein colour, veins), scaled to the baked map's mean."""
    base = ctx.material.base_color
    dark = _scaled(base, 1.0 - min(0.45 * ctx.param("contrast", 1.0), 1.0))
    colour = ctx.node("mix", "color", "color3", fg=dark, bg=_colour(base), mix=marble_veins(ctx))
    veins = float(ctx.stats["marble"]["veins"])
    return ctx.mean_matched(colour, [b + (d - b) * veins for b, d in zip(_colour(base)[1], dark[1])])


def marble_roughness(ctx: Ctx) -> Any:
    r = float(ctx.material.roughness)
    return ctx.node("remap", "roughness", "float", **{"in": marble_veins(ctx)}, outlow=r, outhigh=r + 0.08)


# -------------------------------------------------------------------------------- granite


def granite_minerals(ctx: Ctx) -> Any:
    """Crystals (cellnoise2d, one value per cell) blended with fine worleynoise2d speckles."""
    scale = ctx.param("scale", 1.0)
    crystals = ctx.node("cellnoise2d", "crystals", "float", texcoord=ctx.uv("crystals", 40.0 * scale))
    speckle = ctx.node(
        "worleynoise2d", "speckle", "float", jitter=1.0, texcoord=ctx.uv("speckle", 64.0 * scale, (0.37, 0.71))
    )
    return ctx.node("mix", "minerals", "float", fg=speckle, bg=crystals, mix=0.35)


def granite_color(ctx: Ctx) -> Any:
    """mix(dark speckle colour, light crystal colour, minerals) around base_color."""
    base, contrast = ctx.material.base_color, ctx.param("contrast", 1.0)
    dark = _scaled(base, max(1.0 - 0.85 * contrast, 0.0))
    light = _scaled(base, 1.0 + 0.35 * contrast)
    colour = ctx.node("mix", "color", "color3", fg=light, bg=dark, mix=granite_minerals(ctx))
    minerals = float(ctx.stats["granite"]["minerals"])
    return ctx.mean_matched(colour, [d + (lt - d) * minerals for d, lt in zip(dark[1], light[1])])


def granite_roughness(ctx: Ctx) -> Any:
    r = float(ctx.material.roughness)
    return ctx.node("remap", "roughness", "float", **{"in": granite_minerals(ctx)}, outlow=r + 0.05, outhigh=r - 0.05)


# ----------------------------------------------------------------------------------- rust

RUST_DARK, RUST_LIGHT = (0.09, 0.03, 0.012), (0.5, 0.2, 0.05)


def rust_mask(ctx: Ctx) -> Any:
    """Corrosion patches: fractal2d minus worley pits, thresholded by coverage (soft edge)."""
    scale, coverage = ctx.param("scale", 1.0), ctx.param("coverage", 0.4)
    patches = ctx.node(
        "fractal2d", "patches", "float", octaves=7, diminish=0.6, texcoord=ctx.uv("patches", 3.0 * scale)
    )
    pits = ctx.node("worleynoise2d", "pits", "float", texcoord=ctx.uv("pits", 24.0 * scale, (0.13, 0.59)))
    pitted = ctx.node(
        "subtract",
        "corrosion",
        "float",
        in1=patches,
        in2=ctx.node("multiply", "pits_amount", "float", in1=pits, in2=0.15),
    )
    # full cover from the last per cent up, continuously (the stats table's 0.99 and 1.0 rows): a
    # coverage such as 0.9993 ('heavily rusted') covers nearly all of it, as cnlmc's bake does
    threshold = (0.5 - coverage) * 1.2 - min(max((coverage - 0.99) / 0.01, 0.0), 1.0)
    return ctx.node(
        "smoothstep", "mask", "float", **{"in": pitted}, low=round(threshold - 0.04, 6), high=round(threshold + 0.04, 6)
    )


def rust_flakes(ctx: Ctx) -> Any:
    scale = ctx.param("scale", 1.0)
    flakes = ctx.node("fractal2d", "flakes", "float", octaves=4, texcoord=ctx.uv("flakes", 16.0 * scale, (0.41, 0.23)))
    contrast = ctx.node(
        "multiply", "flakes_contrast", "float", in1=flakes, in2=round(1.5 * ctx.param("contrast", 1.0), 6)
    )
    return ctx.unit("flakes", contrast)


def rust_color(ctx: Ctx) -> Any:
    """mix(base_color, rust colour (dark..orange flakes), mask), scaled to the baked map's mean."""
    flaky = ctx.node("mix", "rust_color", "color3", fg=_colour(RUST_LIGHT), bg=_colour(RUST_DARK), mix=rust_flakes(ctx))
    colour = ctx.node("mix", "color", "color3", fg=flaky, bg=_colour(ctx.material.base_color), mix=rust_mask(ctx))
    table, coverage = ctx.stats["rust"], ctx.param("coverage", 0.4)
    mask = float(np.interp(coverage, table["coverage"], table["mask"]))
    both = float(np.interp(coverage, table["coverage"], table["mask_flakes"]))
    base = _colour(ctx.material.base_color)[1]
    expected = [b * (1 - mask) + d * (mask - both) + lt * both for b, d, lt in zip(base, RUST_DARK, RUST_LIGHT)]
    return ctx.mean_matched(colour, expected)


def rust_roughness(ctx: Ctx) -> Any:
    rough = ctx.node("remap", "rust_roughness", "float", **{"in": rust_flakes(ctx)}, outlow=0.75, outhigh=0.95)
    return ctx.node("mix", "roughness", "float", fg=rough, bg=float(ctx.material.roughness), mix=rust_mask(ctx))


def rust_metallic(ctx: Ctx) -> Any:
    """Metalness = 1 - mask (bare metal between the patches)."""
    return ctx.node("subtract", "metallic", "float", in1=1.0, in2=rust_mask(ctx))


Recipe = Callable[[Ctx], Any]
RECIPES: Mapping[tuple[str, str], Recipe] = {
    ("sandblasted", "roughness"): sandblasted_roughness,
    ("sandblasted", "normal"): sandblasted_normal,
    ("marble", "color"): marble_color,
    ("marble", "roughness"): marble_roughness,
    ("granite", "color"): granite_color,
    ("granite", "roughness"): granite_roughness,
    ("rust", "color"): rust_color,
    ("rust", "roughness"): rust_roughness,
    ("rust", "mask"): rust_metallic,  # the mask drives base metalness = 1 - mask
    ("rust", "metallic"): rust_metallic,
}


def recipe_for(graph: str, output: str) -> Recipe | None:
    return RECIPES.get((graph, output))


def native_roles(material: Material, roles: Collection[str]) -> dict[str, MapRef]:
    """role -> map ref for the maps of a material that have a recipe (roles: the ones used)."""
    return {
        role: ref
        for role, ref in material.maps.items()
        if role in roles and recipe_for(ref.graph, ref.output) is not None
    }


def build(doc: Any, material: Material, ident: str, ref: MapRef, stats: Mapping[str, Any] | None = None) -> Any:
    """Add the recipe's nodes; returns the node standing for the map. `stats`: load_stats()."""
    recipe = recipe_for(ref.graph, ref.output)
    if recipe is None:
        raise KeyError(f"no MaterialX recipe for {ref.graph}.{ref.output}")
    return recipe(Ctx(doc, ident, ref, material, stats if stats is not None else load_stats()))
