"""The Mitsuba 3 BSDF plugin `cnlm`: cnlmc's own reflection model inside Mitsuba.

Mitsuba's native plugins approximate some cnlmc models (a different diffuse-under-glaze
layering in `roughplastic`, no Oren–Nayar, `principled` for coats, no Ward; docs/exchange.md).
With this plugin Mitsuba renders exactly the BSDF the GLSL shader evaluates: every call goes
to the numpy reference `cnlmc.bsdf.evaluate` (docs/bsdf.md), vectorized over Mitsuba's
wavefront. Sampling is the cosine + GGX visible-normal mixture of `cnlmc.bsdf.sampling`.

    from cnlmc.backends.exchange import mitsuba_cnlm
    mitsuba_cnlm.register()            # selects an LLVM/CUDA variant first if none is set
    scene = mi.load_file("scene.xml")  # written with --target mitsuba --option bsdf=cnlm

The plugin needs a vectorized variant (`llvm_ad_rgb`, `cuda_ad_rgb`) with symbolic calls off
(`register` does that): numpy sees concrete arrays. Reflection only: `glass` keeps its native
`roughdielectric` (which is cnlmc's transmission model, docs/bsdf.md). Parameters:
`material` (string, the IR material as JSON) and optional textures `base_color`,
`roughness` (perceptual, the IR convention applies) and `mask` (coverage towards Lambert).
"""

from __future__ import annotations

import dataclasses
import json
import os
from typing import Any

import numpy as np

from cnlmc.bsdf.alpha import alpha_from_roughness
from cnlmc.bsdf.diffuse import lambert
from cnlmc.bsdf.evaluate import lobe_alphas
from cnlmc.bsdf.flakes import coat_trap, evaluate_full  # the base, its flakes under the coat, the sheen over it
from cnlmc.bsdf.sampling import lobe_shares, mixture_pdf, sample_mixture, sampled_weight
from cnlmc.material import RGB, Material

PLUGIN = "cnlm"
LLVM_LIBRARY = "/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1"
VARIANTS = ("llvm_ad_rgb", "cuda_ad_rgb")


class PluginError(RuntimeError):
    """Mitsuba cannot run the plugin here (no vectorized variant)."""


def choose_variant() -> str:
    """Set (if needed) and return a vectorized RGB variant. Mitsuba's llvm variants abort the
    process (not an exception) with Debian's LLVM 15/16, so they are used only with LLVM 19
    (apt libllvm19, found at LLVM_LIBRARY) or a library the user names in DRJIT_LIBLLVM_PATH."""
    import mitsuba as mi

    current = mi.variant()
    if current is not None and current in VARIANTS:
        return current
    if "DRJIT_LIBLLVM_PATH" not in os.environ:
        if not os.path.exists(LLVM_LIBRARY):
            raise PluginError(
                f"the cnlm Mitsuba plugin needs Mitsuba's llvm_ad_rgb variant with LLVM 19 "
                f"({LLVM_LIBRARY}: apt install libllvm19), or DRJIT_LIBLLVM_PATH set to a working libLLVM"
            )
        os.environ["DRJIT_LIBLLVM_PATH"] = LLVM_LIBRARY
    for variant in VARIANTS:
        if variant in mi.variants():
            try:
                mi.set_variant(variant)
                return variant
            except Exception:  # pragma: no cover - depends on the machine's LLVM/CUDA
                continue
    raise PluginError("the cnlm Mitsuba plugin needs the llvm_ad_rgb variant (apt install libllvm19)")


SYMBOLIC_FLAGS = ("SymbolicCalls", "SymbolicLoops")


def register() -> str:
    """Register `cnlm` for the current (or a chosen vectorized) variant and switch symbolic
    calls and loops off (the plugin needs concrete arrays); returns the variant."""
    import mitsuba as mi

    variant = choose_variant()
    set_symbolic(False)
    mi.register_bsdf(PLUGIN, lambda props: _plugin_class()(props))
    return variant


def set_symbolic(enabled: bool) -> dict:
    """Set Dr.Jit's symbolic calls/loops; returns the previous values (to restore). Scenes
    without the plugin render about twice as fast with them on (Mitsuba's default)."""
    import drjit as dr

    previous = {}
    for name in SYMBOLIC_FLAGS:
        flag = getattr(dr.JitFlag, name)
        previous[name] = dr.flag(flag)
        dr.set_flag(flag, enabled)
    return previous


def restore_symbolic(previous: dict) -> None:
    import drjit as dr

    for name, value in previous.items():
        dr.set_flag(getattr(dr.JitFlag, name), value)


def _lanes(value) -> np.ndarray:
    """A Mitsuba vector/colour as (N, k) float64, or a float array as (N,)."""
    array = np.array(value, dtype=np.float64)
    return array.T if array.ndim == 2 else array


def _vector(mi, array: np.ndarray):
    a = np.ascontiguousarray(array, dtype=np.float32)
    return mi.Vector3f(a[:, 0], a[:, 1], a[:, 2])


def _colour(mi, array: np.ndarray):
    a = np.ascontiguousarray(array, dtype=np.float32)
    return mi.Color3f(a[:, 0], a[:, 1], a[:, 2])


class LaneModel:
    """The IR material evaluated per lane: maps (textures) read at each lane's uv."""

    def __init__(self, material: Material, textures: dict[str, Any]):
        self.material = material
        self.textures = textures
        model = material.model
        self.shares = lobe_shares(model.base, bool(model.coat and material.params.coat is not None))
        self.coat_alpha = lobe_alphas(material)[1] or (1.0, 1.0)
        self.trap = coat_trap(material)  # the coat's round trip per unit colour (0: f affine in the colour)

    def params_at(self, si: Any, active: Any) -> Material:
        """The material with α per lane when a roughness map is bound."""
        if "roughness" not in self.textures:
            return self.material
        params = self.material.params
        r = _lanes(self.textures["roughness"].eval_1(si, active))
        aniso = float(params.anisotropy) if self.material.model.anisotropic else 0.0
        alpha = alpha_from_roughness(r, aniso, params.alpha_convention)
        return dataclasses.replace(self.material, params=dataclasses.replace(params, alpha=alpha))

    def base_alpha(self, material: Material) -> Any:
        """The base lobe's (αx, αy) for sampling (per lane with a roughness map)."""
        return lobe_alphas(material)[0] or (1.0, 1.0)

    def f(self, si: Any, material: Material, wo: np.ndarray, wi: np.ndarray, active: Any) -> np.ndarray:
        """f(wo, wi), RGB (N, 3): a colour map costs two calls, f = black + (white - black) g(colour),
        g(c) = c (1 - t) / (1 - c t) (affine, g(c) = c, but under a coat, where the light trapped
        under it makes the diffuse base non-linear in its colour: cnlmc.bsdf.layered)."""
        if "base_color" not in self.textures:
            value = evaluate_full(material, wo, wi)
            albedo = np.asarray(material.params.base_color, np.float64)
        else:
            albedo = _lanes(self.textures["base_color"].eval(si, active))
            black = evaluate_full(_with_colour(material, (0.0, 0.0, 0.0)), wo, wi)
            white = evaluate_full(_with_colour(material, (1.0, 1.0, 1.0)), wo, wi)
            trap = np.clip(self.trap, 0.0, 1.0 - 1e-9)
            value = black + (white - black) * albedo * (1.0 - trap) / (1.0 - albedo * trap)
        if "mask" in self.textures:
            mask = np.clip(_lanes(self.textures["mask"].eval_1(si, active)), 0.0, 1.0)[:, None]
            value = value * (1.0 - mask) + lambert(wo, wi, np.ones(3)) * albedo * mask
        return np.where(np.isfinite(value), value, 0.0)


def _with_colour(material: Material, colour: RGB) -> Material:
    return dataclasses.replace(material, params=dataclasses.replace(material.params, base_color=colour))


def _plugin_class():
    """The mi.BSDF subclass (defined lazily: Mitsuba loads only when the plugin is used)."""
    import drjit as dr
    import mitsuba as mi

    class CnlmBSDF(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            material = Material.from_ir(json.loads(props["material"]))
            textures = {role: props[role] for role in ("base_color", "roughness", "mask") if role in props}
            self.lanes = LaneModel(material, textures)
            flags = mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide
            if material.model.anisotropic:
                flags = flags | mi.BSDFFlags.Anisotropic
            self.m_flags = flags
            self.m_components = [flags]

        def _pair(self, si, wo_mitsuba):
            return _lanes(si.wi), _lanes(wo_mitsuba)

        def _pdf(self, material, wo, wi):
            return mixture_pdf(wo, wi, self.lanes.shares, self.lanes.base_alpha(material), self.lanes.coat_alpha)

        def eval(self, ctx, si, wo, active=True):
            v, l = self._pair(si, wo)
            material = self.lanes.params_at(si, active)
            value = self.lanes.f(si, material, v, l, active) * np.maximum(l[:, 2], 0.0)[:, None]
            return dr.select(active, _colour(mi, value), 0.0)

        def pdf(self, ctx, si, wo, active=True):
            v, l = self._pair(si, wo)
            pdf = self._pdf(self.lanes.params_at(si, active), v, l)
            return dr.select(active, mi.Float(np.ascontiguousarray(pdf, np.float32)), 0.0)

        def eval_pdf(self, ctx, si, wo, active=True):
            return self.eval(ctx, si, wo, active), self.pdf(ctx, si, wo, active)

        def sample(self, ctx, si, sample1, sample2, active=True):
            v, u = _lanes(si.wi), _lanes(sample2)
            material = self.lanes.params_at(si, active)
            base_alpha = self.lanes.base_alpha(material)
            l = sample_mixture(
                v, _lanes(sample1), u[:, 0], u[:, 1], self.lanes.shares, base_alpha, self.lanes.coat_alpha
            )
            pdf = mixture_pdf(v, l, self.lanes.shares, base_alpha, self.lanes.coat_alpha)
            weight = sampled_weight(self.lanes.f(si, material, v, l, active), v, l, pdf)
            bs = mi.BSDFSample3f()
            bs.wo = _vector(mi, l)
            # Mitsuba's stubs type these fields with the scalar variant's classes
            bs.pdf = mi.Float(np.ascontiguousarray(pdf, np.float32))  # type: ignore[assignment]
            bs.eta = 1.0  # type: ignore[assignment]
            bs.sampled_type = mi.UInt32(+mi.BSDFFlags.GlossyReflection)  # type: ignore[assignment]
            bs.sampled_component = mi.UInt32(0)  # type: ignore[assignment]
            ok = active & (bs.pdf > 0)
            return bs, dr.select(ok, _colour(mi, weight), 0.0)

        def to_string(self):
            return f"CnlmBSDF[{self.lanes.material.name}]"

    return CnlmBSDF
