"""The options every exchange target declares (maps, map_size, map_format; seed and output come
with every target), and what maps=none does to a capability table."""

from __future__ import annotations

from collections.abc import Mapping

from ..base import Option
from ..maps.bake import MAX_SIZE, MIN_SIZE
from ..maps.writer import FORMATS

MAP_FORMATS = tuple(FORMATS)
MAP_MODES = ("bake", "none")

Capabilities = Mapping[str, tuple[str, str]]


def map_options(modes: tuple[str, ...] = MAP_MODES) -> tuple[Option, ...]:
    """The map options; `modes`: the values `maps` takes for this target (bake first, the default)."""
    return (
        Option("maps", str, "bake", choices=modes, doc="bake: procedural maps become image files; none: left out"),
        Option(
            "map_size",
            int,
            256,
            doc=f"baked image size in pixels (a power of two, {MIN_SIZE} to {MAX_SIZE})",
            range=(MIN_SIZE, MAX_SIZE),
        ),
        Option("map_format", str, "png8", choices=MAP_FORMATS, doc="baked image encoding"),
    )


MAP_DROPPED = ("drop", "maps=none: procedural maps are not baked; the uniform parameters are used")


def capabilities_for(capabilities: Capabilities, maps: str) -> Capabilities:
    """With maps=none every map feature is dropped (and said so)."""
    if maps != "none":
        return capabilities
    return {f: (MAP_DROPPED if f.startswith("maps.") else p) for f, p in capabilities.items()}
