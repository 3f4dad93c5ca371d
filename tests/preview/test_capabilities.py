"""`cnlmc preview` checks a material against the preview's own capability table, never the GLSL
export's: every note it prints is the preview's, and says what the preview (its tiers) does."""

from __future__ import annotations

import pytest

from cnlmc.backends import glsl
from cnlmc.backends.capabilities import ALL_FEATURES
from cnlmc.backends.preview.capability_table import CAPABILITIES
from tests.helpers import run_cnlmc

pytest.importorskip("moderngl")


def preview_notes(tmp_path, phrase: str) -> list[str]:
    source = tmp_path / "m.cnl"
    source.write_text(phrase + "\n")
    proc = run_cnlmc("preview", str(source), "-o", str(tmp_path / "p.png"), "--size", "32", "--tier", "analytic")
    assert proc.returncode == 0, proc.stderr
    return [line for line in proc.stderr.splitlines() if line.startswith("note:")]


def test_the_table_covers_every_feature():
    assert set(CAPABILITIES) == set(ALL_FEATURES)


def test_a_mask_map_gets_the_previews_note_not_the_glsl_exports(tmp_path):
    """The GLSL export approximates a mask (a Lambert blend in its file); the preview bakes it."""
    assert glsl.TARGET.capabilities["maps.mask"][0] == "approximate"
    notes = preview_notes(tmp_path, "heavily rusted iron")
    assert notes and all(n.startswith("note: preview: ") for n in notes), notes
    assert not any("glsl" in n for n in notes)
    assert any("maps.mask: procedural map baked" in n for n in notes)


@pytest.mark.parametrize(("phrase", "feature"), [("navy blue velvet", "sheen"), ("metallic car paint", "flakes")])
def test_a_layer_says_what_the_preview_tiers_do(tmp_path, phrase, feature):
    notes = preview_notes(tmp_path, phrase)
    (note,) = [n for n in notes if f": {feature}: " in n]
    assert note.startswith("note: preview: ") and "every tier" in note
