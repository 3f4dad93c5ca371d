"""Undo and redo over the document texts a session has shown: each step that compiled to a
different material set is one entry; undo and redo move along them, a new step after an undo
drops the steps that were undone (as every editor's undo does)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class Step:
    """One history entry: the text, its materials' IR, a label ('darker', 'edit') and a thumbnail
    the page made of the frame it drew (a data: URL, or '' until it sends one)."""

    text: str
    materials: list[dict[str, Any]]
    label: str
    thumbnail: str = ""


@dataclass
class History:
    limit: int
    steps: list[Step] = field(default_factory=list)
    at: int = -1

    @property
    def current(self) -> Step | None:
        return self.steps[self.at] if self.steps else None

    def push(self, step: Step) -> bool:
        """Record a step unless its materials equal the current one's; True when recorded."""
        current = self.current
        if current is not None and current.materials == step.materials:
            current.text = step.text  # the same material, typed differently: the newest text
            return False
        del self.steps[self.at + 1 :]
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

    def set_thumbnail(self, index: int, data_url: str) -> None:
        if 0 <= index < len(self.steps):
            self.steps[index].thumbnail = data_url

    def summary(self) -> dict[str, Any]:
        return {
            "at": self.at,
            "steps": [{"label": s.label, "thumbnail": s.thumbnail} for s in self.steps],
            "can_undo": self.at > 0,
            "can_redo": self.at < len(self.steps) - 1,
        }
