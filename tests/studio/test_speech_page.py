"""The studio's microphone button (issue #18) in a real Chromium whose microphone is a recording
(Chromium's fake capture device plays a WAV that espeak-ng spoke): the first utterance becomes the
document and the material, a later one refines it, and what was heard is shown."""

from __future__ import annotations

import subprocess
import time
import wave
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from .conftest import BROWSER_ARGS, CHROMIUM, STARTUP_SECONDS, Server, require_browser

pytestmark = pytest.mark.slow
HEAR_SECONDS = 120  # the first utterance loads the recogniser; a loaded 2-core machine is slow
SENT: list[str] = []


def spoken(folder: Path, text: str) -> tuple[Path, float]:
    """`text` spoken by espeak-ng (en-us, 160 wpm) with 1 s of silence before (the browser takes a
    moment to start recording) and 1.5 s after,
    and how long to record it: to 1 s before the file's end, since Chromium's fake microphone plays
    it in a loop and a recording that ran into the next loop would hear a second, cut phrase."""
    pytest.importorskip("pocketsphinx", reason="speech input needs pocketsphinx (pip install 'cnlmc[speech]')")
    from cnlmc.speech.testset import Utterance, synthesize, tools_missing

    if tools_missing():
        pytest.skip(f"the spoken test needs {' and '.join(tools_missing())}")
    clean = synthesize(Utterance(text, "en-us", 160, False, False), folder, 16000)
    padded = folder / f"padded_{clean.name}"
    subprocess.run(["sox", str(clean), str(padded), "pad", "1.0", "1.5"], check=True, capture_output=True)
    with wave.open(str(padded)) as w:
        return padded, w.getnframes() / w.getframerate() - 1.0


def page_hearing(server: Server, wav: Path) -> Iterator[Any]:
    """A studio page in a Chromium whose microphone plays `wav`."""
    require_browser()
    from playwright.sync_api import sync_playwright

    args = [
        *BROWSER_ARGS,
        "--use-fake-device-for-media-stream",
        "--use-fake-ui-for-media-stream",
        f"--use-file-for-fake-audio-capture={wav}",
    ]
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=args)
        context = browser.new_context(permissions=["microphone"])
        page = context.new_page()
        problems: list[str] = []
        page.on("pageerror", lambda e: problems.append(f"uncaught: {e}"))
        SENT.clear()  # the WebSocket requests the page sends (the streamed utterance's chunks among them)
        page.on("websocket", lambda socket: socket.on("framesent", lambda frame: SENT.append(str(frame))))
        page.goto(server.url)
        page.wait_for_selector("body[data-ready='1']", state="attached", timeout=STARTUP_SECONDS * 1000)
        yield page
        assert not problems, problems
        browser.close()


def say(page: Any, seconds: float) -> str:
    """Press Speak, let the microphone play its recording, press Stop; what the page says it heard."""
    heard = int(page.get_attribute("body", "data-heard") or 0)
    page.click("#speak")
    page.wait_for_selector("#speak[aria-pressed='true']", timeout=20_000)
    time.sleep(seconds)
    page.click("#speak")
    deadline = time.monotonic() + HEAR_SECONDS
    while int(page.get_attribute("body", "data-heard") or 0) <= heard:
        assert time.monotonic() < deadline, f"no answer to the utterance: {page.inner_text('#problem')}"
        time.sleep(0.1)
    return page.inner_text("#heard")


def editor_text(page: Any) -> str:
    return str(page.inner_text(".cm-content")).strip()


def test_the_first_utterance_starts_the_material(server: Server, tmp_path: Path) -> None:
    wav, seconds = spoken(tmp_path, "white varnished oak")
    for page in page_hearing(server, wav):
        message = say(page, seconds)
        assert message.startswith("heard 'white varnished oak'"), message
        assert editor_text(page) == "white varnished oak"
        ops = [op for frame in SENT for op in ('"hear_chunk"', '"hear"') if f'"op":{op}' in frame.replace(" ", "")]
        assert ops.count('"hear_chunk"') >= 2 * int(seconds) - 1 and ops[-1] == '"hear"', ops  # streamed, then ended
        assert "oak" in page.inner_text("#materials")


def test_a_later_utterance_refines_it(server: Server, tmp_path: Path) -> None:
    wav, seconds = spoken(tmp_path, "darker")
    for page in page_hearing(server, wav):
        page.click(".cm-content")
        page.keyboard.type("white varnished oak", delay=5)
        deadline = time.monotonic() + HEAR_SECONDS  # the typed material is analysed: the next utterance refines it
        while "oak" not in page.inner_text("#materials"):
            assert time.monotonic() < deadline, "the typed material was never analysed"
            time.sleep(0.1)
        message = say(page, seconds)
        assert message.startswith("heard 'darker'"), message
        assert editor_text(page) == "white varnished oak\ndarker"
