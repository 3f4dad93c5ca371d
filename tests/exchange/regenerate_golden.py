"""Regenerate tests/exchange/golden/ (run on purpose, then review the diff):

.venv/bin/python -m tests.exchange.regenerate_golden           # outputs from the frozen IR
.venv/bin/python -m tests.exchange.regenerate_golden --refreeze  # also recompile the IR
"""

from __future__ import annotations

import json
import sys

from .golden_cases import CASES, GOLDEN, INPUT, SOURCE, frozen_ir, render


def main(argv) -> int:
    if "--refreeze" in argv or not INPUT.exists():
        from cnlmc.api import compile_source

        ir = compile_source(SOURCE, "golden.cnl").ir
        for material in ir["materials"]:
            material["maps"] = {}  # the golden files test the backends, not the maps library
        INPUT.parent.mkdir(parents=True, exist_ok=True)
        INPUT.write_text(json.dumps(ir, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    ir = frozen_ir()
    for target, options, name in CASES:
        path = GOLDEN / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(render(target, options, ir), encoding="utf-8")
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
