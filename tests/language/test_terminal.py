"""Terminal escapes (issue 13): control characters from a source, a file name or a word reach the
terminal as visible `\\x1b`-style text, never raw, through diagnostics, `explain` and the CLI."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.diagnostics import render, visible, warning
from cnlmc.explain import explain
from cnlmc.spans import Span
from tests.helpers import run_cnlmc

RAW_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
HOSTILE = "# \x1b]0;title\x07\x1b[2J"


def test_visible_escapes_c0_c1_and_bidi_but_keeps_layout() -> None:
    assert visible("a\x1b[2J\x07b\x9b\u202e") == "a\\x1b[2J\\x07b\\x9b\\u202e"
    assert visible("tab\there\nnext") == "tab\there\nnext"
    assert visible("tab\there\nnext\r", one_line=True) == "tab\\x09here\\x0anext\\x0d"
    assert visible("ünïcødé 名前 🔥") == "ünïcødé 名前 🔥"


def test_render_escapes_the_line_and_keeps_the_caret_under_the_span() -> None:
    source = "red plastic\na\x1b]0;t\x07 plastic " + HOSTILE + "\n"
    col = source.split("\n")[1].index("plastic") + 1
    start = source.index("plastic", 12)
    diag = warning(Span(start, start + 7, 2, col), "W101", "word \x1b[31mplastic", ("hint \x07",))
    text = render(diag, source, "evil\x1b]0;x\x07.cnl")
    assert not RAW_CONTROL.search(text), repr(text)
    head, line, caret, hint = text.split("\n")
    assert head.startswith("evil\\x1b]0;x\\x07.cnl:2:") and "word \\x1b[31mplastic" in head
    assert hint.endswith("= hint \\x07")
    gutter = line.index("| ") + 2
    assert line[gutter:] == "a\\x1b]0;t\\x07 plastic # \\x1b]0;title\\x07\\x1b[2J"
    at = caret.index("^")
    assert line[at : at + 7] == "plastic"  # the caret sits under the word in the escaped line
    assert caret[at:] == "^~~~~~~"


def test_render_of_a_plain_line_is_unchanged() -> None:
    source = "blue anodized aluminium\n"
    diag = warning(Span(14, 23, 1, 15), "W101", "unknown word")
    assert render(diag, source, "x.cnl") == (
        "x.cnl:1:15: warning[W101]: unknown word\n   1 | blue anodized aluminium\n     |               ^~~~~~~~~"
    )


def test_explain_escapes_the_phrase() -> None:
    result = compile_source("red plastic " + HOSTILE + "\n", "x.cnl")
    text = explain(result.ir)
    assert not RAW_CONTROL.search(text), repr(text)
    assert "\\x1b]0;title\\x07" in text


def test_cli_stderr_has_no_raw_control_characters(tmp_path: Path) -> None:
    name = tmp_path / "e\x1b[31mvil\x07.cnl"
    name.write_text("red plastic " + HOSTILE + "\nblue \x1bxyz \x9b plastic\ngreen \x1b]0;t\x07wood\n", "utf-8")
    for args in (["compile", str(name)], ["explain", str(name)], ["compile", str(tmp_path / "missing\x1b[2J.cnl")]):
        done = run_cnlmc(*args)
        assert done.stderr, args
        assert not RAW_CONTROL.search(done.stderr), (args, done.stderr)
        assert not RAW_CONTROL.search(done.stdout), (args, done.stdout)
    done = run_cnlmc("compile", "-", stdin="blue \x1b[2Jplastic\n")
    assert done.returncode == 1 and "\\x1b" in done.stderr and not RAW_CONTROL.search(done.stderr)


def test_the_ir_on_stdout_escapes_del_c1_and_line_separators() -> None:
    """JSON allows DEL, C1 and U+2028 raw inside strings; a terminal reads U+009B as CSI and
    JavaScript U+2028 as a line end, so the IR writes them as \\u escapes (still the same JSON)."""
    import json

    source = "x: gold # \x9b[2J \u2028 \x7f\n"
    run = run_cnlmc("compile", "-", stdin=source)
    assert run.returncode == 0, run.stderr
    assert not RAW_CONTROL.search(run.stdout), repr(run.stdout)
    assert "\\u009b" in run.stdout and "\\u007f" in run.stdout and "\\u2028" in run.stdout
    phrase = json.loads(run.stdout)["materials"][0]["phrase"]
    assert "\x9b[2J" in phrase and "\x7f" in phrase  # the text is kept, only its spelling changes


@pytest.mark.parametrize(
    "target", [pytest.param("materialx", marks=pytest.mark.materialx), pytest.param("usd", marks=pytest.mark.usd)]
)
def test_exchange_files_on_stdout_show_control_characters_escaped(target: str) -> None:
    """The phrase goes into doc strings: its control characters are written as visible escapes."""
    run = run_cnlmc(
        "compile", "-", "--target", target, "--option", "maps=none", stdin="x: gold # \x9b[2J \x7f \x1b]0;t\x07\n"
    )
    assert run.returncode == 0, run.stderr
    assert not RAW_CONTROL.search(run.stdout), repr(run.stdout)
    assert "x9b[2J" in run.stdout and "x1b]0;t" in run.stdout
