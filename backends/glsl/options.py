"""The GLSL backend's options (`--option key=value`), declared once; defaults are documented in docs/glsl.md."""

from __future__ import annotations

from dataclasses import dataclass

from ..base import Option, OptionError, Options, parse_options

__all__ = ["OPTIONS", "GlslOptions", "OptionError", "glsl_options", "parse_glsl_options"]

OPTIONS = (
    Option(
        "fresnel",
        str,
        "exact",
        choices=("exact", "f82", "schlick"),
        doc="conductor/dielectric Fresnel: exact (eta + ik / IOR), F82 (Hoffman 2019) or Schlick",
    ),
    Option("multiscatter", str, "off", choices=("off", "on"), doc="Kulla-Conty energy compensation of conductor lobes"),
    Option(
        "profile",
        str,
        "330",
        choices=("330", "es300"),
        doc="#version 330 core, or #version 300 es with precision qualifiers",
    ),
    Option(
        "form",
        str,
        "both",
        choices=("both", "library", "standalone"),
        doc="library: <name>.glsl; standalone: <name>.frag + <name>.vert; both",
    ),
    Option("maps", str, "bake", choices=("bake", "none"), doc="bake: the maps the shader samples, as PNG files"),
    Option(
        "map_size",
        int,
        256,
        doc="baked image size in pixels (a power of two, 8 to 8192)",
        range=(8, 8192),
    ),
    Option("map_format", str, "png8", choices=("png8", "png16"), doc="baked image encoding (sRGB colour, raw data)"),
    Option(
        "specialize",
        str,
        "on",
        choices=("on", "off"),
        doc="on: only the code the model needs; off: every branch compiled in (uber shader)",
    ),
)


@dataclass(frozen=True)
class GlslOptions:
    fresnel: str = "exact"
    multiscatter: bool = False
    profile: str = "330"
    form: str = "both"
    specialize: bool = True
    maps: str = "bake"  # none: no image (a translucent body's table is then a const array in the library)

    def as_dict(self) -> dict[str, str]:
        """The options as the sidecar records them."""
        return {
            "fresnel": self.fresnel,
            "multiscatter": "on" if self.multiscatter else "off",
            "profile": self.profile,
            "form": self.form,
            "specialize": "on" if self.specialize else "off",
        }


def glsl_options(options: Options) -> GlslOptions:
    """Parsed options -> what the plan and templates read."""
    return GlslOptions(
        fresnel=options.fresnel,
        multiscatter=options.multiscatter == "on",
        profile=options.profile,
        form=options.form,
        specialize=options.specialize == "on",
        maps=options.maps,
    )


def parse_glsl_options(pairs: dict[str, object] | None) -> GlslOptions:
    """Raw `--option` pairs -> GlslOptions (OptionError for unknown keys and values)."""
    return glsl_options(parse_options(OPTIONS, pairs, "glsl"))
