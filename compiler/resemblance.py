"""Resemblance (issue #14): what "like X" means when X is a material noun.

`brassy`, `steely`, `pearly`, `leathery`, `silk-like`, `sand coloured`, `chrome finish steel`: a
noun used to describe another material lends it one thing, decided by the noun's class (the
rules are data, `[resemblance]` in word_formation*.toml):

- a noun of a surface class (fabric, leather, glass, rubber, plastic) lends its surface
  character: the describing word of the rules' roughness ladder its roughness falls on
  (silk 0.45: satin; leather 0.6: matte; denim 1.0: rough; glass 0: glossy);
- any other noun lends its apparent colour, as a colour word: the nearest named colour (OKLab
  distance) to its base colour, for a metal base_color x f0 (its colour at normal incidence: a
  metal's base_color is white and its colour is its reflectance), so `coppery`, `brassy`,
  `steely` are the metal's colour on a non-metal;
- a colour head (`sand coloured`, `brass-colored`) always lends the colour, whatever the class;
- a finish head between a noun and a material (`chrome finish steel`) lends what the rules'
  finish_adjectives give its class (a metal: 'plated', so chrome finish steel = chrome plated
  steel), else its colour.

Every reading returns its note text; callers print it as a NOTE.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from .colour import clamp01, linear_to_oklab
from .tagged import Candidate

if TYPE_CHECKING:
    from .lexicon import Lexicon

__all__ = ["Resemblance"]

Found = tuple[Candidate, str]  # the reading and why (for the note)


class Resemblance:
    """The resemblance readings of one lexicon's nouns by the merged [resemblance] rules."""

    __slots__ = ("lexicon", "names", "rules")

    def __init__(self, lexicon: Lexicon, rules: dict[str, Any]) -> None:
        self.lexicon = lexicon
        self.rules = rules
        self.names: list[tuple[str, list[float]]] | None = None  # colour names in OKLab, made on first use

    def noun_entry(self, key: str) -> Any:
        return self.lexicon.entry("nouns", key)

    def is_surface(self, key: str) -> bool:
        entry = self.noun_entry(key)
        return entry is not None and entry.get("class") in self.rules["surface_classes"]

    def like(self, key: str) -> Found | None:
        """'like X' for the noun X: its surface character (surface classes) or its colour."""
        entry = self.noun_entry(key)
        if entry is None:
            return None
        if entry.get("class") in self.rules["surface_classes"]:
            return self.surface(key)
        return self.colour(key)

    def surface(self, key: str) -> Found | None:
        """The describing word of the roughness ladder the noun's roughness falls on."""
        entry = self.noun_entry(key)
        roughness = entry.get("roughness") if entry is not None else None
        ladder = self.rules["surface"]
        if roughness is None or not ladder:
            return None
        adjective = next((a for top, a in ladder if roughness <= top), ladder[-1][1])
        why = f"a {entry.get('class')} lends its surface, roughness {roughness:g}"
        return Candidate("ADJ", adjective, "adjectives"), why

    def colour(self, key: str) -> Found | None:
        """The nearest named colour to the noun's apparent colour (a metal: base_color x f0)."""
        rgb = self.apparent(key)
        if rgb is None:
            return None
        name = self.nearest(rgb)
        metal = self.noun_entry(key).get("f0") is not None
        how = "a metal's colour at normal incidence, base colour x f0" if metal else "its base colour"
        return Candidate("COLOR", name, "colours"), f"the named colour nearest to its colour, {how}"

    def finish(self, key: str, material: str, plating_only: bool = False) -> Found | None:
        """'X finish' before `material`: the class's finish adjective (metal: plated) where it
        applies to the material, else X's colour (none with `plating_only`: the caller has a
        colour word of its own)."""
        entry = self.noun_entry(key)
        if entry is None:
            return None
        adjective = self.rules["finish_adjectives"].get(entry.get("class"))
        if adjective is None or not self._applies(adjective, material):  # gold finish ceramic: its colour
            return None if plating_only else self.colour(key)
        return Candidate(
            "ADJ", adjective, "adjectives"
        ), f"a {entry.get('class')} finish is a plating" if adjective == "plated" else f"a {entry.get('class')} finish"

    def _applies(self, adjective: str, material: str) -> bool:
        """Whether the adjective applies to the material noun's class (its `applies_to`, if any)."""
        entry = self.lexicon.entry("adjectives", adjective)
        target = self.noun_entry(material)
        classes = entry.get("applies_to") if entry is not None else None
        return not classes or target is None or target.get("class") in classes

    def apparent(self, key: str) -> list[float] | None:
        entry = self.noun_entry(key)
        base = entry.get("base_color") if entry is not None else None
        if base is None:
            return None
        f0 = entry.get("f0")
        return clamp01(base if f0 is None else [b * f for b, f in zip(base, f0)])

    def nearest(self, rgb: Sequence[float]) -> str:
        """The colour name (lexicon colours) nearest in OKLab; one word names preferred on a tie."""
        if self.names is None:
            colours = self.lexicon.all_of("colours")
            skipped = frozenset(self.rules["not_nearest"])  # trade names: 'chalky' is not 'glacier'
            self.names = [
                (k, linear_to_oklab(e.get("rgb")))
                for k, e in colours.items()
                if e.get("rgb") is not None and k not in skipped
            ]
        lab = linear_to_oklab(rgb)
        return min(self.names, key=lambda n: (sum((p - q) ** 2 for p, q in zip(lab, n[1])), n[0].count(" ")))[0]
