"""The studio's history: a step per look, not per keystroke or wording; undo, redo, and a new step
after an undo drops what was undone."""

from __future__ import annotations

from cnlmc.api import compile_source
from cnlmc.studio.history import History, Step


def step(text: str) -> Step:
    return Step(text, compile_source(text).materials, text.splitlines()[-1])


def test_a_wording_of_the_same_material_is_not_a_new_step() -> None:
    history = History(limit=10)
    assert history.push(step("lightly brushed, blue anodized alum"))
    assert not history.push(step("lightly brushed, blue anodized aluminum"))
    current = history.current
    assert current is not None and current.text.endswith("aluminum")
    assert current.materials[0]["name"] == "lightly_brushed_blue_anodized_aluminum"
    assert history.push(step("lightly brushed, blue anodized aluminum\ndarker"))
    assert len(history.steps) == 2


def test_undo_redo_and_a_new_step_after_an_undo() -> None:
    history = History(limit=10)
    for text in ("red plastic", "red plastic\ndarker", "red plastic\ndarker\nrougher"):
        assert history.push(step(text))
    undone = history.undo()
    assert undone is not None and undone.text == "red plastic\ndarker"
    redone = history.redo()
    assert redone is not None and redone.text.endswith("rougher")
    assert history.redo() is None
    history.undo()
    history.undo()
    assert history.undo() is None
    assert history.push(step("red plastic\nglossier"))
    assert [s.label for s in history.steps] == ["red plastic", "glossier"]
    assert history.summary()["can_undo"] and not history.summary()["can_redo"]


def test_the_history_is_bounded() -> None:
    history = History(limit=3)
    for shade in ("red", "green", "blue", "yellow", "white"):
        history.push(step(f"{shade} plastic"))
    assert [s.label for s in history.steps] == ["blue plastic", "yellow plastic", "white plastic"]
    assert history.at == 2


def test_steps_keep_their_ids_when_old_ones_go() -> None:
    """The page keeps each step's thumbnail by its id: an id is never reused, and the summary the
    page gets on each edit carries ids and labels, not pictures."""
    history = History(limit=2)
    for shade in ("red", "blue", "green"):
        history.push(step(f"{shade} plastic"))
    summary = history.summary()
    assert summary["steps"] == [{"id": 2, "label": "blue plastic"}, {"id": 3, "label": "green plastic"}]
    history.undo()
    history.push(step("white plastic"))
    assert [s["id"] for s in history.summary()["steps"]] == [2, 4]
