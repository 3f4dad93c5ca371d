"""The 'ir' target: the IR document itself, as JSON."""

from __future__ import annotations

import json

from .capabilities import ALL_FEATURES, EmitResult
from .registry import Artifact

NAME = "ir"
DESCRIPTION = "the intermediate representation as JSON (docs/ir.md)"
CAPABILITIES = dict.fromkeys(ALL_FEATURES, ("exact", "the IR is the source of truth"))


def emit(ir: dict, options: dict) -> EmitResult:
    return EmitResult([Artifact("materials.ir.json", json.dumps(ir, indent=2, ensure_ascii=False) + "\n")])
