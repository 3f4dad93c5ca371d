"""The 'ir' target: the IR document itself, as JSON.

The layout: the document's fields one per line, and each material (and each diagnostic) on a line
of its own. The C JSON encoder does the work (an indented dump goes through the pure-Python
encoder: a 10k-line file spent most of its time there). Given the IR as a mapping (what the CLI
passes), it is validated (typed once, as every target does) and then written as it is, without
the typed records' copy back to JSON; given a Document, each material is copied and let go in turn.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from typing import Any

from cnlmc.material import Document, Material

from .base import DOCUMENT_FIELDS, Artifact, Options, Target, as_document
from .capabilities import ALL_FEATURES, EmitResult


class IrTarget(Target):
    name = "ir"
    description = "the intermediate representation as JSON (docs/ir.md)"
    capabilities = dict.fromkeys(ALL_FEATURES, ("exact", "the IR is the source of truth"))

    def emit(self, document: Document, options: Options) -> EmitResult:
        return EmitResult([Artifact("materials.ir.json", ir_json_text(document))])

    def emit_ir(self, ir: Document | Mapping[str, Any], pairs: Mapping[str, object] | None = None) -> EmitResult:
        options = self.parse_options(pairs)
        if isinstance(ir, Mapping) and set(DOCUMENT_FIELDS) <= set(ir):
            return EmitResult([Artifact("materials.ir.json", ir_json_text(checked(ir)))])
        return self.emit(as_document(ir), options)


def checked(ir: Mapping[str, Any]) -> Mapping[str, Any]:
    """The IR, refused (ValueError) where it is not a valid document: typed as every target types
    it, one material at a time, so that only one material's records exist at once."""
    Document.from_ir({**ir, "materials": []})
    materials = ir["materials"]
    if not isinstance(materials, list):
        raise ValueError(f"materials: expected a list, got {type(materials).__name__}")
    for i, material in enumerate(materials):
        Material.from_ir(material, f"materials[{i}]")
    return ir


def ir_json_text(document: Document | Mapping[str, Any]) -> str:
    """The document as JSON text (the layout in the module's doc)."""
    if isinstance(document, Document):
        ir: Mapping[str, Any] = {**_head(document), "diagnostics": document.diagnostics}
        materials: Iterable[object] = (m.to_ir() for m in document.materials)
    else:
        ir, materials = document, document["materials"]
    pieces = ["{\n"]
    for key in ("ir_version", "source", "lexicon", "colour_space"):
        pieces += ["  ", _dumps(key), ": ", _dumps(ir[key]), ",\n"]
    _add_items(pieces, "materials", materials)
    pieces.append(",\n")
    _add_items(pieces, "diagnostics", ir["diagnostics"])
    pieces.append("\n}\n")
    return "".join(pieces)  # one join of the pieces: the text is copied once


def _add_items(pieces: list[str], key: str, items: Iterable[object]) -> None:
    """`  "key": [` then one item a line, or `[]`."""
    pieces += ["  ", _dumps(key), ": ["]
    empty = True
    for item in items:
        pieces += ["\n    " if empty else ",\n    ", _dumps(item)]
        empty = False
    pieces.append("]" if empty else "\n  ]")


def _head(document: Document) -> dict[str, object]:
    return {
        "ir_version": document.ir_version,
        "source": document.source,
        "lexicon": list(document.lexicon),
        "colour_space": document.colour_space,
    }


def _dumps(value: object) -> str:
    return json.dumps(value, ensure_ascii=False, default=_plain)


def _plain(value: object) -> Any:
    """Read-only records (a diagnostic is a mapping proxy) as plain JSON objects."""
    if isinstance(value, Mapping):
        return dict(value)
    raise TypeError(f"{type(value).__name__} is not JSON")


TARGET = IrTarget()
