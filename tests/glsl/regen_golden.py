"""Regenerate tests/glsl/golden/ (run explicitly: python -m tests.glsl.regen_golden).

Review the diff before committing: a golden change is a change of the emitted code."""

from __future__ import annotations

from .conftest import emit_phrase
from .golden_cases import GOLDEN_CASES, GOLDEN_DIR


def main() -> None:
    GOLDEN_DIR.mkdir(exist_ok=True)
    for stem, (phrase, options) in GOLDEN_CASES.items():
        for suffix, text in emit_phrase(phrase, **options).items():
            if suffix == "vert" and stem != "dielectric":
                continue  # the vertex shader is the same for every material but its name
            (GOLDEN_DIR / f"{stem}.{suffix}").write_text(text)
            print(f"wrote {GOLDEN_DIR / f'{stem}.{suffix}'}")


if __name__ == "__main__":
    main()
