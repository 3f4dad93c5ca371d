"""Live refinement at a prompt (`cnlmc preview FILE --interactive`), headless: the PNG on disk
follows every refinement, errors are reported with a caret and leave the material alone."""

from __future__ import annotations

import io

import numpy as np
import pytest

from tests.helpers import require, run_cnlmc

cv2 = require("cv2", "ar")
pytestmark = pytest.mark.cv2

from cnlmc.backends.preview.live import LiveSession, changes, run  # noqa: E402 -- after the skip


@pytest.fixture
def session(renderer, tmp_path):
    live = LiveSession("blue anodized aluminum\n", tmp_path / "live.png", {"size": "64"})
    yield live
    live.close()  # its renderer's GL context


def mean_colour(path) -> np.ndarray:
    image = cv2.imread(str(path), cv2.IMREAD_COLOR)[..., ::-1].astype(float)
    return image[24:40, 24:40].reshape(-1, 3).mean(0)


def test_darker_halves_the_colour_and_the_picture_follows(session):
    first = session.draw()
    assert "wrote" in first
    before = mean_colour(session.out_path)
    step = session.step("darker")
    assert (
        step.ok
        and "base_color" in step.text
        and "(0.000911, 0.05613, 0.7379) -> (0.000456, 0.02806, 0.369)" in step.text
    )
    after = mean_colour(session.out_path)
    assert after[2] < before[2] - 5


def test_a_misspelling_is_reported_with_a_caret_and_changes_nothing(session):
    session.draw()
    before = session.material
    step = session.step("barker")  # a real word: never read as a slip (cnlmc.typos)
    assert not step.ok
    assert "error[E001]" in step.text and "^" in step.text and "did you mean 'darker'" in step.text
    assert session.material == before and session.lines == []


def test_paper_refinement_sequence_and_undo(session):
    assert "0.3 -> 0.2" in session.step("less diffuse").text
    assert "0.2 -> 0.25" in session.step("more diffuse").text
    assert "0.25 -> 0.2" in session.step(":undo").text
    assert session.step(":undo").ok and session.lines == []
    assert not session.step(":undo").ok


def test_commands_switch_tier_and_reject_unknown_ones(session):
    assert "(analytic," in session.step(":tier analytic").text
    bad = session.step(":tier nonsense")
    assert not bad.ok and "unknown preview tier" in bad.text
    typo = session.step(":tire mc4")
    assert not typo.ok and "did you mean ':tier'" in typo.text
    assert session.step(":quit").quit


def test_run_reads_until_end_of_input(session):
    out = io.StringIO()
    assert run(session, io.StringIO("darker\n\n# a comment\nrougher\n"), out) == 0
    text = out.getvalue()
    assert text.count("refine> ") == 4 and "roughness" in text


def test_changes_lists_only_what_differs():
    a = {"model": {"base": "conductor"}, "params": {"roughness": 0.3, "base_color": [0, 0, 1]}}
    b = {"model": {"base": "conductor"}, "params": {"roughness": 0.3, "base_color": [0, 0, 0.5]}}
    assert changes(a, b) == ["  base_color         (0, 0, 1) -> (0, 0, 0.5)"]


def test_cli_interactive_with_piped_input(renderer, tmp_path):
    material = tmp_path / "m.cnl"
    material.write_text("white varnished oak\n")
    out = tmp_path / "p.png"
    proc = run_cnlmc(
        "preview", str(material), "-o", str(out), "--size", "64", "--interactive", stdin="darker\nfighter\n"
    )
    assert proc.returncode == 0, proc.stderr
    assert (
        "base_color" in proc.stdout and "did you mean" in proc.stdout
    )  # 'fighter' is a real word, no slip: did you mean 'lighter'
    assert cv2.imread(str(out)) is not None
    assert "Traceback" not in proc.stderr


def test_cli_interactive_needs_a_file(tmp_path):
    proc = run_cnlmc("preview", "-", "--interactive", "-o", str(tmp_path / "x.png"), stdin="gold\n", timeout=120)
    assert proc.returncode == 2 and "give the material as a file" in proc.stderr
    assert not (tmp_path / "x.png").exists()


def test_no_window_without_a_display(monkeypatch):
    from cnlmc.backends.preview.live import Window

    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    assert Window.open() is None
    pytest.importorskip("tkinter")
    monkeypatch.setenv("DISPLAY", ":65001")  # no such server: Tk cannot connect, still no window
    assert Window.open() is None


class _Root:
    """Stands in for a Tk root: counts event-loop turns, can be 'closed by the user'."""

    def __init__(self, close_after=None):
        self.turns, self.close_after, self.destroyed, self.on_delete = 0, close_after, False, None

    def update(self):
        self.turns += 1
        if self.close_after is not None and self.turns >= self.close_after:
            self.on_delete()

    def destroy(self):
        self.destroyed = True


def _window(root):
    from cnlmc.backends.preview.live import Window

    window = Window.__new__(Window)
    window.root, window.closed, window.image, window._pending = root, False, None, b""
    root.on_delete = window.close
    return window


def test_window_readline_splits_a_pipe_into_lines_and_turns_the_event_loop():
    import os
    import threading
    import time

    read, write = os.pipe()
    stdin = os.fdopen(read, "r")
    root = _Root()
    window = _window(root)

    def slowly():
        os.write(write, b"darker\nless ")
        time.sleep(0.2)  # the window keeps turning while the line is incomplete
        os.write(write, b"grain\nlast, no newline")
        os.close(write)

    threading.Thread(target=slowly).start()
    assert window.readline(stdin) == "darker\n"
    assert window.readline(stdin) == "less grain\n"
    assert window.readline(stdin) == "last, no newline"
    assert window.readline(stdin) == ""
    assert root.turns >= 3
    stdin.close()


def test_window_closed_while_waiting_ends_run(session):
    import os

    read, write = os.pipe()  # nothing is ever typed
    root = _Root(close_after=5)
    out = io.StringIO()
    with os.fdopen(read, "r") as stdin:
        window = _window(root)
        window.show = lambda path: None
        assert run(session, stdin, out, window) == 0
    os.close(write)
    assert window.closed and root.destroyed
    assert out.getvalue().endswith("window closed\n") and "showing live.png in a window" in out.getvalue()
