"""What the preview's sheen shader (shaders/sheen.glsl.j2) needs: the sheen's colour, its width and
the material's row of the reference's sheen-albedo table (cnlmc.bsdf.sheen, docs/bsdf.md "Sheen")."""

from __future__ import annotations

from cnlmc.bsdf.sheen import has_sheen, sheen_alpha, sheen_row
from cnlmc.material import Material


def sheen_uniforms(material: Material) -> dict[str, object]:
    """The sheen uniforms of a material; none when it has no sheen."""
    if not has_sheen(material):
        return {}
    alpha = float(sheen_alpha(material.params.sheen_roughness))
    return {
        "pv_sheen_color": material.params.sheen_color,
        "pv_sheen_alpha": alpha,
        "pv_sheen_albedo": sheen_row(alpha),
    }
