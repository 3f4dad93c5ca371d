"""Rewrite the golden files: run only after a deliberate change, then review the diff.

.venv/bin/python tests/language/regen_golden.py
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tests.language.golden_cases import CASES, GOLDEN, dump, golden_path, stages

if __name__ == "__main__":
    GOLDEN.mkdir(exist_ok=True)
    for name, text in CASES.items():
        for stage, value in stages(text).items():
            golden_path(name, stage).write_text(dump(value))
    print(f"wrote {len(CASES) * 3} golden files to {GOLDEN}")
