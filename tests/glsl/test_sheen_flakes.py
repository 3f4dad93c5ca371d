"""The GLSL target draws the sheen and the flakes as the reference does (cnlmc.bsdf.flakes.evaluate_full:
the base, its flakes under the coat, the Charlie sheen over it): cnlm_bsdf within 1e-3 relative of
it for a velvet, a metallic paint and a glittery plastic, specialized and in the uber form; the
library compiles in glslangValidator (every profile: test_compile.py runs the stdlib)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from cnlmc.bsdf.flakes import evaluate_full

from .conftest import GLSLANG, emit_material, material_of, run_glslang
from .harness import Evaluator, direction_pairs, relative_error

TOLERANCE = 1e-3
#: (phrase, specialize): every layer specialized; the uber form (slow to compile) once, on a velvet
#: given a metallic paint's flakes as well ("both": a sheen and flakes in one shader)
CASES = [
    *((p, "on") for p in ("navy blue velvet", "metallic car paint", "glittery plastic", "pearlescent white car paint")),
    pytest.param("both", "off", marks=pytest.mark.slow),  # the uber shader: ~10 s to compile on llvmpipe
]


@pytest.fixture(scope="module")
def evaluator(gl):
    return Evaluator(gl)


@pytest.fixture(scope="module")
def directions():
    return direction_pairs()


def uniform_surface(phrase: str) -> dict:
    if phrase == "both":
        velvet, paint = material_of("navy blue velvet"), material_of("metallic car paint")
        flakes = {k: v for k, v in paint["params"].items() if k.startswith("flake")}
        return {**velvet, "maps": {}, "params": {**velvet["params"], **flakes}}
    material = material_of(phrase)
    return {**material, "maps": {}}


@pytest.mark.parametrize(("phrase", "specialize"), CASES)
def test_layers_agree_with_the_reference(evaluator, directions, phrase, specialize):
    material = uniform_surface(phrase)
    files = emit_material(material, form="library", specialize=specialize)
    uniforms = json.loads(files["glsl.json"])["uniforms"]
    assert any(u["name"] in ("cnlm_sheen_color", "cnlm_flake_color") for u in uniforms)
    wo, wi = directions
    gpu = evaluator.evaluate(files["glsl"], uniforms, wo, wi)
    ref = evaluate_full(material, wo.astype(np.float64), wi.astype(np.float64))
    assert np.isfinite(gpu).all()
    err, where = relative_error(gpu, ref)
    assert err <= TOLERANCE, (err, wo[where[:2]], wi[where[:2]], gpu[where[:2]], ref[where[:2]])


def test_the_comparison_can_fail(evaluator, directions):
    """The base alone (what cnlm_bsdf drew before) is far from the sheened reference."""
    material = uniform_surface("navy blue velvet")
    plain = {**material, "params": {k: v for k, v in material["params"].items() if not k.startswith("sheen")}}
    files = emit_material(plain, form="library")
    gpu = evaluator.evaluate(files["glsl"], json.loads(files["glsl.json"])["uniforms"], *directions)
    wo, wi = directions
    err, _ = relative_error(gpu, evaluate_full(material, wo.astype(np.float64), wi.astype(np.float64)))
    assert err > 0.1


@pytest.mark.skipif(GLSLANG is None, reason="glslangValidator is not installed")
def test_glslang_accepts_every_profile():
    sources = []
    for phrase in ("navy blue velvet", "metallic car paint"):
        for profile in ("330", "es300"):
            files = emit_material(uniform_surface(phrase), form="both", profile=profile)
            stem = phrase.replace(" ", "_") + "_" + profile
            sources += [(f"{stem}.frag", files["frag"]), (f"{stem}.vert", files["vert"])]
    failures = [(name, out) for name, code, out in run_glslang(sources) if code != 0]
    assert not failures, failures
