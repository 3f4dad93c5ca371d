"""Emitted files match tests/glsl/golden/ (rewrite with pytest --update-goldens tests/glsl)."""

from __future__ import annotations

import pytest

from .conftest import emit_phrase
from .golden_cases import GOLDEN_CASES, GOLDEN_DIR, golden_files


@pytest.mark.parametrize("stem", sorted(GOLDEN_CASES))
def test_matches_golden(stem, goldens):
    phrase, options = GOLDEN_CASES[stem]
    emitted = emit_phrase(phrase, **options)
    for name, text in golden_files(stem, emitted).items():
        goldens.check_text(
            GOLDEN_DIR / name,
            text,
            f"{name} differs from the emitted text; if the change is intended, "
            "run pytest --update-goldens tests/glsl and review the diff",
        )
