"""lark tree -> AST dataclasses, by way of a reusable *shape*.

A deterministic LALR grammar gives the same tree for the same sequence of terminal types,
so a tree is compiled once into a shape: nested builder functions that know which word
index goes where. Building the AST of any line with that terminal sequence is then a
call of the shape on the line's words, with no parser and no tree walk (see
parser.parse_line_shape, which caches shapes by terminal sequence).

A builder is called as build(words, picks) with `words` the line's AST Words (None where a
keyword is not part of the AST) and returns an AST node; one small compiler per grammar rule.
"""

from __future__ import annotations

from lark import Token, Tree

from . import ast
from .spans import Span

GROUP_RULES = ("adjective_group", "colour_group", "dangling_group")
COLOUR_CATEGORIES = ("colours", "unknown")


class Shape:
    """The compiled tree of one terminal sequence: which words become AST Words, and the root builder."""

    __slots__ = ("used", "root")

    def __init__(self, tree: Tree, index: dict):
        compiler = _Compiler(index)
        self.root = compiler.start(tree)
        self.used = tuple(sorted(compiler.used))

    def build(self, tagged: list, picks: list, text: str):
        """The AST of a line: `tagged` are its words, `picks` the chosen candidate of each."""
        words, make = [None] * len(tagged), ast.Word
        for i in self.used:
            t, c = tagged[i], picks[i]
            words[i] = make(t.text, c.key, c.category, t.span, t.unknown)
        return self.root(words, tagged, text)


def _span(tagged: list, first: int, last: int) -> Span:
    """The span from word `first` to word `last` (as Span.to)."""
    a = tagged[first].span
    if first == last:
        return a
    return Span(a.start, max(a.end, tagged[last].span.end), a.line, a.col)


class _Compiler:
    """One method per grammar rule; each returns a builder for that subtree."""

    def __init__(self, index: dict):
        self.index = index  # token start offset -> word index
        self.used: set[int] = set()

    def word(self, tok: Token) -> int:
        i = self.index[tok.start_pos]
        self.used.add(i)
        return i

    def edges(self, node) -> tuple[int, int]:
        return self._edge(node, 0), self._edge(node, -1)

    def _edge(self, node, end: int) -> int:
        while isinstance(node, Tree):
            node = node.children[end]
        return self.index[node.start_pos]

    def start(self, tree: Tree):
        name, body = None, None
        for child in tree.children:
            if child.data == "name":
                name = self.word(child.children[0])
            else:
                body = child
        if body.data == "material":
            return self.material(body, name)
        return self.refinement(body, name)

    def material(self, tree: Tree, name):
        groups, nouns, coat = None, (), None
        for child in tree.children:
            if isinstance(child, Token):
                continue
            if child.data == "groups":
                groups = self.groups(child)
            elif child.data == "nouns":
                nouns = self.alternatives(child)
            elif child.data == "coat":
                coat = self.coat(child)
        first, last = self.edges(tree)

        def build(words, tagged, text):
            return ast.Material(None if name is None else words[name],
                                groups(words, tagged) if groups else (),
                                tuple([words[i] for i in nouns]),
                                coat(words, tagged) if coat else None,
                                _span(tagged, first, last), text)
        return build

    def groups(self, tree: Tree):
        parts = [self.group(c) for c in tree.children if isinstance(c, Tree) and c.data in GROUP_RULES]
        return lambda words, tagged: tuple([part(words, tagged) for part in parts])

    def group(self, tree: Tree):
        adverbs, colours, adjectives = (), [], ()
        for child in tree.children:
            if child.data == "advs":
                adverbs = tuple(self.word(t) for t in child.children)
            elif child.data == "colours":
                colours = [self.colour(c) for c in child.children if isinstance(c, Tree)]
            elif child.data == "adjs":
                adjectives = self.alternatives(child)
        kind = tree.data.replace("_group", "")
        first, last = self.edges(tree)

        def build(words, tagged):
            return ast.Group(kind, tuple([words[i] for i in adverbs]),
                             tuple([colour(words, tagged) for colour in colours]),
                             tuple([words[i] for i in adjectives]), _span(tagged, first, last))
        return build

    def colour(self, tree: Tree):
        indices = [self.word(t) for t in tree.children]
        may_have_base = tree.data == "colour"
        first, last = indices[0], indices[-1]

        def build(words, tagged):
            chosen = [words[i] for i in indices]
            base = chosen[-1] if may_have_base and chosen[-1].category in COLOUR_CATEGORIES else None
            return ast.Colour(tuple(chosen[:-1] if base else chosen), base, _span(tagged, first, last))
        return build

    def alternatives(self, tree: Tree) -> tuple:
        return tuple(self.word(t) for t in tree.children if t.type != "OR")

    def coat(self, tree: Tree):
        groups, coat_word = None, None
        for child in tree.children:
            if isinstance(child, Tree):
                groups = self.groups(child)
            elif child.type == "COAT":
                coat_word = self.word(child)
        first, last = self.edges(tree)

        def build(words, tagged):
            return ast.Coat(groups(words, tagged) if groups else (), words[coat_word], _span(tagged, first, last))
        return build

    def refinement(self, tree: Tree, name):
        items = [self.refine_item(c) for c in tree.children if isinstance(c, Tree)]
        first, last = self.edges(tree)

        def build(words, tagged, text):
            return ast.Refinement(None if name is None else words[name],
                                  tuple([item(words, tagged) for item in items]), _span(tagged, first, last), text)
        return build

    def refine_item(self, tree: Tree):
        word = self.word(tree.children[0])
        target = None
        if len(tree.children) > 1:
            t = tree.children[1]
            target = self.colour(t) if isinstance(t, Tree) else _single(self.word(t))
        first, last = self.edges(tree)

        def build(words, tagged):
            return ast.RefineItem(words[word], target(words, tagged) if target else None, _span(tagged, first, last))
        return build


def _single(i: int):
    return lambda words, tagged: words[i]
