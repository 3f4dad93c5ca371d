"""How far light goes through a translucent body (#19, session 10): the diffusion profile's width
against the classical dipole the IR's medium is inverted with, and a closed thin shell's cavity
keeping energy (docs/subsurface.md, "The preview's body term")."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.bsdf.subsurface import boundary_a, medium_of, profile_shape


def dipole_mean_radius(albedo: float, eta: float) -> float:
    """The mean distance (in diffuse mean free paths) from where light enters to where it leaves,
    under the classical dipole (Jensen et al. 2001) of the medium the IR's (albedo, l_d = 1) inverts
    to: R_d(r) = alpha' / (4 pi) [z_r (s d_r + 1) e^(-s d_r) / d_r^3 + z_v (s d_v + 1) e^(-s d_v) / d_v^3]."""
    medium = medium_of([albedo], [1.0], 0.0, eta)
    sigma_a, reduced_s = float(medium.sigma_a[0]), float(medium.reduced_scattering[0])
    reduced_t = sigma_a + reduced_s
    sigma_tr = np.sqrt(3.0 * sigma_a * reduced_t)
    z_r = 1.0 / reduced_t
    z_v = z_r * (1.0 + 4.0 / 3.0 * boundary_a(eta))
    r = np.geomspace(1e-5, 60.0, 40_000)
    d_r, d_v = np.hypot(r, z_r), np.hypot(r, z_v)
    profile = z_r * (sigma_tr * d_r + 1) * np.exp(-sigma_tr * d_r) / d_r**3
    profile += z_v * (sigma_tr * d_v + 1) * np.exp(-sigma_tr * d_v) / d_v**3
    ring = profile * r  # x 2 pi alpha' / (4 pi): constant factors cancel in the mean
    return float(np.trapezoid(ring * r, r) / np.trapezoid(ring, r))


@settings(max_examples=25, deadline=None)
@given(albedo=st.floats(0.2, 0.95), eta=st.floats(1.2, 1.7))
def test_the_profile_spreads_light_as_far_as_the_dipole_does(albedo, eta):
    """Christensen-Burley's R(r) = A (e^(-r/d) + e^(-r/3d)) / (8 pi d r) has its mean exit distance at
    2.5 d, d = l_d / s. With the searchlight s for the diffuse mean free path (3.5 + 100 (A - 0.33)^4)
    it is within a factor 1.6 of the dipole's (measured 0.64-1.11x; below A = 0.2 diffusion theory,
    the dipole, is itself poor); the s for the mean free path that was used before
    (1.9 - A + 3.5 (A - 0.8)^2) put it 5.6x too far at A = 0.8 and 9.6x at 0.9: a backlit body glowed
    across its whole belly."""
    burley = 2.5 / float(profile_shape(albedo))
    dipole = dipole_mean_radius(albedo, eta)
    assert dipole / 1.6 <= burley <= dipole * 1.6, (burley, dipole)


@settings(max_examples=40, deadline=None)
@given(
    color=st.tuples(*[st.floats(0.0, 1.0)] * 3),
    radius=st.tuples(*[st.floats(1e-5, 0.02)] * 3),
    thickness=st.floats(1e-5, 0.005),
    base=st.tuples(*[st.floats(0.0, 1.0)] * 3),
    ior=st.floats(1.0, 3.0),
)
def test_a_closed_shells_walls_keep_energy(color, radius, thickness, base, ior):
    """The cavity's gain T / (1 - R_in) is at most 1 (the wall's R_in + T <= 1): a closed thin shell
    sends out no more than comes in (snippets/subsurface.glsl, cnlm_sss_cavity)."""
    from cnlmc.backends.preview.subsurface import TranslucentBody, sheet_optics, wall_reflectance

    body = TranslucentBody("thin", color, radius, thickness=thickness, ior=ior)
    _, through = sheet_optics(body)
    reflect = wall_reflectance({"params": {"base_color": base}}, body)
    assert np.all(reflect >= 0.0) and np.all(reflect + through <= 1.0 + 1e-12)
    assert np.all(through / np.maximum(1.0 - reflect, 1e-4) <= 1.0 + 1e-9)


def backlit_means(phrase: str, mesh: str, size: int, spp: int, key_only: bool) -> tuple[np.ndarray, np.ndarray]:
    """The preview's (splitsum) and Mitsuba's mean radiance over the object (premultiplied sums over
    the covered area: the silhouette's partial pixels count alike), the chart's backlit scene
    (bench/preview_chart_translucent.py), with or without the environment."""
    import sys
    import tempfile
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parents[2] / "bench"))
    from preview_chart_translucent import backlit_key, material

    from cnlmc.backends.preview.environment import Environment
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    with Renderer(size) as renderer:
        lamp = backlit_key(renderer.scene(mesh, "studio"))
        env = Environment(lamp.name + " key only", lamp.image * 0.0, lamp.key) if key_only else lamp
        scene = renderer.scene(mesh, env)
        scene.background = "transparent"
        body = material(phrase)
        preview = renderer.render(body, tier="splitsum", scene=scene, hdr=True).hdr
        with tempfile.TemporaryDirectory() as folder:
            reference, _ = render_subsurface(body, scene, folder, size, spp)
    mean = lambda img: img[..., :3].sum((0, 1)) / max(float(img[..., 3].sum()), 1.0)
    return mean(preview), mean(reference)


@pytest.mark.slow
def test_a_backlit_skin_teapot_glows_about_as_mitsubas():
    """The key light behind a skin II teapot, no environment: what the preview's body lets through
    and spreads past the terminator, against the volumetric reference (64^2, 128 spp). Measured (96^2,
    512 spp) red 2.42x Mitsuba's before session 10 (the profile 5.6x too wide, the crossing light
    c e^(-d/l_d) where a slab lets (1 - c^2) e^(-d/l_d) / (1 - c^2 e^(-2d/l_d)) through), 1.49x after."""
    pytest.importorskip("mitsuba")
    preview, reference = backlit_means("type II skin", "teapot", 64, 128, key_only=True)
    assert np.all(preview <= 1.8 * reference) and np.all(preview >= 0.5 * reference), (preview, reference)


@pytest.mark.slow
def test_a_backlit_leaf_ball_sends_what_mitsubas_does():
    """The chart's backlit leaf: a closed thin shell whose cavity glows (light through one wall, back
    from the walls, out through the others). Mean per channel within 12 % of the reference (48^2,
    64 spp; measured at 512 spp: 0.107/0.327/0.069 against 0.106/0.321/0.068; before session 10 the
    front was drawn with an eighth of its base colour and the cavity without its walls' reflection:
    0.085/0.242/0.062 against 0.086/0.298/0.048 at 32^2)."""
    pytest.importorskip("mitsuba")
    preview, reference = backlit_means("backlit leaf", "sphere", 48, 64, key_only=False)
    assert np.all(np.abs(preview - reference) <= 0.12 * reference), (preview, reference)
