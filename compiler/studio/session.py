"""One browser tab's studio session: its document, analysis, history and output folder.

Every file the session makes goes into its own folder (cnlmc.output writes them) and the server
serves nothing else of the file system; the folder is removed when the session ends."""

from __future__ import annotations

import contextlib
import secrets
import shutil
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..api import compile_source
from ..changes import material_changes
from ..colour import linear_to_hex
from ..diagnostics import Severity
from ..explain import explain_material
from ..lexicon import Lexicon
from ..said_refinement import refined
from ..speech.listen import NOTHING_HEARD, below_threshold, heard_text
from .ar import ARFailed, MarkerComposer
from .editor import EditorEngine
from .exports import Exported, export
from .history import History, Step
from .payloads import PayloadCache, SentParts, ViewData
from .settings import Settings

if TYPE_CHECKING:
    from .speech import StudioEars

JSONDict = dict[str, Any]


#: a history step's label is its document's last line, cut to this many characters
LABEL_CHARS = 24


def last_line(text: str) -> str:
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    label = lines[-1] if lines else ""
    return label if len(label) <= LABEL_CHARS else label[: LABEL_CHARS - 1] + "…"


def _ms(seconds: float) -> float:
    return round(seconds * 1000, 2)


class TooLarge(ValueError):
    """A document over the size limit: the message says the limit."""


class Replaced(Exception):
    """An edit a newer one replaced before its analysis was made: nothing to answer."""


class Closed(Exception):
    """The tab closed: its folder is gone and nothing more is written."""


class StudioSession:
    def __init__(self, root: Path, lexicon: Lexicon, settings: Settings, view: ViewData) -> None:
        self.id = secrets.token_urlsafe(12)
        self.folder = root / self.id
        self.folder.mkdir(mode=0o700)
        self.lexicon = lexicon
        self.settings = settings
        self.view = view
        self.payloads = PayloadCache(view, settings.limits.max_cached_payloads)
        self.sent = SentParts(settings.limits.max_sent_parts)
        self.engine = EditorEngine(lexicon)
        self.history = History(settings.limits.max_history)
        self.text = ""
        self.latest_edit = 0  # the number of the newest edit received (the event loop counts them)
        self.closed = False
        self.writing = threading.Lock()  # held while work writes into the folder; close waits for it

    def announce_edit(self) -> int:
        """Number an edit as it arrives: an older one still waiting is then skipped."""
        self.latest_edit += 1
        return self.latest_edit

    def stop(self) -> None:
        """Refuse any further work (called on the event loop when the tab closes)."""
        self.closed = True

    def close(self) -> None:
        """Stop, wait for the work writing now, remove the folder (blocks: call it off the loop)."""
        self.stop()
        with self.writing:
            shutil.rmtree(self.folder, ignore_errors=True)

    @contextlib.contextmanager
    def guarded(self) -> Iterator[None]:
        """Work that writes into the folder: one at a time, never after the tab closed."""
        with self.writing:
            if self.closed:
                raise Closed("the studio tab was closed")
            yield

    def composite(self, composer: MarkerComposer, photo: bytes, content_type: str) -> str:
        """The marker AR composite of the document on `photo` (see ar.py), in the session's folder."""
        try:
            with self.guarded():
                return composer.composite(photo, content_type, self.text, self.folder)
        except Closed as exc:
            raise ARFailed(str(exc)) from None

    def check_replaced(self, ticket: int | None) -> None:
        if ticket is not None and ticket != self.latest_edit:
            raise Replaced()

    # ------------------------------------------------------------------ the document

    def check_size(self, text: str) -> None:
        limit = self.settings.limits.max_document_bytes
        if len(text.encode("utf-8", "surrogatepass")) > limit:
            raise TooLarge(f"the document is over the studio's limit of {limit // 1024} KiB: split it into files")

    def edit(self, text: str, label: str | None = None, ticket: int | None = None) -> JSONDict:
        """Analyse `text` (the editor's whole document); a result that compiles to different
        materials becomes a history step. Returns what the page shows. An edit numbered `ticket`
        (announce_edit) that a newer one replaced raises Replaced before each costly part."""
        self.check_size(text)
        self.check_replaced(ticket)
        start = time.perf_counter()
        self.text = text
        features = self.engine.features(text)
        materials = self.materials()
        self.check_replaced(ticket)
        ok = bool(materials) and not any(d["severity"] == 1 for d in features["diagnostics"])
        recorded = ok and self.history.push(Step(text, materials, label or last_line(text)))
        analysed = time.perf_counter()
        picture = self.picture(materials, ok)
        timing = {"analysis_ms": _ms(analysed - start), "view_ms": _ms(time.perf_counter() - analysed)}
        return {**features, **picture, "ok": ok, "recorded": recorded, "timing": timing}

    def materials(self) -> list[JSONDict]:
        snapshot = self.engine.analyse(self.text)
        return [m for block in snapshot.blocks for m in block.result.materials]

    def picture(self, materials: list[JSONDict], ok: bool) -> JSONDict:
        """The materials panel (name, swatch, explain table, what changed) and the view's payloads
        of the first materials (at most the settings' number: `not_shown` counts the rest)."""
        previous = self.history.previous()
        before = {m["name"]: m for m in previous.materials} if previous else {}
        panel = [
            {
                "name": m["name"],
                "hex": linear_to_hex(m["params"]["base_color"]) if "base_color" in m["params"] else None,
                "explain": explain_material(m),
                "changes": material_changes(before[m["name"]], m) if m["name"] in before else [],
            }
            for m in materials
        ]
        shown = materials[: self.settings.limits.max_shown_materials] if ok else []
        with self.guarded():
            payloads = self.payloads.payloads(shown, self.folder / "view")
        return {
            "materials": panel,
            "payloads": [self.sent.delta(p) for p in payloads],
            "not_shown": len(materials) - len(shown) if ok else 0,
            "history": self.history.summary(),
        }

    # ------------------------------------------------------------------ refinement and history

    def refine(self, words: str) -> JSONDict:
        """Add a refinement line under the last material ('darker', 'less grain'); a line the
        compiler refuses leaves the document as it was and says why."""
        words = " ".join(words.split())
        if not words:
            raise ValueError("type a refinement such as 'darker' or 'less grain'")
        self.check_size(self.text.rstrip("\n") + "\n" + words)
        text, trial = refined(self.text, words, self.lexicon, "<studio>")  # 'purple': 'make it purple'
        self.check_size(text)
        errors = [d.message for d in trial.diagnostics if d.severity == Severity.ERROR]
        if errors or not trial.materials:
            raise ValueError(f"'{words}' cannot refine this material: " + ("; ".join(errors) or "no material"))
        return {**self.edit(text, words), "text": text}

    def move(self, step: Step | None, what: str) -> JSONDict:
        if step is None:
            raise ValueError(f"nothing to {what}")
        self.text = step.text
        features = self.engine.features(step.text)
        return {**features, **self.picture(step.materials, True), "ok": True, "recorded": False, "text": step.text}

    def undo(self) -> JSONDict:
        return self.move(self.history.undo(), "undo")

    def speak(self, ears: StudioEars, pcm: bytes) -> JSONDict:
        """One spoken utterance, applied as `cnlmc listen` applies it: while the document names no
        material the utterance becomes the document, later ones refine it, 'undo' steps back.
        Below the confidence threshold, or a refinement the compiler refuses, changes nothing:
        {op: heard, message}."""
        has_material = bool(self.materials())  # a typed document with an error elsewhere too
        hypothesis = ears.hear(pcm, has_material)
        if hypothesis is None:
            return {"op": "heard", "applied": False, "message": NOTHING_HEARD}
        listening = ears.settings
        refused = below_threshold(hypothesis, listening.min_confidence)
        if refused is not None:
            return {"op": "heard", "applied": False, "message": refused, "heard": hypothesis.text}
        said = heard_text(hypothesis)
        try:
            if hypothesis.text in listening.undo:
                answer = self.undo()
            elif has_material:
                answer = self.refine(hypothesis.text)
            else:
                self.check_size(hypothesis.text)
                answer = {**self.edit(hypothesis.text, hypothesis.text), "text": hypothesis.text}
        except ValueError as exc:
            return {"op": "heard", "applied": False, "message": f"{said}: not applied: {exc}", "heard": hypothesis.text}
        return {**answer, "heard": hypothesis.text, "message": said}

    def redo(self) -> JSONDict:
        return self.move(self.history.redo(), "redo")

    def chips(self) -> list[str]:
        """Refinement words that change the current material and compile without a new warning."""
        current = self.history.current
        if current is None or current.text != self.text:
            return []
        base = compile_source(self.text, "<studio>", self.lexicon)
        warnings = len([d for d in base.diagnostics if d.severity != Severity.ERROR])
        chips = []
        for word in self.lexicon.all_of("refinements"):
            if word in self.settings.chip_needs_property:
                continue
            trial = compile_source(self.text.rstrip("\n") + "\n" + word, "<studio>", self.lexicon)
            if trial.ok and len(trial.diagnostics) <= warnings and trial.materials != base.materials:
                chips.append(word)
            if len(chips) == self.settings.max_chips:
                break
        return chips

    # ------------------------------------------------------------------ exports

    def export(self, key: str, text: str | None = None) -> Exported:
        """`key`'s export of `text` (the page's document as it is now; default: the last analysed)."""
        kind = self.settings.export(key)
        if kind is None:
            raise ValueError(f"no export called '{key}'")
        text = self.text if text is None else text
        self.check_size(text)
        result = compile_source(text, "<studio>", self.lexicon, keep_stages=False)
        if not result.ok or not result.materials:
            raise ValueError("the document has errors: fix them before exporting")
        with self.guarded():
            return export(result.ir, kind, self.folder)
