"""What the preview's glass shader (shaders/transmission.glsl.j2) needs to know about the scene:
the object's bounding sphere (its second interface, exact for the sphere mesh), the depth through
which the glass's colour is its transmittance (in world units), and whether the object is a solid
or a thin-walled sheet."""

from __future__ import annotations

import numpy as np

from .mesh import Mesh

#: `glass=` option values: a solid refracts at both interfaces; a thin sheet lets the view
#: through undeflected; auto: a closed mesh is a solid, an open one (a pane, a leaf) a sheet
#: (docs/preview.md, "Transparent materials").
GLASS_FORMS = ("auto", "solid", "thin")


def glass_form(mesh: Mesh, form: str = "auto") -> str:
    """ "solid" or "thin" for this mesh: the option's choice, or by whether the mesh is closed."""
    if form == "auto":
        return "solid" if mesh.closed else "thin"
    return form


def bounding_sphere(mesh: Mesh) -> tuple[np.ndarray, float]:
    """(centre, radius) around the box centre, as meshes.fit scales a mesh (radius 1 there)."""
    lo, hi = mesh.bounds
    centre = (np.asarray(lo, np.float64) + np.asarray(hi, np.float64)) / 2.0
    radius = float(np.linalg.norm(np.asarray(mesh.positions, np.float64) - centre, axis=1).max()) or 1.0
    return centre, radius


def reference_units(depth: float) -> float:
    """The glass's transmission_depth (metres) in object units: a unit is METRES_PER_UNIT metres
    (the unit sphere is the 10 cm ball), the unit of a subsurface medium and the Mitsuba export
    (read where `subsurface.metres_per_unit` reads it: that module imports this one)."""
    from ..exchange.mitsuba_subsurface import METRES_PER_UNIT

    return float(depth) / METRES_PER_UNIT


def glass_uniforms(mesh: Mesh, model: np.ndarray, depth: float, form: str = "auto") -> dict[str, object]:
    """The transmission uniforms for the object drawn with `model` (world = model @ object).

    The reference thickness is the glass's transmission_depth in world units: a path of length d
    inside keeps base_colour^(d / reference) (Beer-Lambert), as cnlmc.bsdf.transmission.absorption."""
    centre, radius = bounding_sphere(mesh)
    model = np.asarray(model, np.float64)
    scale = abs(float(np.linalg.det(model[:3, :3]))) ** (1.0 / 3.0) or 1.0
    world_centre = model[:3, :3] @ centre + model[:3, 3]
    return {
        "pv_glass_centre": world_centre,
        "pv_glass_radius": radius * scale,
        "pv_glass_reference": reference_units(depth) * scale,
        "pv_glass_thin": int(glass_form(mesh, form) == "thin"),
    }


#: rows of each half of the internal-paths texture, over sqrt(alpha) in [0, 1] (a roughness map's
#: alpha varies)
PATH_ROWS = 16


def internal_paths(ior: float) -> np.ndarray:
    """The (2 PATH_ROWS, cosines, 4) texture of the light leaving a rough ball, for this index
    (glass_paths.py), row r of each half at alpha = (r / (PATH_ROWS - 1))^2. First half: the share
    that leaves after the first exit, its mean direction's angle, its spread as a prefilter alpha,
    its mean path in radii; second half: its mean cosine, and the first exit's angle, spread and
    mean cosine."""
    from .glass_paths import KEYS, rows_for

    rows = np.stack([rows_for(ior, (r / (PATH_ROWS - 1)) ** 2) for r in range(PATH_ROWS)])
    first = [KEYS.index(k) for k in ("more", "angle", "spread", "length")]
    second = [KEYS.index(k) for k in ("mean_cos", "first_angle", "first_spread", "first_mean_cos")]
    return np.concatenate([rows[..., first], rows[..., second]]).astype(np.float32)
