"""The GLSL backend's options (`--option key=value`): the table, defaults, validation."""

from __future__ import annotations

from dataclasses import dataclass

from ..capabilities import COMPILER_OPTIONS

#: option -> (allowed values, default, what it means). Defaults are documented in docs/glsl.md.
OPTION_TABLE = {
    "fresnel": (
        ("exact", "f82", "schlick"),
        "exact",
        "conductor/dielectric Fresnel: exact (eta + ik / IOR), F82 (Hoffman 2019) or Schlick",
    ),
    "multiscatter": (("off", "on"), "off", "Kulla-Conty energy compensation of conductor lobes"),
    "profile": (("330", "es300"), "330", "#version 330 core, or #version 300 es with precision qualifiers"),
    "form": (
        ("both", "library", "standalone"),
        "both",
        "library: <name>.glsl; standalone: <name>.frag + <name>.vert; both",
    ),
    "specialize": (
        ("on", "off"),
        "on",
        "on: only the code the model needs; off: every branch compiled in (uber shader)",
    ),
}

#: Options the compiler passes to every backend that are not ours to validate.
FOREIGN_OPTIONS = COMPILER_OPTIONS


class OptionError(ValueError):
    """An option name or value the GLSL backend does not know."""


@dataclass(frozen=True)
class GlslOptions:
    fresnel: str = "exact"
    multiscatter: bool = False
    profile: str = "330"
    form: str = "both"
    specialize: bool = True

    def as_dict(self) -> dict:
        return {
            "fresnel": self.fresnel,
            "multiscatter": "on" if self.multiscatter else "off",
            "profile": self.profile,
            "form": self.form,
            "specialize": "on" if self.specialize else "off",
        }


def _value(options: dict, key: str) -> str:
    allowed, default, _ = OPTION_TABLE[key]
    value = str(options.get(key, default)).strip().lower()
    if value not in allowed:
        raise OptionError(f"glsl: option {key}={value!r} is not one of {', '.join(allowed)}")
    return value


def parse_options(options: dict | None) -> GlslOptions:
    """Validate `--option` strings into GlslOptions; unknown keys are an error."""
    options = dict(options or {})
    unknown = sorted(set(options) - set(OPTION_TABLE) - set(FOREIGN_OPTIONS))
    if unknown:
        raise OptionError(f"glsl: unknown option(s) {', '.join(unknown)}; known: {', '.join(OPTION_TABLE)}")
    return GlslOptions(
        fresnel=_value(options, "fresnel"),
        multiscatter=_value(options, "multiscatter") == "on",
        profile=_value(options, "profile"),
        form=_value(options, "form"),
        specialize=_value(options, "specialize") == "on",
    )
