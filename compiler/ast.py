"""The syntax tree: what the phrase says, with a span on every node; no parameter values.

The nodes are frozen dataclasses with a hand-written __init__ that fills the instance's
__dict__ (see spans.Span: twice as fast as the generated one, and nodes are made for every
phrase). Equality, hashing, repr, asdict and replace are the dataclass's own.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostics import Diagnostic
from .spans import Span


@dataclass(frozen=True, init=False)
class Word:
    """A tagged word: its surface text, its lexicon key and category, and where it stands."""

    text: str
    key: str
    category: str
    span: Span
    unknown: bool = False

    def __init__(self, text: str, key: str, category: str, span: Span, unknown: bool = False) -> None:
        fields = self.__dict__
        fields["text"] = text
        fields["key"] = key
        fields["category"] = category
        fields["span"] = span
        fields["unknown"] = unknown


@dataclass(frozen=True, init=False)
class Colour:
    """Shade words then a colour word ("dark slate blue"), or shades alone ("dark"); or a colour
    named after a noun ("walnut brown": noun walnut, base brown) or a noun alone before an
    adjective ("chrome plated": noun chrome, no base)."""

    shades: tuple[Word, ...]
    base: Word | None
    span: Span
    noun: Word | None = None

    def __init__(self, shades: tuple[Word, ...], base: Word | None, span: Span, noun: Word | None = None) -> None:
        fields = self.__dict__
        fields["shades"] = shades
        fields["base"] = base
        fields["span"] = span
        fields["noun"] = noun

    @property
    def words(self) -> tuple[Word, ...]:
        if self.noun is not None:  # "dark walnut", "walnut brown": shades, the noun, the colour word
            return (*self.shades, self.noun, *((self.base,) if self.base else ()))
        return self.shades + ((self.base,) if self.base else ())


@dataclass(frozen=True, init=False)
class Group:
    """Adverbs, colour alternatives and adjective alternatives: "lightly brushed", "red or blue anodized"."""

    kind: str  # "adjective" | "colour" | "dangling"
    adverbs: tuple[Word, ...]
    colours: tuple[Colour, ...]
    adjectives: tuple[Word, ...]
    span: Span

    def __init__(
        self,
        kind: str,
        adverbs: tuple[Word, ...],
        colours: tuple[Colour, ...],
        adjectives: tuple[Word, ...],
        span: Span,
    ) -> None:
        fields = self.__dict__
        fields["kind"] = kind
        fields["adverbs"] = adverbs
        fields["colours"] = colours
        fields["adjectives"] = adjectives
        fields["span"] = span


@dataclass(frozen=True, init=False)
class Coat:
    """'with a glossy white varnish': the coat's own groups and its coat word."""

    groups: tuple[Group, ...]
    coat: Word
    span: Span

    def __init__(self, groups: tuple[Group, ...], coat: Word, span: Span) -> None:
        fields = self.__dict__
        fields["groups"] = groups
        fields["coat"] = coat
        fields["span"] = span


@dataclass(frozen=True, init=False)
class Feature:
    """'with fine grey veins': what the surface shows besides a coat; its groups give degree and colour.

    A second coat clause ('with a varnish and a wax') is kept here too, its word a coat: one coat
    per material, the analysis says the second is ignored."""

    groups: tuple[Group, ...]
    word: Word
    span: Span

    def __init__(self, groups: tuple[Group, ...], word: Word, span: Span) -> None:
        fields = self.__dict__
        fields["groups"] = groups
        fields["word"] = word
        fields["span"] = span


@dataclass(frozen=True, init=False)
class Material:
    """A material phrase: optional 'name:', describing groups, the noun alternatives, an optional coat."""

    name: Word | None
    groups: tuple[Group, ...]
    nouns: tuple[Word, ...]
    coat: Coat | None
    span: Span
    text: str
    refinements: tuple[RefineItem, ...] = ()  # an inline comparative: 'shinier' in 'shinier aluminum'
    features: tuple[Feature, ...] = ()  # 'with' clauses that are not the coat: 'with grey veins'

    def __init__(
        self,
        name: Word | None,
        groups: tuple[Group, ...],
        nouns: tuple[Word, ...],
        coat: Coat | None,
        span: Span,
        text: str,
        refinements: tuple[RefineItem, ...] = (),
        features: tuple[Feature, ...] = (),
    ) -> None:
        fields = self.__dict__
        fields["name"] = name
        fields["groups"] = groups
        fields["nouns"] = nouns
        fields["coat"] = coat
        fields["span"] = span
        fields["text"] = text
        fields["refinements"] = refinements
        fields["features"] = features


@dataclass(frozen=True, init=False)
class RefineItem:
    """One refinement ('darker', 'less diffuse') and what it is about ('blue'), if said;
    the adverbs before it ('much' in 'much rougher', 'a bit' in 'a bit glossier')."""

    word: Word
    target: Word | Colour | None
    span: Span
    adverbs: tuple[Word, ...] = ()

    def __init__(self, word: Word, target: Word | Colour | None, span: Span, adverbs: tuple[Word, ...] = ()) -> None:
        fields = self.__dict__
        fields["word"] = word
        fields["target"] = target
        fields["span"] = span
        fields["adverbs"] = adverbs


@dataclass(frozen=True, init=False)
class Refinement:
    """A refinement line: 'darker blue, less diffuse'."""

    name: Word | None
    items: tuple[RefineItem, ...]
    span: Span
    text: str
    coat: Coat | None = None  # a line of 'with' clauses: 'with a glossy varnish' adds a coat
    features: tuple[Feature, ...] = ()  # ... or features: 'with fine scratches'
    groups: tuple[Group, ...] = ()  # a change of describing words: 'make it blue', 'turn it matte black'
    material: Material | None = None  # a change to another material: 'make it walnut', 'switch to brass'
    removed: tuple[Word, ...] = ()  # words taken off the material above: 'lose the brushed look', 'no rust'
    back: str | None = None  # going back on the change above, at this degree: 'go back a bit' (cnlmc.back)

    def __init__(
        self,
        name: Word | None,
        items: tuple[RefineItem, ...],
        span: Span,
        text: str,
        coat: Coat | None = None,
        features: tuple[Feature, ...] = (),
        groups: tuple[Group, ...] = (),
        material: Material | None = None,
        removed: tuple[Word, ...] = (),
        back: str | None = None,
    ) -> None:
        fields = self.__dict__
        fields["name"] = name
        fields["items"] = items
        fields["span"] = span
        fields["text"] = text
        fields["coat"] = coat
        fields["features"] = features
        fields["groups"] = groups
        fields["material"] = material
        fields["removed"] = removed
        fields["back"] = back

    @property
    def changes_material(self) -> bool:
        """The line makes the material above another one (a change to a named material, or words
        taken off it) rather than refining its values."""
        return self.material is not None or bool(self.removed)

    @property
    def keeps_only(self) -> bool:
        """The line changes nothing: it keeps the material as it is ('keep the grain', 'perfect':
        cnlmc.kept)."""
        return not (self.items or self.coat or self.features or self.groups or self.material or self.removed) and (
            self.back is None
        )


Item = Material | Refinement


@dataclass
class Document:
    filename: str
    source: str
    items: list[Item] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
