"""How far light goes through a translucent body (#19, session 10): the diffusion profile's width
against the classical dipole the IR's medium is inverted with, and a closed thin shell's cavity
keeping energy (docs/subsurface.md, "The preview's body term")."""

from __future__ import annotations

import numpy as np
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
