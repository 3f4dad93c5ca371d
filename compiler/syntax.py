"""lark tree -> AST, by way of a reusable *shape*.

A deterministic LALR grammar gives the same tree for the same sequence of terminal types, so
a tree is read once into a shape: a small tree of plans that mirrors the AST and holds word
positions where the AST holds words. Shape.build makes the AST of any line with that terminal
sequence from the line's tagged words, with no parser and no tree walk. A ShapeCache keeps the
shapes by the words' candidate tags (parser.parse_line_shape fills it). For "blue anodized
aluminum" (words 0, 1, 2) the shape's root is:

    MaterialPlan(name=None,
                 groups=(GroupPlan("adjective", adverbs=slice(0, 0), colours=(ColourPlan(slice(0, 1), True, 0, 0),),
                                   adjectives=slice(1, 2), first=0, last=1),),
                 nouns=slice(2, 3), coat=None, first=0, last=2)

A plan never holds text from the line: each build reads the words of the line it is given.
"""

from collections.abc import Iterable, Sequence
from typing import NamedTuple

from lark import Token, Tree

from . import ast
from .spans import Span
from .tagged import Candidate, Tagged

GROUP_RULES = ("adjective_group", "colour_group", "dangling_group")
COLOUR_CATEGORIES = ("colours", "unknown")
MAX_SHAPES = 4096  # distinct terminal sequences kept; a full cache starts over
NONE = slice(0, 0)  # no words

Words = tuple[ast.Word, ...]  # the AST words of a line, in order (separators such as 'or' and ',' have none)
ShapeKey = tuple[str | tuple[str, ...], ...]  # the candidate tags of each word

# Plans are read once per terminal sequence and built for every line, so their build methods
# are written for speed: no helper calls for what one expression says (span_of is written out),
# and loops rather than comprehensions (in Python 3.11 each comprehension is a function call). The words of a node
# stand side by side once separators are left out (adverbs; "red or blue"), so a plan holds
# them as a slice of the line's words; its first and last are positions in the tagged line.
# Plans are NamedTuples: immutable, typed, and their code is compiled once into the .pyc (a
# dataclass generates and compiles its methods at every import). This module has no
# `from __future__ import annotations`: NamedTuple would compile every string annotation at
# import. Together ~10 ms of a cold CLI start.
SEPARATORS = frozenset({"ARTICLE", "COMMA", "AND", "OR", "WITH", "OF", "COLON"})  # terminals that make no AST word


def span_of(tagged: Sequence[Tagged], first: int, last: int) -> Span:
    """The span from tagged word `first` to tagged word `last` (as Span.to: words stand in order)."""
    a = tagged[first].span
    return a if first == last else Span(a.start, tagged[last].span.end, a.line, a.col)


class ColourPlan(NamedTuple):
    """Shades then a colour word; the last word is the base when it is a colour (not for shades only)."""

    words: slice
    may_have_base: bool
    first: int  # positions in the line's tagged words, for the span
    last: int
    noun_at: int = -1  # where the noun a colour is named after stands in its words ('walnut brown': 0), or -1

    def build(self, words: Words, tagged: Sequence[Tagged]) -> ast.Colour:
        found = words[self.words]
        a, last = tagged[self.first].span, self.last
        span = a if last == self.first else Span(a.start, tagged[last].span.end, a.line, a.col)
        at = self.noun_at
        if at >= 0:  # shades, the noun, a colour word: "dark walnut", "walnut brown"
            return ast.Colour(found[:at], found[at + 1] if len(found) > at + 1 else None, span, found[at])
        base = found[-1]
        if self.may_have_base and base.category in COLOUR_CATEGORIES:
            return ast.Colour(found[:-1], base, span)
        return ast.Colour(found, None, span)


class GroupPlan(NamedTuple):
    kind: str
    adverbs: slice
    colours: tuple[ColourPlan, ...]
    adjectives: slice
    first: int
    last: int

    def build(self, words: Words, tagged: Sequence[Tagged]) -> ast.Group:
        a, last = tagged[self.first].span, self.last  # the span: a word's own, or first to last word
        colours = []
        for c in self.colours:
            colours.append(c.build(words, tagged))
        return ast.Group(
            self.kind,
            words[self.adverbs],
            tuple(colours),
            words[self.adjectives],
            a if last == self.first else Span(a.start, tagged[last].span.end, a.line, a.col),
        )


class CoatPlan(NamedTuple):
    groups: tuple[GroupPlan, ...]
    coat: int
    first: int
    last: int

    def build(self, words: Words, tagged: Sequence[Tagged]) -> ast.Coat:
        groups = []
        for g in self.groups:
            groups.append(g.build(words, tagged))
        return ast.Coat(tuple(groups), words[self.coat], span_of(tagged, self.first, self.last))

    def build_feature(self, words: Words, tagged: Sequence[Tagged]) -> ast.Feature:
        """A feature clause ('with grey veins'), or a second coat clause, which the analysis reports."""
        groups = tuple([g.build(words, tagged) for g in self.groups])
        return ast.Feature(groups, words[self.coat], span_of(tagged, self.first, self.last))


class RefineItemPlan(NamedTuple):
    word: int
    target: int | ColourPlan | None  # a word (ADJ or PROP), a colour, or nothing
    first: int
    last: int
    adverbs: slice = NONE

    def build(self, words: Words, tagged: Sequence[Tagged]) -> ast.RefineItem:
        target = self.target
        built = words[target] if isinstance(target, int) else None if target is None else target.build(words, tagged)
        a, last = tagged[self.first].span, self.last
        span = a if last == self.first else Span(a.start, tagged[last].span.end, a.line, a.col)
        return ast.RefineItem(words[self.word], built, span, words[self.adverbs])


class MaterialPlan(NamedTuple):
    name: int | None
    groups: tuple[GroupPlan, ...]
    nouns: slice
    coat: CoatPlan | None
    first: int
    last: int
    refinements: tuple[RefineItemPlan, ...] = ()  # an inline comparative before the material
    features: tuple[CoatPlan, ...] = ()  # 'with' clauses besides the (first) coat clause

    def build(self, words: Words, tagged: Sequence[Tagged], text: str) -> ast.Material:
        a, last = tagged[self.first].span, self.last  # the span: a word's own, or first to last word
        groups = []
        for g in self.groups:
            groups.append(g.build(words, tagged))
        refinements: tuple[ast.RefineItem, ...] = ()
        if self.refinements:
            refinements = tuple([r.build(words, tagged) for r in self.refinements])
        features: tuple[ast.Feature, ...] = ()
        if self.features:
            features = tuple([f.build_feature(words, tagged) for f in self.features])
        return ast.Material(
            None if self.name is None else words[self.name],
            tuple(groups),
            words[self.nouns],
            None if self.coat is None else self.coat.build(words, tagged),
            a if last == self.first else Span(a.start, tagged[last].span.end, a.line, a.col),
            text,
            refinements,
            features,
        )


class RefinementPlan(NamedTuple):
    name: int | None
    items: tuple[RefineItemPlan, ...]
    first: int
    last: int
    coat: CoatPlan | None = None  # a line of 'with' clauses
    features: tuple[CoatPlan, ...] = ()

    def build(self, words: Words, tagged: Sequence[Tagged], text: str) -> ast.Refinement:
        a, last = tagged[self.first].span, self.last  # the span: a word's own, or first to last word
        items = []
        for item in self.items:
            items.append(item.build(words, tagged))
        return ast.Refinement(
            None if self.name is None else words[self.name],
            tuple(items),
            a if last == self.first else Span(a.start, tagged[last].span.end, a.line, a.col),
            text,
            None if self.coat is None else self.coat.build(words, tagged),
            tuple([f.build_feature(words, tagged) for f in self.features]),
        )


class Shape:
    """The plan of one terminal sequence's tree: build(tagged, picks, text) -> the line's AST node."""

    __slots__ = ("root", "used")

    def __init__(self, tree: Tree[Token], index: dict[int, int]) -> None:
        tokens = tree.scan_values(lambda v: isinstance(v, Token) and v.type not in SEPARATORS)
        self.used = tuple(sorted(index[tok.start_pos or 0] for tok in tokens))  # tagged positions of the words
        self.root = _Reader(index, {position: i for i, position in enumerate(self.used)}).start(tree)

    def build(self, tagged: Sequence[Tagged], picks: Sequence[Candidate], text: str) -> ast.Item:
        """The AST of a line whose words carry this shape's tags; picks[i] is word i's reading."""
        make = ast.Word
        made = []
        for i in self.used:
            t, c = tagged[i], picks[i]
            made.append(make(t.text, c.key, c.category, t.span, t.unknown))
        words = tuple(made)
        return self.root.build(words, tagged, text)


class ShapeCache(dict[ShapeKey, tuple[Shape, tuple[int, ...] | None]]):
    """Shapes by the candidate tags of a line's words, with the reading chosen for each word.

    The choice is None when every word's first candidate was chosen. A dict (its get is the
    parser's fast path) that put() keeps bounded: at MAX_SHAPES sequences it starts over.
    """

    def put(self, key: ShapeKey, shape: Shape, choice: tuple[int, ...] | None) -> None:
        if len(self) >= MAX_SHAPES:
            self.clear()
        self[key] = (shape, choice)


def _tree(node: Tree[Token] | Token) -> Tree[Token]:
    assert isinstance(node, Tree), node
    return node


def _token(node: Tree[Token] | Token) -> Token:
    assert isinstance(node, Token), node
    return node


class _Reader:
    """One method per grammar rule: lark tree -> plan."""

    def __init__(self, index: dict[int, int], word_of: dict[int, int]) -> None:
        self.index = index  # token start offset -> position in the tagged line
        self.word_of = word_of  # position in the tagged line -> index in the line's AST words

    def word(self, tok: Token) -> int:
        return self.word_of[self.index[tok.start_pos or 0]]

    def words(self, tokens: Iterable[Tree[Token] | Token]) -> slice:
        """These tokens as a slice of the line's words (they stand side by side)."""
        indices = [self.word(_token(t)) for t in tokens]
        assert indices == list(range(indices[0], indices[-1] + 1)), indices
        return slice(indices[0], indices[-1] + 1)

    def edges(self, node: Tree[Token]) -> tuple[int, int]:
        return self._edge(node, 0), self._edge(node, -1)

    def _edge(self, node: Tree[Token] | Token, end: int) -> int:
        while isinstance(node, Tree):
            node = node.children[end]
        return self.index[node.start_pos or 0]

    def start(self, tree: Tree[Token]) -> MaterialPlan | RefinementPlan:
        name, body = None, None
        for child in tree.children:
            child = _tree(child)
            if child.data == "name":
                name = self.word(_token(child.children[0]))
            else:
                body = child
        assert body is not None, "the grammar's start rule has a material or a refinement"
        if body.data == "material":
            return self.material(body, name)
        return self.refinement(body, name)

    def material(self, tree: Tree[Token], name: int | None) -> MaterialPlan:
        groups: tuple[GroupPlan, ...] = ()
        nouns = NONE
        coat: CoatPlan | None = None
        features: tuple[CoatPlan, ...] = ()
        refinements: tuple[RefineItemPlan, ...] = ()
        children = [
            c for t in tree.children for c in (t.children if isinstance(t, Tree) and t.data == "tail" else (t,))
        ]
        for child in children:
            if isinstance(child, Token):
                continue  # the article
            if child.data == "groups":
                groups = self.groups(child)
            elif child.data == "postfix":  # "Oak, oiled": after the groups before the noun
                groups = groups + self.groups(_tree(child.children[1]))
            elif child.data == "nouns":
                nouns = self.alternatives(child)
            elif child.data == "clauses":
                coat, features = self.clauses(child)
            elif child.data == "in_colour":  # "steel in charcoal": the colour of the material
                groups = groups + self.groups(child)
            elif child.data == "refine_item":
                refinements = (self.refine_item(child),)
        return MaterialPlan(name, groups, nouns, coat, *self.edges(tree), refinements, features)

    def clauses(self, tree: Tree[Token]) -> tuple[CoatPlan | None, tuple[CoatPlan, ...]]:
        """The first coat clause is the coat; features and any further coat clause are features."""
        coat, features = None, []
        with_at = None  # a clause's span starts at its 'with'
        for child in tree.children:
            if isinstance(child, Token):
                with_at = self.index[child.start_pos or 0] if child.type == "WITH" else None
                continue
            plan = self.coat(child)
            if with_at is not None:
                plan = plan._replace(first=with_at)
            if child.data == "coat" and coat is None:
                coat = plan
            else:
                features.append(plan)
        return coat, tuple(features)

    def groups(self, tree: Tree[Token]) -> tuple[GroupPlan, ...]:
        return tuple([self.group(c) for c in tree.children if isinstance(c, Tree) and c.data in GROUP_RULES])

    def group(self, tree: Tree[Token]) -> GroupPlan:
        adverbs = adjectives = NONE
        colours: tuple[ColourPlan, ...] = ()
        for child in tree.children:
            child = _tree(child)
            if child.data == "advs":
                adverbs = self.words(child.children)
            elif child.data == "colours":
                colours = tuple([self.colour(c) for c in child.children if isinstance(c, Tree)])
            elif child.data == "noun_colour":
                colours = (self.colour(child),)
            elif child.data == "adjs":
                adjectives = self.alternatives(child)
        kind = str(tree.data).replace("_group", "")
        return GroupPlan(kind, adverbs, colours, adjectives, *self.edges(tree))

    def colour(self, tree: Tree[Token]) -> ColourPlan:
        noun_at = 0 if tree.data == "noun_colour" else -1  # NOUN [COLOR]
        return ColourPlan(self.words(tree.children), tree.data == "colour", *self.edges(tree), noun_at)

    def alternatives(self, tree: Tree[Token]) -> slice:
        return self.words(t for t in tree.children if _token(t).type != "OR")

    def coat(self, tree: Tree[Token]) -> CoatPlan:
        groups: tuple[GroupPlan, ...] = ()  # the words before the coat or feature, then a colour after 'of'
        coat_word = None
        for child in tree.children:
            if isinstance(child, Tree) and child.data == "shaded_noun_tint":  # SHADE+ NOUN: one named colour
                colour = ColourPlan(self.words(child.children), False, *self.edges(child), len(child.children) - 1)
                groups += (GroupPlan("colour", NONE, (colour,), NONE, *self.edges(child)),)
            elif isinstance(child, Tree):
                groups += (self.group(child),) if child.data in GROUP_RULES else self.groups(child)
            elif child.type in ("COAT", "FEATURE"):
                coat_word = self.word(child)
        assert coat_word is not None, "the grammar's clause rules end with a COAT or FEATURE word"
        return CoatPlan(groups, coat_word, *self.edges(tree))

    def refinement(self, tree: Tree[Token], name: int | None) -> RefinementPlan:
        first = tree.children[0]
        if isinstance(first, Tree) and first.data == "clauses":
            return RefinementPlan(name, (), *self.edges(tree), *self.clauses(first))
        items = tuple([self.refine_item(c) for c in tree.children if isinstance(c, Tree)])
        return RefinementPlan(name, items, *self.edges(tree))

    def refine_item(self, tree: Tree[Token]) -> RefineItemPlan:
        children = list(tree.children)
        adverbs = NONE
        first = children[0]
        if isinstance(first, Tree) and first.data == "advs":
            adverbs = self.words(first.children)
            children = children[1:]
        word = self.word(_token(children[0]))
        target: int | ColourPlan | None = None
        if len(children) > 1:
            t = children[1]
            target = self.colour(t) if isinstance(t, Tree) else self.word(t)
        return RefineItemPlan(word, target, *self.edges(tree), adverbs)
