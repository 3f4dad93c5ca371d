"""`cnlmc serve [FILE] [--port N] [--host ADDR] [--open]`: the studio in the browser.

Light to import (the CLI lists it on every start): aiohttp, the editor's language-server functions
and the view load only when `serve` runs."""

from __future__ import annotations

import argparse
import socket
import sys
from pathlib import Path

from cnlmc.backends.registry import Command

from ..api import lexicon_for
from ..cli import FRONT_END_COMMANDS
from ..errors import UsageError
from ..inputs import read_text
from ..lexicon_schema import LexiconError

DEFAULT_PORT = 8765  # our choice: free on common desktops (8000/8080 are taken by dev servers)


class ServeCommand(Command):
    name = "serve"
    help = FRONT_END_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument("file", nargs="?", help="a material file to start from (it is read, never written)")
        parser.add_argument(
            "--port", type=int, default=DEFAULT_PORT, help=f"port (default {DEFAULT_PORT}; 0: any free)"
        )
        parser.add_argument(
            "--host",
            default="127.0.0.1",
            help="address to listen on (default 127.0.0.1; 0.0.0.0 serves the LAN with a token and prints a QR code)",
        )
        parser.add_argument("--open", action="store_true", help="open the studio in the default browser")
        parser.add_argument("--lexicon", "-L", action="append", default=[], help="an overlay name or lexicon folder")
        parser.add_argument(
            "--voice", metavar="FILE", help="an enrolled voice for the Speak button (made with cnlmc listen --enrol)"
        )

    def run(self, args: argparse.Namespace) -> int:
        try:
            from aiohttp import web  # the studio's optional dependencies, only for `serve`

            from .server import Studio, make_app
        except ImportError as exc:
            raise UsageError(f"the studio cannot load: {exc}; install it with: pip install 'cnlmc[studio]'") from None
        try:
            lexicon = lexicon_for(tuple(args.lexicon))
        except LexiconError as exc:
            raise UsageError(f"lexicon: {exc}") from None
        if not 0 <= args.port <= 65535:
            raise UsageError(f"--port {args.port}: a port is 0 to 65535")
        folders = tuple(spec for spec in args.lexicon if Path(spec).is_dir())
        voice = enrolled_voice(args.voice)
        studio = Studio(
            lexicon, args.host, args.port, self.initial_text(args.file), lexicon_folders=folders, voice=voice
        )
        listening = listen(args.host, args.port)
        studio.port = listening.getsockname()[1]
        announce(studio.host, studio.port, studio.token, args.open)
        web.run_app(make_app(studio), sock=listening, print=None, access_log=None, shutdown_timeout=2.0)
        return 0

    def initial_text(self, path: str | None) -> str:
        if path is None:
            return ""
        from .settings import studio_settings

        limit = studio_settings().limits.max_document_bytes
        return read_text(path, limit=limit)


def enrolled_voice(path: str | None) -> object:
    """--voice FILE read before the server starts (a UsageError now, not on the first utterance)."""
    if path is None:
        return None
    from ..speech.command import load_voice
    from ..speech.recogniser import SpeechUnavailable

    try:
        return load_voice(path)
    except SpeechUnavailable as exc:
        raise UsageError(str(exc)) from None


def listen(host: str, port: int) -> socket.socket:
    try:
        return socket.create_server((host, port), family=socket.AF_INET6 if ":" in host else socket.AF_INET)
    except OSError as exc:
        raise UsageError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None


def announce(host: str, port: int, token: str | None, open_browser: bool) -> None:
    """Print where the studio is (with the token off loopback, and a QR code for a phone)."""
    from .network import is_loopback, print_qr, shown_host

    shown = shown_host(host)
    url = f"http://{'[' + shown + ']' if ':' in shown else shown}:{port}/" + (f"?token={token}" if token else "")
    print(f"cnlmc studio: {url}", flush=True)
    if not is_loopback(host):
        print("  on your phone (same network): scan this code", flush=True)
        print_qr(url)
        sys.stdout.flush()
    print("  stop it with Ctrl-C", flush=True)
    if open_browser:
        import webbrowser

        webbrowser.open(url)
