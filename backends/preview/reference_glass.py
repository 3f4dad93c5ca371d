"""The chart's reference for rough glass: Mitsuba's `roughdielectric` plus the light it loses
between facets, given back (the Mitsuba plugin `cnlm_glass_ms`).

A single-scattering rough dielectric (Walter et al. 2007; Mitsuba's `roughdielectric`, and
cnlmc.bsdf's transmission, the same model) counts only the light that one facet reflects or
refracts and that leaves unblocked: a ray blocked by a neighbouring facet is dropped. For
frosted glass (α = 0.25) that drops a quarter of a white furnace (0.75). Real rough glass
keeps it: the blocked light scatters again and leaves; a multiple-scattering microfacet
dielectric conserves energy (Heitz, Hanika, d'Eon & Dachsbacher 2016, "Multiple-scattering
microfacet BSDFs with the Smith model", their white-furnace test of the dielectric).

The compensation (Kulla & Conty 2017, "Revisiting physically based shading at Imageworks",
SIGGRAPH course): for a view direction on side s (outside or inside) at cosine μo the missing
energy 1 − E_s(μo), E = E_R + E_T the single-scattering albedo, leaves in a lobe of shape
(1 − E(μi)) / (π (1 − E_avg)) on the side it goes to (which integrates to one). It is split
between reflection and transmission in the single-scattering ratio E_R : E_T at μo (our
choice: the facets that block it are the same facets; Kulla & Conty derive the split from
E_avg of both sides for a smooth-Fresnel interface, which needs the same tables). So
E_R + E_T + compensation = 1 at every angle, tinted as the interface's transmission is.
The tables E_R, E_T are measured from the very `roughdielectric` being compensated
(TABLE_SAMPLES Monte Carlo samples at each of TABLE_COSINES view cosines, per side).
"""

from __future__ import annotations

from typing import Any

import numpy as np

PLUGIN = "cnlm_glass_ms"
#: view cosines per side of the E_R / E_T tables (cell centres) and samples per cosine: the
#: tables' Monte Carlo noise is about 0.3 % (our choice: below FLIP's resolution).
TABLE_COSINES = 64
TABLE_SAMPLES = 1 << 14


def register() -> None:
    """Register the plugin for the current (vectorized) Mitsuba variant."""
    import mitsuba as mi

    mi.register_bsdf(PLUGIN, lambda props: _plugin_class()(props))


def wrap_materials_xml(text: str) -> str:
    """materials.xml with each `roughdielectric` BSDF wrapped by the compensating plugin: the
    interface's own properties travel as the plugin's (alpha, int_ior, ext_ior, tint)."""
    import xml.etree.ElementTree as ET

    root = ET.fromstring(text)
    for bsdf in root.iter("bsdf"):
        if bsdf.get("type") == "roughdielectric":
            bsdf.set("type", PLUGIN)
    return ET.tostring(root, encoding="unicode")


def interface_props(props: Any) -> dict[str, Any]:
    """The wrapped `roughdielectric`'s properties (Mitsuba's defaults where absent)."""
    out = {"type": "roughdielectric", "distribution": "ggx"}
    for name in ("distribution", "alpha", "alpha_u", "alpha_v", "int_ior", "ext_ior", "sample_visible"):
        if name in props:
            out[name] = props[name]
    return out


def cosine_tables(interface: Any, side: float) -> tuple[np.ndarray, np.ndarray]:
    """(E_R, E_T) over TABLE_COSINES view cosines for a view on `side` (+1 outside, −1 inside),
    importance transport (the flux each part carries; no radiance compression)."""
    import drjit as dr
    import mitsuba as mi

    mu = (np.arange(TABLE_COSINES) + 0.5) / TABLE_COSINES
    rng = np.random.default_rng(12345)
    n = TABLE_COSINES * TABLE_SAMPLES
    mu_lanes = np.repeat(mu, TABLE_SAMPLES)
    sin = np.sqrt(1.0 - mu_lanes**2)
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = mi.Vector3f(sin.astype(np.float32), np.zeros(n, np.float32), (side * mu_lanes).astype(np.float32))
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    si.n = mi.Normal3f(0, 0, 1)
    ctx = mi.BSDFContext(mi.TransportMode.Importance)
    u = rng.random((3, n)).astype(np.float32)
    bs, weight = interface.sample(ctx, si, mi.Float(u[0]), mi.Point2f(u[1], u[2]))
    w = np.array(weight, np.float64)[0] if np.array(weight).ndim == 2 else np.array(weight, np.float64)
    w = np.where(np.isfinite(w), w, 0.0)
    reflected = np.array(bs.wo, np.float64)[2] * side > 0
    e_r = np.where(reflected, w, 0.0).reshape(TABLE_COSINES, TABLE_SAMPLES).mean(axis=1)
    e_t = np.where(~reflected, w, 0.0).reshape(TABLE_COSINES, TABLE_SAMPLES).mean(axis=1)
    return e_r, e_t


def crossing_shares(e_r_out, e_t_out, e_r_in, e_t_in, ior: float) -> tuple[float, float]:
    """(t_outside, t_inside): the share of each side's compensation that crosses the interface.
    Energy: each side's reflected and crossing shares sum to one. Reciprocity of the crossing
    lobes a(μo) b(μi) / (π B) and b(μo) a(μi) / (π A) (a, b the missing energy 1 − E outside and
    inside, A, B their cosine-weighted means) ties them: t_inside = t_outside · A / (B ior²) —
    light leaving the glass has only the cone inside the critical angle. t_outside is the
    single-scattering crossing share E_T / E, weighted by where the outside's missing energy
    is (our choice), capped so t_inside <= 1."""
    mu = (np.arange(len(e_r_out)) + 0.5) / len(e_r_out)
    e_out, e_in = e_r_out + e_t_out, e_r_in + e_t_in
    a, b = np.clip(1.0 - e_out, 0.0, 1.0), np.clip(1.0 - e_in, 0.0, 1.0)
    big_a, big_b = float(2.0 * np.mean(a * mu)), float(2.0 * np.mean(b * mu))
    t_out = float(np.sum(a * mu * e_t_out / np.maximum(e_out, 1e-6)) / max(np.sum(a * mu), 1e-12))
    ratio = big_a * ior * ior / max(big_b, 1e-12)
    t_out = min(t_out, 1.0 / ratio) if ratio > 0 else t_out
    return t_out, t_out * ratio


def lobe_norm(e_total: np.ndarray) -> float:
    """π (1 − E_avg), E_avg = 2 ∫ E(μ) μ dμ over the table's cells: the lobe's normalisation."""
    mu = (np.arange(len(e_total)) + 0.5) / len(e_total)
    e_avg = float(2.0 * np.mean(e_total * mu))
    return float(np.pi * max(1.0 - e_avg, 1e-4))


class Tables:
    """E_R, E_T per side as Dr.Jit arrays, looked up linearly in μ, and each side's share of its
    compensation that crosses the interface (reciprocal: see `crossing_shares`)."""

    def __init__(self, interface: Any, ior: float):
        import mitsuba as mi

        self.sides = {}
        raw = {key: cosine_tables(interface, side) for key, side in (("outside", 1.0), ("inside", -1.0))}
        for key, (e_r, e_t) in raw.items():
            total = np.clip(e_r + e_t, 0.0, 1.0)
            self.sides[key] = (mi.Float(e_r.astype(np.float32)), mi.Float(total.astype(np.float32)), lobe_norm(total))
        self.crossing = crossing_shares(*raw["outside"], *raw["inside"], ior)

    def lookup(self, table: Any, mu: Any) -> Any:
        import drjit as dr
        import mitsuba as mi

        x = dr.clip(mu * TABLE_COSINES - 0.5, 0.0, TABLE_COSINES - 1.0)
        i0 = mi.UInt32(dr.floor(x))
        i1 = dr.minimum(i0 + 1, TABLE_COSINES - 1)
        t = x - mi.Float(i0)
        return dr.gather(mi.Float, table, i0) * (1.0 - t) + dr.gather(mi.Float, table, i1) * t

    def at(self, outside: Any, mu: Any) -> tuple[Any, Any, Any]:
        """(E_R, E, lobe normalisation) on the side `outside` (a mask) at cosine mu."""
        import drjit as dr

        er_o, e_o, norm_o = self.sides["outside"]
        er_i, e_i, norm_i = self.sides["inside"]
        e_r = dr.select(outside, self.lookup(er_o, mu), self.lookup(er_i, mu))
        e = dr.select(outside, self.lookup(e_o, mu), self.lookup(e_i, mu))
        return e_r, e, dr.select(outside, norm_o, norm_i)


def _plugin_class():
    """The mi.BSDF subclass (defined lazily: Mitsuba loads only when the plugin is used)."""
    import drjit as dr
    import mitsuba as mi

    class CompensatedGlass(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            spec = interface_props(props)
            self.interface = mi.load_dict(spec)
            self.ior = float(spec.get("int_ior", 1.5046)) / float(spec.get("ext_ior", 1.000277))
            self.tables = Tables(self.interface, self.ior)
            tint = props["specular_transmittance"] if "specular_transmittance" in props else None
            self.tint_texture = tint if isinstance(tint, mi.Texture) else None
            self.tint = (
                mi.Color3f(*[float(c) for c in tint])
                if self.tint_texture is None and tint is not None
                else mi.Color3f(1.0)
            )
            tinted = {"specular_transmittance": tint if self.tint_texture is not None else self._rgb(tint)}
            self.interface_tinted = mi.load_dict({**spec, **(tinted if tint is not None else {})})
            both = mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide | mi.BSDFFlags.NonSymmetric
            self.m_components = [
                mi.BSDFFlags.GlossyReflection | both,
                mi.BSDFFlags.GlossyTransmission | both,
                mi.BSDFFlags.DiffuseReflection | both,
                mi.BSDFFlags.DiffuseTransmission | both,
            ]
            flags = self.m_components[0]
            for component in self.m_components[1:]:
                flags = flags | component
            self.m_flags = flags

        @staticmethod
        def _rgb(tint):
            return {"type": "rgb", "value": [float(c) for c in tint]} if tint is not None else None

        def _tint(self, si, active):
            if self.tint_texture is not None:
                return self.tint_texture.eval(si, active)
            return self.tint

        def _share(self, si):
            """(missing energy, its reflected share, the view's side) at the view direction."""
            outside = mi.Frame3f.cos_theta(si.wi) > 0
            _, e, _ = self.tables.at(outside, dr.abs(mi.Frame3f.cos_theta(si.wi)))
            missing = dr.clip(1.0 - e, 0.0, 1.0)
            t_out, t_in = self.tables.crossing
            return missing, dr.select(outside, 1.0 - t_out, 1.0 - t_in), outside

        def _compensation(self, ctx, si, wo, active):
            """(value × |cos θi|, pdf of the cosine lobes weighted by their sampling shares)."""
            missing, share_r, outside = self._share(si)
            cos_i = mi.Frame3f.cos_theta(wo)
            reflect = (cos_i > 0) == outside
            lands_outside = cos_i > 0
            _, e_land, norm_land = self.tables.at(lands_outside, dr.abs(cos_i))
            lobe = (1.0 - e_land) / norm_land * dr.abs(cos_i)
            share = dr.select(reflect, share_r, 1.0 - share_r)
            eta_view = dr.select(outside, 1.0, self.ior)
            eta_light = dr.select(lands_outside, 1.0, self.ior)
            radiance = ctx.mode == mi.TransportMode.Radiance
            scale = dr.select(reflect | ~radiance, 1.0, dr.square(eta_view / eta_light))
            value = missing * share * lobe * scale
            colour = dr.select(reflect, mi.Color3f(1.0), self._tint(si, active)) * value
            pdf = missing * share * dr.abs(cos_i) * dr.inv_pi
            return dr.select(active, colour, 0.0), dr.select(active, pdf, 0.0)

        def eval(self, ctx, si, wo, active=True):
            value = self.interface_tinted.eval(ctx, si, wo, active)
            extra, _ = self._compensation(ctx, si, wo, active)
            return value + extra

        def pdf(self, ctx, si, wo, active=True):
            missing, _, _ = self._share(si)
            _, extra = self._compensation(ctx, si, wo, active)
            return (1.0 - missing) * self.interface_tinted.pdf(ctx, si, wo, active) + extra

        def eval_pdf(self, ctx, si, wo, active=True):
            value, pdf = self.interface_tinted.eval_pdf(ctx, si, wo, active)
            missing, _, _ = self._share(si)
            extra, extra_pdf = self._compensation(ctx, si, wo, active)
            return value + extra, (1.0 - missing) * pdf + extra_pdf

        def sample(self, ctx, si, sample1, sample2, active=True):
            missing, share_r, outside = self._share(si)
            choose_ms = sample1 < missing
            # the sample reused inside the chosen branch, rescaled to [0, 1)
            u_native = dr.select(choose_ms, 0.0, (sample1 - missing) / dr.maximum(1.0 - missing, 1e-6))
            u_ms = dr.select(choose_ms, sample1 / dr.maximum(missing, 1e-6), 0.0)
            bs, _ = self.interface_tinted.sample(ctx, si, u_native, sample2, active & ~choose_ms)
            local = mi.warp.square_to_cosine_hemisphere(sample2)
            reflect_ms = u_ms < share_r
            up = dr.select(reflect_ms, outside, ~outside)
            ms_dir = mi.Vector3f(local.x, local.y, dr.select(up, local.z, -local.z))
            wo = dr.select(choose_ms, ms_dir, bs.wo)
            value, pdf = self.eval_pdf(ctx, si, wo, active)
            transmitted = (mi.Frame3f.cos_theta(wo) > 0) != outside
            out = mi.BSDFSample3f()
            out.wo = wo
            out.pdf = pdf
            out.eta = dr.select(transmitted, dr.select(outside, self.ior, 1.0 / self.ior), 1.0)  # type: ignore[assignment]
            glossy = dr.select(transmitted, +mi.BSDFFlags.GlossyTransmission, +mi.BSDFFlags.GlossyReflection)
            diffuse = dr.select(transmitted, +mi.BSDFFlags.DiffuseTransmission, +mi.BSDFFlags.DiffuseReflection)
            out.sampled_type = mi.UInt32(dr.select(choose_ms, diffuse, glossy))  # type: ignore[assignment]
            out.sampled_component = mi.UInt32(dr.select(choose_ms, 2, 0) + dr.select(transmitted, 1, 0))  # type: ignore[assignment]
            ok = active & (pdf > 0)
            return out, dr.select(ok, value / dr.maximum(pdf, 1e-12), 0.0)

        def to_string(self):
            return f"CompensatedGlass[ior={self.ior}]"

    return CompensatedGlass
