"""The studio's live view in headless Chromium (WebGL2 on SwiftShader): keystroke -> updated frame
latency, and the frame time at 512x512.

    .venv/bin/python bench/studio.py [--edits 12] [--frames 7] [--through studio|view]
    .venv/bin/python bench/studio.py --sheet docs/studio_view.png   # the browser's frames under the preview's

Latency: through the studio's own page (`cnlmc serve`, the CodeMirror editor, the WebSocket
edit, the server's compile and `material_payload`, the page's debounce, MaterialView.show and
its frames) by default; `--through view` (or when `cnlmc serve` does not start) through
`material_payload` and the view's test page (tests/studio/view_page.html). Each edit replaces
the phrase with the next of its cycle (one input event, as a paste or an accepted completion);
the latency is from just before the edit to the "frame" events of the updated picture: the
view's quick frame (drawn at half the canvas size, stretched) and its full frame. The
first cycle includes what is made once per content (albedo tables, baked maps, the environment
prefiltered at a new alpha, a program per shader); `cold` lists it. Goal (issue #17): p99 <= 150 ms
untextured, <= 400 ms textured.

Frame time: MaterialView.draw() at 512x512 on the view's test page, median of --frames after a
warm-up, per material. Prints the load average: on a shared machine the numbers are inflated.
"""

from __future__ import annotations

import argparse
import io
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from tests.studio.view_server import CHROMIUM, CHROMIUM_ARGS, ViewServer  # noqa: E402

#: kind -> the phrases an edit cycles through (each edit changes the material, not its shader)
CYCLES = {
    "untextured": ("red plastic", "blue plastic", "green plastic"),
    "textured": ("oak", "dark oak", "light oak"),
    "glass": ("clear glass", "blue glass", "green glass"),
}
FRAME_LISTENER = """(canvas) => { window.bench_frames = [];
    document.querySelector(canvas).addEventListener("frame", () => window.bench_frames.push(performance.now())); }"""


def percentile(values: list[float], q: float) -> float:
    return float(np.percentile(np.asarray(values, np.float64), q)) if values else float("nan")


def start_studio() -> tuple[subprocess.Popen[str], str] | None:
    """`cnlmc serve --port 0` on an empty document; (process, url) or None when it does not start."""
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1", "PYTHONUNBUFFERED": "1"}
    cmd = [sys.executable, "-m", "cnlmc", "serve", "--port", "0"]
    process = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    assert process.stdout is not None
    deadline = time.monotonic() + 90
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        if not line:
            break
        if line.startswith("cnlmc studio: "):
            return process, line.split(": ", 1)[1].strip()
    process.kill()
    return None


class StudioPage:
    """Edits through the studio's page: select all in the editor, insert the phrase."""

    canvas = "#view"

    def __init__(self, page: Any, url: str) -> None:
        self.page = page
        page.goto(url)
        page.wait_for_selector("body[data-ready='1']", state="attached", timeout=120_000)
        page.evaluate(FRAME_LISTENER, self.canvas)

    def edit(self, phrase: str) -> tuple[float, float]:
        page = self.page
        shown = int(page.evaluate("Number(document.body.dataset.shown)"))
        page.click(".cm-content")
        page.keyboard.press("Control+A")
        start = page.evaluate("performance.now()")
        page.keyboard.insert_text(phrase + "\n")
        # (a CSS wait: the page's Content-Security-Policy forbids evaluating strings)
        page.wait_for_selector(f"body:not([data-shown='{shown}'])", state="attached", timeout=120_000)
        return frames_after(page, start)


def frames_after(page: Any, start: float) -> tuple[float, float]:
    """(first, last) frame event after `start`, ms from it: the quick frame at half size, the full one."""
    times = page.evaluate(f"window.bench_frames.filter((t) => t > {start})")
    return float(min(times)) - start, float(max(times)) - start


class ViewPage:
    """Edits through material_payload and the view's test page (no editor, no debounce)."""

    canvas = "#view"

    def __init__(self, page: Any, url: str) -> None:
        self.page = page
        page.goto(url + "/page.html?size=512")
        page.evaluate("window.viewReady")
        page.evaluate(FRAME_LISTENER, self.canvas)

    def edit(self, phrase: str) -> tuple[float, float]:
        start = self.page.evaluate("performance.now()")
        self.page.evaluate("(p) => window.showPhrase(p)", phrase)
        return frames_after(self.page, start)


def latencies(driver: Any, edits: int) -> dict[str, dict[str, Any]]:
    out = {}
    for kind, cycle in CYCLES.items():
        driver.edit(cycle[-1])  # the shader compiled, the page settled
        times = [driver.edit(cycle[i % len(cycle)]) for i in range(edits)]
        out[kind] = {
            "cold": [full for _, full in times[: len(cycle)]],
            "quick": [quick for quick, _ in times[len(cycle) :]],
            "warm": [full for _, full in times[len(cycle) :]],
        }
    return out


def frame_times(page: Any, frames: int) -> dict[str, float]:
    out = {}
    for kind, cycle in CYCLES.items():
        page.evaluate("(p) => window.showPhrase(p)", cycle[0])
        page.evaluate("window.view.draw()")
        out[kind] = float(np.median([page.evaluate("window.view.draw()") for _ in range(frames)]))
    return out


def preview_frame_times(frames: int) -> dict[str, float]:
    """The peer: `cnlmc preview`'s splitsum frame of the same scene at 512x512 (llvmpipe, this process)."""
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer

    out = {}
    with Renderer(512) as renderer:
        scene = renderer.scene("sphere", "studio")
        for kind, cycle in CYCLES.items():
            material = compile_source(cycle[0] + "\n").ir["materials"][0]
            out[kind] = renderer.frame_time(scene, material, "splitsum", repeats=frames)
    return out


SHEET = ("lightly brushed, blue anodized aluminum", "clear glass", "velvet", "oak", "clear-coated red car paint")


def sheet(out: Path, size: int = 192) -> None:
    """Top row `cnlmc preview` (splitsum), bottom row the browser's frame of the same scene; FLIP printed."""
    from PIL import Image
    from playwright.sync_api import sync_playwright

    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.scene import scene_mesh
    from cnlmc.backends.preview.web import MESH_PIXELS
    from cnlmc.output import write_atomic
    from tests.helpers import load_module

    chart = load_module("preview_chart", ROOT / "bench" / "preview_chart.py")
    sphere = scene_mesh("sphere", (MESH_PIXELS, MESH_PIXELS))
    top, bottom = [], []
    with ViewServer(Path(tempfile.mkdtemp(prefix="cnlmc-bench-studio-"))) as server, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_page()
        page.goto(f"{server.url}/page.html?size={size}")
        page.evaluate("window.viewReady")
        with Renderer(size) as renderer:
            for phrase in SHEET:
                page.evaluate("(p) => window.showPhrase(p)", phrase)
                web = np.array(page.evaluate("Array.from(window.view.readPixels())"), np.uint8)
                web = web.reshape(size, size, 4)[..., :3]
                ir = compile_source(phrase + "\n").ir["materials"][0]
                ref = renderer.render(ir, mesh=sphere, tier="splitsum").rgba[..., :3]
                flip = chart.errors(ref.astype(np.float32) / 255, web.astype(np.float32) / 255)[0]
                print(f"  {phrase:45s} FLIP {flip:.4f} (browser against cnlmc preview, {size}x{size})")
                top.append(ref)
                bottom.append(web)
        browser.close()
    image = np.vstack([np.hstack(top), np.hstack(bottom)])
    buffer = io.BytesIO()
    Image.fromarray(image).save(buffer, format="PNG")
    write_atomic(out, buffer.getvalue())
    print(f"wrote {out}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--edits", type=int, default=12)
    parser.add_argument("--frames", type=int, default=7)
    parser.add_argument("--through", choices=("studio", "view"), default="studio")
    parser.add_argument("--sheet", type=Path, help="write the preview | browser picture there instead")
    args = parser.parse_args()
    if args.sheet:
        sheet(args.sheet)
        return
    from playwright.sync_api import sync_playwright

    print(f"load average before: {' '.join(f'{x:.1f}' for x in os.getloadavg())} ({os.cpu_count()} cores)")
    studio = start_studio() if args.through == "studio" else None
    with ViewServer(Path(tempfile.mkdtemp(prefix="cnlmc-bench-studio-"))) as server, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 860})
        if studio is not None:
            through = "the studio's page (cnlmc serve: editor -> WebSocket -> compile -> payload -> view)"
            driver: Any = StudioPage(page, studio[1])
        else:
            through = "material_payload + the view's test page (no editor)"
            driver = ViewPage(page, server.url)
        measured = latencies(driver, args.edits)
        view_page = browser.new_page()
        view_page.goto(server.url + "/page.html?size=512")
        view_page.evaluate("window.viewReady")
        frames = frame_times(view_page, args.frames)
        browser.close()
    if studio is not None:
        studio[0].terminate()
        studio[0].wait(20)
    print(f"keystroke -> updated frame, through {through}:")
    goals = {"untextured": 150.0, "textured": 400.0, "glass": 150.0}
    for kind, m in measured.items():
        for label, values in (("first frame (half size)", m["quick"]), ("full frame", m["warm"])):
            p50, p99 = percentile(values, 50), percentile(values, 99)
            met = "met" if p99 <= goals[kind] else "not met"
            print(
                f"  {kind:11s} {label:23s} p50 {p50:6.0f} ms  p99 {p99:6.0f} ms  "
                f"(n={len(values)}; goal p99 <= {goals[kind]:.0f} ms: {met})"
            )
        print(f"  {kind:11s} first cycle (new content), full frame: {', '.join(f'{t:.0f}' for t in m['cold'])} ms")
    peer = preview_frame_times(args.frames)
    print("frame time at 512x512 on SwiftShader (MaterialView.draw, median), and the peer: cnlmc preview (llvmpipe):")
    for kind, ms in frames.items():
        print(
            f"  {kind:11s} {ms:7.1f} ms  preview {peer[kind]:7.1f} ms  ratio {ms / peer[kind]:5.2f}  ({CYCLES[kind][0]})"
        )
    print(f"load average after: {' '.join(f'{x:.1f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
