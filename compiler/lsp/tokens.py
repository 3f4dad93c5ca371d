"""Semantic tokens: every word by its category (the parser's choice), names and comments."""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from ..lexicon import Lexicon
from .incremental import Snapshot
from .lines import comment_start, line_words
from .positions import code_units

TOKEN_TYPES = [
    "noun",
    "adjective",
    "adverb",
    "colour",
    "shade",
    "refinement",
    "property",
    "coat",
    "name",
    "comment",
    "keyword",
]
LEGEND = types.SemanticTokensLegend(token_types=TOKEN_TYPES, token_modifiers=[])
TYPE_OF_CATEGORY = {
    "nouns": "noun",
    "adjectives": "adjective",
    "adverbs": "adverb",
    "colours": "colour",
    "shades": "shade",
    "refinements": "refinement",
    "properties": "property",
    "coats": "coat",
    "features": "coat",  # a feature stands where a coat stands ('with grey veins')
    "name": "name",
    "keyword": "keyword",
}
INDEX = {name: i for i, name in enumerate(TOKEN_TYPES)}


def line_tokens(snapshot: Snapshot, line: int, lexicon: Lexicon) -> list[tuple[int, int, str]]:
    """(start column, end column, token type) on one line, in order."""
    text = snapshot.index.lines[line]
    found = [
        (w.start, w.end, TYPE_OF_CATEGORY[w.category])
        for w in line_words(snapshot, line, lexicon)
        if w.category in TYPE_OF_CATEGORY
    ]
    comment = comment_start(text)
    if comment is not None:
        found.append((comment, len(text), "comment"))
    return sorted(found)


Token = tuple[int, int, int, int]  # line, start and length in code units, token type index


def semantic_tokens(snapshot: Snapshot, lexicon: Lexicon) -> types.SemanticTokens:
    return encode([token for batch in token_batches(snapshot, lexicon) for token in batch])


def token_batches(snapshot: Snapshot, lexicon: Lexicon) -> Iterator[list[Token]]:
    """The tokens of each line, one list per line (the server runs them in time slices)."""
    encoding = snapshot.index.encoding
    for line, text in enumerate(snapshot.index.lines):
        if not text.strip():
            yield []
            continue
        yield [
            (line, code_units(text[:start], encoding), code_units(text[start:end], encoding), INDEX[kind])
            for start, end, kind in line_tokens(snapshot, line, lexicon)
        ]


def encode(tokens: list[Token]) -> types.SemanticTokens:
    """The LSP's relative encoding: each token's line and start as deltas from the one before."""
    data: list[int] = []
    previous_line, previous_start = 0, 0
    for line, start, length, kind in tokens:
        delta_line = line - previous_line
        delta_start = start - previous_start if delta_line == 0 else start
        data += [delta_line, delta_start, length, kind, 0]
        previous_line, previous_start = line, start
    return types.SemanticTokens(data=data)
