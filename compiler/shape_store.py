"""Parse shapes kept in the disk cache between runs, so that a start whose lines all have a stored
shape never loads lark (about a quarter of a cold `cnlmc compile`; docs/language.md "Speed").

A shape (syntax.Shape) depends only on the grammar and on the code that reads lark's tree, so
the entry is keyed by grammar/cnl.lark, syntax.py, shape_reader.py, parser.py, this file and lark's
own package file (cnlmc.cache.source_key), not by the lexicon. It is plain JSON in the verified
cache format (cnlmc.cache: a digest over the payload, a private folder, never pickle):

    {"shapes": [[key, used, root, choice], ...]}

key: the candidate tags of each word (a tag, or a list of tags for an ambiguous word); used:
the tagged positions of the AST words; root: the line's plan, a list of its fields in order (a
slice is [start, stop], a tuple of plans a list, None null, a material plan's list starts with
"M" and a refinement plan's with "R"); choice: null or the reading chosen per word.

A stored entry is decoded only when a line with its key is first met (StoredShapes.recall),
through the plans' own constructors, every field checked against the plan's annotation, and
then built once on stand-in words of the key's length: an entry that fails is dropped and the
line is parsed. Saving writes what is stored plus what this process read (ShapeCache.save).
"""

from __future__ import annotations

import os
import types
from importlib import util
from pathlib import Path
from typing import TYPE_CHECKING, Any, Union, get_args, get_origin

from .cache import Corrupt, DiskCache, dump_json, load_json, source_key
from .package_data import package_folder
from .spans import Span
from .syntax import MAX_SHAPES, GroupPlan, MaterialPlan, RefinementPlan, Shape, ShapeKey
from .tagged import Candidate, Tagged

if TYPE_CHECKING:
    from .syntax import ShapeCache

KIND = "shapes"
ROOTS: dict[str, type[MaterialPlan] | type[RefinementPlan]] = {"M": MaterialPlan, "R": RefinementPlan}
GROUP_KINDS = frozenset(("adjective", "colour", "dangling"))  # GroupPlan.kind: the grammar's group rules
Entry = list[Any]  # [used, root, choice] as stored
Stored = tuple[Shape, tuple[int, ...] | None]


def recall_shape(shapes: ShapeCache, key: ShapeKey) -> Stored | None:
    """The stored shape of this tag sequence from an earlier run (None: not stored, or `shapes` is
    not persistent); the store is read when first needed."""
    stored = _store(shapes)
    return None if stored is None else stored.recall(key)


def save_shapes(shapes: ShapeCache) -> None:
    """Keep the shapes read since the last save in the disk cache (none new: no write)."""
    stored = _store(shapes) if shapes.fresh else None
    if stored is not None:
        stored.save(shapes)
    shapes.fresh = 0


def _store(shapes: ShapeCache) -> StoredShapes | None:
    if not shapes.persistent:
        return None
    if shapes.stored is None:
        shapes.stored = StoredShapes.load()
    return shapes.stored


def shape_sources() -> list[Path]:
    """The files a stored shape depends on: a change to one makes a new cache entry."""
    here = Path(__file__).parent
    sources = [here / f"{name}.py" for name in ("syntax", "shape_reader", "parser", "shape_store")]
    sources.append(package_folder("cnlmc.grammar") / "cnl.lark")
    spec = util.find_spec("lark")  # lark's version, without loading it
    if spec is not None and spec.origin:
        sources.append(Path(spec.origin))
    return sources


class StoredShapes:
    """The shapes of the disk cache's entry (decoded as they are asked for) and how to write it."""

    def __init__(self, cache: DiskCache | None, name: str, entries: dict[ShapeKey, Entry]) -> None:
        self.cache, self.name, self.entries = cache, name, entries

    @classmethod
    def load(cls) -> StoredShapes:
        """The stored shapes; none (and nothing written later) with CNLMC_NO_CACHE or unreadable sources."""
        key = None if os.environ.get("CNLMC_NO_CACHE") else source_key(KIND, shape_sources())
        if key is None:
            return cls(None, "", {})
        cache, name = DiskCache(), f"{KIND}-{key}"
        try:
            entries = _entries(load_json(cache.load(name)))
        except (Corrupt, ValueError, TypeError):
            entries = {}
        return cls(cache, name, entries)

    def recall(self, key: ShapeKey) -> Stored | None:
        """The stored shape and choice of this tag sequence, or None (an entry that fails is dropped)."""
        entry = self.entries.get(key)
        if entry is None:
            return None
        try:
            return decode_entry(key, entry)
        except (ValueError, TypeError, IndexError, KeyError, AttributeError):
            self.entries.pop(key, None)  # (another thread may have dropped it already)
            return None

    def save(self, shapes: ShapeCache) -> None:
        """Store the shapes in `shapes` with those stored already (at most MAX_SHAPES, newest kept)."""
        if self.cache is None:
            return
        merged = dict(self.entries)
        for key, (shape, choice) in list(shapes.items()):  # a copy: another thread may parse meanwhile
            merged.pop(key, None)
            merged[key] = encode_entry(shape, choice)
        kept = list(merged.items())[-MAX_SHAPES:]
        self.entries = dict(kept)
        rows = [[[t if isinstance(t, str) else list(t) for t in key], *entry] for key, entry in kept]
        self.cache.store(self.name, dump_json({"shapes": rows}))


def _entries(data: Any) -> dict[ShapeKey, Entry]:
    """key -> stored entry, undecoded; TypeError or ValueError for data of another form."""
    if type(data) is not dict or type(data.get("shapes")) is not list:
        raise TypeError("not a shapes entry")
    out: dict[ShapeKey, Entry] = {}
    for row in data["shapes"]:
        if type(row) is not list or len(row) != 4 or type(row[0]) is not list:
            raise TypeError("not a stored shape")
        out[tuple(_tag_of(t) for t in row[0])] = row[1:]
    return out


def _tag_of(value: Any) -> str | tuple[str, ...]:
    if type(value) is str:
        return value
    if type(value) is list and len(value) > 1 and all(type(t) is str for t in value):
        return tuple(value)
    raise TypeError("a word's tags are a string or a list of strings")


# ---------------------------------------------------------------- encoding and decoding


def encode_entry(shape: Shape, choice: tuple[int, ...] | None) -> Entry:
    root = shape.root
    tag = "M" if isinstance(root, MaterialPlan) else "R"
    return [list(shape.used), [tag, *[_encode(v) for v in root]], None if choice is None else list(choice)]


def _encode(value: Any) -> Any:
    if isinstance(value, slice):
        return [value.start, value.stop]
    if isinstance(value, tuple):  # a plan (a NamedTuple) or a tuple of plans: both lists
        return [_encode(v) for v in value]
    return value  # int, bool, str or None


def decode_entry(key: ShapeKey, entry: Entry) -> Stored:
    """A stored entry back as (Shape, choice), checked against `key`; ValueError or TypeError if it
    is not what encode_entry writes for a line with these tags."""
    if type(entry) is not list or len(entry) != 3:
        raise TypeError("not a stored shape")
    used_data, root_data, choice_data = entry
    used = tuple(_int_list(used_data))
    if list(used) != sorted(set(used)) or (used and not 0 <= used[0] <= used[-1] < len(key)):
        raise ValueError("the words' positions are not in the line")
    if type(root_data) is not list or not root_data or root_data[0] not in ROOTS:
        raise TypeError("not a plan")
    shape = Shape(used, _decode(root_data[1:], ROOTS[root_data[0]], len(used)))
    choice = None if choice_data is None else tuple(_int_list(choice_data))
    if choice is not None and (
        len(choice) != len(key)
        or not all(0 <= c < (1 if isinstance(t, str) else len(t)) for c, t in zip(choice, key, strict=True))
    ):
        raise ValueError("a reading that the word does not have")
    _try_build(shape, len(key))
    return shape, choice


def _int_list(value: Any) -> list[int]:
    if type(value) is not list or not all(type(v) is int for v in value):
        raise TypeError("expected a list of integers")
    return value


def _decode(value: Any, kind: Any, words: int) -> Any:
    """`value` as the type `kind` (a plan's field annotation) for a line of `words` AST words:
    TypeError or ValueError if it is not one (a negative index, a slice past the words)."""
    if kind is int or kind is bool or kind is str:
        if type(value) is not kind:
            raise TypeError(f"expected {kind.__name__}")
        if type(value) is int and value < 0:
            raise ValueError("a negative index")
        return value
    if kind is slice:
        start, stop = _int_list(value) if type(value) is list and len(value) == 2 else (-1, -1)
        if not 0 <= start <= stop <= words:
            raise ValueError("not a slice of the words")
        return slice(start, stop)
    origin = get_origin(kind)
    if origin is tuple:  # tuple[Plan, ...]
        if type(value) is not list:
            raise TypeError("expected a list")
        return tuple([_decode(v, get_args(kind)[0], words) for v in value])
    if origin is Union or origin is types.UnionType:
        return _decode_union(value, get_args(kind), words)
    if isinstance(kind, type) and issubclass(kind, tuple) and hasattr(kind, "_fields"):
        return _decode_plan(value, kind, words)
    raise TypeError(f"no stored form for {kind!r}")


def _decode_union(value: Any, members: tuple[Any, ...], words: int) -> Any:
    if value is None:
        if type(None) not in members:
            raise TypeError("unexpected null")
        return None
    if type(value) is int and int in members and value >= 0:
        return value
    plans = [m for m in members if isinstance(m, type) and issubclass(m, tuple)]
    if type(value) is not list or len(plans) != 1:
        raise TypeError("not one of the field's types")
    return _decode_plan(value, plans[0], words)


def _decode_plan(value: Any, plan: type[Any], words: int) -> Any:
    fields = plan._fields
    if type(value) is not list or len(value) != len(fields):
        raise TypeError(f"not a {plan.__name__}")
    hints = plan.__annotations__  # real types: syntax.py has no postponed annotations
    made = plan(*[_decode_field(v, hints[f], f, words) for v, f in zip(value, fields, strict=True)])
    if plan is GroupPlan and made.kind not in GROUP_KINDS:
        raise ValueError("not a group's kind")
    return made


def _decode_field(value: Any, kind: Any, field: str, words: int) -> Any:
    if field == "noun_at" and value == -1:  # ColourPlan: -1 says no noun
        return -1
    return _decode(value, kind, words)


def _try_build(shape: Shape, length: int) -> None:
    """Build the shape once on stand-in words: an index outside the line raises here, not later."""
    words = [Tagged(f"w{i}", Span(2 * i, 2 * i + 1, 1, 2 * i + 1), ()) for i in range(length)]
    picks = [Candidate("ADJ", f"w{i}", "adjectives") for i in range(length)]
    shape.build(words, picks, " ".join(w.text for w in words))
