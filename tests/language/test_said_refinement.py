"""Words said as a refinement (the studio's refine box, a later utterance of `cnlmc listen`):
describing words alone would start a material of their own, so below a material they are added as
the change line 'make it ...' (cnlmc.said_refinement); a refinement word is added as it was said."""

from __future__ import annotations

from cnlmc.api import compile_source, lexicon_for
from cnlmc.said_refinement import refined
from cnlmc.speech.listen import Listener
from cnlmc.speech.recogniser import Hypothesis

LEX = lexicon_for()


def test_describing_words_are_a_change_and_a_refinement_word_stays():
    text, result = refined("red plastic", "lavender", LEX, "t.cnl")
    assert text == "red plastic\nmake it lavender" and len(result.materials) == 1
    text, result = refined("red plastic", "darker", LEX, "t.cnl")
    assert text == "red plastic\ndarker" and len(result.materials) == 1


def test_with_no_material_above_the_words_start_the_material():
    _text, result = refined("", "lavender", LEX, "t.cnl")  # 'make it lavender' first: its words alone
    (alone,) = compile_source("lavender", "t.cnl", LEX).materials
    assert [m["params"] for m in result.materials] == [alone["params"]]
    _text, result = refined("", "darker", LEX, "t.cnl")  # nothing to darken
    assert not result.materials


def test_a_later_utterance_of_describing_words_changes_the_spoken_material():
    listener = Listener(LEX, ("undo",), 0.0)
    assert listener.hear(Hypothesis("matte black", 1.0, ())).applied  # the first: its material implied
    heard = listener.hear(Hypothesis("lavender", 1.0, ()))
    assert heard.applied and listener.lines == ["matte black", "make it lavender"]
    assert listener.result is not None and len(listener.result.materials) == 1
