"""The emitted cnlm_bsdf agrees with the numpy reference (cnlmc.bsdf.evaluate):
max relative error <= 1e-3 wherever the reference exceeds 1e-3, for every model kind x
Fresnel option, including grazing angles, roughness 0 and below-horizon pairs (exactly 0)."""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from cnlmc.bsdf.flakes import evaluate_full as evaluate  # the complete BSDF: with a sheen or flakes (#15)

from .conftest import emit_material, material_of
from .harness import Evaluator, direction_pairs, relative_error

TOLERANCE = 1e-3


def _variant(phrase: str, model=None, params=None) -> dict:
    material = copy.deepcopy(material_of(phrase))
    material["maps"] = {}  # the reference has no maps: compare the uniform surface
    material["model"].update(model or {})
    material["params"].update(params or {})
    return material


#: model kind -> the material that exercises it.
MODEL_KINDS = {
    "diffuse_lambert": lambda: _variant("velvet", {"diffuse": "lambert"}),
    "diffuse_oren_nayar": lambda: _variant("velvet"),
    "dielectric_ggx": lambda: _variant("glossy red plastic"),
    "dielectric_oren_nayar": lambda: _variant("terracotta"),
    "dielectric_ward_anisotropic": lambda: _variant("brushed plastic", params={"anisotropy_rotation": 0.6}),
    "dielectric_coat": lambda: _variant("clear-coated red car paint"),
    "dielectric_coat_tinted": lambda: _variant("red varnished oak"),
    "conductor_ggx": lambda: _variant("gold"),
    "conductor_ward_anisotropic": lambda: _variant("lightly brushed, blue anodized aluminum"),
    "conductor_ggx_anisotropic": lambda: _variant(
        "brushed steel", {"distribution": "ggx"}, {"anisotropy_rotation": 0.7}
    ),
    "conductor_coat": lambda: _variant("lacquered brass"),
    "conductor_roughness_0": lambda: _variant("mirror chrome", params={"roughness": 0.0, "alpha": [0.0, 0.0]}),
    "glass_roughness_0": lambda: _variant("glass"),
    "glass_rough": lambda: _variant("frosted glass"),
}
FRESNEL = ("exact", "f82", "schlick")
MULTISCATTER_KINDS = ("conductor_ggx", "conductor_ggx_anisotropic", "conductor_coat", "conductor_roughness_0")


@pytest.fixture(scope="module")
def evaluator(gl):
    return Evaluator(gl)


@pytest.fixture(scope="module")
def directions():
    return direction_pairs()


def check_agreement(evaluator, directions, material, fresnel, multiscatter=False):
    files = emit_material(material, fresnel=fresnel, multiscatter="on" if multiscatter else "off", form="library")
    uniforms = json.loads(files["glsl.json"])["uniforms"]
    wo, wi = directions
    gpu = evaluator.evaluate(files["glsl"], uniforms, wo, wi)
    ref = evaluate(material, wo.astype(np.float64), wi.astype(np.float64), fresnel=fresnel, multiscatter=multiscatter)
    assert np.isfinite(gpu).all(), "NaN/Inf in the shader output"
    below = (wo[..., 2] < 1e-7) | (wi[..., 2] < 1e-7)
    assert np.all(gpu[below] == 0.0), "non-zero below the horizon"
    err, where = relative_error(gpu, ref)
    assert err <= TOLERANCE, (
        f"max relative error {err:.2e} at wo={wo[where[:2]]}, wi={wi[where[:2]]}: "
        f"gpu {gpu[where[:2]]} vs reference {ref[where[:2]]}"
    )
    return err


@pytest.mark.parametrize("fresnel", FRESNEL)
@pytest.mark.parametrize("kind", sorted(MODEL_KINDS))
def test_agreement(evaluator, directions, kind, fresnel):
    check_agreement(evaluator, directions, MODEL_KINDS[kind](), fresnel)


@pytest.mark.parametrize("fresnel", FRESNEL)
@pytest.mark.parametrize("kind", MULTISCATTER_KINDS)
def test_agreement_multiscatter(evaluator, directions, kind, fresnel):
    check_agreement(evaluator, directions, MODEL_KINDS[kind](), fresnel, multiscatter=True)


def test_rotated_frame_matches_local(evaluator, directions):
    """cnlm_bsdf is frame independent: rotating n, t, v and l together gives the local value."""
    material = MODEL_KINDS["conductor_ward_anisotropic"]()
    files = emit_material(material, form="library")
    uniforms = json.loads(files["glsl.json"])["uniforms"]
    wo, wi = directions
    c, s = np.cos(0.9), np.sin(0.9)
    frame = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]) @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    gpu = evaluator.evaluate(files["glsl"], uniforms, wo, wi, frame)
    ref = evaluate(material, wo.astype(np.float64), wi.astype(np.float64))
    err, _ = relative_error(
        gpu[(wo[..., 2] > 1e-3) & (wi[..., 2] > 1e-3)], ref[(wo[..., 2] > 1e-3) & (wi[..., 2] > 1e-3)]
    )
    assert err < 1e-2  # float32 rounding of the rotation itself, amplified at the lobe's flanks


@pytest.mark.parametrize("kind", sorted(MODEL_KINDS))
def test_uber_form_agrees_too(evaluator, directions, kind):
    """specialize=off (every branch compiled in, selected by uniforms) computes the same BRDF."""
    material = MODEL_KINDS[kind]()
    files = emit_material(
        material, form="library", specialize="off", multiscatter="on" if kind in MULTISCATTER_KINDS else "off"
    )
    uniforms = json.loads(files["glsl.json"])["uniforms"]
    wo, wi = directions
    gpu = evaluator.evaluate(files["glsl"], uniforms, wo, wi)
    ref = evaluate(material, wo.astype(np.float64), wi.astype(np.float64), multiscatter=kind in MULTISCATTER_KINDS)
    err, _ = relative_error(gpu, ref)
    assert np.isfinite(gpu).all() and err <= TOLERANCE
