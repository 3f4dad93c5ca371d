"""A spoken session: each utterance is a line of a material file, compiled as typed text is.

The first applied utterance starts the material, later ones refine it ("darker", "more glossy");
"undo" drops the last line. An utterance is applied only when its confidence reaches the
threshold and the document still compiles without errors with it; otherwise the user sees what was
heard, the alternatives and the compiler's diagnostics, and the material stays as it was.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..api import Result, compile_source
from ..diagnostics import render_all
from ..lexicon import Lexicon
from ..said_refinement import refined
from .recogniser import Hypothesis

SOURCE_NAME = "<speech>"
NOTHING_HEARD = "heard no phrase of the language (say it again, or closer to the microphone)"


def heard_text(hypothesis: Hypothesis) -> str:
    return f"heard '{hypothesis.text}' (confidence {hypothesis.confidence:.2f})"


def below_threshold(hypothesis: Hypothesis, min_confidence: float) -> str | None:
    """What the user is told when the utterance is below the threshold (None: it is not)."""
    if hypothesis.confidence >= min_confidence:
        return None
    options = "; ".join(f"'{a}'" for a in hypothesis.alternatives) or "none"
    return f"{heard_text(hypothesis)}: not applied, below {min_confidence:.2f}; alternatives: {options}; say it again"


@dataclass(frozen=True)
class Heard:
    """What one utterance did: `applied` (a line added or 'undo' done), and what to tell the user."""

    hypothesis: Hypothesis | None
    applied: bool
    messages: tuple[str, ...]


@dataclass
class Listener:
    lexicon: Lexicon
    undo_words: tuple[str, ...]
    min_confidence: float
    seed: int = 0
    lines: list[str] = field(default_factory=list)
    result: Result | None = None

    def source(self, extra: tuple[str, ...] = ()) -> str:
        return "\n".join([*self.lines, *extra])

    def hear(self, hypothesis: Hypothesis | None) -> Heard:
        if hypothesis is None:
            return Heard(None, False, (NOTHING_HEARD,))
        said = heard_text(hypothesis)
        refused = below_threshold(hypothesis, self.min_confidence)
        if refused is not None:
            return Heard(hypothesis, False, (refused,))
        if hypothesis.text in self.undo_words:
            return self._undo(hypothesis, said)
        return self._apply(hypothesis, said)

    def _undo(self, hypothesis: Hypothesis, said: str) -> Heard:
        if not self.lines:
            return Heard(hypothesis, False, (f"{said}: nothing to undo",))
        dropped = self.lines.pop()
        self.result = compile_source(self.source(), SOURCE_NAME, self.lexicon, self.seed) if self.lines else None
        return Heard(hypothesis, True, (f"{said}: dropped '{dropped}'",))

    def _apply(self, hypothesis: Hypothesis, said: str) -> Heard:
        """The first utterance starts the material; a later one refines it ('purple' after a
        material is the change 'make it purple': cnlmc.said_refinement)."""
        if self.lines:
            source, result = refined(self.source(), hypothesis.text, self.lexicon, SOURCE_NAME, self.seed)
        else:
            source = hypothesis.text
            result = compile_source(source, SOURCE_NAME, self.lexicon, self.seed)
        shown = tuple(render_all(result.diagnostics, source, SOURCE_NAME))
        if not result.ok or not result.materials:
            reason = "" if result.materials else " (it names no material yet: start with one, e.g. 'brushed aluminum')"
            return Heard(hypothesis, False, (f"{said}: not applied{reason}", *shown))
        self.lines.append(source.rsplit("\n", 1)[-1])
        self.result = result
        return Heard(hypothesis, True, (f"{said}: line {len(self.lines)}", *shown))
