"""Incremental analysis: the document is cut into blocks (a material line and the refinement
lines below it), each block is compiled by `compile_source` and cached by its text.

The compiler does all the language work; this module only decides what to recompile. A block
compiles exactly as it does inside the whole document because a line's parse depends on that
line alone and a refinement attaches to the material line above it. Diagnostics come back
shifted to the block's place in the document (tests/lsp/test_incremental.py checks that the
result equals compiling the whole text).
"""

from __future__ import annotations

import dataclasses
from bisect import bisect_right
from collections import OrderedDict
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any, TypeVar

from .. import ast
from ..api import Result, compile_source
from ..diagnostics import Diagnostic
from ..document import parse_document
from ..lexicon import Lexicon
from ..spans import Span
from .positions import LineIndex

Node = TypeVar("Node")
KeepGoing = Callable[[], bool]  # False once a newer edit made the analysis stale

MAX_CACHED_BLOCKS = 20000
MAX_CACHED_LINES = 50000


class Cancelled(Exception):
    """A newer edit made this analysis stale."""


@dataclass(frozen=True, eq=False)
class BlockResult:
    """What compiling one block gives, in block-relative positions."""

    diagnostics: tuple[Diagnostic, ...]
    materials: tuple[dict[str, Any], ...]  # IR material dicts
    material_lines: tuple[int, ...]  # 1-based block line of each material
    items: tuple[ast.Item, ...]  # AST items (Material / Refinement)


@dataclass(frozen=True, eq=False)
class Block:
    first_line: int  # 0-based document line
    line_count: int
    offset: int  # character offset of the block's first line
    result: BlockResult

    def contains(self, line: int) -> bool:
        return self.first_line <= line < self.first_line + self.line_count


@dataclass
class Snapshot:
    """The analysis of one text: absolute diagnostics, blocks with materials, the line index."""

    text: str
    index: LineIndex
    blocks: list[Block]
    _firsts: list[int] | None = None
    _diagnostics: list[Diagnostic] | None = None

    @property
    def diagnostics(self) -> list[Diagnostic]:
        """Every diagnostic with its span in document positions (computed on first use)."""
        if self._diagnostics is None:
            self._diagnostics = [
                dataclasses.replace(d, span=shift_span(d.span, b.first_line, b.offset))
                for b in self.blocks
                for d in b.result.diagnostics
                if d.span is not None  # every block diagnostic has one (_with_spans)
            ]
        return self._diagnostics

    def block_at(self, line: int) -> Block | None:
        if self._firsts is None:
            self._firsts = [b.first_line for b in self.blocks]
        i = bisect_right(self._firsts, line) - 1
        if i >= 0 and self.blocks[i].contains(line):
            return self.blocks[i]
        return None

    def materials_on(self, line: int) -> list[dict[str, Any]]:
        """IR materials whose phrase stands on the 0-based document `line` (several for 'or')."""
        block = self.block_at(line)
        if block is None:
            return []
        relative = line - block.first_line + 1
        return [m for m, at in zip(block.result.materials, block.result.material_lines) if at == relative]

    def item_on(self, line: int) -> tuple[ast.Item | None, Block | None]:
        """The AST item (Material or Refinement) parsed on `line`, with spans relative to its block."""
        block = self.block_at(line)
        if block is None:
            return None, None
        relative = line - block.first_line + 1
        for item in block.result.items:
            if item.span.line == relative:
                return item, block
        return None, block

    def words_on(self, line: int) -> list[tuple[ast.Word, int]]:
        """(word, 0-based column) of each word the parser chose a category for on `line`."""
        item, block = self.item_on(line)
        if item is None or block is None:
            return []
        base = self.index.starts[line] - self.index.starts[block.first_line]
        return [(w, w.span.start - base) for w in iter_nodes(item, ast.Word)]

    def colours_on(self, line: int) -> list[tuple[ast.Colour, int, int]]:
        """(colour phrase, start column, end column) of each colour on `line`."""
        item, block = self.item_on(line)
        if item is None or block is None:
            return []
        base = self.index.starts[line] - self.index.starts[block.first_line]
        return [(c, c.span.start - base, c.span.end - base) for c in iter_nodes(item, ast.Colour)]


def iter_nodes(node: object, kind: type[Node]) -> Iterator[Node]:
    """Every AST node of `kind` under `node`, in source order."""
    if isinstance(node, kind):
        yield node
    if dataclasses.is_dataclass(node) and not isinstance(node, type):
        for f in dataclasses.fields(node):
            yield from iter_nodes(getattr(node, f.name), kind)
    elif isinstance(node, tuple):
        for child in node:
            yield from iter_nodes(child, kind)


def shift_span(span: Span, lines: int, chars: int) -> Span:
    return Span(span.start + chars, span.end + chars, span.line + lines, span.col)


class Analyzer:
    """Compiles documents block by block and remembers blocks and line kinds by their text."""

    def __init__(self, lexicon: Lexicon, filename: str = "<lsp>") -> None:
        self.lexicon = lexicon
        self.filename = filename
        self._kinds: OrderedDict[str, str | None] = OrderedDict()
        self._blocks: OrderedDict[str, BlockResult] = OrderedDict()

    def line_kind(self, text: str) -> str | None:
        """'material', 'refinement' or None (blank, comment, or a line that does not parse)."""
        if text in self._kinds:
            self._kinds.move_to_end(text)
            return self._kinds[text]
        items = parse_document(text, self.lexicon, self.filename).items
        kind = None
        if items:
            kind = "material" if isinstance(items[0], ast.Material) else "refinement"
        _remember(self._kinds, text, kind, MAX_CACHED_LINES)
        return kind

    def compile_block(self, text: str) -> BlockResult:
        found = self._blocks.get(text)
        if found is not None:
            self._blocks.move_to_end(text)
            return found
        result = compile_source(text, self.filename, self.lexicon)
        block = BlockResult(
            tuple(_with_spans(result)),
            tuple(result.materials),
            tuple(s.selection.span.line for s in result.states),
            tuple(_items(result)),
        )
        _remember(self._blocks, text, block, MAX_CACHED_BLOCKS)
        return block

    def analyse(self, text: str, encoding: str = "utf-16", keep_going: KeepGoing = lambda: True) -> Snapshot:
        index = LineIndex(text, encoding)
        blocks = []
        for first, count in self.block_bounds(index.lines, keep_going):
            if not keep_going():
                raise Cancelled()
            result = self.compile_block("\n".join(index.lines[first : first + count]))
            blocks.append(Block(first, count, index.starts[first], result))
        return Snapshot(text, index, blocks)

    def block_bounds(self, lines: list[str], keep_going: KeepGoing) -> list[tuple[int, int]]:
        """(first line, line count) of each block: a new block starts at every material line."""
        starts = [0]
        for number, line in enumerate(lines):
            if number % 256 == 0 and not keep_going():
                raise Cancelled()
            if number and self.line_kind(line) == "material":
                starts.append(number)
        ends = starts[1:] + [len(lines)]
        return [(a, b - a) for a, b in zip(starts, ends)]


def _with_spans(result: Result) -> Iterator[Diagnostic]:
    """Diagnostics without a span (W108) are placed on their material's phrase."""
    phrase = next((item.span for item in _items(result) if isinstance(item, ast.Material)), None)
    fallback = phrase or Span(0, 0, 1, 1)
    for diag in result.diagnostics:
        yield diag if diag.span is not None else dataclasses.replace(diag, span=fallback)


def _items(result: Result) -> list[ast.Item]:
    assert result.source_document is not None, "compile_source keeps the parsed source"
    return result.source_document.items


def _remember(cache: OrderedDict[str, Any], key: str, value: Any, limit: int) -> None:
    cache[key] = value
    if len(cache) > limit:
        cache.popitem(last=False)
