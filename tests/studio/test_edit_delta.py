"""What an edit sends (aiohttp's test client on the real app, no browser): a payload's shader and
tables go to a page once, then by key alone (an edit that keeps the shader sends its uniforms); an
edit with `fresh` gets every part again; the answer says how long the server took."""

from __future__ import annotations

import json
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import pytest

from .conftest import require_studio

require_studio()

from aiohttp.test_utils import TestClient, TestServer  # noqa: E402

from cnlmc.api import lexicon_for  # noqa: E402
from cnlmc.studio.server import Studio, make_app  # noqa: E402


@pytest.fixture
async def client(tmp_path: Path) -> AsyncIterator[TestClient[Any, Any]]:
    pytest.importorskip("moderngl", reason="the view's payloads need the preview (extra: preview)")
    (tmp_path / "sessions").mkdir()
    studio = Studio(lexicon_for(), "127.0.0.1", 0, root=tmp_path / "sessions")
    async with TestClient(TestServer(make_app(studio))) as test_client:
        yield test_client


async def edit(socket: Any, seq: int, text: str, **more: Any) -> tuple[dict[str, Any], int]:
    """The analysis of `text` and its length as sent (characters of JSON)."""
    await socket.send_json({"op": "edit", "seq": seq, "text": text, **more})
    while True:
        raw = await socket.receive_str(timeout=300)
        answer: dict[str, Any] = json.loads(raw)
        if answer.get("seq") == seq:
            assert answer["op"] == "analysis" and answer["ok"], answer
            return answer, len(raw)


async def test_an_edit_that_keeps_the_shader_sends_its_uniforms(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    assert hello["parts_kept"] > 0
    red, red_size = await edit(socket, 1, "red plastic")
    blue, blue_size = await edit(socket, 2, "blue plastic")
    first, second = red["payloads"][0], blue["payloads"][0]
    assert first["fragment"].startswith("#version 300 es") and all("data" in t for t in first["tables"].values())
    assert second["shader"] == first["shader"] and "fragment" not in second and "vertex" not in second
    assert {n: t["key"] for n, t in second["tables"].items()} == {n: t["key"] for n, t in first["tables"].items()}
    assert not any("data" in t for t in second["tables"].values())
    colour = {u["name"]: u["value"] for u in second["uniforms"]}["cnlm_base_color"]
    assert colour[2] > colour[0]  # blue: the uniforms are what changed
    assert blue_size < red_size / 3, (blue_size, red_size)
    glass, _ = await edit(socket, 3, "clear glass")  # another shader: sent whole
    assert glass["payloads"][0]["fragment"] and glass["payloads"][0]["shader"] != first["shader"]
    again, _ = await edit(socket, 4, "green plastic", fresh=True)  # a page that lost its parts
    assert again["payloads"][0]["fragment"] == first["fragment"]
    assert all("data" in t for t in again["payloads"][0]["tables"].values())
    timing = again["timing"]
    assert 0 <= timing["analysis_ms"] + timing["view_ms"] <= timing["server_ms"]
    await socket.close()


async def test_the_history_in_an_answer_has_no_pictures(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    for seq, shade in enumerate(("red", "blue", "green"), start=1):
        answer, _ = await edit(socket, seq, f"{shade} plastic")
    assert answer["history"]["steps"] == [
        {"id": 1, "label": "red plastic"},
        {"id": 2, "label": "blue plastic"},
        {"id": 3, "label": "green plastic"},
    ]
    await socket.close()


def test_sent_parts_count_as_the_page_holds_them() -> None:
    """The server's side of static/parts.js (test_page.py runs the same sequence in the page)."""
    from cnlmc.studio.payloads import SentParts

    sent = SentParts(2)

    def payload(table: str) -> dict[str, Any]:
        return {"shader": "s", "vertex": "v", "fragment": "f", "tables": {"t": {"key": table, "data": table.upper()}}}

    assert sent.delta(payload("a"))["tables"]["t"]["data"] == "A"
    assert sent.delta(payload("a")) == {"shader": "s", "tables": {"t": {"key": "a"}}}
    sent.delta(payload("b"))  # s and b held: a went, the least recently named of three
    assert sent.delta(payload("a"))["tables"]["t"]["data"] == "A" and "fragment" not in sent.delta(payload("a"))
    sent.forget()
    assert sent.delta(payload("a"))["fragment"] == "f"
