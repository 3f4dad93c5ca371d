"""Markdown for hovers and completion docs, with text from documents and lexicons made inert.

A document (or a lexicon someone else wrote) must not be able to put links, images or HTML into
the editor's hover, nor end a code block early: `text()` escapes every Markdown punctuation
character and shows control characters as escapes (`\\x0d`), and `code_block()` fences with a
run of backticks longer than any inside the block, with every line end a plain newline.
"""

from __future__ import annotations

import re

from ..diagnostics import visible

#: CommonMark lets a backslash escape any ASCII punctuation character: escape all of them.
_PUNCTUATION = re.compile(r"([!\"#$%&'()*+,\-./:;<=>?@\[\\\]^_`{|}~])")
_INLINE_MARKUP = re.compile(r"([\\`*_\[\]<>!|~&])")
_BACKTICKS = re.compile(r"`+")


def text(raw: str) -> str:
    """`raw` shown literally inside Markdown: one line, punctuation escaped, controls visible."""
    return _PUNCTUATION.sub(r"\\\1", visible(raw, one_line=True))


def prose(raw: str) -> str:
    """Lexicon text (docs, effects, examples) as plain prose: no links, images, HTML or emphasis
    it did not mean, controls visible; ordinary punctuation ('e.g.', '0.3') left as it reads."""
    return _INLINE_MARKUP.sub(r"\\\1", visible(raw))


def strong(raw: str) -> str:
    return f"**{text(raw)}**"


def code_block(lines: list[str], info: str = "text") -> str:
    """Lines shown verbatim in a fenced block that nothing inside can close."""
    body = "\n".join(visible(line, one_line=True) for line in lines)
    longest = max((len(run) for run in _BACKTICKS.findall(body)), default=0)
    fence = "`" * max(3, longest + 1)
    return f"{fence}{info}\n{body}\n{fence}"


def code_span(raw: str) -> str:
    """`raw` as inline code: the delimiter is longer than any backtick run inside."""
    shown = visible(raw, one_line=True)
    longest = max((len(run) for run in _BACKTICKS.findall(shown)), default=0)
    ticks = "`" * (longest + 1)
    pad = " " if shown.startswith("`") or shown.endswith("`") else ""
    return f"{ticks}{pad}{shown}{pad}{ticks}"
