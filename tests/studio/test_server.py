"""The studio's server without a browser (aiohttp's test client on the real app): the safety rules
of docs/studio.md "Safety", the WebSocket requests, exports through the same targets and with the
same warnings as the CLI, the marker AR upload, and `cnlmc serve` on the command line."""

from __future__ import annotations

import asyncio
import json
import re
import shutil
import subprocess
import zipfile
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ..helpers import run_cnlmc
from .conftest import require_studio, start_server

require_studio()

from aiohttp import WSServerHandshakeError  # noqa: E402
from aiohttp.test_utils import TestClient, TestServer  # noqa: E402

from cnlmc.api import lexicon_for  # noqa: E402
from cnlmc.studio.server import Studio, make_app  # noqa: E402
from cnlmc.studio.settings import studio_settings  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]

PHRASE = "lightly brushed, blue anodized aluminum"


@pytest.fixture
async def client(tmp_path: Path) -> AsyncIterator[TestClient[Any, Any]]:
    studio = Studio(lexicon_for(), "127.0.0.1", 0, root=tmp_path / "sessions")
    (tmp_path / "sessions").mkdir()
    async with TestClient(TestServer(make_app(studio))) as test_client:
        yield test_client


async def ask(socket: Any, op: str, **fields: Any) -> dict[str, Any]:
    """Send a request and return its answer (skipping unasked messages such as chips)."""
    await socket.send_json({"op": op, "seq": 7, **fields})
    while True:
        answer: dict[str, Any] = await socket.receive_json(timeout=300)
        if answer.get("seq") == 7:
            return answer


async def test_every_response_carries_the_content_security_policy(client: TestClient[Any, Any]) -> None:
    for path in ("/", "/static/app.js", "/static/vendor/codemirror.js", "/no/such/page"):
        response = await client.get(path)
        policy = response.headers["Content-Security-Policy"]
        assert "script-src 'self' 'wasm-unsafe-eval'" in policy and "default-src 'self'" in policy, path
        assert "unsafe-eval'" not in policy.replace("'wasm-unsafe-eval'", "")
        assert response.headers["X-Content-Type-Options"] == "nosniff"
    assert (await client.get("/")).status == 200


async def test_the_page_loads_nothing_from_another_origin() -> None:
    static = Path(__file__).resolve().parents[2] / "compiler" / "studio" / "static"
    page = (static / "index.html").read_text("utf-8")
    assert not re.search(r"""(src|href)=["']?(https?:)?//""", page)
    for script in [*static.glob("*.js"), *static.glob("view/*.js")]:
        assert not re.search(r"""from\s+["'](https?:)?//|import\(["'](https?:)?//""", script.read_text("utf-8")), script
    assert (static / "vendor" / "THIRD_PARTY.txt").is_file()
    assert len(list((static / "vendor" / "licenses").glob("*.LICENSE.txt"))) >= 19


async def test_no_file_outside_the_static_folder_or_a_session_folder(client: TestClient[Any, Any]) -> None:
    for path in (
        "/static/../studio.toml",
        "/static/%2e%2e/studio.toml",
        "/files/nosession/x",
        "/files/../../etc/passwd",
    ):
        assert (await client.get(path)).status == 404, path
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    session = hello["session"]
    for path in (f"/files/{session}/../../../etc/passwd", f"/files/{session}/%2e%2e/%2e%2e/etc/hostname"):
        assert (await client.get(path)).status == 404, path
    await socket.close()


async def test_a_page_from_another_host_or_origin_is_refused(client: TestClient[Any, Any]) -> None:
    response = await client.get("/", headers={"Host": "evil.example:80"})
    assert response.status == 421  # DNS rebinding: another name pointing at 127.0.0.1
    for origin in ("http://evil.example", "null"):  # another site; a local file or a sandboxed frame
        with pytest.raises(WSServerHandshakeError) as refused:
            await client.ws_connect("/ws", headers={"Origin": origin})
        assert refused.value.status == 403


async def test_off_loopback_every_request_needs_the_token(tmp_path: Path) -> None:
    studio = Studio(lexicon_for(), "0.0.0.0", 0, root=tmp_path)
    assert studio.token is not None and len(studio.token) >= 20
    async with TestClient(TestServer(make_app(studio))) as lan:
        assert (await lan.get("/")).status == 403
        assert (await lan.get("/static/app.js")).status == 403
        assert (await lan.get("/?token=wrong")).status == 403
        opened = await lan.get(f"/?token={studio.token}")
        assert opened.status == 200
        assert (await lan.get("/static/app.js")).status == 200  # the cookie the page got carries it


async def test_edits_are_analysed_by_the_language_servers_functions(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    answer = await ask(socket, "edit", text="glossy bleu plastic")
    assert answer["op"] == "analysis" and not answer["ok"]
    (diagnostic,) = answer["diagnostics"]
    assert diagnostic["range"]["start"] == {"line": 0, "character": 7}
    assert diagnostic["range"]["end"] == {"line": 0, "character": 11}
    assert diagnostic["fixes"][0]["title"] == "Replace 'bleu' with 'blue'"
    answer = await ask(socket, "edit", text=PHRASE)
    assert answer["ok"] and answer["recorded"] and answer["materials"][0]["hex"] == "#0343df"
    assert answer["history"]["at"] == 0
    hover = await ask(socket, "hover", text=PHRASE, line=0, character=2)
    assert "adverb" in hover["markdown"]
    await socket.close()


async def test_completion_sends_the_best_items_up_to_the_limit(client: TestClient[Any, Any]) -> None:
    """After a space every word of the slot fits: the list is cut at the settings' limit, best first,
    and says so (the page asks again as letters are typed); after a few letters it is whole."""
    limit = studio_settings().limits.max_completion_items
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    cut = await ask(socket, "complete", text="slightly ", line=0, character=9)
    assert len(cut["items"]) == limit and not cut["complete"]
    assert [i["sort"] for i in cut["items"]] == sorted(i["sort"] for i in cut["items"])
    whole = await ask(socket, "complete", text="blue anodized al", line=0, character=16)
    assert whole["complete"] and 0 < len(whole["items"]) < limit
    assert any(i["label"].startswith("alumin") for i in whole["items"])
    await socket.close()


async def test_errors_are_messages_never_tracebacks(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    limit = studio_settings().limits.max_document_bytes
    too_long = await ask(socket, "edit", text="blue plastic\n" * (limit // 13 + 1))
    assert too_long["op"] == "error" and "KiB" in too_long["message"]
    for answer in (
        await ask(socket, "nonsense"),
        await ask(socket, "edit"),
        await ask(socket, "refine", words="darker"),  # nothing above to darken
        await ask(socket, "undo"),
        await ask(socket, "export", key="glb", text="bleu plastik"),
        await ask(socket, "export", key="no-such-export", text=PHRASE),
    ):
        assert answer["op"] == "error", answer
        assert "Traceback" not in answer["message"] and 'File "' not in answer["message"]
    await socket.close()


async def test_refine_undo_redo(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    first = await ask(socket, "edit", text=PHRASE)
    darker = await ask(socket, "refine", words="darker")
    assert darker["text"] == PHRASE + "\ndarker"
    assert any("base_color" in row for row in darker["materials"][0]["changes"])  # what changed
    undone = await ask(socket, "undo")
    assert undone["text"] == PHRASE and undone["materials"][0]["hex"] == first["materials"][0]["hex"]
    redone = await ask(socket, "redo")
    assert redone["text"] == PHRASE + "\ndarker" and redone["history"]["at"] == 1
    await socket.close()


async def test_describing_words_said_as_a_refinement_change_the_material(client: TestClient[Any, Any]) -> None:
    socket = await client.ws_connect("/ws")
    await socket.receive_json()
    first = await ask(socket, "edit", text=PHRASE)
    purple = await ask(socket, "refine", words="purple")  # alone it would imply a material: purple paint
    assert purple["text"] == PHRASE + "\nmake it purple"
    assert len(purple["materials"]) == len(first["materials"]) == 1
    assert purple["materials"][0]["hex"] != first["materials"][0]["hex"]
    await socket.close()


async def test_exports_are_the_clis_with_its_warnings(client: TestClient[Any, Any], tmp_path: Path) -> None:
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    assert [e["key"] for e in hello["exports"]] == [k.key for k in studio_settings().exports]
    glb = await ask(socket, "export", key="glb", text=PHRASE)
    body = await (await client.get(glb["url"])).read()
    assert body[:4] == b"glTF"
    source = tmp_path / "phrase.cnl"
    source.write_text(PHRASE + "\n", "utf-8")
    cli = run_cnlmc("compile", str(source), "-t", "gltf", "--option", "format=glb", "-o", str(tmp_path / "cli.glb"))
    said = [line for line in cli.stderr.splitlines() if line.startswith("warning[")]
    assert said and glb["notes"] == said
    zipped = await ask(socket, "export", key="materialx", text=PHRASE)
    archive = zipfile.ZipFile(__import__("io").BytesIO(await (await client.get(zipped["url"])).read()))
    assert "materials.mtlx" in archive.namelist()
    assert any(name.endswith("_normal.png") for name in archive.namelist())  # the brushed streaks' map
    await socket.close()


async def test_a_sessions_files_stay_in_its_folder_and_go_with_it(client: TestClient[Any, Any], tmp_path: Path) -> None:
    root = tmp_path / "sessions"
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    await ask(socket, "export", key="usd", text=PHRASE)
    files = [p for p in root.rglob("*") if p.is_file()]
    assert files and all(p.is_relative_to(root / hello["session"]) for p in files)
    await socket.close()
    for _ in range(100):
        if not (root / hello["session"]).exists():
            break
        await __import__("asyncio").sleep(0.05)
    assert not (root / hello["session"]).exists()


async def test_a_photo_without_the_marker_is_said_in_the_page(client: TestClient[Any, Any]) -> None:
    pytest.importorskip("cv2", reason="marker AR needs OpenCV (extra: ar)")
    import cv2

    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    await ask(socket, "edit", text=PHRASE)
    ok, photo = cv2.imencode(".png", np.full((120, 160, 3), 200, np.uint8))
    response = await client.post(
        f"/ar-photo/{hello['session']}", data=photo.tobytes(), headers={"Content-Type": "image/png"}
    )
    answer = json.loads(await response.text())
    assert "marker" in answer["error"] and "Traceback" not in answer["error"]
    refused = await client.post(f"/ar-photo/{hello['session']}", data=b"GIF89a", headers={"Content-Type": "image/gif"})
    assert "JPEG or PNG" in json.loads(await refused.text())["error"]
    too_big = await client.post(
        f"/ar-photo/{hello['session']}",
        data=b"\0" * (studio_settings().limits.max_upload_bytes + 1),
        headers={"Content-Type": "image/png"},
    )
    assert too_big.status == 413
    await socket.close()


@pytest.mark.slow  # renders the object offscreen (llvmpipe): ~13 s on this machine
async def test_a_photo_with_the_marker_gets_the_material_composited(client: TestClient[Any, Any]) -> None:
    pytest.importorskip("cv2", reason="marker AR needs OpenCV (extra: ar)")
    import cv2

    from cnlmc.backends.ar.synthetic import synthetic_photo

    photo, _K, corners = synthetic_photo(np.array([2.2, 0.3, -0.2]), np.array([0.0, 0.02, 0.5]), 320, 240)
    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    await ask(socket, "edit", text=PHRASE)
    ok, encoded = cv2.imencode(".png", photo)
    response = await client.post(
        f"/ar-photo/{hello['session']}", data=encoded.tobytes(), headers={"Content-Type": "image/png"}
    )
    answer = json.loads(await response.text())
    assert "error" not in answer, answer
    made = cv2.imdecode(np.frombuffer(await (await client.get(answer["url"])).read(), np.uint8), cv2.IMREAD_COLOR)
    assert made.shape == photo.shape
    changed = np.abs(made.astype(int) - photo.astype(int)).sum(axis=2) > 30
    x, y = corners.mean(axis=0).astype(int)  # the object stands on the marker's centre
    assert changed[y - 30 : y + 5, x - 20 : x + 20].mean() > 0.3
    assert changed.mean() < 0.5  # the rest of the photo is the photo
    blue = made[changed]  # BGR: what was drawn is the blue anodized metal (or its shadow)
    assert np.median(blue[:, 0]) > np.median(blue[:, 2])
    await socket.close()


def test_serve_on_the_lan_prints_the_address_with_its_token_and_a_qr_code() -> None:
    server = start_server("--host", "0.0.0.0")
    try:
        assert re.fullmatch(r"http://[\d.]+:\d+/\?token=[\w-]{20,}", server.url), server.url
    finally:
        said = "".join(server.said) + server.stop()
    assert "scan this code" in said
    assert sum(line.count("█") + line.count("▀") + line.count("▄") for line in said.splitlines()) > 200  # the QR


def test_serve_starts_from_a_file_and_never_writes_it(tmp_path: Path) -> None:
    import aiohttp

    source = tmp_path / "wood.cnl"
    source.write_text("walnut wood\n", "utf-8")
    before = source.stat()
    server = start_server(str(source))

    async def hello() -> dict[str, Any]:
        async with aiohttp.ClientSession() as http, http.ws_connect(server.url + "ws") as socket:
            said: dict[str, Any] = await socket.receive_json(timeout=60)
            await socket.send_json({"op": "export", "seq": 1, "key": "glb", "text": said["text"]})
            await socket.receive_json(timeout=300)
            return said

    try:
        said = asyncio.run(hello())
    finally:
        server.stop()
    assert said["text"] == "walnut wood\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wood.cnl"]
    assert source.stat().st_mtime_ns == before.st_mtime_ns


def test_serve_refuses_a_bad_port_as_a_usage_error() -> None:
    run = run_cnlmc("serve", "--port", "70000")
    assert run.returncode == 2 and "cnlmc: error: --port 70000" in run.stderr
    assert "Traceback" not in run.stderr


async def test_a_spoken_utterance_that_is_not_audio_or_silence_changes_nothing(client: TestClient[Any, Any]) -> None:
    """`hear`: audio that is not base64 16-bit PCM, or longer than the limit, is an error message;
    silence is 'heard no phrase' and leaves the document as it was (the spoken path: test_speech_page)."""
    import base64

    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    rate, seconds = hello["speech"]["rate"], hello["speech"]["max_seconds"]
    too_long = base64.b64encode(bytes(2 * rate * seconds + 2)).decode()
    for answer in (
        await ask(socket, "hear"),
        await ask(socket, "hear", pcm="not base64!"),
        await ask(socket, "hear", pcm=base64.b64encode(b"odd").decode()),
        await ask(socket, "hear", pcm=too_long),
    ):
        assert answer["op"] == "error" and "Traceback" not in answer["message"], answer
    pytest.importorskip("pocketsphinx", reason="speech input needs pocketsphinx (pip install 'cnlmc[speech]')")
    await ask(socket, "edit", text="white varnished oak")
    for pcm in (b"", bytes(2 * rate), bytes(2 * rate)):  # empty (Speak, Stop at once), then silence twice
        silence = await ask(socket, "hear", pcm=base64.b64encode(pcm).decode())
        assert silence["op"] == "heard" and not silence["applied"] and "no phrase" in silence["message"], silence
    undone = await ask(socket, "undo")  # the document is still the typed one: one step, nothing to undo
    assert undone["op"] == "error" and "nothing to undo" in undone["message"]
    await socket.close()


async def test_an_utterance_streamed_in_chunks_is_heard_as_one(client: TestClient[Any, Any]) -> None:
    """`hear_chunk` keeps each part of the utterance while it is recorded; `hear` adds the rest and
    hears the whole (silence here: 'no phrase'); the length limit counts the chunks, and an utterance
    refused for its length leaves no chunks behind for the next one."""
    import base64

    socket = await client.ws_connect("/ws")
    hello = await socket.receive_json()
    rate, seconds = hello["speech"]["rate"], hello["speech"]["max_seconds"]
    half = base64.b64encode(bytes(rate)).decode()  # half a second of silence
    first = await ask(socket, "hear_chunk", pcm=half)
    second = await ask(socket, "hear_chunk", pcm=half)
    assert (first["op"], first["seconds"], second["seconds"]) == ("hearing", 0.5, 1.0)
    too_much = base64.b64encode(bytes(2 * rate * seconds - 2 * rate + 4)).decode()  # 2 samples past the limit
    refused = await ask(socket, "hear_chunk", pcm=too_much)
    assert refused["op"] == "error" and "at most" in refused["message"], refused
    restarted = await ask(socket, "hear_chunk", pcm=half)
    assert restarted["seconds"] == 0.5  # the refused utterance's chunks are gone
    pytest.importorskip("pocketsphinx", reason="speech input needs pocketsphinx (pip install 'cnlmc[speech]')")
    heard = await ask(socket, "hear", pcm=half)
    assert heard["op"] == "heard" and "no phrase" in heard["message"], heard
    again = await ask(socket, "hear_chunk", pcm=half)
    assert again["seconds"] == 0.5  # `hear` ended the utterance: the next one starts empty
    await socket.close()


def test_the_pages_streamed_resampling_joins_as_one_utterance() -> None:
    """speech.js's Resampler fed 4096-sample blocks (as the page's audio processor gives them) gives
    the samples resampling the whole recording gives, at 44.1 and 48 kHz."""
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is missing: run scripts/setup.sh")
    module = (ROOT / "compiler" / "studio" / "static" / "speech.js").as_uri()
    script = f"""
import {{ Resampler, resample }} from {json.dumps(module)};
const out = [];
for (const rate of [44100, 48000]) {{
  const all = new Float32Array(rate * 2);
  for (let i = 0; i < all.length; i++) all[i] = Math.sin(2 * Math.PI * 300 * i / rate);
  const whole = resample(all, rate, 16000);
  const r = new Resampler(rate, 16000);
  const parts = [];
  for (let i = 0; i < all.length; i += 4096) parts.push(...r.next(all.subarray(i, i + 4096)));
  let err = 0;
  for (let i = 0; i < Math.min(whole.length, parts.length); i++) err = Math.max(err, Math.abs(parts[i] - whole[i]));
  out.push([whole.length, parts.length, err]);
}}
console.log(JSON.stringify(out));
"""
    run = subprocess.run(
        [node, "--input-type=module", "-e", script], capture_output=True, text=True, timeout=60, check=False
    )
    assert run.returncode == 0, run.stderr
    for whole, parts, err in json.loads(run.stdout):
        assert (parts, err) == (whole, 0.0)
