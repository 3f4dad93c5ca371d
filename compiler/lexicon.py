"""The lexicon: words as data (stdlib/lexicon/*.toml), overlays and user lexicons.

Search order for an entry: user lexicon folders (first given wins), then named overlays
(stdlib/overlays/NAME, e.g. 'paper' or the German 'de'; first given wins), then the bundled stdlib. Fields of a later-searched entry that the
earlier one does not set are kept, so an overlay can change one number of a noun.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from pathlib import Path

from .colour import hex_to_linear
from .lexicon_schema import LexiconError, check_entry

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


@dataclass(frozen=True)
class Entry:
    category: str
    key: str
    data: dict
    origin: str

    @property
    def tag(self) -> str:
        return CATEGORY_TAGS[self.category]

    def get(self, name, default=None):
        return self.data.get(name, default)


def normalise(surface: str) -> tuple[str, ...]:
    """'Powder  Coated' -> ('powder', 'coated'): lower case, split on white space."""
    return tuple(surface.lower().split())


class Lexicon:
    """Entries by category, an index of surface forms, inflection rules and settings."""

    def __init__(
        self, entries: dict, settings: dict, inflections: list, sources: list[str], keywords: dict | None = None
    ):
        self.keywords = {**keyword_table(), **(keywords or {})}
        self.entries = entries
        self.settings = settings
        self.inflections = inflections
        self.sources = sources
        self.forms = _index_forms(entries)
        self.max_form_words = max(len(f) for f in self.forms)
        self._suggest_pool = {}
        self.tag_memo = {}  # word tuple -> candidate tags (filled by the tagger)

    def multi_word_followers(self) -> dict[str, frozenset[str]]:
        """First word of a multi-word form -> the words that can come second ("stainless" -> {"steel"})."""
        if getattr(self, "_followers", None) is None:
            followers: dict[str, set[str]] = {}
            for form in self.forms:
                if len(form) > 1:
                    followers.setdefault(form[0], set()).add(form[1])
            self._followers = {first: frozenset(seconds) for first, seconds in followers.items()}
        return self._followers

    def multi_word_lengths(self) -> dict[str, tuple[int, ...]]:
        """First word -> the word counts (> 1) of the forms it starts, longest first."""
        if getattr(self, "_multi_lengths", None) is None:
            lengths: dict[str, set[int]] = {}
            for form in self.forms:
                if len(form) > 1:
                    lengths.setdefault(form[0], set()).add(len(form))
            self._multi_lengths = {first: tuple(sorted(ns, reverse=True)) for first, ns in lengths.items()}
        return self._multi_lengths

    def entry(self, category: str, key: str) -> Entry | None:
        by_key = self.entries.get(category)
        return None if by_key is None else by_key.get(key)

    def lookup(self, words: tuple[str, ...]) -> list[Entry]:
        return self.forms.get(words, [])

    def base_forms(self, word: str) -> list[str]:
        """Candidate base forms of an unknown word by the inflection rules, in order."""
        out = []
        for suffix, repl in self.inflections:
            if word.endswith(suffix) and len(word) > len(suffix) + 2:
                out.append(word[: len(word) - len(suffix)] + repl)
        return out

    def suggest(self, word: str, categories=None, limit: int = 3) -> list[str]:
        """Closest surface forms to `word`, best first (rapidfuzz ratio >= 70)."""
        key = (word.lower(), tuple(categories or CATEGORY_TAGS), limit)
        memo = self.__dict__.setdefault("_suggest_memo", {})
        if key not in memo:
            if len(memo) > 4096:
                memo.clear()
            memo[key] = self._closest(*key)
        return list(memo[key])

    def _closest(self, word: str, categories: tuple, limit: int) -> list[str]:
        from rapidfuzz import fuzz, process  # only needed when a word is unknown

        found = process.extract(word, self._pool(categories), scorer=fuzz.ratio, limit=limit, score_cutoff=70)
        return [match for match, _score, _i in found]

    def _pool(self, categories: tuple) -> list[str]:
        if categories not in self._suggest_pool:
            self._suggest_pool[categories] = sorted(
                " ".join(form) for form, hits in self.forms.items() if any(e.category in categories for e in hits)
            )
        return self._suggest_pool[categories]

    def all_of(self, category: str) -> dict[str, Entry]:
        return self.entries.get(category, {})


def _index_forms(entries: dict) -> dict:
    forms: dict[tuple, list[Entry]] = {}
    for by_key in entries.values():
        for entry in by_key.values():
            for surface in [entry.key, *entry.get("aliases", [])]:
                hits = forms.setdefault(normalise(surface), [])
                if entry not in hits:
                    hits.append(entry)
    return forms


def _schema() -> dict:
    import tomllib

    text = resources.files("cnlmc.stdlib").joinpath("schema.toml").read_text("utf-8")
    return tomllib.loads(text)


def keyword_table(table: dict | None = None) -> dict[str, str]:
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


def _read_toml(path) -> dict:
    import tomllib

    try:
        return tomllib.loads(path.read_text("utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise LexiconError(f"{path}: not valid TOML: {exc}") from None
    except OSError as exc:
        raise LexiconError(f"{path}: cannot read: {exc.strerror}") from None


def _layer_files(folder) -> list:
    return sorted((p for p in folder.iterdir() if p.name.endswith(".toml")), key=lambda p: p.name)


class _Builder:
    """Accumulates layers, most specific first; a field already set is never replaced."""

    def __init__(self):
        self.schema = _schema()
        self.raw: dict[str, dict[str, tuple[dict, str]]] = {c: {} for c in CATEGORY_TAGS}
        self.settings: dict = {}
        self.inflections: list = []
        self.keywords: dict = {}
        self.sources: list[str] = []

    def add_layer(self, folder, strict_entries: bool) -> None:
        self.sources.append(str(folder))
        for path in _layer_files(folder):
            self._add_file(path, strict_entries)

    def _add_file(self, path, strict_entries: bool) -> None:
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

    def _add_entries(self, path, category: str, data: dict, strict_entries: bool) -> None:
        fields = self.schema[category]["fields"]
        for key, entry in data.items():
            where = f"{path} [{key}]"
            if not isinstance(entry, dict):
                raise LexiconError(f"{where}: expected a table of fields")
            known = key in self.raw[category]
            check_entry(entry, fields, where, partial=known or not strict_entries)
            self._merge(category, key, entry, str(path))

    def _merge(self, category: str, key: str, entry: dict, origin: str) -> None:
        current = self.raw[category].get(key)
        if current is None:
            self.raw[category][key] = (dict(entry), origin)
            return
        merged = {**entry, **current[0]}
        merged["aliases"] = sorted(set(current[0].get("aliases", [])) | set(entry.get("aliases", [])))
        self.raw[category][key] = (merged, current[1])

    def _add_keywords(self, path, data: dict) -> None:
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


def _finish(category: str, key: str, data: dict, origin: str) -> Entry:
    if category == "colours" and "rgb" not in data:
        data = {**data, "rgb": hex_to_linear(data["hex"])}
    return Entry(category, key, data, origin)


def stdlib_folder():
    return resources.files("cnlmc.stdlib").joinpath("lexicon")


def overlay_folder(name: str):
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


def _overlay_names(overlay) -> tuple[str, ...]:
    names = (overlay,) if isinstance(overlay, str) else tuple(overlay or ())
    return tuple(n for n in names if n and n != "stdlib")


def load_lexicon(user_paths=(), overlay: str | tuple | None = None) -> Lexicon:
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
def cached_lexicon(user_paths: tuple = (), overlay: str | tuple | None = None) -> Lexicon:
    """The lexicon, from the on-disk cache when no source file changed since it was written."""
    from .cache import cached

    folders = [Path(p) for p in user_paths]
    folders += [Path(str(overlay_folder(name))) for name in _overlay_names(overlay)]
    folders.append(Path(str(stdlib_folder())))
    sources = [
        Path(str(resources.files("cnlmc.stdlib").joinpath("schema.toml"))),
        Path(str(resources.files("cnlmc.grammar").joinpath("keywords.toml"))),
        Path(__file__),
    ]  # the classes that are pickled: a change to them rebuilds the cache
    sources += [p for folder in folders if folder.is_dir() for p in sorted(folder.glob("*.toml"))]
    lexicon = cached("lexicon", sources, lambda: load_lexicon(user_paths, overlay))
    _freeze_long_lived()
    return lexicon


def _freeze_long_lived() -> None:
    """Move what is alive now (modules, the lexicon, parser tables) out of the cyclic GC's way.

    The lexicon is thousands of long-lived containers that every full collection would
    traverse again; frozen, compiling a phrase in-process is about a third faster. Reference
    counting still frees everything; only cyclic garbage that exists at this moment is kept.
    Set CNLMC_NO_GC_FREEZE=1 to leave the collector alone.
    """
    import atexit
    import gc
    import os

    if not os.environ.get("CNLMC_NO_GC_FREEZE"):
        gc.freeze()
        atexit.register(gc.unfreeze)  # let extension modules see their objects freed at exit
