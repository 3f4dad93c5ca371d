"""Completion from the grammar and the lexicon.

The words before the cursor are tagged and fed to the LALR parser (every candidate tag of an
ambiguous word is tried); `accepts()` of the surviving parser states says which terminals may
come next, and the lexicon lists the entries of those categories. Adjectives are offered only
where they apply to the line's noun, and nouns only where the line's adjectives apply to them.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from lark import Token
from lark.exceptions import UnexpectedInput
from lark.parsers.lalr_interactive_parser import InteractiveParser
from lsprotocol import types

from ..lexicon import CATEGORY_TAGS, Entry, Lexicon
from ..parser import lark_parser
from ..tagged import Tagged
from .entries import CATEGORY_NAMES, effect_lines, entry_markdown
from .incremental import Snapshot
from .lines import comment_start, tag_text

PARTIAL_RE = re.compile(r"[^\W\d_][\w'’\-]*$")
MAX_BRANCHES = 256
CATEGORY_OF_TAG = {tag: category for category, tag in CATEGORY_TAGS.items()}
KEYWORDS = {"WITH": "with", "OR": "or", "AND": "and"}
DEFAULT_ORDER = (
    "nouns",
    "adjectives",
    "colours",
    "shades",
    "adverbs",
    "coats",
    "features",
    "refinements",
    "properties",
)
ORDER_AFTER = {  # what to list first after the word before the cursor
    "ADV": ("adjectives", "adverbs", "colours", "shades"),
    "WITH": ("coats", "features", "adjectives", "colours", "shades", "adverbs"),
    "SHADE": ("colours", "shades"),
    "COLOR": ("adjectives", "nouns"),
    "REFINE": ("colours", "properties", "adjectives"),
}
KINDS = {
    "nouns": types.CompletionItemKind.Class,
    "adjectives": types.CompletionItemKind.Function,
    "adverbs": types.CompletionItemKind.Operator,
    "colours": types.CompletionItemKind.Color,
    "shades": types.CompletionItemKind.Color,
    "refinements": types.CompletionItemKind.Event,
    "properties": types.CompletionItemKind.Property,
    "coats": types.CompletionItemKind.Struct,
    "features": types.CompletionItemKind.Struct,
}


@dataclass(frozen=True)
class LineContext:
    """What the rest of the line says about fitting words: its noun and its adjectives."""

    noun: Entry | None
    adjectives: tuple[Entry, ...]


def complete(snapshot: Snapshot, position: types.Position, lexicon: Lexicon) -> types.CompletionList | None:
    found = snapshot.index.line_col(position)
    if found is None:
        return None
    line, col = found
    text = snapshot.index.lines[line]
    prefix = text[:col]
    if comment_start(prefix) is not None:
        return types.CompletionList(is_incomplete=False, items=[])
    match = PARTIAL_RE.search(prefix)
    partial = match.group() if match else ""
    start = col - len(partial)
    before = [t for t in tag_text(prefix[:start], lexicon) if t.candidates]
    accepted = accepted_terminals(before)
    previous = previous_tag(before)
    if previous == "ADV":
        accepted.discard("NOUN")  # 'lightly aluminum' parses, but only to warn W103
    context = line_context(text, start, col, lexicon)
    where = snapshot.index.range_of(line, start, col)
    order = category_order(previous)
    items = [
        *lexicon_items(accepted, partial, context, where, lexicon, order),
        *keyword_items(accepted, partial, where),
    ]
    return types.CompletionList(is_incomplete=False, items=items)


def previous_tag(words: list[Tagged]) -> str | None:
    """The tag of the word before the cursor ('with a' counts as WITH)."""
    tags = [w.candidates[0].tag for w in words]
    if len(tags) >= 2 and tags[-1] == "ARTICLE" and tags[-2] == "WITH":
        return "WITH"
    return tags[-1] if tags else None


def category_order(previous: str | None) -> dict[str, int]:
    first = ORDER_AFTER.get(previous, ()) if previous is not None else ()
    ordered = [*first, *(c for c in DEFAULT_ORDER if c not in first)]
    return {category: i for i, category in enumerate(ordered)}


def accepted_terminals(words: list[Tagged]) -> set[str]:
    """Terminals the parser accepts after `words`, over every reading of ambiguous words."""
    accepted: set[str] = set()
    budget = [MAX_BRANCHES]

    def walk(ip: InteractiveParser, i: int) -> None:
        if i == len(words):
            accepted.update(ip.accepts())
            return
        for cand in words[i].candidates:
            if budget[0] <= 0:
                return
            budget[0] -= 1
            branch = ip.copy()
            try:
                branch.feed_token(Token(cand.tag, words[i].text, words[i].span.start))
            except UnexpectedInput:
                continue
            walk(branch, i + 1)

    walk(lark_parser().parse_interactive(), 0)
    return accepted


def line_context(text: str, start: int, end: int, lexicon: Lexicon) -> LineContext:
    """The noun and adjectives of the line, ignoring the word being typed."""
    words = [t for t in tag_text(text, lexicon) if t.candidates and not (t.span.start < end and t.span.end > start)]
    with_at = next((t.span.start for t in words if any(c.tag == "WITH" for c in t.candidates)), len(text) + 1)
    nouns = [c for t in words if t.span.start < with_at for c in t.candidates if c.tag == "NOUN"]
    noun = lexicon.entry("nouns", nouns[-1].key) if nouns else None
    adjectives = tuple(
        lexicon.entry("adjectives", c.key)
        for t in words
        if t.span.start < with_at
        for c in t.candidates[:1]
        if c.tag == "ADJ"
    )
    return LineContext(noun, tuple(a for a in adjectives if a is not None))


def applies(adjective: Entry, noun: Entry | None) -> bool:
    classes = adjective.get("applies_to")
    return not classes or noun is None or noun.get("class") in classes or noun.key in classes


def fits(entry: Entry, context: LineContext) -> bool:
    if entry.category == "adjectives":
        return applies(entry, context.noun)
    if entry.category == "nouns":
        return all(applies(adjective, entry) for adjective in context.adjectives)
    return True


def surface_for(entry: Entry, partial: str) -> str | None:
    """The key, or the first alias, that starts with what was typed."""
    typed = partial.lower()
    surfaces: list[str] = [entry.key, *entry.get("aliases", [])]
    for surface in surfaces:
        if surface.lower().startswith(typed):
            return surface
    return None


def lexicon_items(
    accepted: set[str], partial: str, context: LineContext, where: types.Range, lexicon: Lexicon, order: dict[str, int]
) -> Iterator[types.CompletionItem]:
    for tag in sorted(accepted):
        category = CATEGORY_OF_TAG.get(tag)
        if category is None:
            continue
        for position, entry in enumerate(lexicon.all_of(category).values()):
            surface = surface_for(entry, partial)
            if surface is None or not fits(entry, context):
                continue
            yield completion_item(entry, surface, where, order[category], position)


def completion_item(
    entry: Entry, surface: str, where: types.Range, rank: int, position: int = 0
) -> types.CompletionItem:
    """An item sorted by its category's rank, then by where the lexicon declares it: the stdlib
    files list the common words first (varnish, lacquer and clear coat before wax)."""
    effects = effect_lines(entry)
    detail = CATEGORY_NAMES[entry.category] + (f": {effects[0]}" if effects else "")
    return types.CompletionItem(
        label=surface,
        kind=KINDS[entry.category],
        detail=detail,
        documentation=types.MarkupContent(types.MarkupKind.Markdown, entry_markdown(entry, surface)),
        sort_text=f"{rank}_{position:05d}_{surface}",
        filter_text=surface,
        text_edit=types.TextEdit(where, surface),
    )


def keyword_items(accepted: set[str], partial: str, where: types.Range) -> Iterator[types.CompletionItem]:
    for tag, word in KEYWORDS.items():
        if tag in accepted and word.startswith(partial.lower()):
            yield types.CompletionItem(
                label=word,
                kind=types.CompletionItemKind.Keyword,
                sort_text=f"9_{word}",
                text_edit=types.TextEdit(where, word),
            )
