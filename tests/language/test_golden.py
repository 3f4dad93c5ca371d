"""Golden files per stage: phrase -> tokens -> AST -> IR (rewrite with pytest --update-goldens)."""

import pytest

from .golden_cases import CASES, dump, golden_path, stages


@pytest.mark.parametrize("name", sorted(CASES))
def test_stages_match_golden(name, goldens):
    produced = stages(CASES[name])
    for stage in ("tokens", "ast", "ir"):
        goldens.check_text(
            golden_path(name, stage), dump(produced[stage]), f"{name}.{stage} differs from its golden file"
        )
