"""The split sum's flake section: under a coat a paint's flakes are a wide lobe (their normals
spread by flake_roughness, widened by the coat's index) inside the sharp coat reflection. The
black table's albedo holds both (cnlmc.bsdf.flakes.albedo_flaked); looked up at the coat's α
alone, the flakes mirror the environment's lights as sharply as the coat does (metallic car
paint: FLIP 0.075 against the reference, a sharp window where the reference shows a broad sheen).
So the tables also hold the flakes' own share (what they add through the coat) and the width
they are seen at; the shader looks that share up at that width (split.glsl.j2).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from cnlmc.bsdf.evaluate import albedo, coat_alpha, local_dirs, the_coat
from cnlmc.bsdf.flakes import flake_alpha, flake_lobe, flake_proposal, has_flakes
from cnlmc.bsdf.layered import coated
from cnlmc.material import Material


def coated_flakes(material: Material) -> bool:
    """Whether the split sum draws the flakes apart: a coated material with flakes (the coat's
    tables are never fitted, so the kernel sections are free)."""
    return bool(material.model.coat and material.params.coat is not None and has_flakes(material))


def _flakes_through_coat(material: Material, wo: Any, wi: Any, **_: Any) -> np.ndarray:
    """What the flakes add to the coated BRDF: the coat over the flake lobe minus the coat alone
    (`coated` is linear in its base)."""
    m = material
    wo, wi = local_dirs(m, wo, wi)
    p, coat = m.params, the_coat(m)
    if coat is None:  # coated_flakes chose the material: it has a coat
        raise ValueError(f"{m.name}: the flake sections are for a coated paint")
    density, alpha = float(p.flake_density), float(flake_alpha(p.flake_roughness))
    zeros = np.zeros(np.broadcast_shapes(np.shape(wo), np.shape(wi))[:-1] + (3,))

    def flakes(a: Any, b: Any) -> tuple[Any, Any]:
        return density * flake_lobe(a, b, p.flake_color, alpha), zeros

    def nothing(a: Any, b: Any) -> tuple[Any, Any]:
        return zeros, zeros

    color = np.broadcast_to(np.asarray(coat.color, np.float64), (3,))
    args = (float(coat.ior), coat_alpha(coat), color, float(coat.thickness))
    rho = np.zeros(3)  # the flakes are a directional part: the diffuse part's series does not see them
    return coated(wo, wi, flakes, *args, rho) - coated(wo, wi, nothing, *args, rho)


def flake_sections(material: Material, mus: np.ndarray, samples: int, lean: Any) -> np.ndarray:
    """(2 * len(mus), 4): section 1 = the flakes' directional albedo (RGB) and lean (A), section 2
    = the flake lobe's α seen from outside (R; flake_proposal), for every cos θv in `mus`.
    `lean(toward, along)` turns first moments into a lean (albedo_tables._lean)."""
    black = dataclasses.replace(material, params=dataclasses.replace(material.params, base_color=(0.0, 0.0, 0.0)))
    lobes = [flake_proposal(black)]
    own = albedo(black, mus, samples, 0.0, bsdf=_flakes_through_coat, extra_lobes=lobes)
    toward = albedo(black, mus, samples, 0.0, lambda wi: wi[..., 0], bsdf=_flakes_through_coat, extra_lobes=lobes)
    along = albedo(black, mus, samples, 0.0, lambda wi: wi[..., 2], bsdf=_flakes_through_coat, extra_lobes=lobes)
    proposal = flake_proposal(black)
    width = float(np.asarray(proposal[0])) if proposal else 1.0
    first = np.concatenate([np.clip(own, 0.0, None), lean(toward.mean(-1), along.mean(-1))[:, None]], 1)
    second = np.zeros((len(mus), 4))
    second[:, 0] = width
    return np.concatenate([first, second]).astype(np.float64)
