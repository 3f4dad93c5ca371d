"""The studio under load and abuse (aiohttp's test client on the real app, no browser): a document
of many materials builds payloads only for the shown ones, once per look; an edit a newer one
replaced is skipped; another site cannot make the server work (no request from another origin, no
environment prefiltered at an alpha no payload asked for); a tab closed during an AR composite
gets nothing written after its folder went."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import AsyncIterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from .conftest import require_studio

require_studio()

from aiohttp.test_utils import TestClient, TestServer  # noqa: E402

from cnlmc.api import lexicon_for  # noqa: E402
from cnlmc.studio.server import STUDIO, Studio, make_app  # noqa: E402
from cnlmc.studio.settings import studio_settings  # noqa: E402


@pytest.fixture
async def client(tmp_path: Path) -> AsyncIterator[TestClient[Any, Any]]:
    (tmp_path / "sessions").mkdir()
    studio = Studio(lexicon_for(), "127.0.0.1", 0, root=tmp_path / "sessions")
    async with TestClient(TestServer(make_app(studio))) as test_client:
        yield test_client


async def answer_to(socket: Any, seq: int) -> dict[str, Any]:
    while True:
        answer: dict[str, Any] = await socket.receive_json(timeout=300)
        if answer.get("seq") == seq:
            return answer


async def test_many_materials_build_payloads_for_the_shown_ones_once_per_look(client: TestClient[Any, Any]) -> None:
    pytest.importorskip("moderngl", reason="the view's payloads need the preview (extra: preview)")
    shown = studio_settings().limits.max_shown_materials
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    text = "".join(f"m{i}: oak\n" for i in range(shown + 4))
    await socket.send_json({"op": "edit", "seq": 1, "text": text})
    answer = await answer_to(socket, 1)
    assert answer["ok"] and len(answer["materials"]) == shown + 4
    assert [p["name"] for p in answer["payloads"]] == [f"m{i}" for i in range(shown)]
    assert answer["not_shown"] == 4
    files = {m["file"] for p in answer["payloads"] for m in p["maps"].values()}
    key = answer["payloads"][0]["key"]
    assert files and all(name.startswith(key + "-") for name in files)  # named by the look alone
    folder = Path(client.server.app[STUDIO].root) / hello["session"] / "view"
    assert {p.name for p in folder.iterdir()} == files  # one look: its maps baked once
    await socket.close()


async def test_an_edit_a_newer_one_replaced_is_skipped(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    for seq, text in enumerate(("glossy red plastic\n" * 40, "blue plastic", "green plastic"), start=1):
        await socket.send_json({"op": "edit", "seq": seq, "text": text})
    middle, last = await answer_to(socket, 2), await answer_to(socket, 3)
    assert middle["op"] == "skipped"
    assert last["op"] == "analysis" and last["ok"] and last["materials"][0]["name"]
    await socket.close()


async def test_another_site_cannot_make_the_server_work(client: TestClient[Any, Any]) -> None:
    for path in ("/", "/static/app.js", "/view-data/shader/tonemap.frag"):
        assert (await client.get(path, headers={"Sec-Fetch-Site": "cross-site"})).status == 403, path
        assert (await client.get(path, headers={"Origin": "http://evil.example"})).status == 403, path
    assert (await client.get("/static/app.js", headers={"Sec-Fetch-Site": "same-origin"})).status == 200
    # an <img> of an environment at an alpha no payload asked for: refused before any GL work
    assert (await client.get("/view-data/env/studio@0.1234")).status == 404


async def test_an_alpha_a_payload_asked_for_is_built(client: TestClient[Any, Any]) -> None:
    pytest.importorskip("moderngl", reason="the view's payloads need the preview (extra: preview)")
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    await socket.send_json({"op": "edit", "seq": 1, "text": "blue plastic"})
    (alpha,) = (await answer_to(socket, 1))["payloads"][0]["prefilter"].values()
    found = await client.get(f"/view-data/env/studio@{alpha}")
    assert found.status == 200 and (await found.read())[:4] == b"CNLV"
    await socket.close()
    await asyncio.sleep(0.2)
    assert (await client.get(f"/view-data/env/studio@{alpha}")).status == 404  # no open session asks


async def test_a_tab_closed_during_an_ar_composite_gets_nothing_written(client: TestClient[Any, Any]) -> None:
    pytest.importorskip("cv2", reason="marker AR needs OpenCV (extra: ar)")
    import cv2

    studio: Studio = client.server.app[STUDIO]
    loop = asyncio.get_running_loop()
    loop.set_default_executor(ThreadPoolExecutor(max_workers=1))
    release = threading.Event()
    busy = loop.run_in_executor(None, release.wait)  # the composite waits behind it
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    folder = studio.root / hello["session"]
    ok, photo = cv2.imencode(".png", np.full((120, 160, 3), 200, np.uint8))
    upload = asyncio.ensure_future(
        client.post(f"/ar-photo/{hello['session']}", data=photo.tobytes(), headers={"Content-Type": "image/png"})
    )
    await asyncio.sleep(0.5)
    await socket.close()  # the tab closes while the composite waits
    while hello["session"] in studio.sessions:
        await asyncio.sleep(0.05)
    release.set()
    await busy
    await (await upload).read()
    for _ in range(100):
        if not folder.exists():
            break
        await asyncio.sleep(0.05)
    await asyncio.sleep(0.3)
    assert not folder.exists(), sorted(folder.rglob("*"))
