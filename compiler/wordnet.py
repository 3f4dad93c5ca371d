"""WordNet readings of unknown words (issue #14): "alder" is a kind of wood, "burnished" ~ polished.

The data is stdlib/data/wordnet_aliases.toml (WordNet 3.0, Princeton University 2006; generated
by scripts/gen_wordnet_aliases.py, English only). Which of it is used is a word formation rule
([wordnet] in word_formation*.toml): `noun_roots` maps a WordNet root the lexicon has no noun
for to one it has ("rock" -> stone), and `adjectives` lists the stdlib adjectives whose
first-sense WordNet synonyms may stand for them (only those whose first sense is the visual one:
"dull" is "boring" first, so it is not listed). The lexicon stays the authority: a word it knows
never comes here, and every reading says it came from WordNet.

The file is read when the first unknown word that no other rule reads needs it (through the
on-disk cache, cnlmc.cache), by the WordNet object of one WordFormation (cnlmc.word_formation),
and kept with it.
"""

from __future__ import annotations

import tomllib
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from .cache import cached, dump_json, load_json
from .tagged import Candidate
from .word_formation_rules import wordnet_file

__all__ = ["WordNet"]

Lookup = Callable[[tuple[str, ...]], tuple[Candidate, ...]]


class WordNet:
    """Nouns by their WordNet hypernyms, adjectives by their WordNet synonyms; see the module doc."""

    def __init__(self, rules: Mapping[str, Any], lookup: Lookup) -> None:
        data = _wordnet_data(rules["file"]) if rules["file"] else {}
        self.nouns: dict[str, Any] = data.get("nouns", {})
        self.noun_roots: dict[str, str] = dict(rules["noun_roots"])
        self.lookup = lookup
        self.synonyms = _synonym_index(data.get("adjectives", {}), rules["adjectives"])

    def noun(self, word: str) -> tuple[Candidate, str] | None:
        """The lexicon noun nearest above `word` in WordNet, and the note that says so."""
        found = self.nouns.get(word)
        if found is None:
            return None
        above = [*found.get("kind_of", ()), found.get("root", "")]
        for kind in above:
            noun = self._noun_named(kind) or self._noun_named(self.noun_roots.get(kind, ""))
            if noun is not None:
                gloss = found.get("gloss", "")
                return noun, f"read '{word}' as a kind of {kind} (WordNet 3.0: {gloss})"
        return None

    def adjective(self, word: str) -> tuple[Candidate, str] | None:
        """The stdlib adjective `word` is a WordNet synonym of, and the note that says so."""
        name = self.synonyms.get(word)
        if name is None:
            return None
        found = next((c for c in self.lookup((name,)) if c.tag == "ADJ"), None)
        if found is None:
            return None
        return found, f"read '{word}' as '{name}' (a synonym in WordNet 3.0)"

    def _noun_named(self, name: str) -> Candidate | None:
        if not name:
            return None
        return next((c for c in self.lookup(tuple(name.split())) if c.tag == "NOUN"), None)


def _wordnet_data(name: str) -> dict[str, Any]:
    """The file's [nouns] and [adjectives] tables; parsed once per file version (the TOML takes
    ~0.2 s), then read from the on-disk cache as JSON (cnlmc.cache, ~10 ms)."""
    path = Path(str(wordnet_file(name)))
    here = Path(__file__)
    return cached("wordnet", [path, here], lambda: _parsed(path), dump_json, _checked)


def _parsed(path: Path) -> dict[str, Any]:
    data = tomllib.loads(path.read_text("utf-8"))
    return {"nouns": data.get("nouns", {}), "adjectives": data.get("adjectives", {})}


def _checked(payload: bytes) -> dict[str, Any]:
    data = load_json(payload)
    if not isinstance(data, dict) or not all(isinstance(data.get(k), dict) for k in ("nouns", "adjectives")):
        raise ValueError("not a WordNet alias table")
    return data


def _synonym_index(adjectives: Mapping[str, Any], allowed: list[str]) -> dict[str, str]:
    """WordNet synonym -> the first allowed stdlib adjective (in the rule's order) it stands for."""
    index: dict[str, str] = {}
    for name in allowed:
        for synonym in adjectives.get(name, {}).get("synonyms", ()):
            index.setdefault(synonym.lower(), name)
    return index
