"""Live refinement: `cnlmc preview FILE -o preview.png --interactive`.

A prompt reads refinement lines ("darker", "less grain", "more diffuse"); each one is added
below the material (docs/refinement.md), recompiled, re-rendered and written to the output
PNG (atomically, so an image viewer that reloads shows every step), and the parameters it
changed are printed. A line that does not compile is reported with its caret and "did you
mean" and leaves the material as it was. Lines starting with ':' are commands (`:help`).

With a display (DISPLAY or WAYLAND_DISPLAY set and Tk able to connect) the image also appears in
a window that follows every step, keeps handling its events while the prompt waits, and ends
the session when closed; headless, the PNG on disk is the view and nothing else changes.
Tested under Xvfb: tests/preview/test_live_window.py.
"""

from __future__ import annotations

import difflib
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TextIO

from cnlmc.api import Session
from cnlmc.changes import fmt, material_changes
from cnlmc.diagnostics import did_you_mean, render
from cnlmc.material import Material

from .frames import preview_command
from .meshes import mesh_choices
from .options import parse_options
from .resources import Resources
from .window import Window

PROMPT = "refine> "
COMMANDS = {
    ":help": "this list",
    ":undo": "drop the last refinement",
    ":tier NAME": "switch the quality tier",
    ":mesh NAME": f"switch the preview mesh ({mesh_choices()}, a file)",
    ":show": "the current material's parameters",
    ":quit": "leave (also end of input)",
}
SOURCE_NAME = "<live>"


@dataclass
class Step:
    ok: bool
    text: str
    quit: bool = False


class LiveSession:
    """A refinement session (cnlmc.api.Session over the material file) and how it is rendered:
    the output PNG, the render options, and the renderer's resources, kept from one step to
    the next until close()."""

    def __init__(self, source: str, out_path: Path, options: dict[str, Any], lexicon: Any = None):
        body = source if source.endswith("\n") else source + "\n"
        # the file's text is the session's first line; refinement lines follow it
        self.session = Session(body[:-1], lexicon, filename=SOURCE_NAME)
        if not self.session.result.ok:
            raise ValueError("the material does not compile")
        self.out_path = Path(out_path)
        self.options = dict(options)
        self._resources: Resources | None = None

    @property
    def lines(self) -> list[str]:
        """The refinement lines typed so far."""
        return self.session.lines[1:]

    @property
    def material(self) -> Material:
        """The refined material: the file's last."""
        return self.session.result.document.materials[-1]

    def close(self) -> None:
        """Release what rendering made (the GL context and its caches)."""
        if self._resources is not None:
            self._resources.release()
            self._resources = None

    # -- one line typed at the prompt
    def step(self, line: str) -> Step:
        line = line.strip()
        if not line or line.startswith("#"):
            return Step(True, "")
        if line.startswith(":"):
            return self.command(line)
        return self.refine(line)

    def refine(self, line: str) -> Step:
        before = self.material
        try:
            self.session.refine(line)
        except ValueError:
            trial = self.session.trial(line)
            source = self.session.text([line])
            return Step(False, "\n".join(render(d, source, SOURCE_NAME) for d in trial.diagnostics if d.is_error))
        rows = changes_of(before, self.material) or ["  (no parameter changed)"]
        return Step(True, "\n".join([*rows, *self.said_of_last_line()]) + "\n" + self.draw())

    def said_of_last_line(self) -> list[str]:
        """The notes and warnings of the line just added ('read 'more matte' relative to ...')."""
        line, source = len(self.session.lines), self.session.text()
        said = self.session.result.diagnostics
        return [render(d, source, SOURCE_NAME) for d in said if not d.is_error and d.span and d.span.line == line]

    def command(self, line: str) -> Step:
        name, _, arg = line.partition(" ")
        arg = arg.strip()
        if name == ":quit":
            return Step(True, "", quit=True)
        if name == ":help":
            return Step(True, "\n".join(f"  {k:12s} {v}" for k, v in COMMANDS.items()))
        if name == ":show":
            params = self.material.to_ir()["params"]
            return Step(True, "\n".join(f"  {k:18s} {fmt(v)}" for k, v in params.items()))
        if name == ":undo":
            return self.undo()
        if name in (":tier", ":mesh") and arg:
            return self.switch(name[1:], arg)
        hint = did_you_mean(difflib.get_close_matches(name, [c.split()[0] for c in COMMANDS], n=2))
        return Step(False, f"unknown command {line!r}" + "".join(f"; {h}" for h in hint) + " (:help lists them)")

    def undo(self) -> Step:
        before = self.material
        try:
            self.session.undo()
        except ValueError as exc:
            return Step(False, str(exc))
        return Step(True, "\n".join(changes_of(before, self.material)) + "\n" + self.draw())

    def switch(self, key: str, value: str) -> Step:
        trial = {**self.options, key: value}
        try:
            parse_options(trial)
            self.options = trial
            return Step(True, self.draw())
        except (ValueError, OSError) as exc:
            return Step(False, str(exc))

    # -- rendering
    def draw(self) -> str:
        """Render the current material to the output PNG; returns a one-line report."""
        if self._resources is None:
            self._resources = Resources()
        report = preview_command(self.session.result.document, self.out_path, self.options, self._resources)
        frame = report.frames[-1][1]
        return f"  wrote {self.out_path} ({frame.tier}, {frame.ms:.0f} ms)"


def changes_of(before: Material, after: Material) -> list[str]:
    """changes() between two typed materials, read in their IR form (what :show prints)."""
    return changes(before.to_ir(), after.to_ir())


def changes(before: dict, after: dict) -> list[str]:
    """'  name  old -> new' for every parameter, coat and map parameter that differs (cnlmc.changes)."""
    return material_changes(before, after)


# ------------------------------------------------------------------------- the loop


def run(
    session: LiveSession, stdin: TextIO | None = None, stdout: TextIO | None = None, window: Window | None = None
) -> int:
    """Read lines until end of input, :quit or the window being closed. Returns 0 (every error
    was reported and undone). Closes the window and the session on the way out."""
    stdin, stdout = stdin or sys.stdin, stdout or sys.stdout
    try:
        return _loop(session, stdin, stdout, window)
    finally:
        if window:
            window.close()
        session.close()


def _loop(session: LiveSession, stdin: TextIO, stdout: TextIO, window: Window | None) -> int:
    interactive = stdin.isatty()
    print(session.draw(), file=stdout)
    if window:
        window.show(session.out_path)
        print(f"  showing {session.out_path.name} in a window (closing it ends the session)", file=stdout)
    print("type a refinement (darker, less grain, ...) or :help", file=stdout, flush=True)
    while True:
        if interactive:
            print(PROMPT, end="", file=stdout, flush=True)
        line = window.readline(stdin) if window else stdin.readline()
        if line is None:
            if interactive:
                print(file=stdout)
            print("window closed", file=stdout, flush=True)
            return 0
        if not line:
            return 0
        if not interactive:
            print(PROMPT + line.rstrip("\n"), file=stdout)
        step = session.step(line)
        if step.text:
            print(step.text, file=stdout, flush=True)
        if step.quit:
            return 0
        if window and step.ok:
            window.show(session.out_path)
