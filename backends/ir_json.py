"""The 'ir' target: the IR document itself, as JSON."""

from __future__ import annotations

import json

from cnlmc.material import Document

from .base import Artifact, Options, Target
from .capabilities import ALL_FEATURES, EmitResult


class IrTarget(Target):
    name = "ir"
    description = "the intermediate representation as JSON (docs/ir.md)"
    capabilities = dict.fromkeys(ALL_FEATURES, ("exact", "the IR is the source of truth"))

    def emit(self, document: Document, options: Options) -> EmitResult:
        text = json.dumps(document.to_ir(), indent=2, ensure_ascii=False) + "\n"
        return EmitResult([Artifact("materials.ir.json", text)])


TARGET = IrTarget()
