"""cnlmc.lines: the one definition of line ends (CRLF, LF, a lone CR; never FF, VT, NEL, U+2028/9)."""

import pytest

from cnlmc.lines import LineTable, iter_lines, line_starts
from tests.helpers import run_cnlmc as cnlmc


@pytest.mark.parametrize(
    ("source", "lines"),
    [
        ("", [""]),
        ("a", ["a"]),
        ("a\n", ["a", ""]),
        ("a\nb", ["a", "b"]),
        ("a\r\nb", ["a", "b"]),
        ("a\rb", ["a", "b"]),
        ("a\r\r\nb", ["a", "", "b"]),
        ("a\n\rb", ["a", "", "b"]),
        ("\r\n\r\n", ["", "", ""]),
        ("a\x0cb\x0bc\x85d\u2028e\u2029f", ["a\x0cb\x0bc\x85d\u2028e\u2029f"]),
    ],
)
def test_line_ends(source, lines):
    got = list(iter_lines(source))
    assert [text for _, _, text in got] == lines
    assert [number for number, _, _ in got] == list(range(1, len(lines) + 1))
    assert [offset for _, offset, _ in got] == line_starts(source)
    for _, offset, text in got:
        assert source[offset : offset + len(text)] == text
    table = LineTable(source)
    assert len(table) == len(lines)
    assert [table.line(n) for n in range(1, len(lines) + 1)] == lines


def test_line_table_positions():
    table = LineTable("ab\r\ncd\ref\ngh")
    assert table.line(0) == table.line(5) == ""
    assert [table.line_of(o) for o in range(12)] == [1, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4]
    assert table.position(5) == (2, 1)
    assert table.position(99) == (4, 89)
    assert table.line_of(-3) == 1
    with pytest.raises(IndexError):
        table.start(5)


def test_a_lone_cr_ends_a_line_in_the_cli_display():
    """The diagnostic quotes the line the error is on, not the whole CR-separated file."""
    r = cnlmc("compile", "-", stdin="polished brass\rpolished bras\rsteel\r")
    assert r.returncode == 1
    assert "<stdin>:2:10: error[E001]: unknown word 'bras'" in r.stderr
    assert "   2 | polished bras\n" in r.stderr
    assert "steel" not in r.stderr


def test_form_feed_and_line_separator_are_not_line_ends_in_the_cli():
    r = cnlmc("compile", "-", stdin="polished\x0c brass\u2028 xyzzy\n")
    assert r.returncode == 1
    assert "<stdin>:1:" in r.stderr and "<stdin>:2:" not in r.stderr
    assert "\\x0c" in r.stderr and "\\u2028" in r.stderr
