"""The words a note quotes for a lexicon entry the user did not type (issue #14).

A note says how a line was read: in the words the user typed and, for a word the rules add (the
substrate of a coat named alone, the opposite of a negated word), in the lexicon's own word for
it in the document's language. An overlay whose settings set `own_words` (German: stdlib/overlays/
de/settings_de.toml) names an entry by the first alias its own file gives it ('Stahl', 'matt'),
capitalised in the categories its `capitalised_categories` lists (German nouns), and 'with' by its
own first WITH terminal ('mit'); any other lexicon by the entry's key ('steel', 'matte', 'with').
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .lexicon import Lexicon

__all__ = ["Spoken"]


class Spoken:
    """The document language's own words for lexicon entries (made once per lexicon user)."""

    __slots__ = ("capitalised", "files", "lexicon", "overlay", "with_word")

    def __init__(self, lexicon: Lexicon) -> None:
        self.lexicon = lexicon
        own = bool(lexicon.settings.get("own_words")) and len(lexicon.sources) > 1
        self.overlay = Path(lexicon.sources[0]) if own else None
        self.capitalised = frozenset(lexicon.settings.get("capitalised_categories", ()))
        self.files: dict[str, dict[str, Any]] = {}
        self.with_word = self._terminal("WITH", "with")

    def word(self, category: str, key: str) -> str:
        """The document language's word for the entry `key` of `category` (its key in English)."""
        if self.overlay is None:
            return key
        entry = self.lexicon.entry(category, key)
        if entry is None or Path(entry.origin).parent != self.overlay:
            return key
        aliases = self._read(entry.origin).get(key, {}).get("aliases", ())
        if not aliases:
            return key
        first = str(aliases[0])
        return first[:1].upper() + first[1:] if category in self.capitalised else first

    def _terminal(self, tag: str, default: str) -> str:
        if self.overlay is None:
            return default
        words = self._read(str(self.overlay / "keywords.toml")).get("terminals", {}).get(tag, ())
        return str(words[0]) if words else default

    def _read(self, path: str) -> dict[str, Any]:
        found = self.files.get(path)
        if found is None:
            try:
                found = tomllib.loads(Path(path).read_text("utf-8"))
            except (OSError, tomllib.TOMLDecodeError):
                found = {}  # a lexicon read from its cache whose files moved: the keys
            self.files[path] = found
        return found
