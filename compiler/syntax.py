"""lark tree -> AST dataclasses, by way of a reusable *shape*.

A deterministic LALR grammar gives the same tree for the same sequence of terminal types,
so a tree is compiled once into a shape: one Python function that builds the AST of any
line with that terminal sequence from the line's words, with no parser and no tree walk
(parser.parse_line_shape caches shapes by terminal sequence).

The function is written as source text by one small compiler method per grammar rule, each
returning the expression that builds its node, and then compiled. For "blue anodized
aluminum" it reads:

    def build(t, p, text):
        w0 = Word(t[0].text, p[0].key, p[0].category, t[0].span, t[0].unknown)
        w1 = ...
        return Material(None, (Group('adjective', (), (colour(t, (w0,), True, 0, 0),), (w1,),
                        span(t, 0, 1)),), (w2,), None, span(t, 0, 2), text)

where t are the line's tagged words and p the chosen candidate of each. The source holds
only word indices and grammar rule names, never text from the line.
"""

from __future__ import annotations

from lark import Token, Tree

from . import ast
from .spans import Span

GROUP_RULES = ("adjective_group", "colour_group", "dangling_group")
COLOUR_CATEGORIES = ("colours", "unknown")


def span(tagged: list, first: int, last: int) -> Span:
    """The span from word `first` to word `last` (as Span.to)."""
    a = tagged[first].span
    if first == last:
        return a
    return Span(a.start, max(a.end, tagged[last].span.end), a.line, a.col)


def colour(tagged: list, words: tuple, may_have_base: bool, first: int, last: int) -> ast.Colour:
    """Shades then a colour word; the last word is the base when it is a colour."""
    base = words[-1] if may_have_base and words[-1].category in COLOUR_CATEGORIES else None
    return ast.Colour(words[:-1] if base else words, base, span(tagged, first, last))


NAMESPACE = {"Word": ast.Word, "Material": ast.Material, "Group": ast.Group, "Coat": ast.Coat,
             "Refinement": ast.Refinement, "RefineItem": ast.RefineItem, "span": span, "colour": colour}


class Shape:
    """The compiled tree of one terminal sequence: build(tagged, picks, text) -> AST node."""

    __slots__ = ("build", "source")

    def __init__(self, tree: Tree, index: dict):
        compiler = _Compiler(index)
        body = compiler.start(tree)
        lines = [f"    w{i} = Word(t[{i}].text, p[{i}].key, p[{i}].category, t[{i}].span, t[{i}].unknown)"
                 for i in sorted(compiler.used)]
        self.source = "def build(t, p, text):\n" + "\n".join([*lines, f"    return {body}"]) + "\n"
        namespace = dict(NAMESPACE)
        exec(self.source, namespace)  # noqa: S102 - the source holds word indices and rule names only
        self.build = namespace["build"]


def _tuple(items) -> str:
    items = list(items)
    return "(" + "".join(f"{item}, " for item in items) + ")" if items else "()"


class _Compiler:
    """One method per grammar rule; each returns the source of the expression that builds it."""

    def __init__(self, index: dict):
        self.index = index  # token start offset -> word index
        self.used: set[int] = set()

    def word(self, tok: Token) -> str:
        i = self.index[tok.start_pos]
        self.used.add(i)
        return f"w{i}"

    def span(self, node) -> str:
        first, last = self._edge(node, 0), self._edge(node, -1)
        return f"t[{first}].span" if first == last else f"span(t, {first}, {last})"

    def _edge(self, node, end: int) -> int:
        while isinstance(node, Tree):
            node = node.children[end]
        return self.index[node.start_pos]

    def start(self, tree: Tree) -> str:
        name, body = "None", None
        for child in tree.children:
            if child.data == "name":
                name = self.word(child.children[0])
            else:
                body = child
        if body.data == "material":
            return self.material(body, name)
        return self.refinement(body, name)

    def material(self, tree: Tree, name: str) -> str:
        groups, nouns, coat = "()", "()", "None"
        for child in tree.children:
            if isinstance(child, Token):
                continue
            if child.data == "groups":
                groups = self.groups(child)
            elif child.data == "nouns":
                nouns = self.alternatives(child)
            elif child.data == "coat":
                coat = self.coat(child)
        return f"Material({name}, {groups}, {nouns}, {coat}, {self.span(tree)}, text)"

    def groups(self, tree: Tree) -> str:
        return _tuple(self.group(c) for c in tree.children if isinstance(c, Tree) and c.data in GROUP_RULES)

    def group(self, tree: Tree) -> str:
        adverbs, colours, adjectives = "()", "()", "()"
        for child in tree.children:
            if child.data == "advs":
                adverbs = _tuple(self.word(t) for t in child.children)
            elif child.data == "colours":
                colours = _tuple(self.colour(c) for c in child.children if isinstance(c, Tree))
            elif child.data == "adjs":
                adjectives = self.alternatives(child)
        kind = tree.data.replace("_group", "")
        return f"Group({kind!r}, {adverbs}, {colours}, {adjectives}, {self.span(tree)})"

    def colour(self, tree: Tree) -> str:
        words = _tuple(self.word(t) for t in tree.children)
        first, last = self._edge(tree, 0), self._edge(tree, -1)
        return f"colour(t, {words}, {tree.data == 'colour'}, {first}, {last})"

    def alternatives(self, tree: Tree) -> str:
        return _tuple(self.word(t) for t in tree.children if t.type != "OR")

    def coat(self, tree: Tree) -> str:
        groups, coat_word = "()", "None"
        for child in tree.children:
            if isinstance(child, Tree):
                groups = self.groups(child)
            elif child.type == "COAT":
                coat_word = self.word(child)
        return f"Coat({groups}, {coat_word}, {self.span(tree)})"

    def refinement(self, tree: Tree, name: str) -> str:
        items = _tuple(self.refine_item(c) for c in tree.children if isinstance(c, Tree))
        return f"Refinement({name}, {items}, {self.span(tree)}, text)"

    def refine_item(self, tree: Tree) -> str:
        word, target = self.word(tree.children[0]), "None"
        if len(tree.children) > 1:
            t = tree.children[1]
            target = self.colour(t) if isinstance(t, Tree) else self.word(t)
        return f"RefineItem({word}, {target}, {self.span(tree)})"
