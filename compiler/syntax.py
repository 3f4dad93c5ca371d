"""lark tree -> AST dataclasses, by way of a reusable *shape*.

A deterministic LALR grammar gives the same tree for the same sequence of terminal types,
so a tree is compiled once into a shape that builds the AST of any line with that terminal
sequence from the line's words, with no parser and no tree walk (parser.parse_line_shape
caches shapes by terminal sequence).

One walk over the tree (_Walk, one method per grammar rule) drives one of two back-ends:

- Closures: nested builder functions. Cheap to make, so a new shape starts with them.
- Source: the text of one flat Python function, compiled once the shape has been used
  PROMOTE_AFTER times (compiling costs a few hundred microseconds; the function then
  builds the AST in about 60% of the closures' time). For "blue anodized aluminum":

      def build(t, p, text):
          w0 = Word(t[0].text, p[0].key, p[0].category, t[0].span, t[0].unknown)
          w1 = ...
          return Material(None, (Group('adjective', (), (colour(t, (w0, ), True, 0, 0), ), (w1, ),
                          span(t, 0, 1)), ), (w2, ), None, span(t, 0, 2), text)

  The source holds only word indices and grammar rule names, never text from the line.

In both, t are the line's tagged words and p the chosen candidate of each.
"""

from __future__ import annotations

from lark import Token, Tree

from . import ast
from .spans import Span

GROUP_RULES = ("adjective_group", "colour_group", "dangling_group")
COLOUR_CATEGORIES = ("colours", "unknown")
PROMOTE_AFTER = 16  # uses of a shape before it is compiled to a Python function


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


class Shape:
    """The compiled tree of one terminal sequence: build(tagged, picks, text) -> AST node."""

    __slots__ = ("tree", "index", "used", "root", "uses", "build")

    def __init__(self, tree: Tree, index: dict):
        self.tree, self.index, self.uses = tree, index, 0
        walk = _Walk(index, _Closures())
        self.root = walk.start(tree)
        self.used = tuple(sorted(walk.used))
        self.build = self._build_with_closures

    def _build_with_closures(self, tagged: list, picks: list, text: str):
        self.uses += 1
        if self.uses == PROMOTE_AFTER:
            self.build = compile_source_builder(self.tree, self.index)
        words, make = [None] * len(tagged), ast.Word
        for i in self.used:
            t, c = tagged[i], picks[i]
            words[i] = make(t.text, c.key, c.category, t.span, t.unknown)
        return self.root(words, tagged, text)


def builder_source(tree: Tree, index: dict) -> str:
    walk = _Walk(index, _Source())
    body = walk.start(tree)
    lines = [
        f"    w{i} = Word(t[{i}].text, p[{i}].key, p[{i}].category, t[{i}].span, t[{i}].unknown)"
        for i in sorted(walk.used)
    ]
    return "def build(t, p, text):\n" + "\n".join([*lines, f"    return {body}"]) + "\n"


def compile_source_builder(tree: Tree, index: dict):
    namespace = {
        "Word": ast.Word,
        "Material": ast.Material,
        "Group": ast.Group,
        "Coat": ast.Coat,
        "Refinement": ast.Refinement,
        "RefineItem": ast.RefineItem,
        "span": span,
        "colour": colour,
    }
    exec(builder_source(tree, index), namespace)
    return namespace["build"]


class _Walk:
    """One method per grammar rule; the back-end makes each node's builder."""

    def __init__(self, index: dict, backend):
        self.index = index  # token start offset -> word index
        self.make = backend
        self.used: set[int] = set()

    def word(self, tok: Token):
        i = self.index[tok.start_pos]
        self.used.add(i)
        return self.make.word(i)

    def words(self, tokens) -> tuple[int, ...]:
        indices = tuple(self.index[t.start_pos] for t in tokens)
        self.used.update(indices)
        return indices

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
        return self.make.material(name, groups, nouns, coat, self.edges(tree))

    def groups(self, tree: Tree):
        return self.make.sequence(
            [self.group(c) for c in tree.children if isinstance(c, Tree) and c.data in GROUP_RULES]
        )

    def group(self, tree: Tree):
        adverbs, colours, adjectives = (), [], ()
        for child in tree.children:
            if child.data == "advs":
                adverbs = self.words(child.children)
            elif child.data == "colours":
                colours = [self.colour(c) for c in child.children if isinstance(c, Tree)]
            elif child.data == "adjs":
                adjectives = self.alternatives(child)
        kind = tree.data.replace("_group", "")
        return self.make.group(kind, adverbs, self.make.sequence(colours), adjectives, self.edges(tree))

    def colour(self, tree: Tree):
        return self.make.colour(self.words(tree.children), tree.data == "colour", self.edges(tree))

    def alternatives(self, tree: Tree) -> tuple[int, ...]:
        return self.words(t for t in tree.children if t.type != "OR")

    def coat(self, tree: Tree):
        groups, coat_word = None, None
        for child in tree.children:
            if isinstance(child, Tree):
                groups = self.groups(child)
            elif child.type == "COAT":
                coat_word = self.word(child)
        return self.make.coat(groups, coat_word, self.edges(tree))

    def refinement(self, tree: Tree, name):
        items = self.make.sequence([self.refine_item(c) for c in tree.children if isinstance(c, Tree)])
        return self.make.refinement(name, items, self.edges(tree))

    def refine_item(self, tree: Tree):
        word, target = self.word(tree.children[0]), None
        if len(tree.children) > 1:
            t = tree.children[1]
            target = self.colour(t) if isinstance(t, Tree) else self.word(t)
        return self.make.refine_item(word, target, self.edges(tree))


class _Closures:
    """Builders as functions of (words, tagged): `words` holds the line's AST Words by index."""

    @staticmethod
    def word(i: int):
        return lambda words, tagged: words[i]

    @staticmethod
    def sequence(parts: list):
        return lambda words, tagged: tuple([part(words, tagged) for part in parts])

    @staticmethod
    def material(name, groups, nouns: tuple, coat, edges):
        first, last = edges

        def build(words, tagged, text):
            return ast.Material(
                name(words, tagged) if name else None,
                groups(words, tagged) if groups else (),
                tuple([words[i] for i in nouns]),
                coat(words, tagged) if coat else None,
                span(tagged, first, last),
                text,
            )

        return build

    @staticmethod
    def group(kind: str, adverbs: tuple, colours, adjectives: tuple, edges):
        first, last = edges

        def build(words, tagged):
            return ast.Group(
                kind,
                tuple([words[i] for i in adverbs]),
                colours(words, tagged),
                tuple([words[i] for i in adjectives]),
                span(tagged, first, last),
            )

        return build

    @staticmethod
    def colour(indices: tuple, may_have_base: bool, edges):
        first, last = edges
        return lambda words, tagged: colour(tagged, tuple([words[i] for i in indices]), may_have_base, first, last)

    @staticmethod
    def coat(groups, coat_word, edges):
        first, last = edges
        return lambda words, tagged: ast.Coat(
            groups(words, tagged) if groups else (),
            coat_word(words, tagged) if coat_word else None,
            span(tagged, first, last),
        )

    @staticmethod
    def refinement(name, items, edges):
        first, last = edges
        return lambda words, tagged, text: ast.Refinement(
            name(words, tagged) if name else None, items(words, tagged), span(tagged, first, last), text
        )

    @staticmethod
    def refine_item(word, target, edges):
        first, last = edges
        return lambda words, tagged: ast.RefineItem(
            word(words, tagged), target(words, tagged) if target else None, span(tagged, first, last)
        )


def _tuple(items) -> str:
    return "(" + "".join(f"{item}, " for item in items) + ")" if items else "()"


def _span(edges) -> str:
    first, last = edges
    return f"t[{first}].span" if first == last else f"span(t, {first}, {last})"


class _Source:
    """Builders as Python expressions over t (tagged words), p (picks), text and w0, w1, ... (Words)."""

    @staticmethod
    def word(i: int) -> str:
        return f"w{i}"

    @staticmethod
    def sequence(parts: list) -> str:
        return _tuple(parts)

    @staticmethod
    def material(name, groups, nouns: tuple, coat, edges) -> str:
        return (
            f"Material({name or 'None'}, {groups or '()'}, {_tuple([f'w{i}' for i in nouns])}, "
            f"{coat or 'None'}, {_span(edges)}, text)"
        )

    @staticmethod
    def group(kind: str, adverbs: tuple, colours: str, adjectives: tuple, edges) -> str:
        return (
            f"Group({kind!r}, {_tuple([f'w{i}' for i in adverbs])}, {colours}, "
            f"{_tuple([f'w{i}' for i in adjectives])}, {_span(edges)})"
        )

    @staticmethod
    def colour(indices: tuple, may_have_base: bool, edges) -> str:
        first, last = edges
        return f"colour(t, {_tuple([f'w{i}' for i in indices])}, {may_have_base}, {first}, {last})"

    @staticmethod
    def coat(groups, coat_word, edges) -> str:
        return f"Coat({groups or '()'}, {coat_word or 'None'}, {_span(edges)})"

    @staticmethod
    def refinement(name, items: str, edges) -> str:
        return f"Refinement({name or 'None'}, {items}, {_span(edges)}, text)"

    @staticmethod
    def refine_item(word: str, target, edges) -> str:
        return f"RefineItem({word}, {target or 'None'}, {_span(edges)})"
