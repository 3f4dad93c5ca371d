"""Light inside the body (docs/subsurface.md): from the IR's (albedo, radius) to a medium, and back.

The IR gives a medium as the appearance an artist or a dataset names: `color`, the
multiple-scattering albedo (what a thick slab reflects), and `radius`, the diffuse mean free path
ℓd = 1/σtr per channel, in metres. A renderer needs the medium's coefficients σa, σs. The
inversion is the one of Jensen & Buhler 2002 ("A Rapid Hierarchical Rendering Technique for
Translucent Materials", §4): the total diffuse reflectance of the classical dipole (Jensen et al.
2001),

    Rd(α') = α'/2 · (1 + exp(−4/3 · A · sqrt(3 (1 − α')))) · exp(−sqrt(3 (1 − α'))),
    A = (1 + Fdr) / (1 − Fdr),  Fdr(η) = −1.440/η² + 0.710/η + 0.668 + 0.0636 η  (Egan & Hilgeman),

(the fit only for η ≤ 2, where it holds; above, the exact integral: Fdr < 1 for every IOR,
cnlmc.bsdf.subsurface_fresnel)

increases monotonically from 0 (α' = 0) to 1 (α' = 1), so the reduced albedo α' = σs'/σt' of a
given `color` is found by bisection (exact to 1e-12, round-trip tested), and then

    σtr = 1/ℓd,  σt' = σtr / sqrt(3 (1 − α')),  σs' = α' σt',  σa = σt' − σs',  σs = σs' / (1 − g).

Check on data (tests): physicallybased.info's Marble and Milk coefficients (Jensen et al. 2001)
give back the dataset's colour and `subsurfaceRadius` (in cm) through `appearance`.

The diffusion profile is Christensen & Burley 2015 ("Approximate Reflectance Profiles for
Efficient Subsurface Scattering"), searchlight fit for the diffuse mean free path:
R(r) = A (e^(−r/d) + e^(−r/3d)) / (8π d r), d = ℓd / s, s = 1.9 − A + 3.5 (A − 0.8)²; its
integral over the plane is A (energy ≤ 1 whenever the albedo is).

A thin sheet (model.subsurface "thin") is a Kubelka–Munk slab: K = 2 σa, S = 3/4 σs' (van Gemert
& Star 1987's mapping for diffuse light), reflectance R and transmittance T of thickness t with
R + T ≤ 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .subsurface_fresnel import diffuse_fresnel as diffuse_fresnel  # re-exported: the dipole's Fdr

Array = npt.NDArray[np.float64]
BISECTION_STEPS = 60  # halves [0, 1] down to 1e-18: below double precision
ALBEDO_CEILING = 1.0 - 1e-9  # a reduced albedo of exactly 1 has no absorption: ℓd would be infinite
#: our choice: the brightest multiple-scattering albedo inverted. A path in a medium of albedo A takes
#: about 1/(3 (1 - α')) scattering events (A 0.8: 200, 0.99: 110 000, 1: endless), so a white word
#: ('white candle', albedo 1 after its colour) is rendered as 0.99; the dataset's whitest is Cream, 0.976
ALBEDO_MAX = 0.99


def boundary_a(eta: float) -> float:
    """The dipole's boundary term A = (1 + Fdr) / (1 − Fdr)."""
    fdr = diffuse_fresnel(eta)
    return (1.0 + fdr) / (1.0 - fdr)


def dipole_albedo(reduced_albedo: npt.ArrayLike, eta: float) -> Array:
    """Rd(α'): the total diffuse reflectance of a semi-infinite medium of reduced albedo α'."""
    a = np.clip(np.asarray(reduced_albedo, dtype=np.float64), 0.0, 1.0)
    root = np.sqrt(3.0 * (1.0 - a))
    result: Array = 0.5 * a * (1.0 + np.exp(-4.0 / 3.0 * boundary_a(eta) * root)) * np.exp(-root)
    return result


def reduced_albedo_of(color: npt.ArrayLike, eta: float) -> Array:
    """α' with Rd(α') = color (at most ALBEDO_MAX), per channel, by bisection (Rd is increasing on [0, 1])."""
    target = np.clip(np.asarray(color, dtype=np.float64), 0.0, ALBEDO_MAX)
    low, high = np.zeros_like(target), np.ones_like(target)
    for _ in range(BISECTION_STEPS):
        mid = 0.5 * (low + high)
        below = dipole_albedo(mid, eta) < target
        low, high = np.where(below, mid, low), np.where(below, high, mid)
    result: Array = np.minimum(0.5 * (low + high), ALBEDO_CEILING)
    return result


@dataclass(frozen=True)
class Medium:
    """A homogeneous medium's coefficients in 1/metre per RGB channel, and its phase function's g."""

    sigma_a: Array
    sigma_s: Array
    g: float

    @property
    def sigma_t(self) -> Array:
        total: Array = self.sigma_a + self.sigma_s
        return total

    @property
    def single_albedo(self) -> Array:
        """σs / σt: the chance a collision scatters (the volume path tracer's `albedo`), < 1."""
        ratio: Array = self.sigma_s / np.maximum(self.sigma_t, 1e-300)
        return ratio

    @property
    def reduced_scattering(self) -> Array:
        reduced: Array = self.sigma_s * (1.0 - self.g)
        return reduced


def medium_of(color: npt.ArrayLike, radius: npt.ArrayLike, g: float, eta: float) -> Medium:
    """The inversion: the IR's (color, radius in m, g) under a boundary of IOR η -> σa, σs (1/m)."""
    alpha = reduced_albedo_of(color, eta)
    sigma_tr = 1.0 / np.maximum(np.asarray(radius, dtype=np.float64), 1e-12)
    sigma_t_reduced = sigma_tr / np.sqrt(3.0 * (1.0 - alpha))
    sigma_s_reduced = alpha * sigma_t_reduced
    return Medium(sigma_a=sigma_t_reduced - sigma_s_reduced, sigma_s=sigma_s_reduced / (1.0 - g), g=g)


def appearance(medium: Medium, eta: float) -> tuple[Array, Array]:
    """The forward map: a medium -> (color = Rd, radius = ℓd = 1/σtr), the inverse of `medium_of`."""
    reduced_t = medium.sigma_a + medium.reduced_scattering
    alpha = medium.reduced_scattering / reduced_t
    radius: Array = 1.0 / np.sqrt(3.0 * medium.sigma_a * reduced_t)
    return dipole_albedo(alpha, eta), radius


def profile_shape(albedo: npt.ArrayLike) -> Array:
    """Christensen–Burley's s for the diffuse mean free path ℓd (searchlight configuration):
    s = 3.5 + 100 (A − 0.33)⁴, d = ℓd / s."""
    a = np.asarray(albedo, dtype=np.float64)
    shape: Array = 3.5 + 100.0 * (a - 0.33) ** 4
    return shape


def diffusion_profile(r: npt.ArrayLike, albedo: float, radius: float) -> Array:
    """R(r) in 1/m² at distance r (m) from where light entered: Christensen–Burley, ∫ R dA = albedo."""
    distance = np.asarray(r, dtype=np.float64)
    if not radius > 0.0:  # no path inside: all light leaves where it entered (a delta at r = 0), none at r > 0
        return np.zeros_like(distance)
    d = radius / float(profile_shape(albedo))
    rr = np.maximum(distance, 1e-12)
    value: Array = albedo * (np.exp(-rr / d) + np.exp(-rr / (3.0 * d))) / (8.0 * np.pi * d * rr)
    return value


def slab(medium: Medium, thickness: float) -> tuple[Array, Array]:
    """Kubelka–Munk reflectance R and transmittance T of a sheet `thickness` metres thick (R + T ≤ 1)."""
    k = 2.0 * medium.sigma_a
    s = np.maximum(0.75 * medium.reduced_scattering, 1e-12)
    a = (s + k) / s
    b = np.sqrt(np.maximum(a * a - 1.0, 0.0))
    x = b * s * thickness
    decay = np.exp(-x)  # tanh and sech from e^-x: no overflow for a thick block
    tanh = (1.0 - decay * decay) / (1.0 + decay * decay)
    sech = 2.0 * decay / (1.0 + decay * decay)
    with np.errstate(invalid="ignore", divide="ignore"):
        reflectance = np.where(b > 1e-9, tanh / (a * tanh + b), s * thickness / (1.0 + s * thickness))
        transmittance = np.where(b > 1e-9, b * sech / (a * tanh + b), 1.0 / (1.0 + s * thickness))
    return reflectance.astype(np.float64), transmittance.astype(np.float64)
