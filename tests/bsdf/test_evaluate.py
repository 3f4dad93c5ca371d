"""evaluate(material): every model on the dense grid, reciprocity, furnace, options."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.bsdf import ALPHA_MIRROR, albedo, evaluate, material_alpha, rotate_tangent
from cnlmc.bsdf.geometry import spherical_dir

from .directions import all_pairs

AL = {
    "eta": [1.5022, 0.9853, 0.606],
    "k": [7.6534, 6.5496, 5.3505],
    "f0": [0.9073, 0.9159, 0.9223],
    "f82": [0.8302, 0.8622, 0.8938],
}
WHITE_MIRROR_METAL = {"eta": [1.0, 1.0, 1.0], "k": [1e6, 1e6, 1e6]}


def material(base, roughness=0.4, **kw):
    model = {
        "base": base,
        "distribution": None if base == "diffuse" else "ggx",
        "anisotropic": False,
        "coat": False,
        "diffuse": "lambert" if base in ("diffuse", "dielectric") else None,
    }
    model.update(kw.pop("model", {}))
    params = {"base_color": [1.0, 1.0, 1.0], "roughness": roughness, "ior": 1.5, "alpha_convention": "squared", **AL}
    params.update(kw)
    return {"model": model, "params": params}


COAT = {"ior": 1.5, "roughness": 0.1, "color": [0.9, 0.6, 0.3], "thickness": 1.0}
CASES = {
    "lambert": material("diffuse"),
    "oren_nayar": material("diffuse", diffuse_roughness=0.6, model={"diffuse": "oren_nayar"}),
    "plastic": material("dielectric", 0.3),
    "plastic_rough0": material("dielectric", 0.0),
    "plastic_eta1": material("dielectric", 0.3, ior=1.0),
    "glass": material("glass", 0.1),
    "aluminium": material("conductor", 0.3),
    "mirror_metal": material("conductor", 0.0),
    "k0_conductor": material("conductor", 0.5, eta=[1.5, 1.0, 0.5], k=[0.0, 0.0, 0.0]),
    "brushed": material("conductor", 0.5, anisotropy=1.0, anisotropy_rotation=0.7, model={"anisotropic": True}),
    "extreme_aniso": material("conductor", alpha=[1.0, 1e-3], model={"anisotropic": True}),
    "ward": material("conductor", 0.5, anisotropy=0.8, model={"anisotropic": True, "distribution": "ward"}),
    "coated_wood": material("dielectric", 0.6, base_color=[0.5, 0.3, 0.1], coat=COAT, model={"coat": True}),
    "coated_metal": material("conductor", 0.3, coat=COAT, model={"coat": True}),
}
ENERGY_BOUNDED = [
    "lambert",
    "plastic",
    "plastic_rough0",
    "glass",
    "aluminium",
    "mirror_metal",
    "k0_conductor",
    "brushed",
    "ward",
    "coated_wood",
    "coated_metal",
]


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.parametrize("fresnel", ["exact", "schlick", "f82"])
def test_finite_nonnegative_reciprocal_on_dense_grid(name, fresnel):
    wo, wi = all_pairs()
    f = evaluate(CASES[name], wo, wi, fresnel=fresnel)
    assert f.shape == wo.shape
    assert np.all(np.isfinite(f)) and np.all(f >= 0)
    np.testing.assert_allclose(f, evaluate(CASES[name], wi, wo, fresnel=fresnel), rtol=1e-10, atol=1e-300)
    assert np.all(f[(wo[:, 2] <= 0) | (wi[:, 2] <= 0)] == 0)


@given(
    name=st.sampled_from(sorted(CASES)),
    t_o=st.floats(0, np.pi / 2),
    p_o=st.floats(0, 2 * np.pi),
    t_i=st.floats(0, np.pi / 2),
    p_i=st.floats(0, 2 * np.pi),
    rough=st.floats(0.0, 1.0),
    ms=st.booleans(),
)
@settings(max_examples=200, deadline=None)
def test_random_directions_and_roughness(name, t_o, p_o, t_i, p_i, rough, ms):
    mat = {**CASES[name], "params": {**CASES[name]["params"], "roughness": rough}}
    wo, wi = spherical_dir(t_o, p_o), spherical_dir(t_i, p_i)
    f = evaluate(mat, wo, wi, multiscatter=ms)
    assert np.all(np.isfinite(f)) and np.all(f >= 0)
    np.testing.assert_allclose(f, evaluate(mat, wi, wo, multiscatter=ms), rtol=1e-9)


@pytest.mark.parametrize("name", ENERGY_BOUNDED)
def test_white_furnace_at_most_one(name):
    mat = CASES[name]
    if mat["model"]["base"] == "conductor" and "eta" in mat["params"]:
        mat = {**mat, "params": {**mat["params"], **WHITE_MIRROR_METAL}}
    if mat["params"].get("coat"):
        mat = {**mat, "params": {**mat["params"], "base_color": [1.0, 1.0, 1.0], "coat": {**COAT, "thickness": 0.0}}}
    for mu in [1.0, 0.6, 0.2, 0.03]:
        a = albedo(mat, mu, 1 << 11)
        # 5e-3: QMC error of 2^11 MIS samples at the sharpest lobes (α = 1e-3)
        assert np.all(a <= 1.0 + 5e-3), (name, mu, a)
        assert np.all(a >= 0)


def test_lambert_and_plastic_albedo_values():
    np.testing.assert_allclose(albedo(CASES["lambert"], 0.5, 1 << 11), 1.0, atol=2e-3)
    a = albedo(CASES["plastic_eta1"], 0.7, 1 << 11)
    np.testing.assert_allclose(a, 1.0, atol=2e-3)  # η = 1: no specular, full diffuse


def test_mirror_metal_is_mirror_limit():
    mat = CASES["mirror_metal"]
    assert material_alpha(mat) == (ALPHA_MIRROR, ALPHA_MIRROR)
    wo = spherical_dir(0.5, 0.0)
    peak = evaluate(mat, wo, wo * np.array([-1, -1, 1]))
    off = evaluate(mat, wo, spherical_dir(0.52, np.pi))
    assert np.all(peak > 1e4) and np.all(off < 2e-4 * peak)
    # the whole lobe still integrates to the Fresnel reflectance at the mirror angle
    np.testing.assert_allclose(albedo(mat, np.cos(0.5), 1 << 12), albedo(mat, np.cos(0.5), 1 << 13), atol=2e-3)


def test_anisotropy_rotation_rotates_the_lobe():
    base = material("conductor", 0.5, anisotropy=1.0, model={"anisotropic": True})
    rotated = {**base, "params": {**base["params"], "anisotropy_rotation": np.pi / 2}}
    wo, wi = all_pairs()
    quarter = rotate_tangent(wo, np.pi / 2), rotate_tangent(wi, np.pi / 2)
    np.testing.assert_allclose(evaluate(rotated, wo, wi), evaluate(base, *quarter), rtol=1e-10)
    wo = np.array([0.0, 0.0, 1.0])
    wx, wy = spherical_dir(0.5, 0.0), spherical_dir(0.5, np.pi / 2)
    assert evaluate(base, wo, wx)[0] > 5 * evaluate(base, wo, wy)[0]
    assert evaluate(rotated, wo, wy)[0] > 5 * evaluate(rotated, wo, wx)[0]


def test_fresnel_modes_agree_roughly_and_conductor_tint():
    mat = CASES["aluminium"]
    wo, wi = spherical_dir(0.3, 0.0), spherical_dir(0.35, np.pi)
    exact = evaluate(mat, wo, wi)
    np.testing.assert_allclose(evaluate(mat, wo, wi, fresnel="schlick"), exact, rtol=0.02)
    np.testing.assert_allclose(evaluate(mat, wo, wi, fresnel="f82"), exact, rtol=0.02)
    blue = {**mat, "params": {**mat["params"], "base_color": [0.0, 0.0, 1.0]}}
    f = evaluate(blue, wo, wi)
    assert f[0] == f[1] == 0.0 and f[2] == exact[2]
    with pytest.raises(ValueError):
        evaluate(mat, wo, wi, fresnel="cook")


def test_coat_absorption_and_clear_coat():
    wo, wi = spherical_dir(0.2, 0.0), spherical_dir(0.6, 2.0)
    coated = CASES["coated_wood"]
    clear = {**coated, "params": {**coated["params"], "coat": {**COAT, "thickness": 0.0}}}
    thick = {**coated, "params": {**coated["params"], "coat": {**COAT, "thickness": 3.0}}}
    f_clear, f_col, f_thick = (evaluate(m, wo, wi) for m in (clear, coated, thick))
    assert np.all(f_col < f_clear) and np.all(f_thick < f_col)
    assert f_col[0] / f_clear[0] > f_col[2] / f_clear[2]  # tinted towards the coat colour
    uncoated = {**coated, "model": {**coated["model"], "coat": False}}
    assert np.all(evaluate(uncoated, wo, wi) > 0)
