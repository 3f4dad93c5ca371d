"""A material file: one material or refinement per line, '#' comments, optional 'name:'."""

from __future__ import annotations

from . import ast
from .diagnostics import did_you_mean, error
from .lexicon import Lexicon
from .parser import ParseFailure, describe_expected, parse_tagged
from .spans import Span
from .syntax import TreeToAst
from .tagger import Tagger

MAX_LINE_CHARS = 2000
MAX_LINE_WORDS = 64


def iter_lines(source: str):
    """(1-based line number, offset, text) for each line."""
    offset = 0
    for number, line in enumerate(source.split("\n"), start=1):
        yield number, offset, line.rstrip("\r")
        offset += len(line) + 1


def parse_document(source: str, lexicon: Lexicon, filename: str = "<input>") -> ast.Document:
    """Parse every line; problems become diagnostics and the next line is parsed anyway."""
    doc = ast.Document(filename, source)
    tagger = Tagger(lexicon)
    for number, offset, text in iter_lines(source):
        node = parse_line(text, number, offset, tagger, doc.diagnostics)
        if node is not None:
            doc.items.append(node)
    return doc


def parse_line(text: str, number: int, offset: int, tagger: Tagger, diags: list):
    if not text.strip() or text.lstrip().startswith("#"):
        return None
    if len(text) > MAX_LINE_CHARS:
        diags.append(error(Span(offset, offset + len(text), number, 1), "E004",
                           f"line is too long ({len(text)} characters; at most {MAX_LINE_CHARS})"))
        return None
    tagged, tag_diags = tagger.tag_line(text, number, offset)
    diags.extend(tag_diags)
    words = [t for t in tagged if t.candidates]
    if not words:
        return None
    if len(words) > MAX_LINE_WORDS:
        diags.append(error(words[0].span.to(words[-1].span), "E004",
                           f"phrase is too long ({len(words)} words; at most {MAX_LINE_WORDS})"))
        return None
    try:
        tree, chosen = parse_tagged(words)
    except ParseFailure as failure:
        diags.append(_syntax_error(failure, words, text, number, offset))
        return None
    return TreeToAst({t.span.start: t for t in words}, chosen, text).build(tree)


def _syntax_error(failure: ParseFailure, words, text, number, offset):
    """E002 for a word in the wrong place; E003 for a phrase that never names its material."""
    has_noun = any(c.tag == "NOUN" for t in words for c in t.candidates)
    if failure.tagged is None and not has_noun:
        span = words[0].span.to(words[-1].span)
        return error(span, "E003", "this phrase names no material: end it with a noun",
                     ("for example 'brushed aluminum' or 'white varnished oak'",))
    if failure.tagged is None:
        last = words[-1]
        return error(last.span, "E002", f"the phrase cannot end after '{last.text}'",
                     (f"expected {describe_expected(failure.expected)}",))
    at = failure.tagged
    hint = _placement_hint(at)
    return error(at.span, "E002", f"'{at.text}' cannot stand here",
                 (f"expected {describe_expected(failure.expected)}", *hint))


def _placement_hint(at) -> tuple[str, ...]:
    tags = {c.tag for c in at.candidates}
    if tags & {"ADJ", "COLOR", "ADV", "SHADE"}:
        return ("describing words come before the noun: 'brushed aluminum', not 'aluminum brushed'",)
    if "NOUN" in tags:
        return ("a phrase names one material, at its end; use 'or' for alternatives",)
    return ()
