"""Regenerate tests/maps/golden/*.npy.  Run explicitly after an intended visual change:
.venv/bin/python tests/maps/regen_golden.py
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from conftest import golden_thumbnails

GOLDEN = Path(__file__).parent / "golden"


def main():
    GOLDEN.mkdir(exist_ok=True)
    for old in GOLDEN.glob("*.npy"):
        old.unlink()
    for name, outputs in golden_thumbnails().items():
        for role, array in outputs.items():
            np.save(GOLDEN / f"{name}__{role}.npy", array.astype(np.float32))
            print(f"wrote {name}__{role}.npy")


if __name__ == "__main__":
    main()
