"""The key light's pre-integrated diffusion (Penner & Borshukov 2011, "Pre-integrated skin shading",
GPU Pro 2) with the Christensen-Burley profile the IR's radius already describes
(cnlmc.bsdf.subsurface.diffusion_profile, docs/subsurface.md).

On a surface of curvature radius r lit at angle theta, light that entered at arc distance x leaves
here with the profile's weight, so the key light's cosine becomes

    D(theta, d / r) = int cos+(theta + x) R1(2 r sin(|x| / 2)) dx / int R1(2 r sin(|x| / 2)) dx

over the quarter turns x in [-pi/2, pi/2] around the point: light that entered farther round the
ring has crossed the body, which the shader's transmission term (T_l, through the body towards the
key light) counts already; counting it here too would light a thick ball's dark side twice (a
10 cm wax ball lit from behind glowed at 7 % of a leaf with the whole ring). R1 is the profile seen along one line through the surface (the 2-D
profile integrated across it): for Christensen-Burley's R(s) ~ (e^(-s/d) + e^(-s/3d)) / s that is
2 (K0(|x|/d) + K0(|x|/3d)), K0 the modified Bessel function, d = l_d / s_A the profile's scale (the
IR's diffuse mean free path l_d over Burley's shape factor). D depends only on cos(theta) and
rho = d / r; the shader looks it up per channel (shaders/subsurface.glsl.j2, pv_sss_lut).

The table's size is data (data/subsurface.toml [profile]); the table is computed once per process
by `PreintegratedTable` (an immutable value, owned by whoever made it)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt


@dataclass(frozen=True)
class BesselK0:
    """K0 by Abramowitz & Stegun's polynomials (coefficients in data/subsurface.toml [bessel])."""

    i0_small: tuple[float, ...]
    k0_small: tuple[float, ...]
    k0_large: tuple[float, ...]

    def __call__(self, z: npt.ArrayLike) -> np.ndarray:
        x = np.maximum(np.asarray(z, np.float64), 1e-12)
        near = np.minimum(x, 2.0)
        i0 = np.polynomial.polynomial.polyval((near / 3.75) ** 2, self.i0_small)
        small = -np.log(near / 2.0) * i0 + np.polynomial.polynomial.polyval((near / 2.0) ** 2, self.k0_small)
        far = np.maximum(x, 2.0)
        large = np.polynomial.polynomial.polyval(2.0 / far, self.k0_large) * np.exp(-far) / np.sqrt(far)
        return np.where(x <= 2.0, small, large)


def line_profile(distance: np.ndarray, k0: BesselK0) -> np.ndarray:
    """Christensen-Burley's profile integrated across a line, in units of its scale d (unnormalised)."""
    s = np.maximum(distance, 1e-9)
    return k0(s) + k0(s / 3.0)


def preintegrated(cos_theta: np.ndarray, rho: float, k0: BesselK0, samples: int = 4096) -> np.ndarray:
    """D(theta, rho) for each cos(theta): the cosine spread by the profile around a ring of radius
    1/rho (in the profile's units). rho = 0 is the plain clamped cosine."""
    theta = np.arccos(np.clip(cos_theta, -1.0, 1.0))
    if rho <= 0.0:
        return np.maximum(np.cos(theta), 0.0)
    x = ((np.arange(samples) + 0.5) / samples - 0.5) * np.pi  # midpoints in [-pi/2, pi/2]: never x = 0
    weight = line_profile(2.0 / rho * np.abs(np.sin(x / 2.0)), k0)
    spread = np.maximum(np.cos(theta[:, None] + x[None, :]), 0.0)
    return np.asarray((spread * weight).sum(1) / weight.sum())


def rho_of(u: np.ndarray) -> np.ndarray:
    """The table's second axis: u = rho / (1 + rho) in [0, 1) covers every curvature."""
    return u / np.maximum(1.0 - u, 1e-6)


@dataclass(frozen=True)
class PreintegratedTable:
    """D on a grid: `cos_steps` values of cos(theta) in [-1, 1] (rows) x `rho_steps` of
    u = rho / (1 + rho) in [0, u_max] (columns), row-major float32, read-only."""

    cos_steps: int
    rho_steps: int
    u_max: float
    k0: BesselK0
    values: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        cos_theta = np.linspace(-1.0, 1.0, self.cos_steps)
        rhos = rho_of(np.linspace(0.0, self.u_max, self.rho_steps))
        columns = [preintegrated(cos_theta, float(rho), self.k0) for rho in rhos]
        table = np.ascontiguousarray(np.stack(columns, 1), np.float32)
        table.setflags(write=False)
        object.__setattr__(self, "values", table)

    def lookup(self, cos_theta: float, rho: float) -> float:
        """Bilinear look-up, as the shader does it (tests)."""
        row = (np.clip(cos_theta, -1.0, 1.0) + 1.0) / 2.0 * (self.cos_steps - 1)
        col = np.clip(rho / (1.0 + rho) / self.u_max, 0.0, 1.0) * (self.rho_steps - 1)
        r0, c0 = min(int(row), self.cos_steps - 2), min(int(col), self.rho_steps - 2)
        fr, fc = row - r0, col - c0
        v = self.values
        top = v[r0, c0] * (1 - fc) + v[r0, c0 + 1] * fc
        bottom = v[r0 + 1, c0] * (1 - fc) + v[r0 + 1, c0 + 1] * fc
        return float(top * (1 - fr) + bottom * fr)
