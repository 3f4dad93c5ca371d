"""The lexicon's model: entries by category, the index of their surface forms, inflection rules,
settings and keywords, and the caches kept with one lexicon while it is used.

Reading lexicon files into this model is cnlmc.lexicon_load's job; cnlmc.lexicon is the public
face of both (load_lexicon, cached_lexicon) and re-exports what is defined here.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import FrozenInstanceError
from functools import lru_cache
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, NamedTuple, Protocol

from .cache import CacheDamaged
from .diagnostics import FailureKey, Mistake
from .package_data import package_folder
from .syntax import ShapeCache
from .tagged import Candidate

if TYPE_CHECKING:  # the tagger reads the lexicon; a lexicon keeps the tagger made for it
    from .suggest import FormIndex
    from .tagger import Tagger
    from .word_formation import WordFormation

CATEGORY_TAGS = {
    "nouns": "NOUN",
    "adjectives": "ADJ",
    "adverbs": "ADV",
    "colours": "COLOR",
    "shades": "SHADE",
    "refinements": "REFINE",
    "properties": "PROP",
    "coats": "COAT",
    "objects": "OBJECT",  # things made of a material ("planks"): the tagger reads them as their material
    "features": "FEATURE",  # what a 'with' clause names besides a coat: "with grey veins" (passes/features.py)
}
SPECIAL_FILES = ("settings", "inflections", "keywords", "word_formation")


class StoredFields(Protocol):
    """Where a stored entry's fields are (cnlmc.lexicon's disk-cache form): `fields(entry, start,
    end)` decodes and checks them (ValueError when they fail a check)."""

    def fields(self, entry: Entry, start: int, end: int) -> dict[str, Any]: ...


class Entry:
    """One lexicon entry: its category, key, fields (`data`) and the file it came from (`origin`).

    Immutable, compared by value (as the frozen dataclass it was). An entry read from the disk
    cache (`Entry.stored`) decodes its fields when they are first asked for: one run reads a few
    dozen of a lexicon's ~1,700 entries (docs/language.md, Speed)."""

    __slots__ = ("category", "key", "origin", "_data", "_stored")

    category: str
    key: str
    origin: str
    _data: dict[str, Any] | None
    _stored: tuple[StoredFields, int, int] | None

    def __init__(self, category: str, key: str, data: dict[str, Any], origin: str) -> None:
        for name, value in (("category", category), ("key", key), ("origin", origin), ("_data", data)):
            object.__setattr__(self, name, value)
        object.__setattr__(self, "_stored", None)

    @classmethod
    def stored(cls, category: str, key: str, origin: str, where: tuple[StoredFields, int, int]) -> Entry:
        """An entry whose fields are decoded from `where` (the store, start, end) on first use."""
        entry = cls.__new__(cls)
        for name, value in (("category", category), ("key", key), ("origin", origin), ("_data", None)):
            object.__setattr__(entry, name, value)
        object.__setattr__(entry, "_stored", where)
        return entry

    @property
    def data(self) -> dict[str, Any]:
        data = self._data
        if data is None:
            assert self._stored is not None
            store, start, end = self._stored
            data = store.fields(self, start, end)
            object.__setattr__(self, "_data", data)
        return data

    @property
    def tag(self) -> str:
        return CATEGORY_TAGS[self.category]

    def get(self, name: str, default: Any = None) -> Any:
        data = self._data  # the data property's common case, without its call (the passes ask often)
        return (self.data if data is None else data).get(name, default)

    def set_value(self, param: str) -> Any:
        """The value the entry's effects set `param` to ('satin': roughness 0.35), or None."""
        return next(
            (e["value"] for e in self.get("effects", []) if e.get("param") == param and e.get("op") == "set"), None
        )

    def __setattr__(self, name: str, value: Any) -> None:
        raise FrozenInstanceError(f"cannot assign to field '{name}'")

    def __reduce__(self) -> tuple[type[Entry], tuple[str, str, dict[str, Any], str]]:
        """Pickled and copied as a plain entry (its fields decoded, never the stored form)."""
        return (Entry, (self.category, self.key, self.data, self.origin))

    def __delattr__(self, name: str) -> None:
        raise FrozenInstanceError(f"cannot delete field '{name}'")

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Entry)
        return (self.category, self.key, self.data, self.origin) == (
            other.category,
            other.key,
            other.data,
            other.origin,
        )

    __hash__ = None  # type: ignore[assignment]  # its fields are a dict (as the dataclass: unhashable)

    def __repr__(self) -> str:
        return f"Entry(category={self.category!r}, key={self.key!r}, data={self.data!r}, origin={self.origin!r})"


Forms = dict[tuple[str, ...], list[Entry]]  # normalised surface form -> the entries spelled so


class StoredIndex(NamedTuple):
    """A lexicon's index as the disk cache keeps it (cnlmc.lexicon), so a cold start does not
    rebuild it from every entry's aliases: each surface form ("stainless steel", its words joined
    by one space) -> the number of its entry in `order`, or a list of them when it names several
    (checked when a form is first looked up); the multi-word followers and lengths."""

    forms: dict[str, Any]
    order: list[Entry]
    followers: dict[str, frozenset[str]]
    lengths_from: dict[str, tuple[int, ...]]
    max_form_words: int

    def entries(self, form: str) -> list[Entry] | None:
        """The entries `form` names (None: it names none); CacheDamaged for a number not in `order`."""
        numbers = self.forms.get(form)
        if numbers is None:
            return None
        if type(numbers) is not list:
            numbers = [numbers]
        order = self.order
        if not all(type(n) is int and 0 <= n < len(order) for n in numbers):
            raise CacheDamaged(
                f"the cached lexicon's form '{form}' names no entry: delete the cache folder (it is rebuilt)"
            )
        return [order[n] for n in numbers]


def normalise(surface: str) -> tuple[str, ...]:
    """'Powder  Coated' -> ('powder', 'coated'): lower case, split on white space."""
    return tuple(surface.lower().split())


class LexiconCaches:
    """What is derived from one lexicon while it is used, kept with it (never written to the disk cache).

    - tagger: the Tagger of this lexicon (document.parse_document makes it on first use)
    - tags: word tuple -> the candidate tags the tagger found for it
    - suggestions: (word, categories, limit) -> the closest surface forms (Lexicon.suggest)
    - suggestion_index: every surface form with its categories, indexed for the typo search (suggest.FormIndex)
    - shapes: parse shapes by the candidate tags of a line's words (parser.parse_line_shape)
    - mistakes: parser failure key -> the friendly message learned from grammar/bad_examples.toml
      (None until a line first fails to parse; mistakes.known_mistake)
    - colour_phrases: (phrase, CIELAB) of every colour and shade+colour (the LSP's colour picker)
    - adjective_plans: (adjective key, noun key) -> the adjective's effect list on that noun, each
      formula read once for the material and for a coat, with its provenance texts by adverb
      weight (passes/words.py: AdjectivePlan)
    - subsurface_tables: adjective key -> its `subsurface` table or None (passes/subsurface.py)
    - rounded_optics: (noun key, parameter) -> the noun's list value rounded for the IR (ir.py)
    - word_formation: the rules of word_formation*.toml, compiled on first use (cnlmc.word_formation)
    - stage_orders: the describing groups' (kind, adjective key, has a colour) -> the canonical order
      they apply in (passes/order.py)
    - noun_plans: noun key -> what apply_noun sets from that noun, read from its entry once (passes/base.py)
    - pattern_colours: (linear RGB, graph) -> the colour a pattern of that graph can carry and the
      OKLab numbers its provenance names (passes/textured_colour.py)
    - coat_facts: adjective key -> (its entry, whether it lays a coat, whether it is a finish word
      that only sets the gloss) (passes/order.py: gloss_on_coat)
    - coat_fields: coat key -> (its entry, the fields a material's coat starts from) (passes/words.py:
      apply_coat_entry)
    """

    MAX_ENTRIES = 4096  # a memo this full starts over

    def __init__(self) -> None:
        self.tagger: Tagger | None = None
        self.tags: dict[tuple[str, ...], tuple[Candidate, ...]] = {}
        self.suggestions: dict[tuple[str, tuple[str, ...], int], list[str]] = {}
        self.suggestion_index: FormIndex | None = None
        self.shapes = ShapeCache()
        self.mistakes: dict[FailureKey, Mistake] | None = None
        self.adjective_plans: dict[tuple[str, str], Any] = {}
        self.subsurface_tables: dict[str, dict[str, Any] | None] = {}
        self.colour_phrases: tuple[tuple[str, tuple[float, float, float]], ...] | None = None
        self.rounded_optics: dict[tuple[str, str], list[float]] = {}
        self.word_formation: WordFormation | None = None
        self.stage_orders: dict[tuple[tuple[str, str | None, bool], ...], tuple[tuple[int, str], ...]] = {}
        self.noun_plans: dict[str, Any] = {}
        self.pattern_colours: dict[tuple[tuple[float, ...], str], Any] = {}
        self.coat_facts: dict[str, tuple[Entry, bool, bool]] = {}
        self.coat_fields: dict[str, tuple[Entry, dict[str, Any]]] = {}


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
        word_formation: list[dict[str, Any]] | None = None,
        *,
        index: StoredIndex | None = None,
    ) -> None:
        """`index`: the stored index of these entries (the disk cache's; `keywords` are then the
        whole table, the bundled keywords already merged in, and grammar/keywords.toml is not read)."""
        self.keywords = dict(keywords or {}) if index is not None else {**keyword_table(), **(keywords or {})}
        self.word_formation = word_formation or []  # each layer's word_formation table, most specific first
        self.entries = entries
        self.settings = settings
        self.inflections = inflections
        self.sources = sources
        self._forms: Forms | None = None
        self._stored: StoredIndex | None = index
        self._found: Forms = {}  # the stored index's look-ups so far (known forms only: bounded by the index)
        if index is None:
            self._forms = forms = _index_forms(entries)
            self.max_form_words = max(len(f) for f in forms)
            self.followers = _multi_word_followers(forms)
            self.lengths_from = _multi_word_lengths(forms)
        else:
            self.max_form_words = index.max_form_words
            self.followers = index.followers
            self.lengths_from = index.lengths_from
        self.caches = LexiconCaches()

    @property
    def forms(self) -> Forms:
        """Every surface form (its lower-case words) -> the entries it names, in entry order."""
        forms = self._forms
        if forms is None:
            stored = self._stored
            assert stored is not None
            forms = {}
            for form in stored.forms:
                found = stored.entries(form)
                assert found is not None
                forms[tuple(form.split(" "))] = found
            self._forms = forms
        return forms

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
        """The entries these lower-case words name (none: an empty list)."""
        forms = self._forms
        if forms is not None:
            return forms.get(words, [])
        found = self._found.get(words)
        if found is None:
            stored = self._stored
            assert stored is not None
            form = " ".join(words)
            found = stored.entries(form)
            if found is None or form.count(" ") != len(words) - 1:  # a "word" with a space in it names nothing
                return []
            self._found[words] = found
        return found

    def base_forms(self, word: str) -> list[str]:
        """Candidate base forms of an unknown word by the inflection rules, in order."""
        out = []
        for suffix, repl in self.inflections:
            if word.endswith(suffix) and len(word) > len(suffix) + 2:
                out.append(word[: len(word) - len(suffix)] + repl)
        return out

    def suggest(self, word: str, categories: Iterable[str] | None = None, limit: int = 3) -> list[str]:
        """Closest surface forms to `word`, best first: typos, never antonyms (cnlmc.suggest)."""
        key = (word.lower(), tuple(categories or CATEGORY_TAGS), limit)
        memo = self.caches.suggestions
        if key not in memo:
            if len(memo) > LexiconCaches.MAX_ENTRIES:
                memo.clear()
            memo[key] = self._closest(*key)
        return list(memo[key])

    def _closest(self, word: str, categories: tuple[str, ...], limit: int) -> list[str]:
        caches = self.caches
        if caches.suggestion_index is None:
            from .suggest import FormIndex  # only needed when a word is unknown

            caches.suggestion_index = FormIndex(
                {" ".join(f): {e.category for e in hits} for f, hits in self.forms.items()}
            )
        return caches.suggestion_index.closest(word, categories, limit)

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
    """Surface form (its lower-case words) -> the entries it names, in entry order. Made for every
    lexicon a process loads (a cold start): loops, not generators, in its inner part."""
    forms: Forms = {}
    for by_key in entries.values():
        for entry in by_key.values():
            aliases = entry.data.get("aliases")
            for surface in (entry.key, *aliases) if aliases else (entry.key,):
                form = tuple(surface.lower().split())
                hits = forms.get(form)
                if hits is None:
                    forms[form] = [entry]
                    continue
                for hit in hits:
                    if hit is entry:  # identity: comparing entries compares their data
                        break
                else:
                    hits.append(entry)
    return forms


def keyword_table(table: dict[str, Any] | None = None) -> dict[str, str]:
    """Closed-class words -> grammar terminal, from grammar/keywords.toml (or a given table)."""
    if table is None:
        return dict(_bundled_keywords())
    return {word: terminal for terminal, words in table["terminals"].items() for word in words}


@lru_cache(maxsize=1)
def _bundled_keywords() -> Mapping[str, str]:
    """grammar/keywords.toml's table, read once per process (immutable package data)."""
    import tomllib

    text = (package_folder("cnlmc.grammar") / "keywords.toml").read_text("utf-8")
    return MappingProxyType(keyword_table(tomllib.loads(text)))
