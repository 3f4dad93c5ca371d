"""The live-refinement window (`cnlmc preview FILE --interactive` with a display), on a private
Xvfb server. What is on the screen is read back from Xvfb's own framebuffer (`-fbdir`, an XWD
file the server keeps mapped), so the assertions are about the pixels the X server shows, not
about Tk's idea of them; window geometry, title and the window manager's close request go
through Xlib (ctypes) on a connection of the test's own.

Skipped only when Xvfb or tkinter is missing (scripts/setup.sh installs both)."""

from __future__ import annotations

import ctypes
import ctypes.util
import io
import os
import select
import shutil
import struct
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

from tests.helpers import require, run_cnlmc

cv2 = require("cv2", "ar")
tkinter = pytest.importorskip("tkinter", reason="tkinter is not available in this Python (apt: python3-tk)")
pytestmark = [pytest.mark.cv2, pytest.mark.tk]

from cnlmc.backends.preview.live import LiveSession, Window, run  # noqa: E402 -- after the skip

SCREEN = (320, 240)
MATERIAL = "white varnished oak\n"


# ----------------------------------------------------------------------------- the X server


def _die_with_parent():
    """In the Xvfb child: get SIGTERM when the test process dies, even if it dies too hard for
    the fixture's finaliser to run (Linux; elsewhere the finaliser alone)."""
    if sys.platform.startswith("linux"):
        ctypes.CDLL(None).prctl(1, 15)  # PR_SET_PDEATHSIG, SIGTERM


class Xvfb:
    def __init__(self, tmp):
        if shutil.which("Xvfb") is None:
            pytest.skip("Xvfb is not installed (apt: xvfb)")
        read, write = os.pipe()
        self.proc = subprocess.Popen(
            [
                "Xvfb",
                "-displayfd",
                str(write),
                "-screen",
                "0",
                f"{SCREEN[0]}x{SCREEN[1]}x24",
                "-fbdir",
                str(tmp),
                "-nolisten",
                "tcp",
                "-br",
                "-noreset",
            ],
            pass_fds=[write],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            preexec_fn=_die_with_parent,
        )
        os.close(write)
        number = b""
        deadline = time.monotonic() + 10
        while not number.endswith(b"\n") and time.monotonic() < deadline:
            if select.select([read], [], [], 0.1)[0]:
                chunk = os.read(read, 16)
                if not chunk:
                    break
                number += chunk
        os.close(read)
        if not number.strip().isdigit():
            self.stop()
            pytest.fail(f"Xvfb did not report a display number (got {number!r})")
        self.display = f":{int(number)}"
        self.framebuffer = tmp / "Xvfb_screen0"

    def stop(self):
        self.proc.terminate()
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()

    def screen(self) -> np.ndarray:
        """The whole screen as an RGB array, read from the server's framebuffer file."""
        data = self.framebuffer.read_bytes()
        head = struct.unpack(">25I", data[:100])
        header_size, version, width, height = head[0], head[1], head[4], head[5]
        bits, stride, ncolors = head[11], head[12], head[19]
        assert version == 7 and bits == 32 and head[7] == 0, head  # XWD, 32-bit LSB-first pixels
        start = header_size + 12 * ncolors
        pixels = np.frombuffer(data, np.uint8, stride * height, start).reshape(height, stride // 4, 4)
        return pixels[:, :width, 2::-1]  # B G R X -> R G B


@pytest.fixture(scope="module")
def xvfb(tmp_path_factory):
    server = Xvfb(tmp_path_factory.mktemp("xvfb"))
    yield server
    server.stop()


@pytest.fixture
def display(xvfb, monkeypatch):
    """DISPLAY set for the code under test only (monkeypatch restores the environment)."""
    monkeypatch.setenv("DISPLAY", xvfb.display)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    return xvfb


class _ClientMessage(ctypes.Structure):
    _fields_ = [
        ("type", ctypes.c_int),
        ("serial", ctypes.c_ulong),
        ("send_event", ctypes.c_int),
        ("display", ctypes.c_void_p),
        ("window", ctypes.c_ulong),
        ("message_type", ctypes.c_ulong),
        ("format", ctypes.c_int),
        ("data", ctypes.c_long * 5),
    ]


class _Event(ctypes.Union):
    _fields_ = [("xclient", _ClientMessage), ("pad", ctypes.c_long * 24)]


class Xlib:
    """A connection of the test's own to the server: what a window manager or a user would see."""

    def __init__(self, display: str):
        name = ctypes.util.find_library("X11")
        if name is None:
            pytest.skip("libX11 not found")
        x = self.x = ctypes.CDLL(name)
        x.XOpenDisplay.restype = ctypes.c_void_p
        x.XOpenDisplay.argtypes = [ctypes.c_char_p]
        ulong, vp, ip, uip = (
            ctypes.c_ulong,
            ctypes.c_void_p,
            ctypes.POINTER(ctypes.c_int),
            ctypes.POINTER(ctypes.c_uint),
        )
        x.XDefaultRootWindow.restype = ulong
        x.XDefaultRootWindow.argtypes = [vp]
        x.XInternAtom.restype = ulong
        x.XInternAtom.argtypes = [vp, ctypes.c_char_p, ctypes.c_int]
        x.XSendEvent.argtypes = [vp, ulong, ctypes.c_int, ctypes.c_long, ctypes.POINTER(_Event)]
        x.XSync.argtypes = [vp, ctypes.c_int]
        x.XCloseDisplay.argtypes = [vp]
        x.XGetGeometry.argtypes = [vp, ulong, ctypes.POINTER(ulong), ip, ip, uip, uip, uip, uip]
        x.XTranslateCoordinates.argtypes = [vp, ulong, ulong, ctypes.c_int, ctypes.c_int, ip, ip, ctypes.POINTER(ulong)]
        x.XFetchName.argtypes = [vp, ulong, ctypes.POINTER(ctypes.c_char_p)]
        x.XCreateSimpleWindow.restype = ulong
        x.XCreateSimpleWindow.argtypes = [
            vp,
            ulong,
            ctypes.c_int,
            ctypes.c_int,
            ctypes.c_uint,
            ctypes.c_uint,
            ctypes.c_uint,
            ulong,
            ulong,
        ]
        x.XMapRaised.argtypes = [vp, ulong]
        x.XQueryTree.argtypes = [
            vp,
            ulong,
            ctypes.POINTER(ulong),
            ctypes.POINTER(ulong),
            ctypes.POINTER(ctypes.POINTER(ulong)),
            uip,
        ]
        x.XFree.argtypes = [vp]
        x.XDestroyWindow.argtypes = [vp, ulong]
        self.d = x.XOpenDisplay(display.encode())
        assert self.d, f"cannot open {display}"
        self.root = x.XDefaultRootWindow(self.d)

    def close(self):
        self.x.XCloseDisplay(self.d)

    def find(self, title_end: str) -> int | None:
        """The top-level window whose title ends with `title_end` (no window manager here, so
        top-level windows are the root's children)."""
        root, parent = ctypes.c_ulong(), ctypes.c_ulong()
        children, count = ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
        if not self.x.XQueryTree(
            self.d, self.root, ctypes.byref(root), ctypes.byref(parent), ctypes.byref(children), ctypes.byref(count)
        ):
            return None
        found = [children[i] for i in range(count.value) if self.title(children[i]).endswith(title_end)]
        if children:
            self.x.XFree(children)
        return found[-1] if found else None

    def geometry(self, window: int) -> tuple[int, int, int, int]:
        """x, y on the screen and width, height of `window`."""
        root, px, py = ctypes.c_ulong(), ctypes.c_int(), ctypes.c_int()
        w, h, border, depth = ctypes.c_uint(), ctypes.c_uint(), ctypes.c_uint(), ctypes.c_uint()
        assert self.x.XGetGeometry(
            self.d,
            window,
            ctypes.byref(root),
            ctypes.byref(px),
            ctypes.byref(py),
            ctypes.byref(w),
            ctypes.byref(h),
            ctypes.byref(border),
            ctypes.byref(depth),
        )
        sx, sy, child = ctypes.c_int(), ctypes.c_int(), ctypes.c_ulong()
        self.x.XTranslateCoordinates(
            self.d, window, self.root, 0, 0, ctypes.byref(sx), ctypes.byref(sy), ctypes.byref(child)
        )
        return sx.value, sy.value, w.value, h.value

    def title(self, window: int) -> str:
        name = ctypes.c_char_p()
        self.x.XFetchName(self.d, window, ctypes.byref(name))
        return (name.value or b"").decode("latin-1")  # (leaks a few bytes; XFree is not worth it)

    def close_request(self, window: int) -> None:
        """What a window manager sends when the user clicks the close button."""
        event = _Event()
        message = event.xclient
        message.type, message.send_event, message.display, message.window = 33, 1, self.d, window  # ClientMessage
        message.message_type = self.x.XInternAtom(self.d, b"WM_PROTOCOLS", 0)
        message.format = 32
        message.data[0] = self.x.XInternAtom(self.d, b"WM_DELETE_WINDOW", 0)
        message.data[1] = 0  # CurrentTime
        assert self.x.XSendEvent(self.d, window, 0, 0, ctypes.byref(event))
        self.x.XSync(self.d, 0)

    def cover(self, x: int, y: int, w: int, h: int, seconds: float = 0.2) -> None:
        """Map a white window over the area, then remove it: the area underneath is exposed and
        stays empty unless its owner redraws it (no backing store without a compositor)."""
        over = self.x.XCreateSimpleWindow(self.d, self.root, x, y, w, h, 0, 0, 0xFFFFFF)
        self.x.XMapRaised(self.d, over)
        self.x.XSync(self.d, 0)
        time.sleep(seconds)
        self.x.XDestroyWindow(self.d, over)
        self.x.XSync(self.d, 0)


# ----------------------------------------------------------------------------- helpers


def png_rgb(path) -> np.ndarray:
    return cv2.imread(str(path), cv2.IMREAD_COLOR)[..., ::-1]


def luminance(rgb: np.ndarray) -> float:
    """Mean Rec. 709 luma of the image's middle (the object), 0..255."""
    h, w = rgb.shape[:2]
    middle = rgb[h * 5 // 16 : h * 11 // 16, w * 5 // 16 : w * 11 // 16].astype(float)
    return float((middle @ [0.2126, 0.7152, 0.0722]).mean())


def wait_until(predicate, timeout=10.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.02)
    return predicate()


def shown(server: Xvfb, box, expected: np.ndarray) -> bool:
    x, y, w, h = box
    return np.array_equal(server.screen()[y : y + h, x : x + w], expected)


class Driver(threading.Thread):
    """Plays the user on the other end of a pipe: `script(send)` runs on this thread while
    live.run() holds the main thread (where Tk lives). Failures are kept for the main thread."""

    def __init__(self, script):
        super().__init__(daemon=True)
        read, write = os.pipe()
        self.stdin = os.fdopen(read, "r")
        self._write = os.fdopen(write, "w")
        self.script, self.error, self.seen = script, None, {}

    def send(self, line: str) -> None:
        self._write.write(line + "\n")
        self._write.flush()

    def run(self):
        try:
            self.script(self)
        except BaseException as exc:
            self.error = exc
        finally:
            self._write.close()  # end of input at the latest

    def finish(self):
        self.join(20)
        self.stdin.close()
        if self.error:
            raise self.error


def open_window(tmp_path):
    session = LiveSession(MATERIAL, tmp_path / "live.png", {"size": "64"})
    window = Window.open()
    assert window is not None, "Window.open() found no display although DISPLAY is set"
    return session, window


# ----------------------------------------------------------------------------- the tests


def test_window_shows_every_step_and_quit_closes_it(display, renderer, tmp_path):
    session, window = open_window(tmp_path)
    x11 = Xlib(display.display)

    def user(d: Driver):
        frame = wait_until(lambda: x11.find("cnlmc preview"))
        assert frame, "no window titled '... cnlmc preview' on the screen"
        box = x11.geometry(frame)
        d.seen["box"], d.seen["title"] = box, x11.title(frame)
        first = png_rgb(session.out_path)
        d.seen["first shown"] = wait_until(lambda: shown(display, box, first))
        d.seen["first"] = first
        d.send("darker")
        wait_until(lambda: not np.array_equal(png_rgb(session.out_path), first))
        darker = png_rgb(session.out_path)
        d.seen["darker shown"] = wait_until(lambda: shown(display, box, darker))
        d.seen["darker"] = darker
        x11.cover(*box)  # the window must redraw while the prompt waits
        d.seen["redrawn"] = wait_until(lambda: shown(display, box, darker), timeout=3)
        d.send(":quit")

    driver = Driver(user)
    out = io.StringIO()
    driver.start()
    try:
        assert run(session, driver.stdin, out, window) == 0
    finally:
        window.close()
        driver.finish()
    seen = driver.seen
    assert seen["box"][2:] == (64, 64), "the window is exactly the image's size"
    assert seen["title"] == "live.png - cnlmc preview"
    assert seen["first shown"], "the first render is on the screen, pixel for pixel"
    assert seen["darker shown"], "after 'darker' the screen shows the new PNG, pixel for pixel"
    assert luminance(seen["darker"]) < luminance(seen["first"]) - 10
    assert seen["redrawn"], "the window repaints itself while waiting at the prompt"
    assert window.closed
    with pytest.raises(tkinter.TclError):
        window.root.winfo_exists()  # the Tk application is gone ...
    x, y, w, h = seen["box"]
    assert wait_until(lambda: not display.screen()[y : y + h, x : x + w].any()), (
        "... and so is the window (-br: black root)"
    )
    assert "base_color" in out.getvalue() and "showing live.png in a window" in out.getvalue()
    x11.close()


def test_end_of_input_closes_the_window(display, renderer, tmp_path):
    session, window = open_window(tmp_path)
    driver = Driver(lambda d: d.send("less diffuse"))
    driver.start()
    try:
        assert run(session, driver.stdin, io.StringIO(), window) == 0
    finally:
        driver.finish()
    assert window.closed
    with pytest.raises(tkinter.TclError):
        window.root.winfo_exists()


def test_the_window_managers_close_button_ends_the_session(display, renderer, tmp_path):
    session, window = open_window(tmp_path)
    x11 = Xlib(display.display)
    released = threading.Event()

    def user(d: Driver):
        frame = wait_until(lambda: x11.find("cnlmc preview"))
        assert frame, "no window titled '... cnlmc preview' on the screen"
        first = png_rgb(session.out_path)
        box = x11.geometry(frame)
        assert wait_until(lambda: shown(display, box, first)), "the image never appeared"
        x11.close_request(frame)  # the user closes the window; stdin stays open
        if not released.wait(10):  # run() did not notice: unblock it, the test fails
            d.send(":quit")

    driver = Driver(user)
    out = io.StringIO()
    driver.start()
    start = time.monotonic()
    try:
        assert run(session, driver.stdin, out, window) == 0
        elapsed = time.monotonic() - start
    finally:
        released.set()
        window.close()
        driver.finish()
        x11.close()
    assert "window closed" in out.getvalue(), out.getvalue()
    assert ":quit" not in out.getvalue()
    assert window.closed and elapsed < 9


def test_cli_opens_the_window_and_leaves_cleanly(display, renderer, tmp_path):
    material = tmp_path / "m.cnl"
    material.write_text(MATERIAL)
    out = tmp_path / "p.png"
    env = {**os.environ, "DISPLAY": display.display}
    proc = run_cnlmc(
        *("preview", str(material), "-o", str(out), "--size", "64", "--tier", "analytic", "--interactive"),
        stdin="darker\n",
        timeout=120,
        env=env,
    )
    assert proc.returncode == 0, proc.stderr
    assert "showing p.png in a window" in proc.stdout and "base_color" in proc.stdout
    assert "Traceback" not in proc.stderr and "TclError" not in proc.stderr
