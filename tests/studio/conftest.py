"""The studio's tests: a real `cnlmc serve` started on a free port, driven by Playwright in
Debian's Chromium (software WebGL2 through SwiftShader; no browser download). One server and one
browser per test module. Everything the page logs as an error, every failed request and every
HTTP error is collected; test_page.py's last test asserts there were none."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
BROWSER_ARGS = ["--enable-unsafe-swiftshader", "--no-sandbox"]
STARTUP_SECONDS = 60


def require_studio() -> None:
    pytest.importorskip("aiohttp", reason="the studio needs aiohttp (pip install 'cnlmc[studio]')")
    pytest.importorskip("segno", reason="the studio needs segno (pip install 'cnlmc[studio]')")


def require_browser() -> None:
    require_studio()
    pytest.importorskip("playwright", reason="the browser tests need playwright (pip install 'cnlmc[studio]')")
    if not Path(CHROMIUM).exists():
        pytest.skip("no chromium: run scripts/setup.sh (apt-get install chromium)")


@dataclass
class Server:
    process: subprocess.Popen[str]
    url: str
    said: list[str] = field(default_factory=list)

    def stop(self) -> str:
        self.process.terminate()
        try:
            out, _ = self.process.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            out, _ = self.process.communicate()
        return out


def start_server(*args: str) -> Server:
    """`cnlmc serve --port 0 ARGS` in its own process; returns once it has said where it is."""
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1", "PYTHONUNBUFFERED": "1"}
    process = subprocess.Popen(
        [sys.executable, "-m", "cnlmc", "serve", "--port", "0", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
    )
    assert process.stdout is not None
    said = []
    deadline = time.monotonic() + STARTUP_SECONDS
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        if not line:
            break
        said.append(line)
        if line.strip() == "stop it with Ctrl-C":  # the last line of the announcement
            url = next(s for s in said if s.startswith("cnlmc studio: ")).split(": ", 1)[1].strip()
            return Server(process, url, said)
    process.kill()
    raise AssertionError("cnlmc serve did not start:\n" + "".join(said) + (process.stdout.read() or ""))


@pytest.fixture(scope="module")
def server() -> Iterator[Server]:
    require_studio()
    running = start_server()
    yield running
    running.stop()


@dataclass
class PageLog:
    """What went wrong in the page: console errors, uncaught exceptions, failed requests."""

    problems: list[str] = field(default_factory=list)

    def watch(self, page: Any) -> None:
        page.on("console", lambda m: self.problems.append(f"console {m.type}: {m.text}") if m.type == "error" else None)
        page.on("pageerror", lambda e: self.problems.append(f"uncaught: {e}"))
        page.on("requestfailed", self._failed)
        page.on("response", lambda r: self.problems.append(f"HTTP {r.status}: {r.url}") if r.status >= 400 else None)

    def _failed(self, request: Any) -> None:
        """A request that failed; not one the page cancelled itself (net::ERR_ABORTED: the AR
        dialog closed while its model-viewer was still loading the .glb, on a slow machine)."""
        if "ERR_ABORTED" not in str(request.failure):
            self.problems.append(f"request failed: {request.url}: {request.failure}")


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    require_browser()
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=CHROMIUM, args=BROWSER_ARGS)
        yield launched
        launched.close()


@pytest.fixture(scope="module")
def page_log() -> PageLog:
    return PageLog()


@pytest.fixture(scope="module")
def page(browser: Any, server: Server, page_log: PageLog) -> Iterator[Any]:
    context = browser.new_context(viewport={"width": 1280, "height": 860}, accept_downloads=True)
    opened = context.new_page()
    page_log.watch(opened)
    opened.goto(server.url)
    opened.wait_for_selector("body[data-ready='1']", state="attached", timeout=STARTUP_SECONDS * 1000)
    yield opened
    context.close()
