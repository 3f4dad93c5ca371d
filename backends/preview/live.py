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

import base64
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

PROMPT = "refine> "
COMMANDS = {
    ":help": "this list",
    ":undo": "drop the last refinement",
    ":tier NAME": "switch the quality tier",
    ":mesh NAME": "switch the preview mesh (sphere, shader_ball, teapot, a file)",
    ":show": "the current material's parameters",
    ":quit": "leave (also end of input)",
}
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
        self._resources = None  # the renderer's resources, made on the first draw, kept till close()

    def close(self) -> None:
        """Release what rendering made (the GL context and its caches)."""
        if self._resources is not None:
            self._resources.release()
            self._resources = None

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
        return Step(
            True, "\n".join(changes(before, self.material) or ["  (no parameter changed)"]) + "\n" + self.draw()
        )

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
        from .resources import Resources

        if self._resources is None:
            self._resources = Resources()
        report = preview_command(self.result.ir, self.out_path, self.options, self._resources)
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
    """A Tk window showing the output PNG after every step; `Window.open()` is None without a
    display. The window is exactly the image's size; closing it (the window manager's close
    button, WM_DELETE_WINDOW) ends the session like :quit."""

    TICK = 0.03  # seconds between event-loop turns while the prompt waits for a line

    def __init__(self, root):
        import tkinter

        self.root = root
        self.closed = False
        self.image = None
        self._pending = b""  # what stdin gave after the last full line
        root.title("cnlmc preview")
        self.label = tkinter.Label(root, borderwidth=0, highlightthickness=0, padx=0, pady=0)
        self.label.pack()
        root.protocol("WM_DELETE_WINDOW", self.close)

    @classmethod
    def open(cls):
        if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
            return None
        try:
            import tkinter
        except ImportError:  # Python built without Tk
            return None
        try:
            return cls(tkinter.Tk(className="cnlmc"))
        except tkinter.TclError:  # the display refuses the connection
            return None

    def show(self, png_path: Path) -> None:
        """Display the PNG at `png_path` (replacing the previous image) and draw it now."""
        if self.closed:
            return
        import tkinter

        png_path = Path(png_path)
        try:
            image = tkinter.PhotoImage(master=self.root, format="png", data=base64.b64encode(png_path.read_bytes()))
            self.label.configure(image=image)
            self.image = image  # the label does not keep the image alive
            self.root.title(f"{png_path.name} - cnlmc preview")
        except tkinter.TclError:  # the window went away under us
            self.close()
            return
        self.update()

    def update(self) -> None:
        """Handle pending window events (redraws, the close button)."""
        if self.closed:
            return
        import tkinter

        try:
            self.root.update()
        except tkinter.TclError:
            self.closed = True

    def close(self) -> None:
        if self.closed:
            return
        self.closed = True
        import tkinter

        try:
            self.root.destroy()
        except tkinter.TclError:
            pass

    def readline(self, stdin) -> str | None:
        """stdin's next line, keeping the window alive (redrawn, closable) while waiting;
        None when the window was closed first."""
        try:
            fd = stdin.fileno()
        except (AttributeError, OSError, ValueError):
            fd = None
        if fd is None or os.name == "nt":  # no descriptor to wait on: read, then catch up
            line = stdin.readline()
            self.update()
            return None if self.closed else line
        import select

        pending = self._pending
        while True:
            end = pending.find(b"\n")
            if end >= 0:
                self._pending = pending[end + 1 :]
                return _decode(pending[: end + 1], stdin)
            self.update()
            if self.closed:
                self._pending = pending
                return None
            ready, _, _ = select.select([fd], [], [], self.TICK)
            if ready:
                chunk = os.read(fd, 65536)
                if not chunk:  # end of input: the last line may lack its newline
                    self._pending = b""
                    return _decode(pending, stdin)
                pending += chunk


def _decode(data: bytes, stdin) -> str:
    return data.decode(getattr(stdin, "encoding", None) or "utf-8", errors="replace")


def run(session: LiveSession, stdin=None, stdout=None, window=None) -> int:
    """Read lines until end of input, :quit or the window being closed. Returns 0 (every error
    was reported and undone). Closes the window and the session on the way out."""
    stdin, stdout = stdin or sys.stdin, stdout or sys.stdout
    try:
        return _loop(session, stdin, stdout, window)
    finally:
        if window:
            window.close()
        session.close()


def _loop(session: LiveSession, stdin, stdout, window) -> int:
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
