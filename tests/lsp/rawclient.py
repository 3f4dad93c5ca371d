"""A raw JSON-RPC client for `cnlmc lsp`: writes any bytes, reads every frame the server sends,
and sees the process (exit status, stderr). For the tests a typed client cannot express."""

from __future__ import annotations

import itertools
import json
import queue
import subprocess
import tempfile
import threading
import time
from typing import Any

from .conftest import SERVER_COMMAND

TIMEOUT = 30.0


class RawServer:
    """One `cnlmc lsp` process; use as a context manager (it is killed at the end if still up)."""

    def __init__(self) -> None:
        self._stderr = tempfile.TemporaryFile()
        self.proc = subprocess.Popen(SERVER_COMMAND, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self._stderr)
        self._inbox: queue.Queue[dict[str, Any] | None] = queue.Queue()
        self.received: list[dict[str, Any]] = []
        self._ids = itertools.count(1)
        threading.Thread(target=self._read_frames, daemon=True).start()

    def __enter__(self) -> RawServer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------ sending

    def send_bytes(self, data: bytes) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message: Any) -> None:
        body = json.dumps(message).encode()
        self.send_bytes(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def request(self, method: str, params: Any = None, msg_id: int | str | None = None) -> int | str:
        msg_id = next(self._ids) if msg_id is None else msg_id
        message: dict[str, Any] = {"jsonrpc": "2.0", "id": msg_id, "method": method}
        if params is not None:
            message["params"] = params
        self.send(message)
        return msg_id

    def notify(self, method: str, params: Any = None) -> None:
        message: dict[str, Any] = {"jsonrpc": "2.0", "method": method}
        if params is not None:
            message["params"] = params
        self.send(message)

    def call(self, method: str, params: Any = None) -> dict[str, Any]:
        """Send a request and wait for its response (the whole response message)."""
        return self.response(self.request(method, params))

    def initialize(self, encoding: str = "utf-16", **options: Any) -> dict[str, Any]:
        capabilities = {"general": {"positionEncodings": [encoding]}}
        answer = self.call(
            "initialize",
            {"processId": None, "rootUri": None, "capabilities": capabilities, "initializationOptions": options},
        )
        self.notify("initialized", {})
        return answer

    def open(self, uri: str, text: str, version: int = 1) -> None:
        self.notify(
            "textDocument/didOpen",
            {"textDocument": {"uri": uri, "languageId": "cnl", "version": version, "text": text}},
        )

    def change(self, uri: str, version: int, *changes: dict[str, Any]) -> None:
        self.notify(
            "textDocument/didChange",
            {"textDocument": {"uri": uri, "version": version}, "contentChanges": list(changes)},
        )

    def shutdown_and_exit(self) -> int:
        self.call("shutdown")
        self.notify("exit")
        return self.wait()

    # ------------------------------------------------------------------ receiving

    def wait_for(self, wanted: Any, timeout: float = TIMEOUT) -> dict[str, Any]:
        """The first message (already received or arriving) for which wanted(message) is true."""
        for message in self.received:
            if wanted(message):
                return message
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError(f"no such message; stderr: {self.stderr()[-2000:]}")
            try:
                message = self._inbox.get(timeout=left)
            except queue.Empty:
                continue
            if message is None:
                raise EOFError(f"the server closed stdout; stderr: {self.stderr()[-2000:]}")
            self.received.append(message)
            if wanted(message):
                return message

    def response(self, msg_id: int | str, timeout: float = TIMEOUT) -> dict[str, Any]:
        return self.wait_for(lambda m: m.get("id") == msg_id and "method" not in m, timeout)

    def diagnostics(self, uri: str, version: int, timeout: float = TIMEOUT) -> list[dict[str, Any]]:
        message = self.wait_for(
            lambda m: (
                m.get("method") == "textDocument/publishDiagnostics"
                and m["params"]["uri"] == uri
                and m["params"].get("version") == version
            ),
            timeout,
        )
        diagnostics: list[dict[str, Any]] = message["params"]["diagnostics"]
        return diagnostics

    def shown_messages(self) -> list[str]:
        """The window/showMessage texts received so far (reads what has arrived)."""
        self._drain()
        return [m["params"]["message"] for m in self.received if m.get("method") == "window/showMessage"]

    def _drain(self) -> None:
        while True:
            try:
                message = self._inbox.get_nowait()
            except queue.Empty:
                return
            if message is not None:
                self.received.append(message)

    def alive(self) -> bool:
        """The process runs and answers a request."""
        if self.proc.poll() is not None:
            return False
        self.call("cnlmc/noSuchMethod", {})
        return True

    # ------------------------------------------------------------------ the process

    def wait(self, timeout: float = TIMEOUT) -> int:
        return self.proc.wait(timeout)

    def stderr(self) -> str:
        self._stderr.seek(0)
        return self._stderr.read().decode("utf-8", "replace")

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        for stream in (self.proc.stdin, self.proc.stdout):
            if stream is not None:
                try:
                    stream.close()
                except OSError:
                    pass
        self._stderr.close()

    def _read_frames(self) -> None:
        stdout = self.proc.stdout
        assert stdout is not None
        while True:
            length = None
            while True:
                line = stdout.readline()
                if not line:
                    self._inbox.put(None)
                    return
                if line in (b"\r\n", b"\n"):
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value.strip())
            assert length is not None, "the server sent a frame without Content-Length"
            self._inbox.put(json.loads(stdout.read(length)))
