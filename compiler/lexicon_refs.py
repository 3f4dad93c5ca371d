"""Checks between entries, once every layer is merged: a name an entry uses must exist.

A noun's or adjective's coat is a coat entry; an adjective's `material` a metal noun; its
`applies_to` and `on` names are nouns or noun classes; `opposes` names adjectives; a
refinement's target is 'colour', 'any' or a property; a property names exactly one of a
parameter or a graph parameter. Each complaint points at the file that set the field.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

from .graphs import all_graph_params
from .lexicon_schema import Checker, did_you_mean
from .lexicon_source import SourceText
from .params import PARAMS

#: What a property's `param` may name: a scalar parameter, the base colour, or the saturation.
PROPERTY_PARAMS = (*(s.name for s in PARAMS if s.kind == "number"), "base_color", "saturation")
REFINEMENT_TARGETS = ("colour", "any")
CONDUCTOR_OPTICS = ("eta", "k", "f0", "f82")


@dataclass
class RawEntry:
    """One entry while layers merge: its fields and the file each field came from."""

    data: dict[str, Any]
    source: SourceText  # the most specific file that has the entry (its origin)
    field_sources: dict[str, SourceText] = field(default_factory=dict)

    def checker(self, name: str) -> Checker:
        return Checker(self.field_sources.get(name, self.source))


Raw = dict[str, dict[str, RawEntry]]  # category -> key -> entry


class References:
    """The names entries may refer to, from the merged layers."""

    def __init__(self, raw: Raw) -> None:
        self.raw = raw
        nouns = raw["nouns"]
        self.noun_names = set(nouns) | {e.data["class"] for e in nouns.values() if isinstance(e.data.get("class"), str)}

    def check(self) -> None:
        for key, entry in self.raw["nouns"].items():
            self._name(entry, key, "coat", self.raw["coats"], "coat")
            self._optics(key, entry)
        for key, entry in self.raw["adjectives"].items():
            self._adjective(key, entry)
        for key, entry in self.raw["refinements"].items():
            self._refinement(key, entry)
        for key, entry in self.raw["properties"].items():
            self._property(key, entry)
        for key, entry in self.raw["objects"].items():  # "planks" alone reads as its material noun
            self._name(entry, key, "material", self.raw["nouns"], "noun")

    def _name(self, entry: RawEntry, key: str, name: str, known: Collection[str], what: str) -> None:
        value = entry.data.get(name)
        if value is not None and value not in known:
            entry.checker(name).fail((key, name), f"no {what} named '{value}'{did_you_mean(value, known)}")

    def _names(self, entry: RawEntry, key: str, name: str, known: Collection[str], what: str) -> None:
        for i, value in enumerate(entry.data.get(name, [])):
            if value not in known:
                entry.checker(name).fail((key, name, i), f"no {what} named '{value}'{did_you_mean(value, known)}")

    def _optics(self, key: str, entry: RawEntry) -> None:
        """A metal noun carries its measured optics: eta, k, f0 and f82."""
        if entry.data.get("model") != "conductor":
            return
        missing = [p for p in CONDUCTOR_OPTICS if p not in entry.data]
        if missing:
            entry.checker("model").fail(
                (key,),
                f"a conductor (model = 'conductor') needs its optics {', '.join(CONDUCTOR_OPTICS)}; missing: "
                f"{', '.join(missing)} (f0 and f82 are the reflectances at 0 degrees and at acos(1/7); "
                "cnlmc.bsdf.fresnel.fresnel_conductor(cos, eta, k) computes them from eta and k)",
            )

    def _adjective(self, key: str, entry: RawEntry) -> None:
        self._name(entry, key, "coat", self.raw["coats"], "coat")
        self._names(entry, key, "applies_to", self.noun_names, "noun or noun class")
        self._names(entry, key, "opposes", self.raw["adjectives"], "adjective")
        self._name(entry, key, "opposite", self.raw["adjectives"], "adjective")  # what 'not X' reads as
        for table in ("on", "features_on"):
            for target in entry.data.get(table, {}):
                if target not in self.noun_names:
                    hint = did_you_mean(target, self.noun_names)
                    entry.checker(table).fail((key, table, target), f"no noun or noun class named '{target}'{hint}")
        for target, feature in entry.data.get("features_on", {}).items():
            if feature not in self.raw["features"]:
                hint = did_you_mean(str(feature), self.raw["features"])
                entry.checker("features_on").fail((key, "features_on", target), f"no feature named '{feature}'{hint}")
        metal = entry.data.get("material")
        if metal is not None:
            self._name(entry, key, "material", self.raw["nouns"], "noun")
            if self.raw["nouns"][metal].data.get("model") != "conductor":
                entry.checker("material").fail((key, "material"), f"'{metal}' is not a metal (model = 'conductor')")

    def _refinement(self, key: str, entry: RawEntry) -> None:
        targets = (*REFINEMENT_TARGETS, *self.raw["properties"])
        self._name(entry, key, "target", targets, "refinement target (a property, 'colour' or 'any')")
        target = entry.data.get("target")
        if target != "colour" and "step" in entry.data:
            where = f"properties.{target}.step" if target != "any" else "the step of the property it names"
            entry.checker("step").fail(
                (key, "step"), f"a step is used only with target = 'colour' (here {where} applies)"
            )
        if target == "colour" and "step" not in entry.data and "ops" not in entry.data:
            entry.checker("target").fail(
                (key,), "a refinement of the colour needs a step, e.g. step = { op = 'mul', value = 0.5 }, or ops"
            )
        if target != "colour" and ("ops" in entry.data or "axis" in entry.data):
            field = "ops" if "ops" in entry.data else "axis"
            entry.checker(field).fail(
                (key, field), f"'{field}' belongs to a refinement of the colour (target = 'colour')"
            )

    def _property(self, key: str, entry: RawEntry) -> None:
        named = [n for n in ("param", "map_param") if n in entry.data]
        if len(named) != 1:
            here = [n for n in named if entry.field_sources.get(n) is entry.source] or named  # the newest file's
            path = (key, here[0]) if here else (key,)
            entry.checker(here[0] if here else "").fail(
                path, "a property names exactly one of param = (a material parameter) or map_param = (a graph's)"
            )
        self._name(entry, key, "param", PROPERTY_PARAMS, "parameter a property can change")
        self._name(entry, key, "map_param", sorted(all_graph_params()), "graph parameter")
        self._name(entry, key, "draws", self.raw["features"], "feature")
        step = entry.data.get("step", {})
        if step.get("op") == "blend" and entry.data.get("param") != "base_color":
            entry.checker("step").fail(
                (key, "step", "op"), "a blend step moves towards a colour: it is for param = 'base_color' only"
            )
