"""What the preview's flake sparkle (shaders/flakes.glsl.j2) needs: a flake's area in the mesh's UV
units and the key light's apparent size (docs/preview.md "Flakes", cnlmc.bsdf.flakes)."""

from __future__ import annotations

from cnlmc.bsdf.flakes import has_flakes
from cnlmc.material import Material

from .mesh import Mesh
from .meshes import UV_UNIT_M

#: The solid angle (sr) within which a flake's normal must point to mirror the key light into the
#: eye: 0.003 sr, a disc about 3.5 degrees across. Our choice: a lamp a few metres away, widened
#: by the flakes' own curvature (a point light would light none). Looked at: 0.01 sr lit so many
#: flakes around the highlight that it read as snow rather than sparkle.
LIGHT_SOLID_ANGLE = 0.003


def flake_uniforms(material: Material, mesh: Mesh) -> dict[str, object]:
    """The sparkle's uniforms; none without flakes. A mesh without a stated UV scale (a user mesh)
    is taken at the generated meshes' UV_UNIT_M metres per UV unit."""
    if not has_flakes(material):
        return {}
    metres_per_uv = mesh.metres_per_uv or UV_UNIT_M
    size = float(material.params.flake_size) / metres_per_uv
    return {"pv_flake_area": size * size, "pv_light_solid_angle": LIGHT_SOLID_ANGLE}
