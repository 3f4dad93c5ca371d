"""Pronunciations of the grammar's words: the recogniser's CMU dictionary first, then a lexicon
folder's own speech/pronunciations.toml, then the bundled stdlib/speech/pronunciations.toml
(generated from espeak-ng by scripts/gen_pronunciations.py), then, for a user lexicon's new
word, espeak-ng at run time when it is installed. A word with none of these is left out of the
grammar and named (Pronunciations.missing)."""

from __future__ import annotations

import tomllib
from collections.abc import Iterable
from pathlib import Path

from .phonemes import IpaTable, espeak_available, espeak_pronunciations
from .settings import speech_data

USER_FILE = Path("speech") / "pronunciations.toml"  # inside a lexicon folder (--lexicon DIR)


def read_dictionary(path: Path, wanted: set[str]) -> dict[str, list[str]]:
    """The CMU-format dictionary's pronunciations of `wanted` ('word(2) PH ONES' lines)."""
    found: dict[str, list[str]] = {}
    with path.open(encoding="utf-8", errors="replace") as lines:
        for line in lines:
            head, _, phones = line.partition(" ")
            word = head.split("(")[0]
            if word in wanted:
                found.setdefault(word, []).append(phones.strip())
    return found


def read_pronunciations(text: str, section: str = "words") -> dict[str, list[str]]:
    """A pronunciations.toml: `[words]` word = ["PH ONES", ...] (or the `[british]` variants)."""
    words = tomllib.loads(text).get(section, {})
    return {str(w).lower(): [str(p) for p in (v if isinstance(v, list) else [v])] for w, v in words.items()}


def user_pronunciations(folders: Iterable[str | Path]) -> dict[str, list[str]]:
    """speech/pronunciations.toml of each lexicon folder, the first given winning."""
    found: dict[str, list[str]] = {}
    for folder in reversed([Path(f) for f in folders]):
        path = folder / USER_FILE
        if path.is_file():
            found.update(read_pronunciations(path.read_text("utf-8")))
    return found


class Pronunciations:
    """The pronunciations of a set of words, and which words have none."""

    def __init__(
        self,
        words: set[str],
        dictionary: Path,
        folders: Iterable[str | Path] = (),
        espeak: bool = True,
        british: bool = True,
    ):
        self.table = read_dictionary(dictionary, words)
        self.english = frozenset(self.table)  # the words English has (the recogniser's dictionary)
        bundled = read_pronunciations(speech_data("pronunciations.toml"))
        if british:
            self._add_variants(read_pronunciations(speech_data("pronunciations.toml"), "british"))
        users = user_pronunciations(folders)
        for word in words - set(self.table):
            phones = users.get(word) or bundled.get(word)
            if phones:
                self.table[word] = phones
        rest = sorted(words - set(self.table))
        if rest and espeak and espeak_available():
            self.table.update(espeak_pronunciations(rest, IpaTable.bundled()))
        self.missing = words - set(self.table)

    def _add_variants(self, variants: dict[str, list[str]]) -> None:
        """Second pronunciations of words the dictionary has (British beside American)."""
        for word, phones in variants.items():
            if word in self.table:
                self.table[word].extend(p for p in phones if p not in self.table[word])

    def dictionary_text(self) -> str:
        """The CMU-format dictionary of these words, for the recogniser."""
        lines = []
        for word in sorted(self.table):
            for number, phones in enumerate(self.table[word], 1):
                lines.append(f"{word if number == 1 else f'{word}({number})'} {phones}")
        return "\n".join(lines) + "\n"
