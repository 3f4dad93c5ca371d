"""The syntax tree: what the phrase says, with a span on every node; no parameter values."""

from __future__ import annotations

from dataclasses import dataclass, field

from .records import record
from .spans import Span


@record
class Word:
    """A tagged word: its surface text, its lexicon key and category, and where it stands."""

    text: str
    key: str
    category: str
    span: Span
    unknown: bool = False


@record
class Colour:
    """Shade words then a colour word ("dark slate blue"), or shades alone ("dark")."""

    shades: tuple[Word, ...]
    base: Word | None
    span: Span

    @property
    def words(self) -> tuple[Word, ...]:
        return self.shades + ((self.base,) if self.base else ())


@record
class Group:
    """Adverbs, colour alternatives and adjective alternatives: "lightly brushed", "red or blue anodized"."""

    kind: str  # "adjective" | "colour" | "dangling"
    adverbs: tuple[Word, ...]
    colours: tuple[Colour, ...]
    adjectives: tuple[Word, ...]
    span: Span


@record
class Coat:
    groups: tuple[Group, ...]
    coat: Word
    span: Span


@record
class Material:
    name: Word | None
    groups: tuple[Group, ...]
    nouns: tuple[Word, ...]
    coat: Coat | None
    span: Span
    text: str


@record
class RefineItem:
    word: Word
    target: Word | Colour | None
    span: Span


@record
class Refinement:
    name: Word | None
    items: tuple[RefineItem, ...]
    span: Span
    text: str


@dataclass
class Document:
    filename: str
    source: str
    items: list = field(default_factory=list)
    diagnostics: list = field(default_factory=list)
