"""Mitsuba 3 for a material with light inside (docs/subsurface.md): the volumetric reference.

`volume`: a `dielectric` (or `roughdielectric`) boundary of the IR's IOR and alpha around a
`homogeneous` medium: σt and the single-scattering albedo σs/σt from the IR's (color, radius, g)
by cnlmc.bsdf.subsurface.medium_of (the dipole inversion, Jensen & Buhler 2002), a Henyey–Greenstein
phase function of g; the RGB `sigma_t` is divided by its largest channel (Mitsuba reads an RGB as a
reflectance in [0, 1]) and `scale` = that channel × METRES_PER_UNIT (σ per metre, the scene's unit
METRES_PER_UNIT metres). The scene then uses `volpathmis` (spectral MIS: Mitsuba's `volpath` is biased dark for a chromatic medium, 0.69 instead of 1 in blue in a white furnace; volpathmis 0.96-1.02). This is exact: a path tracer of
the medium the IR names.

`thin`: Mitsuba 3 has no thin translucent slab BSDF and no layering, so the sheet is a `blendbsdf`
of weight w = max T (T the Kubelka–Munk slab's transmittance at the IR's thickness,
cnlmc.bsdf.subsurface.slab): (1 - w) a two-sided `roughplastic` (`plastic` when smooth) of the IR's
IOR and alpha over the diffuse base_color — the waxy cuticle on both faces: GGX interface
reflection, the diffuse base under it sees only what the interface lets in (Mitsuba's
(1 - F)(1 - F) with internal re-reflection; the colour scaled to the IR's diffuse energy as for a
plastic) — and w a pure diffuse transmitter (`principledthin`, diff_trans 2) of colour T / w.
The blend gives the cuticle weight 1 - w, so its `specular_reflectance` is 1 / (1 - w) (the
interface at full strength), bounded so that the cuticle alone returns at most 1 at every incidence
(`interface_boost`): the sheet then returns (1 - w) x at most 1 + T <= 1 (white furnace <= 1). Limits
of a convex blend (Mitsuba 3 has no layered BSDF): the light through is not Fresnel-attenuated, and
where the bound binds the interface is weaker than the IR's.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from cnlmc.bsdf.subsurface import medium_of, slab
from cnlmc.bsdf.transmission import DARKEST_TRANSMITTANCE, interface_albedo
from cnlmc.conventions import ALPHA_MIRROR
from cnlmc.material import Material

from .conversions import alpha_pair, diffuse_colour, roughplastic_diffuse_energy, rounded

Prop = dict[str, Any]
#: our choice: a preview sphere of radius 1 unit is a 10 cm ball (a candle, an apple, a teapot's
#: body), so millimetre mean free paths show as they would on such an object
METRES_PER_UNIT = 0.05
#: volpathmis's depth counts scattering events, and a bright medium needs about 1/(3 (1 - α')) of
#: them per path (wax 200, marble 300, cream 20 000): a scene with a medium renders to any depth (-1;
#: Russian roulette ends the paths), unbiased; `mitsuba scene.xml -D max_depth=N` caps it (darker)
VOLUME_MAX_DEPTH = -1
#: Mitsuba's volume path tracers play Russian roulette from `rr_depth` events on (default 5), a path
#: surviving with at most 0.95 a step and its weight divided by that: in a bright medium, whose paths
#: take about 1/(3 (1 - α')) events, the few that survive hundreds of steps carry weights of 1/0.95^k,
#: and the picture is speckle. So a scene with a medium starts the roulette after the events its
#: brightest channel's paths take (`roulette_depth`), at most this many (our choice: the cost bound).
#: Measured (white porcelain, white furnace, 64², 64 spp, 2 cores): rr_depth 5: mean 0.446, pixel std
#: 1.07, max 22.9, 1.1 s; 1500: 0.771 / 0.147 / 3.4, 9.3 s; no roulette: 0.959 / 0.083 / 1.2, 292 s.
VOLUME_RR_DEPTH_MAX = 2000
MITSUBA_RR_DEPTH = 5  # Mitsuba's own default
#: our choice: the margin for a diffuse base's reflectance at normal incidence over its hemispherical
#: mean (the interface's (1 - F) entry factor peaks there), in the bound on the sheet's interface boost
DIFFUSE_PEAK = 1.1
#: the incidences (cos theta) at which the interface's reflectance is found for that bound, to grazing
BOOST_MUS = np.linspace(0.01, 1.0, 25)


def _prop(kind: str, name: str, value: Any) -> Prop:
    if kind == "float":
        value = f"{float(value):.6g}"
    elif kind == "rgb":
        value = [f"{float(v):.6g}" for v in value]
    return {"kind": kind, "name": name, "value": value}


def _node(plugin: str, props: list[Prop]) -> Prop:
    return {"type": plugin, "id": None, "props": props, "children": []}


def medium_coefficients(material: Material) -> tuple[list[float], list[float], float]:
    """(σt in 1/m, single-scattering albedo, g) of the material's medium."""
    sub = material.params.subsurface
    assert sub is not None, "only a material with a medium has coefficients"
    medium = medium_of(sub.color, sub.radius, float(sub.anisotropy), float(material.params.ior))
    return [float(v) for v in medium.sigma_t], [float(v) for v in medium.single_albedo], float(sub.anisotropy)


def glass_absorption(material: Material) -> list[float] | None:
    """σa (1/m) of the glass's medium, per channel: −ln(base_color) / transmission_depth
    (Beer-Lambert); None for a colourless glass (nothing to absorb)."""
    colour = [min(max(float(c), DARKEST_TRANSMITTANCE), 1.0) for c in material.params.base_color]
    if min(colour) >= 1.0:
        return None
    return [(0.0 - float(np.log(c))) / float(material.params.transmission_depth) for c in colour]  # 0, not -0


def medium_entry(material: Material, ident: str, metres_per_unit: float = METRES_PER_UNIT) -> dict[str, Any] | None:
    """The `<medium>` a material's shapes take as their interior: a volume's scattering medium, a
    tinted glass's absorbing one (albedo 0); None for a thin sheet, a clear glass, an opaque model."""
    if material.model.base == "glass":
        sigma_a = glass_absorption(material)
        return None if sigma_a is None else _medium(ident, sigma_a, [0.0, 0.0, 0.0], 0.0, metres_per_unit)
    if material.model.subsurface != "volume":
        return None
    sigma_t, albedo, g = medium_coefficients(material)
    return _medium(ident, sigma_t, albedo, g, metres_per_unit)


def scattering_events(albedo: Sequence[float], g: float) -> float:
    """The scattering events a path takes in a medium's brightest channel: 1/(3 (1 - α')) with
    α' = α (1 - g)/(1 - α g), finite where α' reaches 1."""
    events = 0.0
    for value in albedo:
        reduced = value * (1.0 - g) / max(1.0 - value * g, 1e-12)
        events = max(events, 1.0 / (3.0 * max(1.0 - reduced, 1e-12)))
    return events


def roulette_depth(media: list[dict[str, Any]]) -> int:
    """The `rr_depth` for a scene with these `medium_entry` media: the events their paths take
    (`scattering_events`, kept in each entry), between Mitsuba's default and VOLUME_RR_DEPTH_MAX
    (VOLUME_RR_DEPTH_MAX's comment)."""
    events = max([float(MITSUBA_RR_DEPTH)] + [float(medium["events"]) for medium in media])
    return int(min(events, VOLUME_RR_DEPTH_MAX))


def _medium(ident: str, sigma_t: list[float], albedo: list[float], g: float, metres_per_unit: float) -> dict[str, Any]:
    largest = max(sigma_t)  # Mitsuba reads an RGB sigma_t as a reflectance in [0, 1]: the magnitude goes to scale
    return {
        "id": f"{ident}_medium",
        "sigma_t": [f"{v / largest:.6g}" for v in sigma_t],
        "albedo": [f"{min(v, 1.0):.6g}" for v in albedo],
        "g": f"{g:.6g}",
        "scale": f"{largest * metres_per_unit:.6g}",
        "events": scattering_events([min(v, 1.0) for v in albedo], g),
    }


def subsurface_bsdf(material: Material) -> Prop:
    """The boundary (volume) or the thin-walled sheet's BSDF."""
    if material.model.subsurface == "thin":
        return thin_bsdf(material)
    params = material.params
    alpha = float(max(alpha_pair(params)))
    props = [_prop("float", "int_ior", params.ior), _prop("float", "ext_ior", 1.0)]
    if alpha < ALPHA_MIRROR:
        return _node("dielectric", props)
    return _node("roughdielectric", [_prop("string", "distribution", "ggx"), _prop("float", "alpha", alpha), *props])


def sheet_transmittance(material: Material) -> list[float]:
    """T of the Kubelka–Munk slab of the material's sheet, per channel."""
    sub = material.params.subsurface
    assert sub is not None and sub.thickness is not None, "a thin sheet has a thickness"
    medium = medium_of(sub.color, sub.radius, float(sub.anisotropy), float(material.params.ior))
    _reflectance, transmittance = slab(medium, float(sub.thickness))
    return [float(v) for v in np.clip(transmittance, 0.0, 1.0)]


def cuticle_bsdf(material: Material, weight: float) -> Prop:
    """The sheet's faces: the IR's interface (IOR, alpha) over the diffuse base_color, a
    `roughplastic` (`plastic` when smooth) whose diffuse energy is the IR's (as mitsuba.plastic_bsdf),
    its interface boosted for the blend's weight 1 - `weight` (`interface_boost`)."""
    params = material.params
    alpha = float(max(alpha_pair(params)))
    smooth = alpha < ALPHA_MIRROR
    energy = plastic_diffuse_energy(float(params.ior), 0.0 if smooth else alpha)
    base = np.clip(diffuse_colour(material, energy), 0.0, 1.0)
    boost = interface_boost(float(params.ior), 0.0 if smooth else alpha, float(base.max()) * energy, weight)
    props = [
        _prop("float", "int_ior", params.ior),
        _prop("float", "ext_ior", 1.0),
        _prop("rgb", "diffuse_reflectance", rounded(base)),
        _prop("float", "specular_reflectance", boost),
    ]
    if smooth:
        return _node("plastic", props)
    return _node("roughplastic", [_prop("string", "distribution", "ggx"), _prop("float", "alpha", alpha), *props])


def interface_boost(ior: float, alpha: float, diffuse: float, weight: float) -> float:
    """roughplastic's specular_reflectance in the sheet's blend: 1 / (1 - w), so that the interface
    reflects at full strength though the blend gives the cuticle weight 1 - w; at most what keeps the
    cuticle at or under 1 at every incidence, (1 - DIFFUSE_PEAK x its diffuse energy `diffuse`) / the
    interface's largest reflectance (Mitsuba's separable Smith G), and at least 1. Then the sheet
    returns (1 - w) x at most 1 + T <= 1 per channel (T <= w)."""
    reflected, _ = interface_albedo(BOOST_MUS, ior, max(alpha, ALPHA_MIRROR), n=256, g2="separable")
    bound = max(1.0 - DIFFUSE_PEAK * diffuse, 0.0) / max(float(np.max(reflected)), 1e-6)
    return max(1.0, min(1.0 / max(1.0 - weight, 1e-6), bound))


def plastic_diffuse_energy(ior: float, alpha: float) -> float:
    """roughplastic's hemispherical diffuse energy per unit colour (a smooth plastic as alpha 1e-3)."""
    return roughplastic_diffuse_energy(ior, max(alpha, 1e-3))


def transmitter_bsdf(colour: list[float], ior: float) -> Prop:
    """A pure diffuse transmitter: principledthin with all of its diffuse share transmitted."""
    return _node(
        "principledthin",
        [
            _prop("rgb", "base_color", rounded(colour)),
            _prop("float", "diff_trans", 2.0),
            _prop("float", "spec_trans", 0.0),
            _prop("float", "roughness", 1.0),
            _prop("float", "eta", ior),
        ],
    )


def thin_bsdf(material: Material) -> Prop:
    """blendbsdf: weight w = max T; (1 - w) the two-sided cuticle (interface over base_color),
    w a diffuse transmitter of colour T / w: it transmits T, at most 1 in every channel (T <= w)."""
    transmittance = sheet_transmittance(material)
    weight = max(max(transmittance), 1e-6)
    through = transmitter_bsdf([t / weight for t in transmittance], float(material.params.ior))
    blend = _node("blendbsdf", [_prop("float", "weight", weight)])
    blend["children"] = [{**_node("twosided", []), "children": [cuticle_bsdf(material, weight)]}, through]
    return blend
