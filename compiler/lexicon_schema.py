"""Checks lexicon entries against stdlib/schema.toml; errors name the file and the key."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from .params import COAT_PARAMS, PARAMS, ParamSpec

COMMON_FIELDS: dict[str, dict[str, Any]] = {
    "aliases": {"type": "strlist"},
    "doc": {"type": "str", "required": True},
    "example": {"type": "str", "required": True},
}


class LexiconError(Exception):
    """A lexicon file is malformed; the message names the file and the key."""


FieldSpec = dict[str, Any]  # one field of stdlib/schema.toml: type, required, choices, range, from


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _is_rgb(value: Any) -> bool:
    return isinstance(value, list) and len(value) == 3 and all(_is_number(v) for v in value)


def _is_effects(value: Any) -> bool:
    return isinstance(value, list) and all(isinstance(e, dict) and "param" in e and "op" in e for e in value)


def _is_ops(value: Any) -> bool:
    return isinstance(value, list) and all(isinstance(e, dict) and "op" in e for e in value)


TYPE_CHECKS: dict[str, Callable[[Any], bool]] = {
    "str": lambda v: isinstance(v, str),
    "float": _is_number,
    "int": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "bool": lambda v: isinstance(v, bool),
    "rgb": _is_rgb,
    "strlist": lambda v: isinstance(v, list) and all(isinstance(s, str) for s in v),
    "table": lambda v: isinstance(v, dict),
    "effects": _is_effects,
    "ops": _is_ops,
    "maps": lambda v: isinstance(v, dict) and all(isinstance(m, dict) and "graph" in m for m in v.values()),
    "on": lambda v: isinstance(v, dict) and all(_is_effects(e) for e in v.values()),
    "step": lambda v: isinstance(v, dict) and "op" in v and _is_number(v.get("value")),
}


_LEXICON_TYPES = {"number": "float", "rgb": "rgb", "str": "str", "enum": "str"}


def _table_field(spec: ParamSpec) -> FieldSpec:
    field: FieldSpec = {"type": _LEXICON_TYPES[spec.kind]}
    if spec.range is not None:
        field["range"] = list(spec.range)
    if spec.choices:
        field["choices"] = list(spec.choices)
    return field


#: "params.<name>" / "coat.<name>" -> the field's type and range, from the parameter table (cnlmc.params).
#: A schema.toml field written `{ from = "params.ior" }` takes them from here: the range lives in one place.
TABLE_FIELDS = {
    **{f"params.{s.name}": _table_field(s) for s in PARAMS if s.kind in _LEXICON_TYPES},
    **{f"coat.{s.name}": _table_field(s) for s in COAT_PARAMS if s.kind in _LEXICON_TYPES},
}


def check_entry(entry: dict[str, Any], fields: dict[str, FieldSpec], where: str, partial: bool = False) -> None:
    """Raise LexiconError for an unknown field, a wrong type, a bad choice or a value out of range."""
    allowed: dict[str, FieldSpec] = {**COMMON_FIELDS, **fields}
    for name, value in entry.items():
        spec = allowed.get(name)
        if spec is None:
            raise LexiconError(f"{where}: unknown field '{name}' (allowed: {', '.join(sorted(allowed))})")
        _check_value(value, spec, f"{where}.{name}")
    if not partial:
        for name, spec in allowed.items():
            if spec.get("required") and name not in entry:
                raise LexiconError(f"{where}: missing required field '{name}'")


def _check_value(value: Any, spec: FieldSpec, where: str) -> None:
    source = spec.get("from")
    if source is not None:
        spec = {**TABLE_FIELDS[source], **spec}
    kind = spec["type"]
    if not TYPE_CHECKS[kind](value):
        raise LexiconError(f"{where}: expected {kind}, got {value!r}")
    if "choices" in spec and value not in spec["choices"]:
        raise LexiconError(f"{where}: {value!r} is not one of {spec['choices']}")
    low, high = spec.get("range", (-math.inf, math.inf))
    if kind == "float" and not low <= value <= high:
        raise LexiconError(f"{where}: {value} is outside [{low}, {high}]")
