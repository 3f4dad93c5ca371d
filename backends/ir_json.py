"""The 'ir' target: the IR document itself, as JSON.

The layout: the document's fields one per line, and each material (and each diagnostic) on a line
of its own. The C JSON encoder does the work (an indented dump goes through the pure-Python
encoder: a 10k-line file spent most of its time there). Given the IR as a mapping (what the CLI
passes), it is validated (typed once, as every target does) and then written as it is, without
the typed records' copy back to JSON; given a Document, each material is copied and let go in turn.
"""

from __future__ import annotations

import io
from collections.abc import Iterable, Mapping, Sequence
from typing import Any, BinaryIO

from cnlmc.ir import EncodedMaterial, json_text
from cnlmc.ir_check import check_material
from cnlmc.material import Document

from .base import DOCUMENT_FIELDS, Artifact, Options, Target, as_document
from .capabilities import ALL_FEATURES, EmitResult

HEAD_FIELDS = ("ir_version", "source", "lexicon", "colour_space")


class IrTarget(Target):
    name = "ir"
    description = "the intermediate representation as JSON (docs/ir.md)"
    capabilities = dict.fromkeys(ALL_FEATURES, ("exact", "the IR is the source of truth"))

    def emit(self, document: Document, options: Options) -> EmitResult:
        return EmitResult([Artifact("materials.ir.json", ir_json_text(document))])

    def material_writer(self, out: BinaryIO, head: Mapping[str, Any]) -> IrWriter:
        """Streaming (cnlmc.commands.compile_streamed): the document written to `out` as its
        materials come, each one checked before it is written."""
        return IrWriter(out, head, check=True)

    def emit_ir(self, ir: Document | Mapping[str, Any], pairs: Mapping[str, object] | None = None) -> EmitResult:
        options = self.parse_options(pairs)
        if isinstance(ir, Mapping) and set(DOCUMENT_FIELDS) <= set(ir):
            return EmitResult([Artifact("materials.ir.json", ir_json_text(checked(ir)))])
        return self.emit(as_document(ir), options)


def checked(ir: Mapping[str, Any]) -> Mapping[str, Any]:
    """The IR, refused (ValueError) where it is not a valid document: checked as every target types
    it (cnlmc.ir_check: what Material.from_ir accepts, without building the records)."""
    Document.from_ir({**ir, "materials": []})
    materials = ir["materials"]
    if not isinstance(materials, list):
        raise ValueError(f"materials: expected a list, got {type(materials).__name__}")
    for i, material in enumerate(materials):
        check_material(material, f"materials[{i}]")
    return ir


def ir_json_text(document: Document | Mapping[str, Any]) -> str:
    """The document as JSON text (the layout in the module's doc)."""
    if isinstance(document, Document):
        head: Mapping[str, Any] = _head(document)
        materials: Iterable[object] = (m.to_ir() for m in document.materials)
        diagnostics: Sequence[object] = document.diagnostics
    else:
        head, materials, diagnostics = document, document["materials"], document["diagnostics"]
    out = io.BytesIO()
    writer = IrWriter(out, head)
    for material in materials:
        writer.write(material)
    writer.finish(diagnostics)
    return out.getvalue().decode("utf-8")


class IrWriter:
    """The IR document written to a binary file as it is made, in the layout of the module's doc
    (what ir_json_text gives, byte for byte): the head at once, each material as it comes, the
    diagnostics at the end. With `check`, each material is validated as every target types it
    (ValueError naming it) before it is written, and the head and diagnostics at `finish`."""

    def __init__(self, out: BinaryIO, head: Mapping[str, Any], check: bool = False) -> None:
        self.out, self.head, self.check, self.count = out, head, check, 0
        if check:
            Document.from_ir({**head, "materials": [], "diagnostics": []})
        pieces = ["{\n"]
        for key in HEAD_FIELDS:
            pieces += ["  ", json_text(key), ": ", json_text(head[key]), ",\n"]
        pieces += ["  ", json_text("materials"), ": ["]
        self.out.write("".join(pieces).encode("utf-8"))

    def write(self, material: object) -> None:
        """One material: a mapping (checked with `check`), or an EncodedMaterial (checked where it
        was encoded: its text is copied)."""
        if isinstance(material, EncodedMaterial):
            text = material.text
        else:
            if self.check:
                check_material(material, f"materials[{self.count}]")
            text = json_text(material)
        self.out.write(((",\n    " if self.count else "\n    ") + text).encode("utf-8"))
        self.count += 1

    def finish(self, diagnostics: Sequence[object]) -> None:
        if self.check:
            Document.from_ir({**self.head, "materials": [], "diagnostics": list(diagnostics)})
        pieces = ["]" if not self.count else "\n  ]", ",\n", "  ", json_text("diagnostics"), ": ["]
        for i, item in enumerate(diagnostics):
            pieces += [",\n    " if i else "\n    ", json_text(item)]
        pieces.append("\n  ]" if diagnostics else "]")
        pieces.append("\n}\n")
        self.out.write("".join(pieces).encode("utf-8"))


def _head(document: Document) -> dict[str, object]:
    return {
        "ir_version": document.ir_version,
        "source": document.source,
        "lexicon": list(document.lexicon),
        "colour_space": document.colour_space,
    }


TARGET = IrTarget()
