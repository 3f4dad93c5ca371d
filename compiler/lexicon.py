"""The lexicon: words as data (stdlib/lexicon/*.toml), overlays and user lexicons.

Search order for an entry: user lexicon folders (first given wins), then named overlays
(stdlib/overlays/NAME, e.g. 'paper' or the German 'de'; first given wins), then the bundled stdlib. Fields of a later-searched entry that the
earlier one does not set are kept, so an overlay can change one number of a noun.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from importlib.resources.abc import Traversable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .cache import cached
from .colour import hex_to_linear
from .diagnostics import FailureKey, Mistake
from .lexicon_schema import LexiconError, check_entry
from .syntax import ShapeCache
from .tagged import Candidate

if TYPE_CHECKING:  # the tagger reads the lexicon; a lexicon keeps the tagger made for it
    from .tagger import Tagger

CATEGORY_TAGS = {
    "nouns": "NOUN",
    "adjectives": "ADJ",
    "adverbs": "ADV",
    "colours": "COLOR",
    "shades": "SHADE",
    "refinements": "REFINE",
    "properties": "PROP",
    "coats": "COAT",
}
SPECIAL_FILES = ("settings", "inflections", "keywords")
Folder = Path | Traversable  # a lexicon folder or file: the user's, or inside the installed package
Overlays = str | tuple[str, ...] | None  # overlay names, e.g. "paper" or ("de", "paper")


@dataclass(frozen=True)
class Entry:
    category: str
    key: str
    data: dict[str, Any]
    origin: str

    @property
    def tag(self) -> str:
        return CATEGORY_TAGS[self.category]

    def get(self, name: str, default: Any = None) -> Any:
        return self.data.get(name, default)


Forms = dict[tuple[str, ...], list[Entry]]  # normalised surface form -> the entries spelled so


def normalise(surface: str) -> tuple[str, ...]:
    """'Powder  Coated' -> ('powder', 'coated'): lower case, split on white space."""
    return tuple(surface.lower().split())


class LexiconCaches:
    """What is derived from one lexicon while it is used, kept with it and never pickled with it.

    - tagger: the Tagger of this lexicon (document.parse_document makes it on first use)
    - tags: word tuple -> the candidate tags the tagger found for it
    - suggestions: (word, categories, limit) -> the closest surface forms (Lexicon.suggest)
    - suggestion_pools: categories -> the sorted surface forms suggestions are drawn from
    - shapes: parse shapes by the candidate tags of a line's words (parser.parse_line_shape)
    - mistakes: parser failure key -> the friendly message learned from grammar/bad_examples.toml
      (None until a line first fails to parse; mistakes.known_mistake)
    - colour_phrases: (phrase, CIELAB) of every colour and shade+colour (the LSP's colour picker)
    - effect_rules: (rule, where the effect list is, effect index, weight) -> the provenance text
      of that lexicon effect (passes/words.py)
    - rounded_optics: (noun key, parameter) -> the noun's list value rounded for the IR (ir.py)
    """

    MAX_ENTRIES = 4096  # a memo this full starts over

    def __init__(self) -> None:
        self.tagger: Tagger | None = None
        self.tags: dict[tuple[str, ...], tuple[Candidate, ...]] = {}
        self.suggestions: dict[tuple[str, tuple[str, ...], int], list[str]] = {}
        self.suggestion_pools: dict[tuple[str, ...], list[str]] = {}
        self.shapes = ShapeCache()
        self.mistakes: dict[FailureKey, Mistake] | None = None
        self.effect_rules: dict[tuple[str, str, int, float], str] = {}
        self.colour_phrases: tuple[tuple[str, tuple[float, float, float]], ...] | None = None
        self.rounded_optics: dict[tuple[str, str], list[float]] = {}


class Lexicon:
    """Entries by category, an index of surface forms, inflection rules and settings.

    Everything derived from it while it is used lives in `caches` (a LexiconCaches).
    """

    def __init__(
        self,
        entries: dict[str, dict[str, Entry]],
        settings: dict[str, Any],
        inflections: list[tuple[str, str]],
        sources: list[str],
        keywords: dict[str, str] | None = None,
    ) -> None:
        self.keywords = {**keyword_table(), **(keywords or {})}
        self.entries = entries
        self.settings = settings
        self.inflections = inflections
        self.sources = sources
        self.forms = _index_forms(entries)
        self.max_form_words = max(len(f) for f in self.forms)
        self.followers = _multi_word_followers(self.forms)
        self.lengths_from = _multi_word_lengths(self.forms)
        self.caches = LexiconCaches()

    def __getstate__(self) -> dict[str, Any]:
        return {name: value for name, value in self.__dict__.items() if name != "caches"}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        self.caches = LexiconCaches()

    def multi_word_followers(self) -> dict[str, frozenset[str]]:
        """First word of a multi-word form -> the words that can come second ("stainless" -> {"steel"})."""
        return self.followers

    def multi_word_lengths(self) -> dict[str, tuple[int, ...]]:
        """First word -> the word counts (> 1) of the forms it starts, longest first."""
        return self.lengths_from

    def entry(self, category: str, key: str) -> Entry | None:
        by_key = self.entries.get(category)
        return None if by_key is None else by_key.get(key)

    def require(self, category: str, key: str) -> Entry:
        """The entry of a word the tagger found in this lexicon (KeyError if there is none)."""
        return self.entries[category][key]

    def lookup(self, words: tuple[str, ...]) -> list[Entry]:
        return self.forms.get(words, [])

    def base_forms(self, word: str) -> list[str]:
        """Candidate base forms of an unknown word by the inflection rules, in order."""
        out = []
        for suffix, repl in self.inflections:
            if word.endswith(suffix) and len(word) > len(suffix) + 2:
                out.append(word[: len(word) - len(suffix)] + repl)
        return out

    def suggest(self, word: str, categories: Iterable[str] | None = None, limit: int = 3) -> list[str]:
        """Closest surface forms to `word`, best first (rapidfuzz ratio >= 70)."""
        key = (word.lower(), tuple(categories or CATEGORY_TAGS), limit)
        memo = self.caches.suggestions
        if key not in memo:
            if len(memo) > LexiconCaches.MAX_ENTRIES:
                memo.clear()
            memo[key] = self._closest(*key)
        return list(memo[key])

    def _closest(self, word: str, categories: tuple[str, ...], limit: int) -> list[str]:
        from rapidfuzz import fuzz, process  # only needed when a word is unknown

        found = process.extract(word, self._pool(categories), scorer=fuzz.ratio, limit=limit, score_cutoff=70)
        return [match for match, _score, _i in found]

    def _pool(self, categories: tuple[str, ...]) -> list[str]:
        pools = self.caches.suggestion_pools
        if categories not in pools:
            pools[categories] = sorted(
                " ".join(form) for form, hits in self.forms.items() if any(e.category in categories for e in hits)
            )
        return pools[categories]

    def all_of(self, category: str) -> dict[str, Entry]:
        return self.entries.get(category, {})


def _multi_word_followers(forms: Forms) -> dict[str, frozenset[str]]:
    followers: dict[str, set[str]] = {}
    for form in forms:
        if len(form) > 1:
            followers.setdefault(form[0], set()).add(form[1])
    return {first: frozenset(seconds) for first, seconds in followers.items()}


def _multi_word_lengths(forms: Forms) -> dict[str, tuple[int, ...]]:
    lengths: dict[str, set[int]] = {}
    for form in forms:
        if len(form) > 1:
            lengths.setdefault(form[0], set()).add(len(form))
    return {first: tuple(sorted(ns, reverse=True)) for first, ns in lengths.items()}


def _index_forms(entries: dict[str, dict[str, Entry]]) -> Forms:
    forms: Forms = {}
    for by_key in entries.values():
        for entry in by_key.values():
            for surface in [entry.key, *entry.get("aliases", [])]:
                hits = forms.setdefault(normalise(surface), [])
                if entry not in hits:
                    hits.append(entry)
    return forms


def _schema() -> dict[str, Any]:
    import tomllib

    text = resources.files("cnlmc.stdlib").joinpath("schema.toml").read_text("utf-8")
    return tomllib.loads(text)


def keyword_table(table: dict[str, Any] | None = None) -> dict[str, str]:
    """Closed-class words -> grammar terminal, from grammar/keywords.toml (or a given table)."""
    if table is None:
        import tomllib

        text = resources.files("cnlmc.grammar").joinpath("keywords.toml").read_text("utf-8")
        table = tomllib.loads(text)
    return {word: terminal for terminal, words in table["terminals"].items() for word in words}


def _category_of(stem: str) -> str | None:
    for category in (*CATEGORY_TAGS, *SPECIAL_FILES):
        if stem == category or stem.startswith(category + "_"):
            return category
    return None


def _read_toml(path: Folder) -> dict[str, Any]:
    import tomllib

    try:
        return tomllib.loads(path.read_text("utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise LexiconError(f"{path}: not valid TOML: {exc}") from None
    except OSError as exc:
        raise LexiconError(f"{path}: cannot read: {exc.strerror}") from None


def _layer_files(folder: Folder) -> list[Folder]:
    return sorted((p for p in folder.iterdir() if p.name.endswith(".toml")), key=lambda p: p.name)


class _Builder:
    """Accumulates layers, most specific first; a field already set is never replaced."""

    def __init__(self) -> None:
        self.schema = _schema()
        self.raw: dict[str, dict[str, tuple[dict[str, Any], str]]] = {c: {} for c in CATEGORY_TAGS}
        self.settings: dict[str, Any] = {}
        self.inflections: list[tuple[str, str]] = []
        self.keywords: dict[str, str] = {}
        self.sources: list[str] = []

    def add_layer(self, folder: Folder, strict_entries: bool) -> None:
        self.sources.append(str(folder))
        for path in _layer_files(folder):
            self._add_file(path, strict_entries)

    def _add_file(self, path: Folder, strict_entries: bool) -> None:
        stem = path.name[:-5]
        category = _category_of(stem)
        if category is None:
            raise LexiconError(
                f"{path}: unknown lexicon file (its name must start with one of: "
                f"{', '.join([*CATEGORY_TAGS, *SPECIAL_FILES])})"
            )
        data = _read_toml(path)
        if category == "inflections":  # every layer's rules, the most specific layer's first
            self.inflections += [tuple(r) for r in data.get("rules", [])]
            return
        if category == "keywords":  # a language's closed-class words (and, or, with, articles)
            self._add_keywords(path, data)
            return
        if category == "settings":
            check_entry(data, self.schema["settings"]["fields"], str(path), partial=True)
            self.settings = {**data, **self.settings}
            return
        self._add_entries(path, category, data, strict_entries)

    def _add_entries(self, path: Folder, category: str, data: dict[str, Any], strict_entries: bool) -> None:
        fields = self.schema[category]["fields"]
        for key, entry in data.items():
            where = f"{path} [{key}]"
            if not isinstance(entry, dict):
                raise LexiconError(f"{where}: expected a table of fields")
            known = key in self.raw[category]
            check_entry(entry, fields, where, partial=known or not strict_entries)
            self._merge(category, key, entry, str(path))

    def _merge(self, category: str, key: str, entry: dict[str, Any], origin: str) -> None:
        current = self.raw[category].get(key)
        if current is None:
            self.raw[category][key] = (dict(entry), origin)
            return
        merged = {**entry, **current[0]}
        merged["aliases"] = sorted(set(current[0].get("aliases", [])) | set(entry.get("aliases", [])))
        self.raw[category][key] = (merged, current[1])

    def _add_keywords(self, path: Folder, data: dict[str, Any]) -> None:
        terminals = set(keyword_table().values())
        table = data.get("terminals")
        if not isinstance(table, dict) or not set(table) <= terminals:
            raise LexiconError(f"{path} [terminals]: expected a table of {', '.join(sorted(terminals))}")
        self.keywords = {**keyword_table(data), **self.keywords}

    def check_complete(self) -> None:
        """Entries added only by a user layer must still carry every required field."""
        for category, by_key in self.raw.items():
            for key, (data, origin) in by_key.items():
                check_entry(data, self.schema[category]["fields"], f"{origin} [{key}]")

    def build(self) -> Lexicon:
        entries = {c: {k: _finish(c, k, d, o) for k, (d, o) in by.items()} for c, by in self.raw.items()}
        return Lexicon(entries, self.settings, self.inflections, self.sources, self.keywords)


def _finish(category: str, key: str, data: dict[str, Any], origin: str) -> Entry:
    if category == "colours" and "rgb" not in data:
        data = {**data, "rgb": hex_to_linear(data["hex"])}
    return Entry(category, key, data, origin)


def stdlib_folder() -> Traversable:
    return resources.files("cnlmc.stdlib").joinpath("lexicon")


def overlay_folder(name: str) -> Traversable:
    folder = resources.files("cnlmc.stdlib").joinpath("overlays").joinpath(name)
    if not folder.is_dir():
        import difflib

        close = difflib.get_close_matches(name, available_overlays(), n=1)
        hint = f"; did you mean '{close[0]}'?" if close else ""
        raise LexiconError(f"no lexicon overlay named '{name}' (available: {', '.join(available_overlays())}){hint}")
    return folder


def available_overlays() -> list[str]:
    root = resources.files("cnlmc.stdlib").joinpath("overlays")
    return sorted(p.name for p in root.iterdir() if p.is_dir())


def _overlay_names(overlay: Overlays) -> tuple[str, ...]:
    names = (overlay,) if isinstance(overlay, str) else tuple(overlay or ())
    return tuple(n for n in names if n and n != "stdlib")


def load_lexicon(user_paths: Iterable[str | Path] = (), overlay: Overlays = None) -> Lexicon:
    """Load the lexicon: user folders first, then the overlays in order, then the bundled stdlib."""
    builder = _Builder()
    for folder in user_paths:
        path = Path(folder)
        if not path.is_dir():
            raise LexiconError(f"{path}: lexicon path is not a folder")
        builder.add_layer(path, strict_entries=False)
    for name in _overlay_names(overlay):
        builder.add_layer(overlay_folder(name), strict_entries=False)
    builder.add_layer(stdlib_folder(), strict_entries=True)
    builder.check_complete()
    return builder.build()


@lru_cache(maxsize=8)
def cached_lexicon(user_paths: tuple[str | Path, ...] = (), overlay: Overlays = None) -> Lexicon:
    """The lexicon, from the on-disk cache when no source file changed since it was written."""
    folders = [Path(p) for p in user_paths]
    folders += [Path(str(overlay_folder(name))) for name in _overlay_names(overlay)]
    folders.append(Path(str(stdlib_folder())))
    sources = [
        Path(str(resources.files("cnlmc.stdlib").joinpath("schema.toml"))),
        Path(str(resources.files("cnlmc.grammar").joinpath("keywords.toml"))),
        Path(__file__),
    ]  # the classes that are pickled: a change to them rebuilds the cache
    sources += [p for folder in folders if folder.is_dir() for p in sorted(folder.glob("*.toml"))]
    return cached("lexicon", sources, lambda: load_lexicon(user_paths, overlay))
