"""A tiny aiohttp server for the view's tests and bench/studio.py: the view's ES modules, a
test page, `material_payload` of a phrase and `static_asset` by name (the contract STUDIO-APP's
server serves too), run in a thread.

    with ViewServer(tmp_path) as server:
        page.goto(server.url + "/page.html")
"""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path
from typing import Any

HERE = Path(__file__).parent
VIEW = Path(__file__).resolve().parents[2] / "compiler" / "studio" / "static" / "view"
#: Chromium as PLATFORM.md "Browser" says: Debian's build, WebGL2 on SwiftShader
CHROMIUM = "/usr/bin/chromium"
#: The page itself (text, panels) is rasterised on the CPU, as Chromium does on a software GPU by
#: default: Debian's launcher adds --enable-gpu-rasterization and --ignore-gpu-blocklist kept it, so
#: every repainted DOM tile went through SwiftShader on the GPU thread, queued before the WebGL
#: frame (chrome://gpu: "Rasterization: Hardware accelerated on all pages"). docs/studio_view.md.
CHROMIUM_ARGS = [
    "--enable-unsafe-swiftshader",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--ignore-gpu-blocklist",
    "--disable-gpu-rasterization",
    "--disable-accelerated-2d-canvas",
]


class ViewServer:
    """Serves /view/<module>, /page.html, /payload?phrase=..., /view-data/<name>, /files/<name>."""

    def __init__(self, files: Path) -> None:
        self.files = Path(files)
        self.url = ""
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._runner: Any = None

    def app(self) -> Any:
        from aiohttp import web

        from cnlmc.api import compile_source
        from cnlmc.studio.view_payload import material_payload, static_asset

        async def payload(request: web.Request) -> web.Response:
            ir = compile_source(request.query["phrase"] + "\n").ir
            body = [material_payload(m, self.files) for m in ir["materials"]]
            return web.json_response(body)

        async def asset(request: web.Request) -> web.Response:
            found = static_asset(request.match_info["name"])
            if found is None:
                raise web.HTTPNotFound()
            return web.Response(body=found[0], content_type=found[1].split(";")[0])

        app = web.Application()
        app.router.add_get("/payload", payload)
        app.router.add_get("/view-data/{name:.+}", asset)
        app.router.add_static("/files", self.files)
        app.router.add_static("/view", VIEW)

        async def page(request: web.Request) -> web.FileResponse:
            return web.FileResponse(HERE / "view_page.html")

        app.router.add_get("/page.html", page)
        return app

    def __enter__(self) -> ViewServer:
        from aiohttp import web

        ready = threading.Event()

        def run() -> None:
            self._loop = asyncio.new_event_loop()
            asyncio.set_event_loop(self._loop)
            self._runner = web.AppRunner(self.app())
            self._loop.run_until_complete(self._runner.setup())
            site = web.TCPSite(self._runner, "127.0.0.1", 0)
            self._loop.run_until_complete(site.start())
            port = site._server.sockets[0].getsockname()[1]  # type: ignore[union-attr]
            self.url = f"http://127.0.0.1:{port}"
            ready.set()
            self._loop.run_forever()

        self._thread = threading.Thread(target=run, daemon=True)
        self._thread.start()
        ready.wait(30)
        return self

    def __exit__(self, *exc: object) -> None:
        loop = self._loop
        if loop is None:
            return
        asyncio.run_coroutine_threadsafe(self._runner.cleanup(), loop).result(10)
        loop.call_soon_threadsafe(loop.stop)
        if self._thread:
            self._thread.join(10)
