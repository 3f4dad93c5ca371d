"""Backend output for a frozen IR equals the reviewed golden files
(rewrite with pytest --update-goldens; add --refreeze to recompile the frozen IR first)."""

from __future__ import annotations

import pytest

from tests.helpers import require

from .golden_cases import CASES, GOLDEN, INPUT, fresh_ir_text, frozen_ir, render

#: The optional packages a target's emit imports: (module, extra).
NEEDS = {"materialx": (("MaterialX", "materialx"),), "usd": (("pxr", "usd"), ("MaterialX", "usd"))}


@pytest.fixture(scope="module")
def ir(goldens) -> dict:
    if goldens.refreeze or (goldens.updating and not INPUT.exists()):
        goldens.write(INPUT, fresh_ir_text().encode("utf-8"))
    return frozen_ir()


@pytest.mark.parametrize("target, options, name", CASES, ids=[c[2] for c in CASES])
def test_golden(target, options, name, ir, goldens):
    for module, extra in NEEDS.get(target, ()):
        require(module, extra)
    goldens.check_text(
        GOLDEN / name,
        render(target, options, ir),
        f"{name} changed; if intended, run: .venv/bin/python -m pytest tests/exchange --update-goldens",
    )
