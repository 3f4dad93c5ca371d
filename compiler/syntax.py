"""Parse tree -> AST, by way of a reusable *shape*.

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

from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, NamedTuple

from . import ast
from .spans import Span
from .tagged import Candidate, Tagged

if TYPE_CHECKING:
    from .shape_store import StoredShapes

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
    """The plan of one terminal sequence's tree: build(tagged, picks, text) -> the line's AST node.

    `used` holds the positions in the tagged line of the words that become AST words (not the
    separators); `root` is the line's plan. shape_reader.read_shape makes one from lark's tree;
    shape_store.decode_entry from its stored form (so a start whose shapes are all stored never
    loads lark)."""

    __slots__ = ("root", "used")

    def __init__(self, used: tuple[int, ...], root: "MaterialPlan | RefinementPlan") -> None:
        self.used = used
        self.root = root

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Shape) and (self.used, self.root) == (other.used, other.root)

    __hash__ = None  # type: ignore[assignment]  # compared by value, never a key

    def build(self, tagged: Sequence[Tagged], picks: Sequence[Candidate], text: str) -> ast.Item:
        """The AST of a line whose words carry this shape's tags; picks[i] is word i's reading."""
        make = ast.Word
        made = []
        implied = False
        for i in self.used:
            t, c = tagged[i], picks[i]
            if t.implied_by is None:
                made.append(make(t.text, c.key, c.category, t.span, t.unknown))
            else:  # a word no one typed ('wood' in 'satin varnish'): the span of the word that implies it
                made.append(make(t.text, c.key, c.category, t.implied_by, t.unknown))
                implied = True
        words = tuple(made)
        if not implied:
            return self.root.build(words, tagged, text)
        shown = _shown(tagged)
        item = self.root.build(words, shown, text)
        if isinstance(item, ast.Material):  # from its first typed word to its last ('satin varnish')
            spans = [shown[i].span for i in self.used]
            first = min(spans, key=lambda s: s.start)
            end = max(s.end for s in spans)
            if (first.start, end) != (item.span.start, item.span.end):
                item = replace(item, span=Span(first.start, end, first.line, first.col))
        return item


class ShapeCache(dict[ShapeKey, tuple[Shape, tuple[int, ...] | None]]):
    """Shapes by the candidate tags of a line's words, with the reading chosen for each word.

    The choice is None when every word's first candidate was chosen. A dict (its get is the
    parser's fast path) that put() keeps bounded: at MAX_SHAPES sequences it starts over.

    A persistent cache (the default) also recalls shapes kept in the disk cache by earlier runs
    (shape_store.recall_shape, the store read on the first miss, kept in `stored`), and
    shape_store.save_shapes writes the shapes this process read to it: a start whose lines all
    have stored shapes never loads lark. With persistent=False it lives in memory only.
    """

    def __init__(self, persistent: bool = True) -> None:
        super().__init__()
        self.persistent = persistent
        self.fresh = 0  # shapes the parser read since the store was last written
        self.stored: StoredShapes | None = None  # shape_store's, read on the first miss

    def put(self, key: ShapeKey, shape: Shape, choice: tuple[int, ...] | None, fresh: bool = True) -> None:
        if len(self) >= MAX_SHAPES:
            self.clear()
        self[key] = (shape, choice)
        self.fresh += fresh


def _shown(tagged: Sequence[Tagged]) -> list[Tagged]:
    """The words of a line with an implied word's span that of the word implying it (the tree's spans)."""
    return [t if t.implied_by is None else Tagged(t.text, t.implied_by, t.candidates, t.unknown) for t in tagged]
