"""The studio's web server (aiohttp): the page, its vendored assets, one WebSocket per tab for
the live editor, the session's files, the photo upload for marker AR.

Safety (docs/studio.md "Safety"): every response carries the Content-Security-Policy of
studio.toml; requests are size-limited; the Host header must name this server and a WebSocket's
Origin must be this server (no other site can drive it); off loopback every request needs the
random token; the only files served are the package's static assets and a session's own folder;
an error is a message in the page, never a traceback."""

from __future__ import annotations

import asyncio
import contextlib
import logging
import secrets
import tempfile
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

from aiohttp import web
from aiohttp.typedefs import Middleware

from ..lexicon import Lexicon
from .ar import ARFailed, MarkerComposer
from .exports import ExportFailed
from .network import is_loopback
from .payloads import ViewData
from .protocol import Dispatcher
from .session import StudioSession
from .settings import Settings, studio_settings
from .speech import StudioEars

Handler = Callable[[web.Request], Awaitable[web.StreamResponse]]
TOKEN_COOKIE = "cnlmc_studio"
log = logging.getLogger("cnlmc.studio")


@dataclass
class Studio:
    """What the server owns: settings, the lexicon, the sessions and their root folder."""

    lexicon: Lexicon
    host: str
    port: int
    initial_text: str = ""
    settings: Settings = field(default_factory=studio_settings)
    token: str | None = None
    sessions: dict[str, StudioSession] = field(default_factory=dict)
    view: ViewData = field(default_factory=ViewData)
    composer: MarkerComposer = field(default_factory=MarkerComposer)
    root: Path = field(default_factory=lambda: Path(tempfile.mkdtemp(prefix="cnlmc-studio-")))
    lexicon_folders: tuple[str, ...] = ()  # the user's lexicon folders (their speech pronunciations)
    voice: Any = None  # an enrolled speaker's voice (cnlmc.speech.voice.Voice) for the Speak button
    ears: StudioEars = field(init=False)

    def __post_init__(self) -> None:
        self.ears = StudioEars(self.lexicon, self.lexicon_folders, self.voice)
        if self.token is None and not is_loopback(self.host):
            self.token = secrets.token_urlsafe(16)

    def open_session(self) -> StudioSession | None:
        if len(self.sessions) >= self.settings.limits.max_sessions:
            return None
        session = StudioSession(self.root, self.lexicon, self.settings, self.view)
        self.sessions[session.id] = session
        return session

    def forget_session(self, session: StudioSession) -> None:
        """The tab closed: no more work for it (its folder goes with session.close, off the loop)."""
        self.sessions.pop(session.id, None)
        session.stop()

    def allowed_alphas(self) -> set[float]:
        """The alphas the open sessions' payloads prefilter their environment at."""
        return {alpha for session in self.sessions.values() for alpha in session.payloads.alphas()}

    def close(self) -> None:
        for session in list(self.sessions.values()):
            self.forget_session(session)
            session.close()
        self.view.close()
        with contextlib.suppress(OSError):
            self.root.rmdir()


STUDIO = web.AppKey("studio", Studio)


def static_folder() -> Path:
    return Path(str(resources.files("cnlmc.studio").joinpath("static")))


# ---------------------------------------------------------------- middlewares


def security_middleware(studio: Studio) -> Middleware:
    @web.middleware
    async def guard(request: web.Request, handler: Handler) -> web.StreamResponse:
        refusal = refuse(studio, request)
        if refusal is not None:
            return web.Response(status=refusal[0], text=refusal[1])
        try:
            response = await handler(request)
        except web.HTTPException as exc:
            response = web.Response(status=exc.status, text=exc.reason)
        except Exception as exc:  # the last line of defence: a message, never a traceback
            log.error("studio: %s: %s", type(exc).__name__, exc)
            response = web.Response(status=500, text="the studio could not answer this request")
        headers = response.headers
        headers["Content-Security-Policy"] = studio.settings.content_security_policy
        headers["X-Content-Type-Options"] = "nosniff"
        headers["Referrer-Policy"] = "no-referrer"
        headers["Cross-Origin-Opener-Policy"] = "same-origin"
        headers.setdefault("Cache-Control", "no-store")
        return response

    return guard


#: Sec-Fetch-Site values of a request the studio's own page (or a typed address) makes
OWN_FETCH_SITES = ("same-origin", "none")


def refuse(studio: Studio, request: web.Request) -> tuple[int, str] | None:
    """Why a request is refused (status, text), or None. A Host that is not this server's is a
    DNS-rebinding page; a request another page made (its Origin, or the browser's Sec-Fetch-Site)
    is another site using the studio: refused on every route (an <img> of /view-data/... would
    make the server work for it)."""
    host = request.host.rsplit(":", 1)[0].strip("[]")
    if is_loopback(studio.host) and not is_loopback(host):
        return 421, "this studio answers only on localhost"
    origin = request.headers.get("Origin")
    if origin is not None and origin != f"http://{request.host}":
        return 403, "a request from another site"
    site = request.headers.get("Sec-Fetch-Site")
    if site is not None and site not in OWN_FETCH_SITES:
        return 403, "a request from another site"
    if studio.token is not None:
        given = request.query.get("token") or request.cookies.get(TOKEN_COOKIE)
        if given is None or not secrets.compare_digest(given, studio.token):
            return 403, "open the address the studio printed (it carries the access token)"
    return None


# ---------------------------------------------------------------- routes


async def index(request: web.Request) -> web.StreamResponse:
    studio: Studio = request.app[STUDIO]
    response = web.FileResponse(static_folder() / "index.html")
    if studio.token is not None:
        response.set_cookie(TOKEN_COOKIE, studio.token, httponly=True, samesite="Strict")
    return response


async def view_data(request: web.Request) -> web.StreamResponse:
    """A named asset, built on the view's own thread; an environment prefiltered at an alpha only
    when an open session's payload asked for that alpha (each new one is seconds of GPU work)."""
    studio: Studio = request.app[STUDIO]
    name = request.match_info["name"]
    _, at, alpha = name.partition("@")
    if at and _number(alpha) not in studio.allowed_alphas():
        raise web.HTTPNotFound(reason="no such view data")
    found = await studio.view.static_asset(name)
    if found is None:
        raise web.HTTPNotFound(reason="no such view data")
    body, content_type = found
    return web.Response(body=body, headers={"Content-Type": content_type, "Cache-Control": "max-age=3600"})


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def session_file(studio: Studio, session_id: str, relative: str) -> Path:
    """A file inside the session's folder (no '..', no link out of it), or HTTPNotFound."""
    session = studio.sessions.get(session_id)
    if session is None:
        raise web.HTTPNotFound(reason="no such session")
    folder = session.folder.resolve()
    path = (folder / relative).resolve()
    if not path.is_relative_to(folder) or not path.is_file():
        raise web.HTTPNotFound(reason="no such file")
    return path


async def files(request: web.Request) -> web.StreamResponse:
    studio: Studio = request.app[STUDIO]
    path = session_file(studio, request.match_info["session"], request.match_info["path"])
    headers = {"Content-Disposition": f'attachment; filename="{path.name}"'} if "download" in request.query else {}
    return web.FileResponse(path, headers=headers)


async def ar_photo(request: web.Request) -> web.StreamResponse:
    studio: Studio = request.app[STUDIO]
    session = studio.sessions.get(request.match_info["session"])
    if session is None:
        raise web.HTTPNotFound(reason="no such session")
    photo = await request.read()
    loop = asyncio.get_running_loop()
    try:
        made = await loop.run_in_executor(None, session.composite, studio.composer, photo, request.content_type)
    except ARFailed as exc:
        return web.json_response({"error": str(exc)})
    return web.json_response({"url": f"/files/{session.id}/{made}"})


async def websocket(request: web.Request) -> web.StreamResponse:
    studio: Studio = request.app[STUDIO]
    socket = web.WebSocketResponse(max_msg_size=studio.settings.limits.max_message_bytes, heartbeat=30)
    await socket.prepare(request)
    session = studio.open_session()
    if session is None:
        await socket.send_json({"op": "error", "message": "too many studio tabs are open: close one"})
        await socket.close()
        return socket
    dispatcher = Dispatcher(session, socket, studio.initial_text, studio.ears)
    try:
        await dispatcher.hello([{"key": k.key, "label": k.label} for k in studio.settings.exports])
        await dispatcher.serve()
    finally:
        dispatcher.stop()
        studio.forget_session(session)
        # waits for the work writing into the folder now (an export, an AR composite): off the loop,
        # shielded (aiohttp cancels the handler of a dropped connection; the folder must still go)
        await asyncio.shield(asyncio.get_running_loop().run_in_executor(None, session.close))
    return socket


def make_app(studio: Studio) -> web.Application:
    app = web.Application(
        middlewares=[security_middleware(studio)], client_max_size=studio.settings.limits.max_upload_bytes
    )
    app[STUDIO] = studio
    app.router.add_get("/", index)
    app.router.add_get("/ws", websocket)
    app.router.add_get("/view-data/{name:.+}", view_data)
    app.router.add_get("/files/{session}/{path:.+}", files)
    app.router.add_post("/ar-photo/{session}", ar_photo)
    app.router.add_static("/static", static_folder(), follow_symlinks=False)
    app.on_cleanup.append(_cleanup)
    return app


async def _cleanup(app: web.Application) -> None:
    app[STUDIO].close()


__all__ = ["ExportFailed", "Studio", "make_app"]
