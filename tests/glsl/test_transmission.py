"""The emitted cnlm_btdf (glass) agrees with cnlmc.bsdf.evaluate_transmission: max relative
error <= 1e-3 wherever the reference exceeds 1e-3, for both sides of the interface, grazing
angles, the refraction peak at roughness 0 (alpha = 1e-3) and the total-internal-reflection
region; exactly 0 for same-side and in-plane pairs. Both profiles pass glslangValidator."""

from __future__ import annotations

import json

import numpy as np
import pytest

from cnlmc.bsdf import evaluate_transmission

from .conftest import emit_material, run_glslang
from .harness import Evaluator, relative_error, transmission_pairs
from .test_agreement import TOLERANCE, _variant

#: glass variant -> the material (maps stripped: the reference has none).
GLASS_KINDS = {
    "roughness_0": lambda: _variant("glass"),
    "frosted": lambda: _variant("frosted glass"),
    "diamond_rough": lambda: _variant("frosted glass", params={"ior": 2.42, "base_color": [0.7, 0.9, 1.0]}),
    "anisotropic": lambda: _variant(
        "frosted glass", {"anisotropic": True}, {"anisotropy": 0.8, "anisotropy_rotation": 0.5}
    ),
    "near_index_1": lambda: _variant("frosted glass", params={"ior": 1.05}),
}


@pytest.fixture(scope="module")
def evaluator(gl):
    return Evaluator(gl)


def ior_of(material):
    return float(material["params"].get("ior", 1.5))


@pytest.mark.parametrize("fresnel", ("exact", "schlick"))
@pytest.mark.parametrize("kind", sorted(GLASS_KINDS))
def test_btdf_agreement(evaluator, kind, fresnel):
    material = GLASS_KINDS[kind]()
    files = emit_material(material, fresnel=fresnel, form="library")
    uniforms = json.loads(files["glsl.json"])["uniforms"]
    wo, wi = transmission_pairs(ior_of(material))
    gpu = evaluator.evaluate(files["glsl"], uniforms, wo, wi, entry="cnlm_btdf")
    ref = evaluate_transmission(material, wo.astype(np.float64), wi.astype(np.float64), fresnel=fresnel)
    assert np.isfinite(gpu).all(), "NaN/Inf in the shader output"
    zero = (wo[..., 2] * wi[..., 2] >= 0) | (np.abs(wo[..., 2]) < 1e-7) | (np.abs(wi[..., 2]) < 1e-7)
    assert np.all(gpu[zero] == 0.0), "non-zero for a same-side or in-plane pair"
    assert np.count_nonzero(ref[..., 0] > 1e-3) > 400
    err, where = relative_error(gpu, ref)
    assert err <= TOLERANCE, (
        f"max relative error {err:.2e} at wo={wo[where[:2]]}, wi={wi[where[:2]]}: "
        f"gpu {gpu[where[:2]]} vs reference {ref[where[:2]]}"
    )
    # where the reference is exactly 0 (TIR region, no refracting microfacet) the shader is 0
    assert np.all(gpu[ref[..., 0] == 0.0] == 0.0)


def test_btdf_index_1_is_zero(evaluator):
    material = _variant("frosted glass", params={"ior": 1.0})
    files = emit_material(material, form="library")
    wo, wi = transmission_pairs(1.5)
    gpu = evaluator.evaluate(files["glsl"], json.loads(files["glsl.json"])["uniforms"], wo, wi, entry="cnlm_btdf")
    assert np.all(gpu == 0.0)


def test_btdf_frame_independent(evaluator):
    material = GLASS_KINDS["frosted"]()
    files = emit_material(material, form="library")
    wo, wi = transmission_pairs(1.5)
    c, s = np.cos(0.9), np.sin(0.9)
    frame = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    gpu = evaluator.evaluate(
        files["glsl"], json.loads(files["glsl.json"])["uniforms"], wo, wi, frame, entry="cnlm_btdf"
    )
    ref = evaluate_transmission(material, wo.astype(np.float64), wi.astype(np.float64))
    keep = (np.abs(wo[..., 2]) > 1e-2) & (np.abs(wi[..., 2]) > 1e-2)
    err, _ = relative_error(gpu[keep], ref[keep])
    assert err < 1e-2


@pytest.mark.parametrize("profile", ("330", "es300"))
def test_glslang_accepts_btdf(glslang, profile):
    probe = """
out vec4 cnlm_probe_out;
void main() {
    vec3 n = vec3(0, 0, 1), v = vec3(0.3, 0.0, 0.954), l = vec3(-0.2, 0.1, -0.97);
    cnlm_probe_out = vec4(cnlm_btdf(n, v, l, vec2(0)) + cnlm_bsdf(n, v, -l, vec2(0)), 1);
}
"""
    version = {"330": "#version 330 core\n", "es300": "#version 300 es\n"}[profile]
    sources = []
    for kind, make in GLASS_KINDS.items():
        for fresnel in ("exact", "schlick"):
            files = emit_material(make(), profile=profile, fresnel=fresnel)
            sources += [
                (f"{kind}_{fresnel}_{profile}_lib.frag", version + files["glsl"] + probe),
                (f"{kind}_{fresnel}_{profile}.frag", files["frag"]),
            ]
            assert "cnlm_btdf(n, v_tangent, v, l, v_uv)" in files["frag"]
    failures = [f"{name}:\n{out}" for name, code, out in run_glslang(sources) if code != 0]
    assert not failures, "\n".join(failures[:3])


def test_sidecar_and_header_list_btdf():
    files = emit_material(GLASS_KINDS["frosted"]())
    meta = json.loads(files["glsl.json"])
    assert meta["btdf_entry_points"][0].startswith("vec3 cnlm_btdf(vec3 n, vec3 t")
    assert "vec3 cnlm_btdf(vec3 n, vec3 v, vec3 l, vec2 uv)" in files["glsl"].split("uniform")[0]
    plastic = emit_material(_variant("glossy red plastic"))
    assert "cnlm_btdf" not in plastic["glsl"] and "btdf_entry_points" not in json.loads(plastic["glsl.json"])
