"""Memory the language server keeps after documents close (#13: opening and closing 40 documents
of unknown words left 2.83 GB). Goal: after opening and closing 100 large documents, the
server's RSS is back within 50 MB of where it started.

    .venv/bin/python bench/lsp_memory.py [--documents 100] [--lines 1000] [--open-at-once 10]

Talks to `cnlmc lsp` over stdio with raw JSON-RPC frames; RSS is the server process's VmRSS
from /proc/PID/status (Linux). "start" is after initialize and one small document like the others
(and a long unknown word: the suggestion index is made once per lexicon) opened and closed (what
the first analysis loads is not retention); "peak" is the highest RSS sampled
while documents are open; "after close" is once every document is closed (the server clears a
closed document's problems after it has dropped what it kept for it).
"""

from __future__ import annotations

import argparse
import json
import random
import string
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

SERVER = [sys.executable, "-m", "cnlmc", "lsp"]
GOAL_MB = 50


def rss_mb(pid: int) -> float:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    raise RuntimeError("no VmRSS in /proc/PID/status (Linux only)")


class Server:
    def __init__(self) -> None:
        self.proc = subprocess.Popen(SERVER, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
        self.messages: list[dict[str, Any]] = []
        self.arrived = threading.Condition()
        self.next_id = 0
        threading.Thread(target=self._read, daemon=True).start()

    def send(self, message: dict[str, Any]) -> None:
        body = json.dumps(message).encode()
        assert self.proc.stdin is not None
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()

    def request(self, method: str, params: Any) -> dict[str, Any]:
        self.next_id += 1
        msg_id = self.next_id
        self.send({"jsonrpc": "2.0", "id": msg_id, "method": method, "params": params})
        return self.wait(lambda m: m.get("id") == msg_id and "method" not in m)

    def notify(self, method: str, params: Any) -> None:
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def wait(self, wanted: Any, timeout: float = 600) -> dict[str, Any]:
        deadline = time.monotonic() + timeout
        with self.arrived:
            while True:
                for i, message in enumerate(self.messages):
                    if wanted(message):
                        return self.messages.pop(i)
                if not self.arrived.wait(max(0.0, deadline - time.monotonic())):
                    raise TimeoutError("the server did not answer")

    def _read(self) -> None:
        out = self.proc.stdout
        assert out is not None
        while True:
            length = 0
            while (line := out.readline()) not in (b"\r\n", b""):
                if line.lower().startswith(b"content-length:"):
                    length = int(line.split(b":")[1])
            if not line:
                return
            message = json.loads(out.read(length))
            with self.arrived:
                self.messages.append(message)
                self.arrived.notify_all()


def unknown_words_document(seed: int, lines: int) -> str:
    """Lines of made-up words: every one unknown, so every one is tagged, suggested and reported."""
    rng = random.Random(seed)

    def word() -> str:
        return "".join(rng.choice(string.ascii_lowercase) for _ in range(rng.randint(5, 9)))

    return "\n".join(f"{word()} {word()} {word()} {word()} {word()}" for _ in range(lines))


def open_and_wait(server: Server, uri: str, text: str) -> int:
    server.notify(
        "textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "cnl", "version": 1, "text": text}}
    )
    published = server.wait(
        lambda m: (
            m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"] == uri
            and m["params"].get("version") == 1
        )
    )
    return len(published["params"]["diagnostics"])


def close(server: Server, uri: str) -> None:
    """Close a document and wait until the server has dropped it (it clears the document's
    problems last, after giving the memory back)."""
    server.notify("textDocument/didClose", {"textDocument": {"uri": uri}})
    server.wait(
        lambda m: (
            m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"] == uri
            and not m["params"]["diagnostics"]
            and "version" not in m["params"]
        )
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--documents", type=int, default=100)
    parser.add_argument("--lines", type=int, default=1000, help="lines of 5 unknown words per document")
    parser.add_argument("--open-at-once", type=int, default=10)
    args = parser.parse_args()

    server = Server()
    pid = server.proc.pid
    server.request(
        "initialize",
        {"processId": None, "rootUri": None, "capabilities": {}, "initializationOptions": {"debounceMs": 0}},
    )
    server.notify("initialized", {})
    cold = rss_mb(pid)
    open_and_wait(server, "file:///warm-up.cnl", f"blu plastic\nzorblatwix steel\n{unknown_words_document(-1, 3)}")
    close(server, "file:///warm-up.cnl")
    start = rss_mb(pid)
    peak, chars, diagnostics = start, 0, 0
    t0 = time.perf_counter()
    for batch in range(0, args.documents, args.open_at_once):
        uris = []
        for n in range(batch, min(args.documents, batch + args.open_at_once)):
            uri, text = f"file:///unknown-{n}.cnl", unknown_words_document(n, args.lines)
            diagnostics += open_and_wait(server, uri, text)
            chars += len(text)
            uris.append(uri)
            peak = max(peak, rss_mb(pid))
        for uri in uris:
            close(server, uri)
        print(f"  {batch + len(uris):4d} documents opened and closed: RSS {rss_mb(pid):8.1f} MB", flush=True)
    after = rss_mb(pid)
    elapsed = time.perf_counter() - t0
    server.request("shutdown", None)
    server.notify("exit", None)
    server.proc.wait(30)

    print(
        f"{args.documents} documents of {args.lines} lines of unknown words "
        f"({chars / args.documents / 1e6:.2f} MB, {diagnostics // args.documents} diagnostics each), "
        f"{args.open_at_once} open at once, {elapsed:.0f} s"
    )
    print(f"RSS after initialize   {cold:8.1f} MB")
    print(f"RSS start (warmed up)  {start:8.1f} MB")
    print(f"RSS peak               {peak:8.1f} MB")
    print(f"RSS after close        {after:8.1f} MB")
    verdict = "within" if after - start <= GOAL_MB else "OVER"
    print(f"retained               {after - start:8.1f} MB ({verdict} the {GOAL_MB} MB goal)")


if __name__ == "__main__":
    main()
