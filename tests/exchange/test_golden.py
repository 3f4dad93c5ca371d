"""Backend output for a frozen IR equals the reviewed golden files (regenerate_golden.py)."""

from __future__ import annotations

import pytest

from .golden_cases import CASES, GOLDEN, frozen_ir, render


@pytest.mark.parametrize("target, options, name", CASES, ids=[c[2] for c in CASES])
def test_golden(target, options, name):
    expected = (GOLDEN / name).read_text(encoding="utf-8")
    assert render(target, options, frozen_ir()) == expected, (
        f"{name} changed; if intended, run: .venv/bin/python -m tests.exchange.regenerate_golden"
    )
