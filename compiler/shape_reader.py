"""lark's parse tree -> a Shape (syntax.py): the only place a tree is read, so lark is loaded
only when a line's shape is neither in memory nor stored (parser._read_shape)."""

from collections.abc import Iterable

from lark import Token, Tree

from .syntax import (
    GROUP_RULES,
    NONE,
    SEPARATORS,
    CoatPlan,
    ColourPlan,
    GroupPlan,
    MaterialPlan,
    RefineItemPlan,
    RefinementPlan,
    Shape,
)


def read_shape(tree: Tree[Token], index: dict[int, int]) -> Shape:
    """The shape of `tree`; index: token start offset -> position in the tagged line."""
    tokens = tree.scan_values(lambda v: isinstance(v, Token) and v.type not in SEPARATORS)
    used = tuple(sorted(index[tok.start_pos or 0] for tok in tokens))  # tagged positions of the words
    root = _Reader(index, {position: i for i, position in enumerate(used)}).start(tree)
    return Shape(used, root)


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
                groups = groups + self.groups(_tree(child.children[-1]))  # past the comma (and 'but')
            elif child.data == "nouns":
                nouns = self.alternatives(child)
            elif child.data == "clauses":
                coat, features = self.clauses(child)
            elif child.data == "in_colour":  # "steel in charcoal": the colour of the material
                groups = groups + self.groups(child)
            elif child.data == "refine_item":
                refinements += (self.refine_item(child),)
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
        items = tuple([self.refine_item(c) for c in tree.children if isinstance(c, Tree) and c.data == "refine_item"])
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
