"""What is generated from the parameter table (cnlmc.params): the IR's JSON schema and the docs' table.

    python -m cnlmc.params_doc          # rewrite compiler/ir_schema.json and the table in docs/ir.md

tests/language/test_params_table.py checks that both committed files are current.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from .params import (
    BASES,
    COAT_PARAMS,
    DIFFUSE_LOBES,
    DISTRIBUTIONS,
    PARAMS,
    SPECULAR,
    SUBSURFACE_MODELS,
    SUBSURFACE_PARAMS,
    WHEN,
    ParamSpec,
)

SCHEMA_PATH = Path(__file__).with_name("ir_schema.json")
DOCS_PATH = Path(__file__).resolve().parent.parent / "docs" / "ir.md"
TABLE_START = "<!-- parameter table: generated from cnlmc.params by `python -m cnlmc.params_doc`; do not edit -->"
TABLE_END = "<!-- end of the generated parameter table -->"
MAP_ROLES = ["base_color", "normal", "roughness", "metallic", "mask"]

JSONDict = dict[str, Any]


# -- the JSON schema


def _numbers(n: int, spec: ParamSpec) -> JSONDict:
    item: JSONDict = {"type": "number"}
    if spec.range is not None:
        item.update(minimum=spec.range[0], maximum=spec.range[1])
    return {"type": "array", "items": item, "minItems": n, "maxItems": n}


def _property(spec: ParamSpec) -> JSONDict:
    """One table row as a JSON schema property."""
    if spec.kind == "number":
        out: JSONDict = {"type": "number"}
        if spec.range is not None:
            out.update(minimum=spec.range[0], maximum=spec.range[1])
        return {"oneOf": [{"type": "null"}, out]} if spec.optional else out
    if spec.kind == "rgb":
        return _numbers(3, spec)
    if spec.kind == "alpha":
        return _numbers(2, spec)
    if spec.kind == "enum":
        return {"enum": list(spec.choices)}
    if spec.kind == "coat":
        return {"oneOf": [{"type": "null"}, {"$ref": "#/$defs/coat"}]}
    if spec.kind == "subsurface":
        return {"oneOf": [{"type": "null"}, {"$ref": "#/$defs/subsurface"}]}
    return {"type": "string"}


def _object(specs: tuple[ParamSpec, ...]) -> JSONDict:
    return {
        "type": "object",
        "required": [s.name for s in specs if s.required],
        "additionalProperties": False,
        "properties": {s.name: _property(s) for s in specs},
    }


def _material() -> JSONDict:
    variant = {
        "type": "object",
        "required": ["group", "name", "choices"],
        "properties": {
            "group": {"type": "string"},
            "name": {"type": "string"},
            "choices": {"type": "array", "items": {"type": "string"}},
        },
    }
    return {
        "type": "object",
        "required": ["name", "phrase", "variant", "model", "params", "maps", "provenance"],
        "additionalProperties": False,
        "properties": {
            "name": {"type": "string", "pattern": "^[A-Za-z_][A-Za-z0-9_]*$"},
            "label": {"type": "string"},
            "phrase": {"type": "string"},
            "variant": {"oneOf": [{"type": "null"}, variant]},
            "model": {"$ref": "#/$defs/model"},
            "params": {"$ref": "#/$defs/params"},
            "maps": {
                "type": "object",
                "propertyNames": {"enum": MAP_ROLES},
                "additionalProperties": {"$ref": "#/$defs/map"},
            },
            "provenance": {
                "type": "object",
                "additionalProperties": {"type": "array", "items": {"$ref": "#/$defs/step"}},
            },
        },
    }


def _model() -> JSONDict:
    return {
        "type": "object",
        "required": ["base", "distribution", "anisotropic", "coat", "diffuse"],
        "additionalProperties": False,
        "properties": {
            "base": {"enum": list(BASES)},
            "distribution": {"enum": list(DISTRIBUTIONS)},
            "anisotropic": {"type": "boolean"},
            "coat": {"type": "boolean"},
            "diffuse": {"enum": list(DIFFUSE_LOBES)},
            "subsurface": {"enum": list(SUBSURFACE_MODELS)},
        },
    }


def _map() -> JSONDict:
    return {
        "type": "object",
        "required": ["graph", "output", "params", "seed"],
        "additionalProperties": False,
        "properties": {
            "graph": {"type": "string"},
            "output": {"type": "string"},
            "params": {"type": "object", "additionalProperties": {"type": "number"}},
            "seed": {"type": "integer"},
        },
    }


def _step() -> JSONDict:
    span = {"type": "array", "items": {"type": "integer"}, "minItems": 3, "maxItems": 3}
    return {
        "type": "object",
        "required": ["rule", "words", "spans", "value"],
        "properties": {
            "rule": {"type": "string"},
            "words": {"type": "array", "items": {"type": "string"}},
            "spans": {"type": "array", "items": span},
            "source": {"type": "string"},
            "value": {},
        },
    }


def _diagnostic() -> JSONDict:
    strings = {"type": "array", "items": {"type": "string"}}
    return {
        "type": "object",
        "required": ["severity", "code", "message"],
        "properties": {
            "severity": {"enum": ["error", "warning", "note"]},
            "code": {"type": "string"},
            "message": {"type": "string"},
            "line": {"type": "integer"},
            "col": {"type": "integer"},
            "end_col": {"type": "integer"},
            "hints": strings,
            "suggestions": strings,
        },
    }


def ir_schema() -> JSONDict:
    """The IR's JSON schema (draft 2020-12), its parameters from the table."""
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": "cnlmc-ir-1",
        "title": "cnlmc IR, version 1 (docs/ir.md); generated from cnlmc.params by `python -m cnlmc.params_doc`",
        "type": "object",
        "required": ["ir_version", "source", "lexicon", "colour_space", "materials", "diagnostics"],
        "additionalProperties": False,
        "properties": {
            "ir_version": {"const": 1},
            "source": {"type": "string"},
            "lexicon": {"type": "array", "items": {"type": "string"}},
            "colour_space": {"const": "linear Rec.709"},
            "materials": {"type": "array", "items": {"$ref": "#/$defs/material"}},
            "diagnostics": {"type": "array", "items": {"$ref": "#/$defs/diagnostic"}},
        },
        "$defs": {
            "material": _material(),
            "model": _model(),
            "params": _object(PARAMS),
            "coat": _object(COAT_PARAMS),
            "subsurface": _object(SUBSURFACE_PARAMS),
            "map": _map(),
            "step": _step(),
            "diagnostic": _diagnostic(),
        },
    }


def schema_text() -> str:
    return json.dumps(ir_schema(), indent=2, ensure_ascii=False) + "\n"


# -- the docs table


def _kind(spec: ParamSpec) -> str:
    if spec.kind == "enum":
        return " \\| ".join(f'`"{c}"`' for c in spec.choices)
    return {"number": "number", "rgb": "RGB", "alpha": "[x, y]", "coat": "null \\| coat", "str": "string"}.get(
        spec.kind, f"null \\| {spec.kind}"
    )


def _default(spec: ParamSpec) -> str:
    if spec.name == "alpha" or (spec.kind == "alpha"):
        return "from roughness"
    value = spec.default
    if value is None:
        return "null"
    if isinstance(value, tuple):
        return "(" + ", ".join(f"{v:g}" for v in value) + ")"
    if isinstance(value, str):
        return f'`"{value}"`' if value else '`""`'
    return f"{value:g}"


def _range(spec: ParamSpec) -> str:
    return f"[{spec.range[0]:g}, {spec.range[1]:g}]" if spec.range else ""


def _used_by(spec: ParamSpec) -> str:
    if spec.when == "base":
        return "all" if spec.models == BASES else ", ".join(spec.models)
    if spec.when == "specular" and spec.models == SPECULAR:
        return "all but diffuse"
    return WHEN[spec.when]


def _rows(specs: tuple[ParamSpec, ...], used_by: bool) -> list[str]:
    head = "| key | type | range | default | unit | " + ("in the IR when | " if used_by else "") + "meaning |"
    rule = "| --- | --- | --- | --- | --- | " + ("--- | " if used_by else "") + "--- |"
    rows = [head, rule]
    for s in specs:
        cells = [f"`{s.name}`", _kind(s), _range(s), _default(s), s.unit]
        if used_by:
            cells.append(_used_by(s))
        cells.append(s.doc)
        rows.append("| " + " | ".join(cells) + " |")
    return rows


def params_table() -> str:
    """The markdown between the markers in docs/ir.md: the params and the coat tables."""
    lines = [TABLE_START, "", *_rows(PARAMS, True), "", "`coat` (every key present when the coat is):", ""]
    lines += [*_rows(COAT_PARAMS, False), ""]
    lines += ["`subsurface` (every key present when the medium is; docs/subsurface.md):", ""]
    lines += [*_rows(SUBSURFACE_PARAMS, False), "", TABLE_END]
    return "\n".join(lines)


def with_params_table(doc: str) -> str:
    """docs/ir.md's text with the generated table between its markers."""
    head, found, rest = doc.partition(TABLE_START)
    _, found_end, tail = rest.partition(TABLE_END)
    if not (found and found_end):
        raise ValueError(f"docs/ir.md lacks the markers {TABLE_START!r} ... {TABLE_END!r}")
    return head + params_table() + tail


def main() -> int:
    SCHEMA_PATH.write_text(schema_text())
    DOCS_PATH.write_text(with_params_table(DOCS_PATH.read_text()))
    print(f"wrote {SCHEMA_PATH} and the parameter table in {DOCS_PATH}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
