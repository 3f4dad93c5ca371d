"""The 'maps' target: every material's procedural maps, baked to image files.

Options: size (default 1024, a power of two), format (png8 | png16 | exr-half | exr-float).
Uniform materials produce no files (nothing varies over their surface).
"""

from __future__ import annotations

from cnlmc.material import Document, Material

from ..base import Artifact, Option, Options, Target, emit_each
from ..capabilities import ALL_FEATURES, EmitResult
from .service import MapBakeError, bake_artifacts
from .writer import FORMATS


class MapsTarget(Target):
    name = "maps"
    description = "baked procedural maps (PNG/EXR through OpenImageIO)"
    capabilities = dict.fromkeys(
        ALL_FEATURES, ("exact", "maps are this target's whole output; BSDF features are not its concern")
    )
    options = (
        Option("size", int, 1024, doc="map size in pixels, a power of two from 8 to 8192"),
        Option("format", str, "png8", choices=tuple(FORMATS), doc="image format"),
    )

    def emit(self, document: Document, options: Options) -> EmitResult:
        return emit_each(self, document, lambda material: self.bake(material, options))

    def bake(self, material: Material, options: Options) -> list[Artifact]:
        if not material.maps:
            return []
        try:
            return bake_artifacts(material, options.size, options.format, options.seed)
        except MapBakeError as exc:
            raise ValueError(f"maps: {exc}") from None


TARGET = MapsTarget()
