"""lark tree -> AST dataclasses. One small builder per grammar rule."""

from __future__ import annotations

from lark import Token, Tree

from . import ast
from .spans import Span


GROUP_RULES = ("adjective_group", "colour_group", "dangling_group")


class TreeToAst:
    """Builds AST nodes; `words` maps a token's start offset to its tagged word."""

    def __init__(self, words: dict, chosen: dict, text: str):
        self.words = words
        self.chosen = chosen
        self.text = text

    def word(self, tok: Token) -> ast.Word:
        tagged = self.words[tok.start_pos]
        cand = self.chosen[tok.start_pos]
        return ast.Word(tagged.text, cand.key, cand.category, tagged.span, tagged.unknown)

    def build(self, tree: Tree):
        name, body = None, None
        for child in tree.children:
            if child.data == "name":
                name = self.word(child.children[0])
            else:
                body = child
        if body.data == "material":
            return self.material(body, name)
        return self.refinement(body, name)

    def material(self, tree: Tree, name) -> ast.Material:
        groups, nouns, coat = (), (), None
        for child in tree.children:
            if isinstance(child, Token):
                continue
            if child.data == "groups":
                groups = self.groups(child)
            elif child.data == "nouns":
                nouns = self.alternatives(child)
            elif child.data == "coat":
                coat = self.coat(child)
        return ast.Material(name, groups, nouns, coat, self.span_of(tree), self.text)

    def groups(self, tree: Tree) -> tuple:
        return tuple(self.group(c) for c in tree.children if isinstance(c, Tree) and c.data in GROUP_RULES)

    def group(self, tree: Tree) -> ast.Group:
        adverbs, colours, adjectives = (), (), ()
        for child in tree.children:
            if child.data == "advs":
                adverbs = tuple(self.word(t) for t in child.children)
            elif child.data == "colours":
                colours = tuple(self.colour(c) for c in child.children if isinstance(c, Tree))
            elif child.data == "adjs":
                adjectives = self.alternatives(child)
        kind = tree.data.replace("_group", "")
        return ast.Group(kind, adverbs, colours, adjectives, self.span_of(tree))

    def colour(self, tree: Tree) -> ast.Colour:
        words = [self.word(t) for t in tree.children]
        base = words[-1] if tree.data == "colour" and words[-1].category in ("colours", "unknown") else None
        shades = tuple(words[:-1] if base else words)
        return ast.Colour(shades, base, self.span_of(tree))

    def alternatives(self, tree: Tree) -> tuple:
        return tuple(self.word(t) for t in tree.children if t.type not in ("OR",))

    def coat(self, tree: Tree) -> ast.Coat:
        groups, coat_word = (), None
        for child in tree.children:
            if isinstance(child, Tree):
                groups = self.groups(child)
            elif child.type == "COAT":
                coat_word = self.word(child)
        return ast.Coat(groups, coat_word, self.span_of(tree))

    def refinement(self, tree: Tree, name) -> ast.Refinement:
        items = tuple(self.refine_item(c) for c in tree.children if isinstance(c, Tree))
        return ast.Refinement(name, items, self.span_of(tree), self.text)

    def refine_item(self, tree: Tree) -> ast.RefineItem:
        word = self.word(tree.children[0])
        target = None
        if len(tree.children) > 1:
            t = tree.children[1]
            target = self.colour(t) if isinstance(t, Tree) else self.word(t)
        return ast.RefineItem(word, target, self.span_of(tree))

    def span_of(self, tree: Tree) -> Span:
        return self._edge(tree, 0).to(self._edge(tree, -1))

    def _edge(self, node, index: int) -> Span:
        """The span of the first (index 0) or last (-1) token under a node."""
        while isinstance(node, Tree):
            node = node.children[index]
        return self.words[node.start_pos].span
