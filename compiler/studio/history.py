"""Undo and redo over the document texts a session has shown: each step that compiled to
materials that look different is one entry; undo and redo move along them, a new step after an undo
drops the steps that were undone (as every editor's undo does)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

#: what a material's IR says beyond its look: its name, its words and where each value came from
WORDING = ("name", "phrase", "provenance")


def appearance(materials: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The materials without their wording: what the view draws and the exports hold."""
    return [{k: v for k, v in m.items() if k not in WORDING} for m in materials]


@dataclass
class Step:
    """One history entry: the text, its materials' IR, a label ('darker', 'edit') and its number in
    the session (`id`, given by History.push: the page keeps the thumbnail it drew under it)."""

    text: str
    materials: list[dict[str, Any]]
    label: str
    id: int = 0


@dataclass
class History:
    limit: int
    steps: list[Step] = field(default_factory=list)
    at: int = -1
    recorded: int = 0  # steps pushed so far: the next one's id

    @property
    def current(self) -> Step | None:
        return self.steps[self.at] if self.steps else None

    def push(self, step: Step) -> bool:
        """Record a step unless it looks as the current one does (the same materials, however they
        are worded: 'alum' and 'aluminum' are one step); True when recorded."""
        current = self.current
        if current is not None and appearance(current.materials) == appearance(step.materials):
            current.text, current.materials = step.text, step.materials  # the same look, worded anew
            return False
        del self.steps[self.at + 1 :]
        self.recorded += 1
        step.id = self.recorded
        self.steps.append(step)
        if len(self.steps) > self.limit:
            del self.steps[: len(self.steps) - self.limit]
        self.at = len(self.steps) - 1
        return True

    def undo(self) -> Step | None:
        if self.at <= 0:
            return None
        self.at -= 1
        return self.steps[self.at]

    def redo(self) -> Step | None:
        if self.at >= len(self.steps) - 1:
            return None
        self.at += 1
        return self.steps[self.at]

    def previous(self) -> Step | None:
        """The step before the current one (what the explain panel compares with)."""
        return self.steps[self.at - 1] if self.at >= 1 else None

    def summary(self) -> dict[str, Any]:
        """What the page's history strip shows: each step's id and label (its thumbnail is the
        page's own picture of the frame it drew, kept there by id: never sent back on each edit)."""
        return {
            "at": self.at,
            "steps": [{"id": s.id, "label": s.label} for s in self.steps],
            "can_undo": self.at > 0,
            "can_redo": self.at < len(self.steps) - 1,
        }
