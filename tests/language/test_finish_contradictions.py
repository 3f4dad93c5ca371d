"""Two finishes that set one parameter far apart contradict (issue #14): 'satin high-gloss paint'
warns and says which word won, in either order; finishes that agree do not warn."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source, lexicon_for

LEX = lexicon_for()


def warnings(text: str) -> list[str]:
    return [d.message for d in compile_source(text + "\n", "t.cnl", LEX).diagnostics if d.code == "W101"]


@pytest.mark.parametrize(("a", "b"), [("satin", "glossy"), ("satin", "matte"), ("flamed", "glossy")])
def test_two_finishes_set_apart_warn_in_either_order(a, b):
    for first, then in ((a, b), (b, a)):
        said = warnings(f"{first} {then} granite")
        assert len(said) == 1 and "contradicts" in said[0], (first, then, said)


@pytest.mark.parametrize("text", ["satin rubbed bronze", "matte flamed granite", "satin nickel", "glossy red plastic"])
def test_finishes_that_agree_do_not_warn(text):
    assert warnings(text) == []
