"""The IR writer's check of one material, without building the typed records (#13 speed).

`check_material(ir, path)` accepts exactly what `Material.from_ir(ir, path)` accepts and raises
the same ValueError where it refuses: a plain-JSON material (dicts, lists, str, int, float) whose
every value lies where the parameter table says is accepted here by one pass of table lookups;
anything else (a mapping that is not a dict, a tuple, a value out of range, a key the table
lacks) is handed to `Material.from_ir`, which names the bad value or accepts the unusual form.
So this is a fast accept, never a second set of rules: what it accepts, from_ir accepts
(tests/fuzz/test_ir_check.py compares the two on mutated materials). Typing a material costs
more than making its IR; the streamed IR target checks every material it writes.
"""

from __future__ import annotations

import sys
from typing import Any

from .material import MAP_ROLES, Material
from .params import (
    BASES,
    COAT_PARAMS,
    DIFFUSE_LOBES,
    DISTRIBUTIONS,
    PARAMS,
    SUBSURFACE_MODELS,
    SUBSURFACE_PARAMS,
    ParamSpec,
)

__all__ = ["check_material"]

_BIGGEST = sys.float_info.max
_KINDS_OF_NUMBER = (float, int)  # exact types: bool is an int subclass and not a number here

#: name -> (kind, low, high, choices, optional): a table row as the check reads it
Rule = tuple[str, float, float, tuple[Any, ...], bool]


def _rules(specs: tuple[ParamSpec, ...]) -> dict[str, Rule]:
    out: dict[str, Rule] = {}
    for s in specs:
        low, high = s.range if s.range is not None else (-_BIGGEST, _BIGGEST)
        out[s.name] = (s.kind, low, high, s.choices, s.optional)
    return out


_PARAM_RULES = _rules(PARAMS)
_COAT_RULES = _rules(COAT_PARAMS)
_SUBSURFACE_RULES = _rules(SUBSURFACE_PARAMS)
_SUBSURFACE_MODELS = frozenset(SUBSURFACE_MODELS)
_BASES, _DISTRIBUTIONS, _LOBES = frozenset(BASES), frozenset(DISTRIBUTIONS), frozenset(DIFFUSE_LOBES)
_ROLES = frozenset(MAP_ROLES)
_STRING_FIELDS = ("name", "phrase", "label")


def check_material(ir: object, path: str = "") -> None:
    """Raise the ValueError Material.from_ir(ir, path) raises; return where it accepts `ir`."""
    if not _plainly_valid(ir):
        Material.from_ir(ir, path)


def _plainly_valid(d: object) -> bool:
    """Whether `d` is a plain-JSON material that from_ir accepts (False: not sure; from_ir decides)."""
    if type(d) is not dict:
        return False
    for key in _STRING_FIELDS:
        if key in d and type(d[key]) is not str:
            return False
    model = d.get("model")
    return (
        type(model) is dict
        and _model_ok(model)
        and _variant_ok(d.get("variant"))
        and _params_ok(d.get("params"), _PARAM_RULES)
        and _maps_ok(d.get("maps", {}))
        and _provenance_ok(d.get("provenance", {}))
    )


def _model_ok(model: dict[str, Any]) -> bool:
    for key, choices in _MODEL_CHOICES:  # _member of each, written out
        value = model.get(key)
        if not ((value is None or type(value) is str) and value in choices):
            return False
    return type(model.get("anisotropic", False)) is bool and type(model.get("coat", False)) is bool


_MODEL_CHOICES = (
    ("base", _BASES),
    ("distribution", _DISTRIBUTIONS),
    ("diffuse", _LOBES),
    ("subsurface", _SUBSURFACE_MODELS),
)


def _variant_ok(variant: object) -> bool:
    if variant is None:
        return True
    if type(variant) is not dict:
        return False
    choices = variant.get("choices")
    return (
        type(variant.get("group")) is str
        and type(variant.get("name")) is str
        and type(choices) is list
        and all(type(c) is str for c in choices)
    )


def _params_ok(params: object, rules: dict[str, Rule]) -> bool:
    if type(params) is not dict:
        return False
    for key, value in params.items():
        rule = rules.get(key)
        if rule is None:
            return False
        kind = type(value)
        if kind is float:  # most values: _value_ok's number case, written out
            if rule[0] != "number" or not rule[1] <= value <= rule[2]:
                return False
        elif kind is list and (rule[0] == "rgb" or rule[0] == "alpha"):  # _value_ok's lists, written out
            if len(value) != (3 if rule[0] == "rgb" else 2):
                return False
            low, high = rule[1], rule[2]
            for v in value:
                if type(v) not in _KINDS_OF_NUMBER or not low <= v <= high:
                    return False
        elif not _value_ok(value, rule):
            return False
    return True


def _value_ok(value: object, rule: Rule) -> bool:
    kind, low, high, choices, optional = rule
    if value is None:
        return optional
    if kind == "number":
        return type(value) in _KINDS_OF_NUMBER and low <= value <= high  # type: ignore[operator]
    if kind == "rgb" or kind == "alpha":
        return _numbers_ok(value, 3 if kind == "rgb" else 2, low, high)
    if kind == "enum":
        return type(value) is str and value in choices
    if kind == "str":
        return type(value) is str
    if kind == "coat":
        return _params_ok(value, _COAT_RULES)
    if (
        kind == "subsurface"
    ):  # a translucent material's medium: checked here as a coat is (from_ir took 30 % of the check)
        return _params_ok(value, _SUBSURFACE_RULES)
    return False


def _numbers_ok(value: object, count: int, low: float, high: float) -> bool:
    if type(value) is not list or len(value) != count:
        return False
    for v in value:
        if type(v) not in _KINDS_OF_NUMBER or not low <= v <= high:
            return False
    return True


def _maps_ok(maps: object) -> bool:
    if type(maps) is not dict:
        return False
    for role, ref in maps.items():
        if role not in _ROLES or type(ref) is not dict:
            return False
        params = ref.get("params", {})
        if type(params) is not dict:
            return False
        for v in params.values():  # _number_ok, written out
            if type(v) not in _KINDS_OF_NUMBER or not -_BIGGEST <= v <= _BIGGEST:
                return False
        if type(ref.get("seed", 0)) is not int or type(ref.get("graph")) is not str:
            return False
        if type(ref.get("output")) is not str:
            return False
    return True


def _provenance_ok(provenance: object) -> bool:
    if type(provenance) is not dict:
        return False
    for steps in provenance.values():
        if type(steps) is not list:
            return False
        for step in steps:
            if type(step) is not dict:
                return False
    return True
