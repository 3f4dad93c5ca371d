"""The parser: tagged words -> AST, with lark's LALR parser over grammar/cnl.lark.

A word with several candidate tags ("gold": colour or noun) is resolved by a depth-first
search over the interactive parser: each candidate is fed in the tagger's order of
preference and the first one that lets the whole line parse wins. Lines without
ambiguous words take a single pass.

The tree depends only on the sequence of terminal types, so parse_line_shape keeps the
shape of each sequence it has parsed (syntax.Shape, with the chosen candidate per word) in
a ShapeCache keyed by the candidate tags of each word (the lexicon's, lexicon.caches.shapes):
a line whose words carry the same tags as an earlier line skips the parser. Failures are
never cached.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from functools import lru_cache
from typing import TYPE_CHECKING, Any, TypedDict

from . import ast
from .diagnostics import FailureKey
from .package_data import package_folder
from .shape_store import recall_shape
from .syntax import Shape, ShapeCache, ShapeKey
from .tagged import Candidate, Tagged

if TYPE_CHECKING:  # lark is loaded only when a line's shape must be read (about 60 ms of a start)
    from lark import Lark, Token, Tree
    from lark.exceptions import UnexpectedToken
    from lark.parsers.lalr_interactive_parser import InteractiveParser

MAX_BRANCHES = 256  # ambiguous words are few; this bounds the search on hostile input
Chosen = dict[int, Candidate]  # word start offset -> the candidate chosen for it

TERMINAL_NAMES = {
    "NOUN": "a material noun (e.g. 'aluminum')",
    "ADJ": "an adjective (e.g. 'brushed')",
    "ADV": "an adverb (e.g. 'lightly')",
    "COLOR": "a colour (e.g. 'blue')",
    "SHADE": "a shade (e.g. 'dark')",
    "COAT": "a coat (e.g. 'varnish')",
    "REFINE": "a refinement (e.g. 'darker')",
    "PROP": "a property (e.g. 'grain')",
    "ARTICLE": "an article",
    "AND": "'and'",
    "OR": "'or'",
    "WITH": "'with'",
    "COMMA": "','",
    "NAME": "a name",
    "COLON": "':'",
    "$END": "the end of the line",
}


@lru_cache(maxsize=1)
def lark_parser() -> Lark:
    """The LALR parser; its tables come from the disk cache as verified plain data (cnlmc.grammar_cache)."""
    from .grammar_cache import cached_lark

    grammar = (package_folder("cnlmc.grammar") / "cnl.lark").read_text("utf-8")
    return cached_lark(grammar, lexer_class(), parser="lalr", propagate_positions=False, maybe_placeholders=False)


@lru_cache(maxsize=1)
def lexer_class() -> type:
    """The parser's lexer (a class lark instantiates): it hands lark the tokens it was given."""
    from lark.lexer import Lexer, LexerState

    class _Lexer(Lexer):
        """lark calls lex() with whatever parse() was given: here, a ready list of Tokens."""

        def __init__(self, lexer_conf: Any) -> None:
            pass

        def lex(self, lexer_state: LexerState | Sequence[Token], parser_state: Any = None) -> Iterator[Token]:
            assert not isinstance(lexer_state, LexerState), "parse() is given tokens, never text"
            yield from lexer_state

    return _Lexer


def __getattr__(name: str) -> Any:
    if name == "_Lexer":  # the lexer class by its old name, made when first asked for
        return lexer_class()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _token(t: Tagged, tag: str) -> Token:
    from lark import Token

    return Token(tag, t.text, t.span.start, t.span.line, t.span.col)


class ParseFailure(Exception):
    def __init__(self, tagged: Tagged | None, expected: set[str], key: FailureKey | None = None) -> None:
        super().__init__("parse failure")
        self.tagged = tagged
        self.expected = expected
        self.key = key  # (LALR state, token type): what the bad-examples table is keyed by


def failure_key(exc: UnexpectedToken) -> FailureKey | None:
    """(the state under the top, the top state, the token): where a line failed, with its context.

    The state under the top tells failures in a merged LALR state apart: "aluminum brushed" (a
    noun, then an adjective: "aluminum brushed steel" parses) from "lightly brushed"."""
    state = exc.state
    if state is None:
        return None
    stack = state.state_stack
    return (stack[-2] if len(stack) > 1 else -1, state.position, exc.token.type)


def parse_tagged(tagged: list[Tagged]) -> tuple[Tree[Token], Chosen]:
    """Parse a line of tagged words; returns the tree and the chosen tag per word start."""
    words = [t for t in tagged if t.candidates]
    if all(len(t.candidates) == 1 for t in words):
        return _parse_direct(words), {t.span.start: t.candidates[0] for t in words}
    return _parse_search(words)


def parsed_item(words: list[Tagged], text: str, shapes: ShapeCache) -> ast.Item | None:
    """The line's node when the words parse, else None (a reading tried on a line that failed)."""
    try:
        shape, picks = parse_line_shape(words, shapes)
    except ParseFailure:
        return None
    return shape.build(words, picks, text)


def parsed_material(words: list[Tagged], text: str, shapes: ShapeCache) -> ast.Material | None:
    """parsed_item, only when the line is a material."""
    node = parsed_item(words, text, shapes)
    return node if isinstance(node, ast.Material) else None


def parse_line_shape(words: list[Tagged], shapes: ShapeCache) -> tuple[Shape, list[Candidate]]:
    """The shape of a line's parse and the chosen candidate of each word (raises ParseFailure)."""
    key: ShapeKey = tuple(
        [t.candidates[0].tag if len(t.candidates) == 1 else tuple([c.tag for c in t.candidates]) for t in words]
    )
    found = shapes.get(key)
    if found is None:
        found = recall_shape(shapes, key)  # stored by an earlier run
        if found is None:
            found = _read_shape(words)
            shapes.put(key, *found)
        else:
            shapes.put(key, *found, fresh=False)
    shape, choice = found
    if choice is None:
        return shape, [t.candidates[0] for t in words]
    return shape, [t.candidates[k] for t, k in zip(words, choice)]


def _read_shape(words: list[Tagged]) -> tuple[Shape, tuple[int, ...] | None]:
    tree, chosen = parse_tagged(words)
    if _reads_as_refinement(tree) and _may_end_in_noun(words, chosen):
        tree, chosen = _material_reading(words) or (tree, chosen)
    from .shape_reader import read_shape

    choice = tuple(_position(t.candidates, chosen[t.span.start]) for t in words)
    shape = read_shape(tree, {t.span.start: i for i, t in enumerate(words)})
    return shape, (choice if any(choice) else None)


def _reads_as_refinement(tree: Tree[Token]) -> bool:
    last = tree.children[-1]
    return not isinstance(last, str) and last.data == "refinement"  # a Tree (a Token is a str)


def _may_end_in_noun(words: list[Tagged], chosen: Chosen) -> bool:
    last = words[-1]
    return chosen[last.span.start].tag != "NOUN" and any(c.tag == "NOUN" for c in last.candidates)


def _material_reading(words: list[Tagged]) -> tuple[Tree[Token], Chosen] | None:
    """A line that reads as a refinement or as a material ending in its noun is the material:
    'slightly duller copper' is copper, one step duller, not the copper colour made duller."""
    last = words[-1]
    nouns_first = sorted(last.candidates, key=lambda c: c.tag != "NOUN")
    try:
        tree, chosen = parse_tagged([*words[:-1], Tagged(last.text, last.span, tuple(nouns_first), last.unknown)])
    except ParseFailure:
        return None
    return None if _reads_as_refinement(tree) else (tree, chosen)


def _position(candidates: tuple[Candidate, ...], chosen: Candidate) -> int:
    return next(k for k, c in enumerate(candidates) if c is chosen)


def _parse_direct(words: list[Tagged]) -> Tree[Token]:
    from lark.exceptions import UnexpectedInput, UnexpectedToken

    try:
        return lark_parser().parse([_token(t, t.candidates[0].tag) for t in words])
    except UnexpectedToken as exc:
        raise _failure(words, exc) from None
    except UnexpectedInput as exc:  # pragma: no cover - other lark errors
        raise ParseFailure(None, set()) from exc


def _failure(words: list[Tagged], exc: UnexpectedToken) -> ParseFailure:
    at = next((t for t in words if t.span.start == exc.token.start_pos and exc.token.type != "$END"), None)
    return ParseFailure(at, set(exc.expected), failure_key(exc))


class _Search(TypedDict):
    budget: int  # branches left to try
    deepest: tuple[int, Tagged | None, set[str], FailureKey | None]  # the failure furthest into the line


def _parse_search(words: list[Tagged]) -> tuple[Tree[Token], Chosen]:
    state: _Search = {"budget": MAX_BRANCHES, "deepest": (-1, None, set(), None)}
    ip = lark_parser().parse_interactive()  # loads lark
    result = _search(ip, words, 0, {}, state)
    if result is None:
        _index, at, expected, key = state["deepest"]
        raise ParseFailure(at, expected, key)
    return result


def _search(
    ip: InteractiveParser, words: list[Tagged], i: int, chosen: Chosen, state: _Search
) -> tuple[Tree[Token], Chosen] | None:
    from lark.exceptions import UnexpectedToken

    while i < len(words) and len(words[i].candidates) == 1:  # no choice: no copy of the parser
        cand = words[i].candidates[0]
        try:
            ip.feed_token(_token(words[i], cand.tag))
        except UnexpectedToken as exc:
            _note_failure(state, i, words[i], exc)
            return None
        chosen = {**chosen, words[i].span.start: cand}
        i += 1
    if i == len(words):
        return _finish(ip, words, chosen, state)
    for cand in words[i].candidates:
        if state["budget"] <= 0:
            return None
        state["budget"] -= 1
        branch = ip.copy()  # deep: lark may reuse child lists when it reduces
        try:
            branch.feed_token(_token(words[i], cand.tag))
        except UnexpectedToken as exc:
            _note_failure(state, i, words[i], exc)
            continue
        found = _search(branch, words, i + 1, {**chosen, words[i].span.start: cand}, state)
        if found is not None:
            return found
    return None


def _finish(
    ip: InteractiveParser, words: list[Tagged], chosen: Chosen, state: _Search
) -> tuple[Tree[Token], Chosen] | None:
    from lark.exceptions import UnexpectedToken

    try:
        last = _token(words[-1], chosen[words[-1].span.start].tag) if words else None
        return ip.feed_eof(last), chosen
    except UnexpectedToken as exc:
        _note_failure(state, len(words), None, exc)
        return None


def _note_failure(state: _Search, index: int, at: Tagged | None, exc: UnexpectedToken) -> None:
    if index > state["deepest"][0]:
        state["deepest"] = (index, at, set(exc.expected), failure_key(exc))


def describe_expected(expected: set[str]) -> str:
    names = sorted({TERMINAL_NAMES.get(e, e) for e in expected if e in TERMINAL_NAMES})
    if not names:
        return "something else"
    return ", ".join(names[:-1]) + (" or " if len(names) > 1 else "") + names[-1]
