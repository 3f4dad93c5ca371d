"""The lexicon: words as data (stdlib/lexicon/*.toml), overlays and user lexicons.

Search order for an entry: user lexicon folders (first given wins), then named overlays
(stdlib/overlays/NAME, e.g. 'paper' or the German 'de'; first given wins), then the bundled stdlib.
Fields of a later-searched entry that the earlier one does not set are kept, so an overlay can
change one number of a noun.

The model (Entry, Lexicon, ...) is cnlmc.lexicon_model's, reading files cnlmc.lexicon_load's;
this module loads (load_lexicon), caches on disk as plain data (cached_lexicon) and re-exports.

The disk cache's form (`stored_form`, read back by `from_stored`) is made for a cold start: a
JSON header line with the settings, the keywords and the index of surface forms (StoredIndex), then
each entry's fields as JSON, one after another; an entry's fields are decoded and checked when
they are first read (Entry.stored), so a run that reads a few dozen entries never decodes the rest.
`to_data` / `from_data` are the plain, editable form of the whole lexicon.
"""

from __future__ import annotations

import os
from collections import OrderedDict
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .cache import CacheDamaged, cache_dir, cached, dump_json, load_json
from .graphs import graph_names
from .lexicon_model import (
    CATEGORY_TAGS,
    SPECIAL_FILES,
    Entry,
    Forms,
    Lexicon,
    LexiconCaches,
    StoredIndex,
    keyword_table,
    normalise,
)
from .material import MAP_ROLES
from .package_data import package_folder

__all__ = [
    "CATEGORY_TAGS",
    "SPECIAL_FILES",
    "Entry",
    "Forms",
    "Lexicon",
    "LexiconCaches",
    "LexiconStore",
    "Overlays",
    "cached_lexicon",
    "from_data",
    "from_stored",
    "keyword_table",
    "lexicon_sources",
    "load_lexicon",
    "normalise",
    "stored_form",
    "to_data",
]

#: The modules that read and check lexicon files: a change to one of them makes a new cache entry.
READER_MODULES = (
    "lexicon",
    "lexicon_model",
    "lexicon_load",
    "lexicon_schema",
    "lexicon_refs",
    "lexicon_source",
    "colour",
    "graphs",
    "params",
    "word_formation_rules",
)
Overlays = str | tuple[str, ...] | None  # overlay names, e.g. "paper" or ("de", "paper")


def load_lexicon(user_paths: Iterable[str | Path] = (), overlay: Overlays = None) -> Lexicon:
    """Load the lexicon: user folders first, then the overlays in order, then the bundled stdlib.
    A malformed file is a LexiconError naming FILE:LINE:COL and the key (cnlmc.lexicon_load)."""
    from .lexicon_load import load

    return load(user_paths, overlay)


class LexiconStore:
    """The lexicons a program has loaded, each kept while it is one of the `limit` used last
    (least recently used out) and while its user folders' files are as they were: the key holds
    the folders' and overlays' names and the names, sizes and times of the user folders' files
    (os.stat of each, on every lookup), so a user lexicon edited while a program runs (the
    language server, a build pipeline) is read again. The bundled stdlib and overlays are package
    data: not stat'ed per lookup (an installed package does not change under a running program;
    the disk cache keys them by their files all the same). A Lexicon keeps its own bounded memos
    (Lexicon.caches); `clear()` lets every lexicon go. The process's store is STORE (its owner:
    this module; cached_lexicon and cnlmc.api.lexicon_for read it); a program that wants its
    own lifetime makes its own LexiconStore."""

    def __init__(self, limit: int = 8) -> None:
        self.limit = limit
        self._entries: OrderedDict[tuple[Any, ...], Lexicon] = OrderedDict()

    def get(self, user_paths: tuple[str | Path, ...] = (), overlay: Overlays = None) -> Lexicon:
        """The lexicon of these folders and overlays as their files are now (LexiconError if bad)."""
        key = (user_paths, overlay, _user_files(user_paths))
        found = self._entries.get(key)
        if found is not None:
            self._entries.move_to_end(key)
            return found
        lexicon = _from_disk_cache(user_paths, overlay)
        stale = [k for k in self._entries if k[:2] == (user_paths, overlay)]  # the same folders, edited since
        for old in stale:
            del self._entries[old]
        self._entries[key] = lexicon
        while len(self._entries) > self.limit:
            self._entries.popitem(last=False)
        return lexicon

    __call__ = get

    @staticmethod
    def __wrapped__(user_paths: tuple[str | Path, ...] = (), overlay: Overlays = None) -> Lexicon:
        """The lexicon without the store: from the disk cache, or loaded (functools' name for it)."""
        return _from_disk_cache(user_paths, overlay)

    def clear(self) -> None:
        self._entries.clear()

    def __len__(self) -> int:
        return len(self._entries)


def _user_files(user_paths: tuple[str | Path, ...]) -> tuple[tuple[str, int, int], ...]:
    """(name, size, mtime) of each user folder and of the .toml files in it (missing: -1)."""
    stamps = []
    for folder in user_paths:
        for path in (Path(folder), *sorted(Path(folder).glob("*.toml"))):
            try:
                st = os.stat(path)
                stamps.append((str(path), st.st_size, st.st_mtime_ns))
            except OSError:
                stamps.append((str(path), -1, -1))
    return tuple(stamps)


STORE = LexiconStore()

#: The lexicon from the process's store (STORE), else from the on-disk cache when no source file
#: changed since it was written, else loaded; `cached_lexicon.__wrapped__(...)` skips the store.
cached_lexicon = STORE


def _from_disk_cache(user_paths: tuple[str | Path, ...], overlay: Overlays) -> Lexicon:
    sources = lexicon_sources(user_paths, overlay)
    return cached("lexicon", sources, lambda: load_lexicon(user_paths, overlay), _dump, _load)


def _dump(lexicon: Lexicon) -> bytes:
    return stored_form(lexicon)


def _load(payload: bytes) -> Lexicon:
    return from_stored(payload)


def lexicon_sources(user_paths: tuple[str | Path, ...], overlay: Overlays) -> list[Path]:
    """Every file a lexicon is made from: a change to one of them makes a new cache entry."""
    package = package_folder("cnlmc.stdlib")
    folders = [Path(p) for p in user_paths]
    folders += [Path(str(package.joinpath("overlays").joinpath(name))) for name in _overlay_names(overlay)]
    folders += [Path(str(package.joinpath("lexicon"))), Path(str(package.joinpath("graphs")))]
    here = Path(__file__).parent  # how entries are read and checked
    sources = [here / f"{name}.py" for name in READER_MODULES]
    sources += [
        Path(str(package.joinpath("schema.toml"))),
        package_folder("cnlmc.grammar") / "keywords.toml",
        Path(str(package.joinpath("data").joinpath("colour_names.toml"))),  # the everyday colours
        Path(str(package.joinpath("data").joinpath("colour_rules.toml"))),  # how the survey joins the lexicon
    ]
    sources += folders  # a file added to or removed from a folder changes its time
    sources += [p for folder in folders if folder.is_dir() for p in _toml_files(folder)]
    return sources


def _toml_files(folder: Path) -> list[Path]:
    """The folder's *.toml entries, by name (what sorted(folder.glob("*.toml")) lists, without
    compiling a pattern on every start)."""
    return [folder / name for name in sorted(os.listdir(folder)) if name.endswith(".toml")]


def _overlay_names(overlay: Overlays) -> tuple[str, ...]:
    names = (overlay,) if isinstance(overlay, str) else tuple(overlay or ())
    return tuple(n for n in names if n and n != "stdlib")


# ---------------------------------------------------------------- the cache's plain-data form


def to_data(lexicon: Lexicon) -> dict[str, Any]:
    """The lexicon as plain JSON data (what from_data rebuilds it from)."""
    return {
        "entries": {c: {k: [e.data, e.origin] for k, e in by.items()} for c, by in lexicon.entries.items()},
        "settings": lexicon.settings,
        "inflections": [list(rule) for rule in lexicon.inflections],
        "sources": lexicon.sources,
        "keywords": lexicon.keywords,
        "word_formation": lexicon.word_formation,
    }


def from_data(data: dict[str, Any]) -> Lexicon:
    """A Lexicon from to_data's form; ValueError or TypeError for data of any other shape."""
    entries = {
        c: {k: _entry_from(c, k, value) for k, value in _table(data["entries"][c]).items()} for c in CATEGORY_TAGS
    }
    inflections = [(_text(s), _text(r)) for s, r in data["inflections"]]
    sources = [_text(s) for s in data["sources"]]
    keywords = {_text(k): _text(v) for k, v in _table(data["keywords"]).items()}
    word_formation = [_table(layer) for layer in data.get("word_formation", [])]
    return Lexicon(entries, _table(data["settings"]), inflections, sources, keywords, word_formation)


def _entry_from(category: str, key: str, value: list[Any]) -> Entry:
    fields, origin = value
    return Entry(category, _text(key), _checked_fields(category, key, fields), _text(origin))


def _checked_fields(category: str, key: str, fields: Any) -> dict[str, Any]:
    """An entry's fields as read from a cache: a table whose maps name map roles and bundled graphs
    (names that become paths stay checked); ValueError or TypeError otherwise."""
    table = _table(fields)
    for role, ref in _table(table.get("maps", {})).items():
        if role not in MAP_ROLES or _table(ref).get("graph") not in graph_names():
            raise ValueError(f"cached {category} '{key}' has a map that is not in the schema")
    return table


# ---------------------------------------------------------------- the disk cache's form

STORED_FORMAT = "cnlmc-lexicon 3"


def stored_form(lexicon: Lexicon) -> bytes:
    """The lexicon as the disk cache keeps it: a JSON header line, then the entries' fields."""
    body = bytearray()
    origins: dict[str, int] = {}
    numbers: dict[tuple[str, str], int] = {}
    table: dict[str, dict[str, list[Any]]] = {}
    for category, by_key in lexicon.entries.items():
        rows: dict[str, list[Any]] = {"keys": [], "ends": [], "origins": []}  # fields: from the last end to this one
        for key, entry in by_key.items():
            body += dump_json(entry.data)
            rows["keys"].append(key)
            rows["ends"].append(len(body))
            rows["origins"].append(origins.setdefault(entry.origin, len(origins)))
            numbers[(category, key)] = len(numbers)
        table[category] = rows
    forms: dict[str, Any] = {}
    for form, hits in lexicon.forms.items():
        found = [numbers[(e.category, e.key)] for e in hits]
        forms[" ".join(form)] = found[0] if len(found) == 1 else found
    head = {
        "format": STORED_FORMAT,
        "entries": table,
        "origins": list(origins),
        "forms": forms,
        "followers": {first: sorted(seconds) for first, seconds in lexicon.followers.items()},
        "lengths": {first: list(lengths) for first, lengths in lexicon.lengths_from.items()},
        "max_form_words": lexicon.max_form_words,
        "settings": lexicon.settings,
        "inflections": [list(rule) for rule in lexicon.inflections],
        "sources": lexicon.sources,
        "keywords": lexicon.keywords,
        "word_formation": lexicon.word_formation,
    }
    return dump_json(head) + b"\n" + bytes(body)


class StoredEntries:
    """The entries' fields of one stored lexicon (the payload after its header line)."""

    def __init__(self, body: bytes) -> None:
        self.body = body

    def fields(self, entry: Entry, start: int, end: int) -> dict[str, Any]:
        try:
            return _checked_fields(entry.category, entry.key, load_json(self.body[start:end]))
        except (ValueError, TypeError) as exc:
            raise CacheDamaged(
                f"the cached lexicon's entry '{entry.key}' ({entry.category}) fails its check ({exc}): "
                f"delete the cache folder {cache_dir()} (it is rebuilt), or set CNLMC_NO_CACHE=1"
            ) from None


def from_stored(payload: bytes) -> Lexicon:
    """A Lexicon from stored_form's bytes; ValueError, TypeError, KeyError or IndexError for a
    payload of any other shape (the cache then rebuilds it). Entries' fields are checked when read."""
    head_text, newline, body = payload.partition(b"\n")
    head = _table(load_json(head_text))
    if not newline or head.get("format") != STORED_FORMAT:
        raise ValueError("not a stored lexicon of this format")
    store = StoredEntries(body)
    origins = [_text(origin) for origin in head["origins"]]
    entries: dict[str, dict[str, Entry]] = {}
    order: list[Entry] = []
    start, size = 0, len(body)
    for category in CATEGORY_TAGS:
        by_key = entries[category] = {}
        rows = _table(head["entries"][category])
        for key, end, origin in zip(rows["keys"], rows["ends"], rows["origins"], strict=True):
            if type(key) is not str or type(end) is not int or not start <= end <= size or not _whole(origin):
                raise ValueError(f"a stored {category} entry is not where its fields are")
            entry = by_key[key] = Entry.stored(category, key, origins[origin], (store, start, end))
            order.append(entry)
            start = end
    index = StoredIndex(
        _table(head["forms"]),  # each form's entry numbers are checked when it is looked up
        order,
        {first: frozenset(map(_text, _list(seconds))) for first, seconds in _table(head["followers"]).items()},
        {first: tuple(map(_whole_number, _list(lengths))) for first, lengths in _table(head["lengths"]).items()},
        _whole_number(head["max_form_words"]),
    )
    inflections = [(_text(s), _text(r)) for s, r in head["inflections"]]
    sources = [_text(s) for s in head["sources"]]
    keywords = {_text(k): _text(v) for k, v in _table(head["keywords"]).items()}
    word_formation = [_table(layer) for layer in head["word_formation"]]
    return Lexicon(entries, _table(head["settings"]), inflections, sources, keywords, word_formation, index=index)


def _whole(value: Any) -> bool:
    return type(value) is int and value >= 0


def _whole_number(value: Any) -> int:
    if not _whole(value):
        raise TypeError(f"expected a whole number, got {value!r:.40}")
    number: int = value
    return number


def _list(value: Any) -> list[Any]:
    if not isinstance(value, list):
        raise TypeError(f"expected a list, got {type(value).__name__}")
    return value


def _table(value: Any) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise TypeError(f"expected a table, got {type(value).__name__}")
    return value


def _text(value: Any) -> str:
    if not isinstance(value, str):
        raise TypeError(f"expected a string, got {type(value).__name__}")
    return value
