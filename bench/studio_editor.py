"""The studio's editor round trip: a keystroke's analysis (diagnostics, tokens, swatches, the
materials panel and the view's payloads) over the WebSocket, against the same analysis called in
the process (EditorEngine.features + the materials: the language server's functions without the
transport) as the peer. Each phrase is typed one character at a time, one `edit` per character.

    .venv/bin/python bench/studio_editor.py [--repeat 2]

Prints p50/p99 per phrase in ms and the ratio of the medians; the load average (a shared machine
inflates both). One untimed pass per phrase first: what is made once per content (the albedo
tables, baked maps) is not in the numbers."""

from __future__ import annotations

import argparse
import asyncio
import os
import statistics
import tempfile
import time
from pathlib import Path

from aiohttp.test_utils import TestClient, TestServer

from cnlmc.api import lexicon_for
from cnlmc.studio.payloads import ViewData
from cnlmc.studio.server import Studio, make_app
from cnlmc.studio.session import StudioSession
from cnlmc.studio.settings import studio_settings

PHRASES = {
    "untextured": "lightly brushed, blue anodized aluminum",
    "textured": "weathered walnut wood with a satin varnish",
    "glass": "frosted green glass",
}


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def prefixes(phrase: str) -> list[str]:
    return [phrase[: i + 1] for i in range(len(phrase))]


def in_process(phrase: str, repeat: int) -> list[float]:
    times = []
    for _ in range(repeat):
        session = StudioSession(Path(tempfile.mkdtemp()), lexicon_for(), studio_settings(), ViewData())
        for text in prefixes(phrase):
            start = time.perf_counter()
            session.edit(text)
            times.append(time.perf_counter() - start)
        session.close()
    return times


async def over_websocket(phrase: str, repeat: int) -> list[float]:
    times = []
    studio = Studio(lexicon_for(), "127.0.0.1", 0)
    async with TestClient(TestServer(make_app(studio))) as client:
        for _ in range(repeat):
            socket = await client.ws_connect("/ws")
            await socket.receive_json()
            for seq, text in enumerate(prefixes(phrase)):
                start = time.perf_counter()
                await socket.send_json({"op": "edit", "seq": seq, "text": text})
                while (await socket.receive_json()).get("seq") != seq:
                    pass
                times.append(time.perf_counter() - start)
            await socket.close()
    return times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.1f}; ms per keystroke (p50 / p99)")
    print(f"{'phrase':<11} {'websocket':>17} {'in process':>17} {'ratio p50':>9}")
    for name, phrase in PHRASES.items():
        in_process(phrase, 1)  # warm-up: what is made once per content (tables, baked maps) is made here
        peer = in_process(phrase, args.repeat)
        socket = asyncio.run(over_websocket(phrase, args.repeat))
        row = [statistics.median(socket), percentile(socket, 0.99), statistics.median(peer), percentile(peer, 0.99)]
        ms = [f"{1000 * v:7.1f}" for v in row]
        print(f"{name:<11} {ms[0]} / {ms[1]} {ms[2]} / {ms[3]} {row[0] / row[2]:9.2f}")


if __name__ == "__main__":
    main()
