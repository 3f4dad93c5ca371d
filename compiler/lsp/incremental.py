"""Incremental analysis: the document is cut into blocks (a material line and the refinement
lines below it), each block is compiled by `compile_source` and cached by its text.

Which lines are materials is found by compiling each line alone, kept in the same cache: a
material line with no refinement below it (the usual case, and every line of a document of
unknown words) is its own block, so each line is parsed once.

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
from collections.abc import Callable, Generator, Iterator
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

from .. import ast
from ..api import Result, compile_source
from ..diagnostics import Diagnostic
from ..lexicon import Lexicon
from ..spans import Span
from .positions import LineIndex

Node = TypeVar("Node")

Value = TypeVar("Value")
KeepGoing = Callable[[], bool]  # False once a newer edit made the analysis stale

#: What the analyzer keeps between edits (blocks, lines among them, by their text), at most.
MAX_CACHED_BLOCKS = 50000
MAX_CACHED_BLOCK_CHARS = 4_000_000


class Cancelled(Exception):
    """A newer edit made this analysis stale."""


@dataclass(frozen=True, eq=False)
class BlockResult:
    """What compiling one block gives, in block-relative positions."""

    diagnostics: tuple[Diagnostic, ...]
    materials: tuple[dict[str, Any], ...]  # IR material dicts
    material_lines: tuple[int, ...]  # 1-based block line of each material
    items: tuple[ast.Item, ...]  # AST items (Material / Refinement)
    _words: dict[int, tuple[ast.Word, ...]] = field(default_factory=dict, repr=False)
    _colours: dict[int, tuple[ast.Colour, ...]] = field(default_factory=dict, repr=False)

    def words_of(self, at: int) -> tuple[ast.Word, ...]:
        """The words of items[at] (found once per block: the walk over the AST is the slow part)."""
        if at not in self._words:
            self._words[at] = tuple(iter_nodes(self.items[at], ast.Word))
        return self._words[at]

    def colours_of(self, at: int) -> tuple[ast.Colour, ...]:
        if at not in self._colours:
            self._colours[at] = tuple(iter_nodes(self.items[at], ast.Colour))
        return self._colours[at]


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

    def diagnostics_between(self, first: int, last: int) -> list[Diagnostic]:
        """The diagnostics of the blocks that overlap 0-based lines first..last, in document
        positions (only those blocks are converted: a code action on a huge document stays cheap)."""
        out = []
        for block in self.blocks[max(0, self._block_index(first)) :]:
            if block.first_line > last:
                break
            out += [
                dataclasses.replace(d, span=shift_span(d.span, block.first_line, block.offset))
                for d in block.result.diagnostics
                if d.span is not None
            ]
        return out

    def _block_index(self, line: int) -> int:
        if self._firsts is None:
            self._firsts = [b.first_line for b in self.blocks]
        return bisect_right(self._firsts, line) - 1

    def block_at(self, line: int) -> Block | None:
        i = self._block_index(line)
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

    def item_index_on(self, line: int) -> tuple[int, Block] | None:
        """(index in its block's items, block) of the item parsed on `line`."""
        block = self.block_at(line)
        if block is None:
            return None
        relative = line - block.first_line + 1
        for at, item in enumerate(block.result.items):
            if item.span.line == relative:
                return at, block
        return None

    def words_on(self, line: int) -> list[tuple[ast.Word, int]]:
        """(word, 0-based column) of each word the parser chose a category for on `line`."""
        found = self.item_index_on(line)
        if found is None:
            return []
        at, block = found
        base = self.index.starts[line] - self.index.starts[block.first_line]
        return [(w, w.span.start - base) for w in block.result.words_of(at)]

    def colours_on(self, line: int) -> list[tuple[ast.Colour, int, int]]:
        """(colour phrase, start column, end column) of each colour on `line`."""
        found = self.item_index_on(line)
        if found is None:
            return []
        at, block = found
        base = self.index.starts[line] - self.index.starts[block.first_line]
        return [(c, c.span.start - base, c.span.end - base) for c in block.result.colours_of(at)]


def iter_nodes(node: object, kind: type[Node]) -> Iterator[Node]:
    """Every AST node of `kind` under `node`, in source order."""
    if isinstance(node, kind):
        yield node
    fields = getattr(type(node), "__dataclass_fields__", None)
    if fields is not None and not isinstance(node, type):
        for name in fields:
            yield from iter_nodes(getattr(node, name), kind)
    elif isinstance(node, tuple):
        for child in node:
            yield from iter_nodes(child, kind)


def shift_span(span: Span, lines: int, chars: int) -> Span:
    return Span(span.start + chars, span.end + chars, span.line + lines, span.col)


class TextCache(Generic[Value]):
    """Values by the text they were computed from, least recently used first out; bounded both in
    entries and in the characters of the texts it keeps (a text over a quarter of that is not kept)."""

    def __init__(self, max_entries: int, max_chars: int) -> None:
        self.max_entries = max_entries
        self.max_chars = max_chars
        self.chars = 0
        self._values: OrderedDict[str, Value] = OrderedDict()

    def get(self, text: str) -> Value | None:
        found = self._values.get(text)
        if found is not None:
            self._values.move_to_end(text)
        return found

    def put(self, text: str, value: Value) -> None:
        if len(text) > self.max_chars // 4 or text in self._values:
            return
        self._values[text] = value
        self.chars += len(text)
        while len(self._values) > self.max_entries or self.chars > self.max_chars:
            old, _ = self._values.popitem(last=False)
            self.chars -= len(old)

    def discard(self, text: str) -> None:
        if self._values.pop(text, None) is not None:
            self.chars -= len(text)

    def clear(self) -> None:
        self._values.clear()
        self.chars = 0

    def __len__(self) -> int:
        return len(self._values)


class Analyzer:
    """Compiles documents block by block and remembers blocks and line kinds by their text."""

    def __init__(self, lexicon: Lexicon, filename: str = "<lsp>") -> None:
        self.lexicon = lexicon
        self.filename = filename
        self._blocks: TextCache[BlockResult] = TextCache(MAX_CACHED_BLOCKS, MAX_CACHED_BLOCK_CHARS)

    def line_kind(self, text: str) -> str | None:
        """'material', 'refinement' or None (blank, comment, or a line that does not parse), from
        the line compiled alone (kept: a material line followed by another is that block)."""
        stripped = text.lstrip()
        if not stripped or stripped.startswith("#"):
            return None
        items = self.compile_block(text).items
        if not items:
            return None
        return "material" if isinstance(items[0], ast.Material) else "refinement"

    def compile_block(self, text: str) -> BlockResult:
        found = self._blocks.get(text)
        if found is not None:
            return found
        result = compile_source(text, self.filename, self.lexicon)
        block = BlockResult(
            tuple(_with_spans(result)),
            tuple(result.materials),
            tuple(s.selection.span.line for s in result.states),
            tuple(_items(result)),
        )
        self._blocks.put(text, block)
        return block

    def analysis(self, text: str, encoding: str = "utf-16") -> Generator[None, None, Snapshot]:
        """The analysis of `text` in small steps: the caller may stop between any two (see
        lsp/work.py, which runs steps in time slices so that other requests are answered)."""
        index = LineIndex(text, encoding)
        yield
        bounds = yield from self.block_bounds(index.lines)
        blocks = []
        for first, count in bounds:
            block_text = text[index.starts[first] : index.line_end_offset(first + count - 1)]
            blocks.append(Block(first, count, index.starts[first], self.compile_block(block_text)))
            yield
        return Snapshot(text, index, blocks)

    def analyse(self, text: str, encoding: str = "utf-16", keep_going: KeepGoing = lambda: True) -> Snapshot:
        """The whole analysis at once; Cancelled as soon as `keep_going()` is False."""
        steps = self.analysis(text, encoding)
        while True:
            try:
                next(steps)
            except StopIteration as done:
                return done.value  # type: ignore[no-any-return]
            if not keep_going():
                raise Cancelled()

    def block_bounds(self, lines: list[str]) -> Generator[None, None, list[tuple[int, int]]]:
        """(first line, line count) of each block: a new block starts at every material line."""
        starts = [0]
        for number, line in enumerate(lines):
            if number and self.line_kind(line) == "material":
                starts.append(number)
            yield
        ends = starts[1:] + [len(lines)]
        return [(a, b - a) for a, b in zip(starts, ends)]

    def forget(self, snapshot: Snapshot) -> None:
        """Drop what was cached for a closed document's text (its blocks and its lines)."""
        for block in snapshot.blocks:
            first = snapshot.index.starts[block.first_line]
            self._blocks.discard(
                snapshot.text[first : snapshot.index.line_end_offset(block.first_line + block.line_count - 1)]
            )
        for line in snapshot.index.lines:
            self._blocks.discard(line)

    def clear(self) -> None:
        """Drop everything learnt from documents (when none is open): the blocks and lines kept
        here and what the lexicon memoised about their words: its tagger (with its word memo) and
        its word formation engine (with its memo and the look-up of the tagger that made it), both
        made again on first use, its suggestions and the typos its suggestion index remembers (not
        the index, made once per lexicon). A memo entry that outlived its document would keep a
        whole block of the allocator's memory from going back to the system."""
        self._blocks.clear()
        caches = self.lexicon.caches
        caches.tagger = None
        caches.word_formation = None
        caches.suggestions.clear()
        if caches.suggestion_index is not None:
            caches.suggestion_index.forget_words()


def _with_spans(result: Result) -> Iterator[Diagnostic]:
    """Diagnostics without a span (W108) are placed on their material's phrase."""
    phrase = next((item.span for item in _items(result) if isinstance(item, ast.Material)), None)
    fallback = phrase or Span(0, 0, 1, 1)
    for diag in result.diagnostics:
        yield diag if diag.span is not None else dataclasses.replace(diag, span=fallback)


def _items(result: Result) -> list[ast.Item]:
    assert result.source_document is not None, "compile_source keeps the parsed source"
    return result.source_document.items
