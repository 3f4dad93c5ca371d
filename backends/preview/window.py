"""The live preview's window: a Tk window showing the output PNG after every step, kept alive
(redrawn, closable) while the prompt waits for a line; None without a display. Tested under
Xvfb: tests/preview/test_live_window.py."""

from __future__ import annotations

import base64
import os
from pathlib import Path


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
