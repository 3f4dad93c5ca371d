"""Live refinement: `cnlmc preview FILE -o preview.png --interactive`.

A prompt reads refinement lines ("darker", "less grain", "more diffuse"); each one is added
below the material (docs/refinement.md), recompiled, re-rendered and written to the output
PNG (atomically, so an image viewer that reloads shows every step), and the parameters it
changed are printed. A line that does not compile is reported with its caret and "did you
mean" and leaves the material as it was. Lines starting with ':' are commands (`:help`).

With a display (DISPLAY or WAYLAND_DISPLAY set and Tk available) the image also appears in a
window that follows every step; headless, the PNG on disk is the view.
"""
from __future__ import annotations

import base64
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

PROMPT = "refine> "
COMMANDS = {":help": "this list", ":undo": "drop the last refinement", ":tier NAME": "switch the quality tier",
            ":mesh NAME": "switch the preview mesh (sphere, shader_ball, teapot, a file)",
            ":show": "the current material's parameters", ":quit": "leave (also end of input)"}
SOURCE_NAME = "<live>"


@dataclass
class Step:
    ok: bool
    text: str
    quit: bool = False


@dataclass
class LiveSession:
    """The material file plus the refinement lines typed so far, and how it is rendered."""
    source: str
    out_path: Path
    options: dict
    lexicon: object = None
    lines: list = field(default_factory=list)

    def __post_init__(self):
        self.result = self._compile(self.lines)
        if not self.result.ok:
            raise ValueError("the material does not compile")

    # -- compiling
    def text(self, lines=None) -> str:
        body = self.source if self.source.endswith("\n") else self.source + "\n"
        return body + "".join(line + "\n" for line in (self.lines if lines is None else lines))

    def _compile(self, lines):
        from cnlmc.api import compile_source
        return compile_source(self.text(lines), SOURCE_NAME, self.lexicon)

    @property
    def material(self) -> dict:
        return self.result.ir["materials"][-1]

    # -- one line typed at the prompt
    def step(self, line: str) -> Step:
        line = line.strip()
        if not line or line.startswith("#"):
            return Step(True, "")
        if line.startswith(":"):
            return self.command(line)
        return self.refine(line)

    def refine(self, line: str) -> Step:
        from cnlmc.diagnostics import render
        trial = self._compile(self.lines + [line])
        if not trial.ok:
            source = self.text(self.lines + [line])
            return Step(False, "\n".join(render(d, source, SOURCE_NAME) for d in trial.diagnostics if d.is_error))
        before = self.material
        self.lines.append(line)
        self.result = trial
        return Step(True, "\n".join(changes(before, self.material) or ["  (no parameter changed)"]) + "\n" + self.draw())

    def command(self, line: str) -> Step:
        name, _, arg = line.partition(" ")
        arg = arg.strip()
        if name == ":quit":
            return Step(True, "", quit=True)
        if name == ":help":
            return Step(True, "\n".join(f"  {k:12s} {v}" for k, v in COMMANDS.items()))
        if name == ":show":
            return Step(True, "\n".join(f"  {k:18s} {_fmt(v)}" for k, v in self.material["params"].items()))
        if name == ":undo":
            if not self.lines:
                return Step(False, "nothing to undo")
            before = self.material
            self.lines.pop()
            self.result = self._compile(self.lines)
            return Step(True, "\n".join(changes(before, self.material)) + "\n" + self.draw())
        if name in (":tier", ":mesh") and arg:
            return self.switch(name[1:], arg)
        import difflib

        from cnlmc.diagnostics import did_you_mean
        hint = did_you_mean(difflib.get_close_matches(name, [c.split()[0] for c in COMMANDS], n=2))
        return Step(False, f"unknown command {line!r}" + "".join(f"; {h}" for h in hint) + " (:help lists them)")

    def switch(self, key: str, value: str) -> Step:
        from . import parse_options
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
        from . import preview_command
        report = preview_command(self.result.ir, self.out_path, self.options)
        frame = report.frames[-1][1]
        return f"  wrote {self.out_path} ({frame.tier}, {frame.ms:.0f} ms)"


def changes(before: dict, after: dict) -> list[str]:
    """'  name  old -> new' for every parameter that differs."""
    rows = []
    old, new = before["params"], after["params"]
    for key in dict.fromkeys(list(old) + list(new)):
        if _fmt(old.get(key)) != _fmt(new.get(key)):
            rows.append(f"  {key:18s} {_fmt(old.get(key))} -> {_fmt(new.get(key))}")
    if before["model"] != after["model"]:
        rows.append(f"  {'model':18s} {_model(before)} -> {_model(after)}")
    return rows


def _model(material: dict) -> str:
    m = material["model"]
    return ", ".join(str(v) if not isinstance(v, bool) else k for k, v in m.items() if v)


def _fmt(value) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(_fmt(v) for v in value) + ")"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_fmt(v)}" for k, v in value.items()) + "}"
    return str(value)


# ------------------------------------------------------------------------- the loop

class Window:
    """A Tk window showing the PNG; None when there is no display."""

    def __init__(self, root):
        import tkinter
        self.root = root
        self.label = tkinter.Label(root)
        self.label.pack()
        root.title("cnlmc preview")

    @classmethod
    def open(cls):
        if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
            return None
        try:
            import tkinter
            return cls(tkinter.Tk())
        except Exception:                      # no Tk, or the display refuses the connection
            return None

    def show(self, png_path: Path) -> None:
        import tkinter
        self.image = tkinter.PhotoImage(data=base64.b64encode(Path(png_path).read_bytes()))
        self.label.configure(image=self.image)
        self.root.update()


def run(session: LiveSession, stdin=None, stdout=None, window=None) -> int:
    """Read lines until end of input or :quit. Returns 0 (every error was reported and undone)."""
    stdin, stdout = stdin or sys.stdin, stdout or sys.stdout
    interactive = stdin.isatty()
    print(session.draw(), file=stdout)
    if window:
        window.show(session.out_path)
    print("type a refinement (darker, less grain, ...) or :help", file=stdout)
    while True:
        if interactive:
            print(PROMPT, end="", file=stdout, flush=True)
        line = stdin.readline()
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
