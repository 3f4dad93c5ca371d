"""Emitted files match tests/glsl/golden/ (regenerate with python -m tests.glsl.regen_golden)."""

from __future__ import annotations

import pytest

from .conftest import emit_phrase
from .golden_cases import GOLDEN_CASES, GOLDEN_DIR


@pytest.mark.parametrize("stem", sorted(GOLDEN_CASES))
def test_matches_golden(stem):
    phrase, options = GOLDEN_CASES[stem]
    emitted = emit_phrase(phrase, **options)
    goldens = sorted(GOLDEN_DIR.glob(f"{stem}.*"))
    assert goldens, f"no golden files for {stem}: run python -m tests.glsl.regen_golden"
    for path in goldens:
        suffix = path.name[len(stem) + 1 :]
        assert emitted[suffix] == path.read_text(), (
            f"{path.name} differs from the emitted text; if the change is intended, "
            "run python -m tests.glsl.regen_golden and review the diff"
        )
