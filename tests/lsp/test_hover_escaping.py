"""Hover text cannot be steered by the document (#13: a lone CR in a comment closed the hover's
code fence and injected Markdown links and images): user text is escaped, code fences are longer
than any backtick run inside, and no raw control character reaches the editor."""

from __future__ import annotations

import re

import pytest

from cnlmc.lsp.markdown import code_block, code_span, prose, text

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

HOSTILE = [
    "blue plastic # note\r```\n[click](http://evil.example) ![img](http://evil.example/i.png)",
    "hull: blue plastic # ```` <img src=x onerror=alert(1)> \x1b]0;title\x07\x1b[2J",
    "`hull`: blue plastic # `` <b>bold</b> *em* _em_",
    "[x](http://evil.example): blue plastic",
    "blue ![i](http://evil.example/i.png) plastic",
    "bl`ue pl**as**tic # \u202eevil\u2028 line separator\x85 next line",
    "deck: white varnished oak\r# [a](javascript:alert(1))\rdarker",
]
LINK = re.compile(r"(?<!\\)!?(?<!\\)\[[^\]\n]*(?<!\\)\]\(")
HTML = re.compile(r"(?<!\\)<[A-Za-z/]")
CONTROL = re.compile(r"[\x00-\x09\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
FENCE = re.compile(r"^(`{3,})")


def fences_hold(markdown: str) -> bool:
    """Every fenced block is closed by its own fence and nothing inside could close it earlier."""
    lines = markdown.split("\n")
    i = 0
    while i < len(lines):
        opened = FENCE.match(lines[i])
        i += 1
        if not opened:
            continue
        fence = opened.group(1)
        while i < len(lines) and not lines[i].startswith(fence):
            if lines[i].startswith("```"):
                return False  # a shorter run that a sloppier renderer could take for the end
            i += 1
        if i == len(lines) or lines[i] != fence:
            return False
        i += 1
    return True


def outside_code_blocks(markdown: str) -> str:
    return re.sub(r"^(`{3,})[^\n]*\n.*?^\1$", "", markdown, flags=re.M | re.S)


def assert_inert(markdown: str) -> None:
    assert not CONTROL.search(markdown), repr(markdown)
    assert fences_hold(markdown), markdown
    prose_part = outside_code_blocks(markdown)
    assert not LINK.search(prose_part), markdown
    assert not HTML.search(prose_part), markdown


@pytest.fixture(scope="module")
def server():
    with RawServer() as raw:
        raw.initialize(debounceMs=0)
        yield raw
        assert "Traceback" not in raw.stderr()


@pytest.mark.parametrize("number", range(len(HOSTILE)))
def test_hover_on_hostile_documents_is_inert(server, number):
    uri, document = f"file:///tmp/cnlmc-tests/hostile-{number}.cnl", HOSTILE[number]
    server.open(uri, document)
    server.diagnostics(uri, 1)
    hovers = []
    for line in range(document.count("\n") + document.count("\r") + 1):
        for character in range(0, 60, 2):
            where = {"textDocument": {"uri": uri}, "position": {"line": line, "character": character}}
            answer = server.call("textDocument/hover", where)
            if answer["result"] is not None:
                hovers.append(answer["result"]["contents"]["value"])
    assert hovers  # the words and the materials are still described
    for markdown in hovers:
        assert_inert(markdown)


def test_markdown_helpers():
    assert text("[x](http://e)") == "\\[x\\]\\(http\\:\\/\\/e\\)"
    assert text("a\rb\x1b") == "a\\\\x0db\\\\x1b"
    assert code_span("a``b") == "```a``b```"
    assert code_span("`x") == "`` `x ``"
    assert code_block(["x ```` y", "z\r"]) == "`````text\nx ```` y\nz\\x0d\n`````"
    assert prose("roughness = 0.3, e.g. [x](y) <b>") == "roughness = 0.3, e.g. \\[x\\](y) \\<b\\>"
