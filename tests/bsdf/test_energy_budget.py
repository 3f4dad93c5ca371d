"""One energy budget (issue #15 item 6): the white furnace on the numpy reference for every model.

Each model kind, made white (base colour 1, a clear coat), at roughness 0 and 1 and at normal,
oblique and grazing views: the directional albedo A(mu) = integral of f cos(theta_i) is at most 1
(plus the QMC tolerance). Materials are compiled from phrases through cnlmc.api, then whitened.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.bsdf import albedo
from cnlmc.conventions import alpha_of

TOLERANCE = 5e-3  # QMC error at 2^12 samples (docs/bsdf.md)
MUS = np.array([1.0, 0.5, 0.1, 0.02])
# one phrase per model kind and layer (docs/bsdf.md "Finishes and layers")
PHRASES = {
    "diffuse": "white paper",
    "oren_nayar": "white felt",
    "dielectric": "white plastic",
    "conductor": "silver",
    "gold": "gold",
    "ward": "brushed aluminium",
    "coated dielectric": "white varnished oak",
    "coated conductor": "steel with a clear coat",
    "car paint": "red car paint",
    "anodized": "black anodized aluminium",
    "tinted film": "matte black metal",
    "powder coat": "white powder-coated steel",
    "enamel": "white enameled steel",
}
KWARGS = [{}, {"fresnel": "schlick"}, {"fresnel": "f82"}, {"multiscatter": True}]


def compiled(phrase: str) -> dict:
    result = compile_source(phrase, "energy.cnl")
    assert result.ok, [d.message for d in result.diagnostics]
    return result.ir["materials"][0]


def whitened(material: dict, roughness: float) -> dict:
    """The material with a white base and a clear coat at the given roughness (base and coat)."""
    m = copy.deepcopy(material)
    p = m["params"]
    p["base_color"] = [1.0, 1.0, 1.0]
    aniso = p.get("anisotropy", 0.0) if m["model"]["anisotropic"] else 0.0
    convention = p.get("alpha_convention", "squared")
    if "alpha" in p:
        p["roughness"] = roughness
        p["alpha"] = list(alpha_of(roughness, aniso, convention))
    if p.get("coat"):
        p["coat"].update(color=[1.0, 1.0, 1.0], roughness=roughness)
        p["coat"]["alpha"] = list(alpha_of(roughness, 0.0, convention))
    return m


@pytest.fixture(scope="module")
def materials():
    return {kind: compiled(phrase) for kind, phrase in PHRASES.items()}


@pytest.mark.parametrize("kind", list(PHRASES))
@pytest.mark.parametrize("roughness", [0.0, 1.0])
def test_white_furnace_at_most_one(materials, kind, roughness):
    material = whitened(materials[kind], roughness)
    variants = KWARGS if material["model"]["base"] == "conductor" else KWARGS[:1]
    # Oren-Nayar's qualitative model rises 0.4 % above 1 at mu = 0.02 for sigma 0.3 (docs/bsdf.md):
    # within the tolerance once the QMC error is below it (8192 samples; cheap for a diffuse lobe)
    samples = 8192 if material["model"]["base"] == "diffuse" else 2048
    for kwargs in variants:
        a = albedo(material, MUS, n_samples=samples, **kwargs)
        assert np.all(np.isfinite(a)), (kind, kwargs)
        assert a.max() <= 1.0 + TOLERANCE, (kind, roughness, kwargs, a.max(axis=1))


def test_the_furnace_can_fail():
    """Ward-Duer (docs/bsdf.md: 2.1 at 89 degrees) breaks the budget, so the check is live."""
    m = whitened(compiled("brushed aluminium"), 0.2)
    assert albedo(m, np.array([0.02]), n_samples=2048, ward_form="duer").max() > 1.0 + TOLERANCE


def test_a_white_coated_metal_keeps_most_light():
    """A clear oxide over a white metal returns most of the light (the check is tight from below
    too: an albedo near 0 would also pass the upper bound). Light the metal reflects outside the
    oxide's escape cone is lost in the single-pass stack (docs/bsdf.md), ~25 % at n = 1.77."""
    a = albedo(whitened(compiled("black anodized aluminium"), 0.3), np.array([1.0]), n_samples=2048)
    assert 0.7 < a.min() <= 1.0 + TOLERANCE
