"""Sizes, thicknesses and grades are read past with a note (cnlmc.measures): a specification's
'2cm', '3 mm', '60x60' or '18k' says nothing of the look. A bare number keeps its error. The
phrases here are not in tests/language/everyday.toml."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import run_cnlmc

LEX = lexicon_for()
CASES = [
    ("polished granite, 3cm", "polished granite", "3cm"),
    ("14k rose gold", "rose gold", "14k"),
    ("glazed ceramic tile, 30x60", "glazed ceramic tile", "30x60"),
    ("6 mm frosted glass", "frosted glass", "6 mm"),
    ("white oak, 18 mm thick", "white oak", "18 mm thick"),
]


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    assert not {row["text"].lower() for row in data["phrase"]} & {text.lower() for text, _, _ in CASES}


@pytest.mark.parametrize(("text", "same_as", "said"), CASES)
def test_a_measure_is_read_past_with_a_note(text, same_as, said):
    result = compile_source(text, "t.cnl", LEX)
    assert result.ok
    assert [d.message for d in result.diagnostics if "size" in d.message] == [
        f"read past '{said}': a size, thickness or grade says nothing of how the surface looks"
    ]
    assert result.materials[0]["params"] == compile_source(same_as, "t.cnl", LEX).materials[0]["params"]


@pytest.mark.parametrize("text", ["30% rusty iron", "3 2 1", "12"])
def test_a_bare_number_keeps_its_error(text):
    result = compile_source(text, "t.cnl", LEX)
    assert not result.ok
    assert "numbers are not part of the language" in result.diagnostics[0].message


def test_through_the_cli():
    done = run_cnlmc("compile", "-", "--target", "ir", "-o", "-", stdin="14k rose gold\n")
    assert done.returncode == 0 and "note[N101]: read past '14k'" in done.stderr
