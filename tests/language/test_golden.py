"""Golden files per stage: phrase -> tokens -> AST -> IR (regenerate with regen_golden.py)."""

import pytest

from .golden_cases import CASES, dump, golden_path, stages


@pytest.mark.parametrize("name", sorted(CASES))
def test_stages_match_golden(name):
    produced = stages(CASES[name])
    for stage in ("tokens", "ast", "ir"):
        expected = golden_path(name, stage).read_text()
        assert dump(produced[stage]) == expected, f"{name}.{stage} differs from its golden file"
