"""The 'ir' target: the IR document itself, as JSON."""

from __future__ import annotations

import json

from .registry import Artifact

NAME = "ir"
DESCRIPTION = "the intermediate representation as JSON (docs/ir.md)"
CAPABILITIES = {"diffuse": "exact", "dielectric": "exact", "conductor": "exact", "glass": "exact",
                "anisotropic": "exact", "coat": "exact", "maps": "exact"}


def emit(ir: dict, options: dict) -> list[Artifact]:
    return [Artifact("materials.ir.json", json.dumps(ir, indent=2, ensure_ascii=False) + "\n")]
