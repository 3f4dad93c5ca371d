"""The example files the README points at compile without a warning."""

from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.cnl"))
LEXICON = {"deutsch.cnl": ("de",)}


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_example_compiles_cleanly(path):
    result = compile_source(path.read_text(), path.name, lexicon_for(LEXICON.get(path.name, ())))
    assert result.ok and not result.diagnostics, [d.message for d in result.diagnostics]
    assert result.materials
