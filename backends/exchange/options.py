"""The options every exchange target takes (maps, map_size, map_format, seed), and what
maps=none does to a capability table."""

from __future__ import annotations

from ..capabilities import COMPILER_OPTIONS

MAP_MODES = ("bake", "none")
MAP_FORMATS = ("png8", "png16", "exr-half", "exr-float")
COMMON_OPTIONS = {"maps": "bake", "map_size": "256", "map_format": "png8", "seed": "0"}


def exchange_options(options: dict | None, target: str, extra: dict[str, tuple]) -> dict:
    """Validate options: `extra` is name -> (default, allowed values or None for any int)."""
    known = {**{k: (v, None) for k, v in COMMON_OPTIONS.items()}, **extra}
    options = {k: v for k, v in (options or {}).items() if k in known or k not in COMPILER_OPTIONS}
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise ValueError(f"{target}: unknown option(s) {', '.join(unknown)}; known: {', '.join(sorted(known))}")
    out = {}
    for name, (default, allowed) in known.items():
        value = str(options.get(name, default))
        if allowed is not None and value not in allowed:
            raise ValueError(f"{target}: option {name}={value!r}: use one of {', '.join(allowed)}")
        out[name] = value
    for name in ("map_size", "seed"):
        out[name] = _int_option(target, name, out[name])
    if out["maps"] not in MAP_MODES:
        raise ValueError(f"{target}: option maps={out['maps']!r}: use one of {', '.join(MAP_MODES)}")
    if out["map_format"] not in MAP_FORMATS:
        raise ValueError(f"{target}: option map_format={out['map_format']!r}: use one of {', '.join(MAP_FORMATS)}")
    return out


def _int_option(target: str, name: str, value: str) -> int:
    try:
        return int(value)
    except ValueError:
        raise ValueError(f"{target}: option {name}={value!r} must be a whole number") from None


def capabilities_for(capabilities: dict, opts: dict) -> dict:
    """With maps=none every map feature is dropped (and said so)."""
    if opts["maps"] != "none":
        return capabilities
    dropped = ("drop", "maps=none: procedural maps are not baked; the uniform parameters are used")
    return {f: (dropped if f.startswith("maps.") else p) for f, p in capabilities.items()}
