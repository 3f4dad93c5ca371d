"""The studio's live view in headless Chromium (WebGL2 on SwiftShader): keystroke -> updated frame
latency with where it goes, stage by stage, and the frame time at 512x512.

    .venv/bin/python bench/studio.py [--edits 12] [--frames 7] [--through studio|view]
                                     [--kinds untextured,textured,glass] [--no-frame-times] [--chromium-arg=FLAG]
    .venv/bin/python bench/studio.py --sheet docs/studio_view.png   # the browser's frames under the preview's

Latency: through the studio's own page (`cnlmc serve`, the CodeMirror editor, the WebSocket
edit, the server's compile and `material_payload`, MaterialView.show and its frames) by default;
`--through view` (or when `cnlmc serve` does not start) through `material_payload` and the view's
test page (tests/studio/view_page.html). Each edit replaces the phrase with the next of its cycle
(one input event, as a paste or an accepted completion). The page marks each stage of an edit
(static/view/trace.js: User Timing marks "cnlmc:<stage>"); the latency runs from just before the
keystroke (before Playwright's insert) to the frame on screen (the task after the browser's next
rendering update once it is drawn): the first picture (the quick frame, smaller and stretched,
when the view draws one) and the full frame. The table under it gives each stage's median and
the server's own timing of the analysis. The first cycle includes what is made once per content
(albedo tables, baked maps, the environment prefiltered at a new alpha, a program per shader);
`cold` lists it. Goal (issue #17): p99 <= 150 ms untextured, <= 400 ms textured.

Frame time: MaterialView.draw() at 512x512 on the view's test page, median of --frames after a
warm-up, per material, against `cnlmc preview`'s frame of the same scene on llvmpipe in this
process. Prints the load average: on a shared machine the numbers are inflated.
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
#: the page's trace marks (static/view/trace.js), in order: each stage runs from the mark before it
STAGES = (
    ("change", "keystroke -> CodeMirror update"),
    ("send", "-> edit sent (the page's debounce)"),
    ("message", "-> answer arrives (socket, server, JSON)"),
    ("parsed", "-> JSON parsed"),
    ("applied", "-> editor marks and panels"),
    ("setup", "-> view setup (program, tables, textures)"),
    ("quick-drawn", "-> quick frame drawn"),
    ("quick-shown", "-> quick frame on screen"),
    ("drawn", "-> full frame drawn"),
    ("shown", "-> full frame on screen"),
)
#: the server's own timing of an edit (the analysis's `timing`), in the answer's stage
SERVER_PARTS = ("queued_ms", "analysis_ms", "view_ms", "server_ms")
#: waits for the edit started after `start` to be on screen; its marks, ms from `start`
TRACE_JS = """async ([start, until]) => {
  const ours = () => performance.getEntriesByType("mark").filter((m) => m.name.startsWith("cnlmc:") && m.startTime >= start);
  for (let i = 0; i < 2400; i++) {
    const changes = ours().filter((m) => m.name === "cnlmc:change");
    if (changes.length) {
      const edit = changes[changes.length - 1].detail.edit;
      const marks = ours().filter((m) => m.detail.edit === edit);
      if (marks.some((m) => m.name === "cnlmc:" + until))
        return marks.map((m) => [m.name.slice(6), m.startTime - start, m.detail]);
    }
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
  return null;
}"""


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

    def __init__(self, page: Any, url: str) -> None:
        self.page = page
        page.goto(url)
        page.wait_for_selector("body[data-ready='1']", state="attached", timeout=120_000)

    def edit(self, phrase: str) -> dict[str, Any]:
        page = self.page
        page.click(".cm-content")
        page.keyboard.press("Control+A")
        start = page.evaluate("performance.now()")
        page.keyboard.insert_text(phrase + "\n")
        return traced(page, start)


def traced(page: Any, start: float, until: str = "shown") -> dict[str, Any]:
    """The edit's stages until mark `until`: mark -> ms from just before the keystroke; `server` the server's timing."""
    marks = page.evaluate(TRACE_JS, [start, until])
    if marks is None:
        raise RuntimeError("the edit's frame did not reach the screen in 120 s")
    out: dict[str, Any] = {"server": {}, "chars": 0, "quick_scale": 1.0, "quick_ms": 0.0, "full_ms": 0.0, "bands": 1}
    for name, at, detail in marks:
        out.setdefault(name, at)
        out["server"] = detail.get("server") or out["server"]
        out["chars"] = detail.get("chars") or out["chars"]
        if name == "quick-drawn":
            out["quick_scale"], out["quick_ms"] = detail["scale"], detail["ms"]
        if name == "drawn":
            out["full_ms"], out["bands"] = detail["ms"], detail.get("bands", 1)
    return out


class ViewPage:
    """Edits through material_payload and the view's test page (no editor, no debounce)."""

    def __init__(self, page: Any, url: str) -> None:
        self.page = page
        page.goto(url + "/page.html?size=512")
        page.evaluate("window.viewReady")

    def edit(self, phrase: str) -> dict[str, Any]:
        start = self.page.evaluate("performance.now()")
        self.page.evaluate("(p) => { window.showPhrase(p); }", phrase)
        return traced(self.page, start)


def latencies(driver: Any, edits: int, kinds: list[str]) -> dict[str, dict[str, Any]]:
    """Per kind: `cold` (the first cycle, new content: full frame on screen, ms) and `warm` (the traces after it)."""
    out = {}
    for kind in kinds:
        cycle = CYCLES[kind]
        driver.edit(cycle[-1])  # the shader compiled, the page settled
        traces = [driver.edit(cycle[i % len(cycle)]) for i in range(edits)]
        out[kind] = {"cold": [on_screen(t)[1] for t in traces[: len(cycle)]], "warm": traces[len(cycle) :]}
    return out


def on_screen(trace: dict[str, Any]) -> tuple[float, float]:
    """(first picture of the new material on screen, the full frame on screen), ms from the keystroke."""
    full = float(trace.get("shown", float("nan")))
    return float(trace.get("quick-shown", full)), full


def stage_table(measured: dict[str, dict[str, Any]]) -> list[str]:
    """Median ms of each stage per kind (a stage an edit skipped counts 0), the server's parts below."""
    kinds = list(measured)
    lines = [f"  {'stage (median ms)':46s}" + "".join(f"{k:>12s}" for k in kinds)]
    previous = {k: [0.0] * len(measured[k]["warm"]) for k in kinds}
    for mark, label in STAGES:
        row = []
        for k in kinds:
            durations = []
            for i, t in enumerate(measured[k]["warm"]):
                if mark in t:
                    durations.append(t[mark] - previous[k][i])
                    previous[k][i] = t[mark]
                else:
                    durations.append(0.0)
            row.append(percentile(durations, 50))
        lines.append(f"  {label:46s}" + "".join(f"{v:12.1f}" for v in row))
        if mark == "message":
            for part in SERVER_PARTS:
                values = {k: [t["server"].get(part) for t in measured[k]["warm"] if t["server"]] for k in kinds}
                if any(values.values()):
                    cells = "".join(f"{percentile([v for v in values[k] if v is not None], 50):12.1f}" for k in kinds)
                    lines.append(f"  {'    of which server ' + part[:-3]:46s}" + cells)
            sizes = "".join(f"{percentile([t['chars'] for t in measured[k]['warm']], 50) / 1000:11.1f}k" for k in kinds)
            lines.append(f"  {'    answer size (characters)':46s}" + sizes)
        if mark == "quick-drawn":
            for key, label in (("quick_scale", "quick frame's scale"), ("quick_ms", "quick frame's draw (ms)")):
                cells = "".join(f"{percentile([t[key] for t in measured[k]['warm']], 50):12.2f}" for k in kinds)
                lines.append(f"  {'    ' + label:46s}" + cells)
        if mark == "drawn":
            for key, label in (("full_ms", "full frame draw (ms)"), ("bands", "full frame's bands")):
                cells = "".join(f"{percentile([t[key] for t in measured[k]['warm']], 50):12.1f}" for k in kinds)
                lines.append(f"  {'    ' + label:46s}" + cells)
    return lines


def frame_times(page: Any, frames: int, kinds: list[str]) -> dict[str, float]:
    out = {}
    for kind in kinds:
        cycle = CYCLES[kind]
        page.evaluate("(p) => window.showPhrase(p)", cycle[0])
        page.evaluate("window.view.draw()")
        out[kind] = float(np.median([page.evaluate("window.view.draw()") for _ in range(frames)]))
    return out


def preview_frame_times(frames: int, kinds: list[str]) -> dict[str, float]:
    """The peer: `cnlmc preview`'s splitsum frame of the same scene at 512x512 (llvmpipe, this process)."""
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer

    out = {}
    with Renderer(512) as renderer:
        scene = renderer.scene("sphere", "studio")
        for kind in kinds:
            material = compile_source(CYCLES[kind][0] + "\n").ir["materials"][0]
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
    parser.add_argument("--kinds", default=",".join(CYCLES), help="which of them (comma-separated)")
    parser.add_argument("--no-frame-times", action="store_true", help="only the keystroke latency")
    parser.add_argument("--chromium-arg", action="append", default=[], help="another Chromium flag (repeatable)")
    args = parser.parse_args()
    kinds = [k for k in CYCLES if k in args.kinds.split(",")]
    if args.sheet:
        sheet(args.sheet)
        return
    from playwright.sync_api import sync_playwright

    print(f"load average before: {' '.join(f'{x:.1f}' for x in os.getloadavg())} ({os.cpu_count()} cores)")
    studio = start_studio() if args.through == "studio" else None
    with ViewServer(Path(tempfile.mkdtemp(prefix="cnlmc-bench-studio-"))) as server, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS + args.chromium_arg)
        print(f"Chromium flags: {' '.join(CHROMIUM_ARGS + args.chromium_arg)}")
        page = browser.new_page(viewport={"width": 1280, "height": 860})
        if studio is not None:
            through = "the studio's page (cnlmc serve: editor -> WebSocket -> compile -> payload -> view)"
            driver: Any = StudioPage(page, studio[1])
        else:
            through = "material_payload + the view's test page (no editor)"
            driver = ViewPage(page, server.url)
        measured = latencies(driver, args.edits, kinds)
        frames = {}
        if not args.no_frame_times:
            view_page = browser.new_page()
            view_page.goto(server.url + "/page.html?size=512")
            view_page.evaluate("window.viewReady")
            frames = frame_times(view_page, args.frames, kinds)
        browser.close()
    if studio is not None:
        studio[0].terminate()
        studio[0].wait(20)
    print(f"keystroke -> updated frame on screen, through {through}:")
    goals = {"untextured": 150.0, "textured": 400.0, "glass": 150.0}
    for kind, m in measured.items():
        quick = [on_screen(t)[0] for t in m["warm"]]
        full = [on_screen(t)[1] for t in m["warm"]]
        for label, values in (("first picture", quick), ("full frame", full)):
            p50, p99 = percentile(values, 50), percentile(values, 99)
            met = "met" if p99 <= goals[kind] else "not met"
            print(
                f"  {kind:11s} {label:23s} p50 {p50:6.0f} ms  p99 {p99:6.0f} ms  "
                f"(n={len(values)}; goal p99 <= {goals[kind]:.0f} ms: {met})"
            )
        print(f"  {kind:11s} first cycle (new content), full frame: {', '.join(f'{t:.0f}' for t in m['cold'])} ms")
    print("where the time goes (each stage from the one above; ms from just before the keystroke):")
    print("\n".join(stage_table(measured)))
    if not frames:
        print(f"load average after: {' '.join(f'{x:.1f}' for x in os.getloadavg())}")
        return
    peer = preview_frame_times(args.frames, kinds)
    print("frame time at 512x512 on SwiftShader (MaterialView.draw, median), and the peer: cnlmc preview (llvmpipe):")
    for kind, ms in frames.items():
        print(
            f"  {kind:11s} {ms:7.1f} ms  preview {peer[kind]:7.1f} ms  ratio {ms / peer[kind]:5.2f}  ({CYCLES[kind][0]})"
        )
    print(f"load average after: {' '.join(f'{x:.1f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
