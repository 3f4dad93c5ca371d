"""Checks lexicon entries against stdlib/schema.toml, down to every formula and map reference.

Every complaint is a LexiconError reading `FILE:LINE:COL: key 'brushed.effects[1].op': ...`:
the file, the key's line and column in it, what is wrong and, for a mistyped name, the
closest valid one. Numbers are finite and bounded (a parameter's range where the parameter
table has one, else MAX_MAGNITUDE); lists are bounded in length.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable, Collection, Iterable
from typing import Any, NoReturn

from .colour import parse_hex
from .graphs import graph_names, graph_outputs, graph_params
from .lexicon_source import Path_, SourceText, dotted
from .material import MAP_ROLES
from .params import COAT_PARAMS, PARAMS, SUBSURFACE_PARAMS, ParamSpec

COMMON_FIELDS: dict[str, dict[str, Any]] = {
    "aliases": {"type": "strlist"},
    "doc": {"type": "str", "required": True},
    "example": {"type": "str", "required": True},
}

MAX_MAGNITUDE = 1e6  # a number without a declared range lies in [-1e6, 1e6]
MAX_FACTOR = 1e3  # what a formula may multiply or add by
MAX_ITEMS = 256  # formulas, shade operations or aliases in one list
MAX_TEXT = 4096  # characters in one string field
#: what a formula's `param = "model"` may set (a metal needs a noun's optics: `material = "copper"`)
EFFECT_MODELS = ("dielectric", "glass")
FORMULA_OPS = ("set", "mul", "add", "blend")  # a refinement step's
EFFECT_OPS = (*FORMULA_OPS, "mix")  # an adjective's: 'mix' is blend in OKLab, for a colour (compiler/formulas.py)
SHADE_OPS = {
    "saturate": ("amount",),
    "blend": ("value", "amount"),
    "mul": ("value",),
    "lightness": ("toward", "amount"),  # OKLab L toward 0 or 1 (compiler/colour.py)
    "chroma": ("scale",),  # OKLCh chroma times scale
    "toward": ("oklab", "amount"),  # OKLab a, b toward a colour's ("reddish")
}
#: fields an operation may have besides those it needs
SHADE_OP_OPTIONS = {"chroma": ("keep",)}  # a lowered chroma stays at least min(C, keep) ('pale oak' is a wood colour)
PARAM_SPECS = {s.name: s for s in PARAMS}
#: What an adjective's formula may change: the scalar parameters, the base colour and the model.
#: (A metal's optics come whole from a noun: `material = "copper"`.)
EFFECT_PARAMS = (*(s.name for s in PARAMS if s.kind == "number"), "base_color", "flake_color", "model")


class LexiconError(Exception):
    """A lexicon file is malformed; the message names the file (FILE:LINE:COL where known) and the key."""


FieldSpec = dict[str, Any]  # one field of stdlib/schema.toml: type, required, choices, range, from


def did_you_mean(word: object, choices: Iterable[str]) -> str:
    """ " (did you mean 'x'?)" for the closest choice, or ""."""
    if not isinstance(word, str):
        return ""
    close = difflib.get_close_matches(word, sorted(choices), n=1, cutoff=0.6)
    return f" (did you mean '{close[0]}'?)" if close else ""


def _short(value: object) -> str:
    """repr(value), cut to 60 characters."""
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def shown(value: object) -> str:
    """A value as the error shows it: its type and a short repr."""
    text = _short(value)
    kinds = {bool: "a boolean", int: "a number", float: "a number", str: "a string", list: "a list", dict: "a table"}
    return f"{kinds.get(type(value), type(value).__name__)} {text}"


class Checker:
    """Checks values from one file; every failure says FILE:LINE:COL and the key's path."""

    def __init__(self, source: SourceText) -> None:
        self.source = source

    def fail(self, path: Path_, message: str) -> NoReturn:
        where = self.source.where(path)
        raise LexiconError(f"{where}: key '{dotted(path)}': {message}" if path else f"{where}: {message}")

    def table(self, value: object, path: Path_, what: str = "a table") -> dict[str, Any]:
        if not isinstance(value, dict):
            self.fail(path, f"expected {what}, got {shown(value)}")
        return value

    def array(self, value: object, path: Path_, what: str = "a list") -> list[Any]:
        if not isinstance(value, list):
            self.fail(path, f"expected {what}, got {shown(value)}")
        if len(value) > MAX_ITEMS:
            self.fail(path, f"a list of {len(value)} items; at most {MAX_ITEMS} are allowed")
        return value

    def string(self, value: object, path: Path_, blank: bool = True) -> str:
        if not isinstance(value, str):
            self.fail(path, f"expected a string, got {shown(value)}")
        if len(value) > MAX_TEXT:
            self.fail(path, f"a string of {len(value)} characters; at most {MAX_TEXT} are allowed")
        if not blank and not value.strip():
            self.fail(path, "expected a word, got an empty string")
        return value

    def number(self, value: object, path: Path_, low: float = -MAX_MAGNITUDE, high: float = MAX_MAGNITUDE) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(path, f"expected a number, got {shown(value)}")
        if isinstance(value, float) and not math.isfinite(value):
            self.fail(path, f"expected a finite number, got {value}")
        if not low <= value <= high:
            self.fail(path, f"{_short(value)} is outside [{low:g}, {high:g}]")
        return float(value)

    def rgb(self, value: object, path: Path_, low: float = -MAX_MAGNITUDE, high: float = MAX_MAGNITUDE) -> list[float]:
        if not isinstance(value, list) or len(value) != 3:
            self.fail(path, f"expected an RGB triple [r, g, b], got {shown(value)}")
        return [self.number(c, (*path, i), low, high) for i, c in enumerate(value)]

    def choice(self, value: object, choices: Collection[Any], path: Path_, what: str) -> Any:
        if isinstance(value, bool) or not isinstance(value, (str, int, float)) or value not in choices:
            listed = ", ".join(repr(c) for c in choices)
            given = _short(value) if isinstance(value, str) else shown(value)
            self.fail(path, f"{given} is not a known {what}{did_you_mean(value, map(str, choices))}; one of: {listed}")
        return value

    def known_keys(self, table: dict[str, Any], allowed: Collection[str], path: Path_, what: str = "field") -> None:
        for key in table:
            if key not in allowed:
                hint = did_you_mean(key, allowed)
                self.fail((*path, key), f"unknown {what} '{key}'{hint}; allowed: {', '.join(sorted(allowed))}")

    def required(self, table: dict[str, Any], key: str, path: Path_, note: str = "") -> Any:
        if key not in table:
            self.fail(path, f"missing required field '{key}'{note}")
        return table[key]


# ---------------------------------------------------------------- entries and plain fields

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
    **{f"subsurface.{s.name}": _table_field(s) for s in SUBSURFACE_PARAMS if s.kind in _LEXICON_TYPES},
}


def check_entry(
    c: Checker, entry: object, fields: dict[str, FieldSpec], path: Path_, partial: bool = False, common: bool = True
) -> dict[str, Any]:
    """Fail on a non-table, an unknown field, a wrong type, a bad choice, a value out of range, or
    (unless `partial`) a missing required field. `common`: the entry also takes aliases, doc, example."""
    table = c.table(entry, path, "a table of fields")
    allowed: dict[str, FieldSpec] = {**COMMON_FIELDS, **fields} if common else fields
    c.known_keys(table, allowed, path)
    for name, value in table.items():
        check_field(c, value, allowed[name], (*path, name))
    if not partial:
        check_required(c, table, fields, path)
    return table


def check_required(
    c: Checker, table: dict[str, Any], fields: dict[str, FieldSpec], path: Path_, others: Collection[str] = ()
) -> None:
    """Every required field is there; `others`: the names of the entries there are (a new entry named
    close to one of them is most likely a change to it, mistyped)."""
    for name, spec in {**COMMON_FIELDS, **fields}.items():
        if spec.get("required") and name not in table:
            key = str(path[0]) if path else ""
            close = difflib.get_close_matches(key, [o for o in others if o != key], n=1, cutoff=0.6)
            hint = f"; did you mean to change '{close[0]}'?" if close else ""
            c.fail(path, f"missing required field '{name}' (a new entry needs: {_required_list(fields)}){hint}")


def _required_list(fields: dict[str, FieldSpec]) -> str:
    return ", ".join(n for n, s in {**COMMON_FIELDS, **fields}.items() if s.get("required"))


def check_field(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    source = spec.get("from")
    if source is not None:
        spec = {**TABLE_FIELDS[source], **spec}
    FIELD_CHECKS[spec["type"]](c, value, spec, path)


def _check_str(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    c.string(value, path)
    if "choices" in spec:
        c.choice(value, spec["choices"], path, "value")


def _check_float(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    low, high = spec.get("range", (-MAX_MAGNITUDE, MAX_MAGNITUDE))
    c.number(value, path, low, high)


def _check_int(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    if isinstance(value, bool) or not isinstance(value, int):
        c.fail(path, f"expected a whole number, got {shown(value)}")
    if "choices" in spec:
        c.choice(value, spec["choices"], path, "value")
    c.number(value, path)


def _check_bool(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    if not isinstance(value, bool):
        c.fail(path, f"expected true or false, got {shown(value)}")


def _check_rgb(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    low, high = spec.get("range", (-MAX_MAGNITUDE, MAX_MAGNITUDE))
    c.rgb(value, path, low, high)


def _check_strlist(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    for i, item in enumerate(c.array(value, path, "a list of strings")):
        c.string(item, (*path, i), blank=False)


def _check_table(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    c.table(value, path)


def _check_hex(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    if parse_hex(c.string(value, path)) is None:
        c.fail(path, f"{shown(value)} is not a hex colour; write '#rrggbb' (or the shorthand '#rgb')")


# ---------------------------------------------------------------- formulas (adjectives' effects)


def _check_effects(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    for i, item in enumerate(c.array(value, path, "a list of formulas")):
        check_effect(c, item, (*path, i))


def check_effect(c: Checker, raw: object, path: Path_) -> None:
    """{ param = "roughness", op = "mul", value = 1.2 } (blend also takes `amount`)."""
    effect = c.table(raw, path, "a formula table { param = ..., op = ..., value = ... }")
    c.known_keys(effect, ("param", "op", "value", "amount"), path)
    param = c.choice(c.required(effect, "param", path), EFFECT_PARAMS, (*path, "param"), "parameter")
    op = c.choice(c.required(effect, "op", path), EFFECT_OPS, (*path, "op"), "formula op")
    if op == "mix" and PARAM_SPECS.get(param) is not None and PARAM_SPECS[param].kind != "rgb":
        c.fail((*path, "op"), f"op = 'mix' blends colours in OKLab: '{param}' is not a colour")
    if "amount" in effect:
        if op not in ("blend", "mix"):
            c.fail((*path, "amount"), f"'amount' belongs to op = 'blend' or 'mix' only (this formula's op is '{op}')")
        c.number(effect["amount"], (*path, "amount"), 0.0, 1.0)
    value = c.required(effect, "value", path)
    if param == "model":
        if op != "set":
            c.fail((*path, "op"), "the model can only be set: op = 'set'")
        if value == "conductor":
            c.fail((*path, "value"), "a formula cannot make a metal: its optics come from a noun (material = 'copper')")
        c.choice(value, EFFECT_MODELS, (*path, "value"), "model")
        return
    _check_formula_value(c, PARAM_SPECS[param], op, value, (*path, "value"))


def _check_formula_value(c: Checker, spec: ParamSpec, op: str, value: object, path: Path_) -> None:
    """set/blend move towards a value in the parameter's range; mul/add scale or shift by a bounded amount."""
    low, high = spec.range or (-MAX_MAGNITUDE, MAX_MAGNITUDE)
    if op in ("mul", "add"):
        low, high = -MAX_FACTOR, MAX_FACTOR
    if spec.kind == "rgb" and isinstance(value, list):
        c.rgb(value, path, low, high)
    else:
        c.number(value, path, low, high)


def _check_on(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    for name, effects in c.table(value, path, "a table of noun or class -> formulas").items():
        _check_effects(c, effects, spec, (*path, name))


def _check_step(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    """A refinement step: { op = "add", value = 0.1 }; blend moves `value` of the way `to` a colour."""
    step = c.table(value, path, "a step table { op = ..., value = ... }")
    c.known_keys(step, ("op", "value", "to"), path)
    op = c.choice(c.required(step, "op", path), FORMULA_OPS, (*path, "op"), "step op")
    amount = c.required(step, "value", path)
    if op == "blend":
        c.number(amount, (*path, "value"), 0.0, 1.0)
        if "to" in step:
            c.rgb(step["to"], (*path, "to"), 0.0, 1.0)
        return
    if "to" in step:
        c.fail((*path, "to"), f"'to' belongs to op = 'blend' only (this step's op is '{op}')")
    low = 1 / MAX_FACTOR if op == "mul" else -MAX_FACTOR
    c.number(amount, (*path, "value"), low, MAX_FACTOR)


# ---------------------------------------------------------------- shades' colour operations


def _check_ops(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    ops = c.array(value, path, "a list of colour operations")
    if not ops:
        c.fail(path, "expected at least one colour operation")
    for i, raw in enumerate(ops):
        check_shade_op(c, raw, (*path, i))


def check_shade_op(c: Checker, raw: object, path: Path_) -> None:
    """saturate (amount), blend (value = [r, g, b], amount), mul (value), and in OKLab: lightness
    (toward = 0 or 1, amount), chroma (scale, and optionally keep) or toward (oklab = [L, a, b], amount)."""
    op_table = c.table(raw, path, "an operation table { op = ..., ... }")
    op = c.choice(c.required(op_table, "op", path), SHADE_OPS, (*path, "op"), "colour operation")
    needs = SHADE_OPS[op]
    c.known_keys(op_table, ("op", *needs, *SHADE_OP_OPTIONS.get(op, ())), path, f"field for op = '{op}'")
    for name in needs:
        c.required(op_table, name, path, f" (op = '{op}' takes {' and '.join(needs)})")
    if op == "saturate":
        c.number(op_table["amount"], (*path, "amount"), -1.0, 10.0)
    elif op == "blend":
        c.rgb(op_table["value"], (*path, "value"), 0.0, 1.0)
        c.number(op_table["amount"], (*path, "amount"), 0.0, 1.0)
    elif op == "lightness":
        c.number(op_table["toward"], (*path, "toward"), 0.0, 1.0)
        c.number(op_table["amount"], (*path, "amount"), 0.0, 1.0)
    elif op == "chroma":
        c.number(op_table["scale"], (*path, "scale"), 0.0, 4.0)
        if "keep" in op_table:
            c.number(op_table["keep"], (*path, "keep"), 0.0, 0.4)
    elif op == "toward":
        c.rgb(op_table["oklab"], (*path, "oklab"), -1.0, 1.0)
        c.number(op_table["amount"], (*path, "amount"), 0.0, 1.0)
    else:
        c.number(op_table["value"], (*path, "value"), 0.0, MAX_FACTOR)


# ---------------------------------------------------------------- procedural maps


def _check_maps(c: Checker, value: object, spec: FieldSpec, path: Path_) -> None:
    """{ normal = { graph = "brushed", output = "normal", params = {...}, weighted = [...] } }."""
    for role, ref in c.table(value, path, "a table of map role -> graph reference").items():
        c.choice(role, MAP_ROLES, (*path, role), "map role")
        check_map_ref(c, ref, (*path, role))


def check_map_ref(c: Checker, raw: object, path: Path_) -> None:
    ref = c.table(raw, path, "a graph reference { graph = ..., output = ... }")
    c.known_keys(ref, ("graph", "output", "params", "weighted"), path)
    graph = c.choice(c.required(ref, "graph", path), sorted(graph_names()), (*path, "graph"), "graph")
    outputs = graph_outputs(graph)
    output = ref.get("output", "color")
    if output not in outputs:
        if "output" not in ref:
            c.fail(path, f"graph '{graph}' has no 'color' output; name one: output = one of {', '.join(outputs)}")
        c.choice(output, outputs, (*path, "output"), f"output of graph '{graph}'")
    ranges = graph_params(graph)
    for name, number in c.table(ref.get("params", {}), (*path, "params")).items():
        c.choice(name, sorted(ranges), (*path, "params", name), f"parameter of graph '{graph}'")
        low, high, _default = ranges[name]
        c.number(number, (*path, "params", name), low, high)
    for i, name in enumerate(c.array(ref.get("weighted", []), (*path, "weighted"), "a list of parameter names")):
        c.choice(name, sorted(ranges), (*path, "weighted", i), f"parameter of graph '{graph}'")


FIELD_CHECKS: dict[str, Callable[[Checker, Any, FieldSpec, Path_], None]] = {
    "str": _check_str,
    "float": _check_float,
    "int": _check_int,
    "bool": _check_bool,
    "rgb": _check_rgb,
    "strlist": _check_strlist,
    "table": _check_table,
    "hex": _check_hex,
    "effects": _check_effects,
    "ops": _check_ops,
    "maps": _check_maps,
    "on": _check_on,
    "step": _check_step,
}
