"""Semantic tokens: every word by its category (the parser's choice), names and comments."""

from __future__ import annotations

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


def semantic_tokens(snapshot: Snapshot, lexicon: Lexicon) -> types.SemanticTokens:
    data: list[int] = []
    encoding = snapshot.index.encoding
    previous_line, previous_start = 0, 0
    for line, text in enumerate(snapshot.index.lines):
        if not text.strip():
            continue
        for start, end, kind in line_tokens(snapshot, line, lexicon):
            unit_start = code_units(text[:start], encoding)
            length = code_units(text[start:end], encoding)
            delta_line = line - previous_line
            delta_start = unit_start - previous_start if delta_line == 0 else unit_start
            data += [delta_line, delta_start, length, INDEX[kind], 0]
            previous_line, previous_start = line, unit_start
    return types.SemanticTokens(data=data)
