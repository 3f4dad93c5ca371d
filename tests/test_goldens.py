"""The golden-file helper behind pytest --update-goldens: compare by default; when updating,
write only the files whose content the test rejects, and remember which."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from tests.helpers import Goldens


def test_comparing_accepts_equal_text_and_rejects_the_rest(tmp_path: Path) -> None:
    golden = tmp_path / "a.txt"
    golden.write_text("same\n")
    goldens = Goldens()
    goldens.check_text(golden, "same\n", "differs")
    with pytest.raises(AssertionError, match="differs"):
        goldens.check_text(golden, "other\n", "differs")
    with pytest.raises(AssertionError, match="missing.*--update-goldens"):
        goldens.check_text(tmp_path / "absent.txt", "x", "differs")
    assert golden.read_text() == "same\n" and not goldens.rewritten


def test_updating_rewrites_only_what_changed(tmp_path: Path) -> None:
    same, changed, new = tmp_path / "same.txt", tmp_path / "changed.txt", tmp_path / "sub" / "new.txt"
    same.write_text("kept\n")
    changed.write_text("old\n")
    before = same.stat().st_mtime_ns
    goldens = Goldens(updating=True)
    for path, text in ((same, "kept\n"), (changed, "new\n"), (new, "made\n")):
        goldens.check_text(path, text, "differs")
    assert goldens.rewritten == [changed, new]
    assert (changed.read_text(), new.read_text()) == ("new\n", "made\n")
    assert same.stat().st_mtime_ns == before


def test_a_tolerant_comparison_keeps_a_golden_it_accepts(tmp_path: Path) -> None:
    golden = tmp_path / "value.txt"
    golden.write_bytes(b"1.0000")

    def near(value: float) -> Callable[[bytes], None]:
        def agrees(existing: bytes) -> None:
            assert abs(float(existing) - value) < 1e-3

        return agrees

    goldens = Goldens(updating=True)
    goldens.check(golden, b"1.00001", near(1.00001))
    assert golden.read_bytes() == b"1.0000" and not goldens.rewritten
    goldens.check(golden, b"2.0", near(2.0))
    assert golden.read_bytes() == b"2.0" and goldens.rewritten == [golden]


def test_refreeze_implies_updating() -> None:
    assert Goldens(refreeze=True).updating
