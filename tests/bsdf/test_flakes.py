"""Flakes (cnlmc.bsdf.flakes): the words that ask for them put them in the IR, the flake lobe under
the coat keeps the white furnace <= 1 (where adding it without the density's mix does not), and a
metallic paint is brighter than its flakeless paint near the mirror direction and darker away
from it (the flop)."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.api import compile_source
from cnlmc.bsdf import albedo
from cnlmc.bsdf.flakes import albedo_full, evaluate_full, has_flakes

MUS = (1.0, 0.5, 0.1, 0.02)
FLAKED = ("metallic car paint", "pearlescent white car paint", "glittery plastic", "red paint with metallic flakes")


def material(phrase: str) -> dict:
    return compile_source(phrase + "\n").ir["materials"][0]


def whitened(m: dict) -> dict:
    """The material with a white base, white flakes and a clear coat: the furnace's worst case."""
    params = {**m["params"], "base_color": [1.0, 1.0, 1.0], "flake_color": [1.0, 1.0, 1.0]}
    if params.get("coat"):
        params["coat"] = {**params["coat"], "color": [1.0, 1.0, 1.0]}
    return {**m, "params": params}


@pytest.mark.parametrize("phrase", FLAKED)
def test_flake_words_put_flakes_in_the_ir(phrase):
    m = material(phrase)
    assert has_flakes(m)
    assert {"flake_color", "flake_density", "flake_roughness", "flake_size"} <= set(m["params"])


@pytest.mark.parametrize("phrase", ["red car paint", "white plastic", "polished steel", "velvet"])
def test_no_flake_word_no_flakes(phrase):
    assert not any(k.startswith("flake") for k in material(phrase)["params"])


def test_flake_clause_no_longer_warns():
    result = compile_source("red paint with metallic flakes\n")
    assert not [d for d in result.ir["diagnostics"] if d.get("code") == "W120"]


@pytest.mark.parametrize("phrase", FLAKED)
def test_white_furnace_at_most_one(phrase):
    a = albedo_full(whitened(material(phrase)), np.asarray(MUS), n_samples=2048)
    assert np.all(a <= 1.0 + 5e-3), a


@pytest.mark.parametrize("phrase", FLAKED)
def test_white_body_under_its_own_flakes_at_most_one(phrase):
    """Coloured or partly transparent flakes (pearl: s = 0.35) hide less of the base: still <= 1."""
    m = material(phrase)
    params = {**m["params"], "base_color": [1.0, 1.0, 1.0]}
    if params.get("coat"):
        params["coat"] = {**params["coat"], "color": [1.0, 1.0, 1.0]}
    a = albedo_full({**m, "params": params}, np.asarray(MUS), n_samples=2048)
    assert np.all(a <= 1.0 + 5e-3), a


def test_the_furnace_check_can_fail():
    """The flakes added on top of the whole base (no 1 - density share) break the budget."""
    m = whitened(material("glittery plastic"))
    unmixed = {**m, "params": {**m["params"], "flake_density": 1.0}}
    base = {**m, "params": {k: v for k, v in m["params"].items() if not k.startswith("flake")}}
    summed = albedo(base, np.asarray(MUS), 4096) + albedo_full(unmixed, np.asarray(MUS), 4096)
    assert np.any(summed > 1.05)


def in_plane(theta_deg: float) -> np.ndarray:
    """A direction in the x-z plane, theta from the normal (negative: the other side)."""
    t = np.radians(theta_deg)
    return np.array([np.sin(t), 0.0, np.cos(t)])


def face_and_flop(m: dict) -> tuple[float, float]:
    """The paint industry's geometry (light at 45 deg): green radiance factor 15 deg and 110 deg
    off the mirror direction (the 'face' and the 'flop' angles of a multi-angle meter)."""
    light = in_plane(-45.0)
    return tuple(float(evaluate_full(m, in_plane(45.0 - aspecular), light)[1]) for aspecular in (15.0, 110.0))


def test_metallic_paint_face_and_flop():
    """Against the same grey paint without flakes: the face is brighter (the flakes' lobe is wider
    than the coat's) and the face/flop ratio much larger (the flop: darker away from the mirror)."""
    paint = material("metallic car paint")
    plain = {**paint, "params": {k: v for k, v in paint["params"].items() if not k.startswith("flake")}}
    (face, flop), (plain_face, plain_flop) = face_and_flop(paint), face_and_flop(plain)
    assert face > 3.0 * plain_face
    assert face / flop > 3.0 * (plain_face / plain_flop)
