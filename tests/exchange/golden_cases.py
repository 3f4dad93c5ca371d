"""The golden cases of test_golden.py.

The IR input is frozen in golden/input.ir.json so the golden outputs change only when a
backend changes (not when the lexicon does). Rewrite the outputs, then review the diff:
    .venv/bin/python -m pytest tests/exchange/test_golden.py --update-goldens
and with --refreeze also recompile the frozen IR from SOURCE first.
"""

from __future__ import annotations

import json
from pathlib import Path

GOLDEN = Path(__file__).parent / "golden"
INPUT = GOLDEN / "input.ir.json"
SOURCE = (
    "\n".join(
        [
            "white varnished oak",
            "lightly brushed, blue anodized aluminum",
            "red or green glass",
            "deep red velvet",
            "clear-coated red car paint",
            "polished gold",
            "frosted glass",
        ]
    )
    + "\n"
)
# (target, options, golden file name)
CASES = [
    ("materialx", {"maps": "none"}, "materialx/open_pbr.mtlx"),
    ("materialx", {"maps": "none", "surface": "standard_surface"}, "materialx/standard_surface.mtlx"),
    ("usd", {"maps": "none"}, "usd/materials.usda"),
    ("mitsuba", {"maps": "none"}, "mitsuba/scene.xml"),
    ("mitsuba", {"maps": "none", "form": "fragment"}, "mitsuba/materials.xml"),
]


def fresh_ir_text() -> str:
    """SOURCE compiled now, without maps (the golden files test the backends, not the maps
    library), in the form golden/input.ir.json keeps."""
    from cnlmc.api import compile_source

    ir = compile_source(SOURCE, "golden.cnl").ir
    for material in ir["materials"]:
        material["maps"] = {}
    return json.dumps(ir, indent=1, ensure_ascii=False) + "\n"


def frozen_ir() -> dict:
    return json.loads(INPUT.read_text(encoding="utf-8"))


def render(target: str, options: dict, ir: dict) -> str:
    from cnlmc.api import emit

    (artifact,) = emit(ir, target, options).artifacts
    return artifact.content
