"""The parser's LALR tables in the disk cache (cnlmc.cache) as plain data, not as lark's pickle.

lark's own `cache=` option pickles the parser, and unpickling a crafted file runs code. Here the
tables are lark's serialized form (`memo_serialize`: dicts, lists, tuples, strings, numbers)
written as JSON, with tuples and non-string keys tagged so they come back as they were; the
custom lexer class, the only object in that form, is written as a marker and put back on
load. A file that fails verification or that lark cannot load is ignored and rebuilt.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import lark
from lark import Lark
from lark.grammar import Rule
from lark.lexer import TerminalDef

from .cache import cached, dump_json

LEXER_MARKER = "<cnlmc custom lexer>"
LEXER_PLACES = (("options", "lexer"), ("parser", "lexer_conf", "lexer_type"))  # where the lexer class sits


def plain(value: Any) -> Any:
    """lark's serialized data -> JSON data: a table is {"d": [[key, value], ...]}, a tuple {"t": [...]}."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, tuple):
        return {"t": [plain(v) for v in value]}
    if isinstance(value, dict):
        return {"d": [[plain(k), plain(v)] for k, v in value.items()]}
    raise TypeError(f"not plain data: {type(value).__name__}")


def _untag(table: dict[str, Any]) -> Any:
    """json.loads' object_hook: plain()'s tagged tables and tuples back (the decoder calls it inner first)."""
    if set(table) == {"t"} and isinstance(table["t"], list):
        return tuple(table["t"])
    if set(table) == {"d"} and isinstance(table["d"], list):
        return dict(table["d"])  # pairs; a list as a key is a TypeError: rebuilt
    raise ValueError("not a tagged table or tuple")


def unplain(payload: bytes) -> Any:
    """The data plain() wrote, from its JSON; ValueError or TypeError for anything else."""
    try:
        return json.loads(payload, object_hook=_untag, parse_constant=_refuse)
    except RecursionError:
        raise ValueError("nested too deeply") from None


def _refuse(name: str) -> Any:
    raise ValueError(f"{name} is not a finite number")


def _swap(data: dict[str, Any], old: object, new: object) -> None:
    for place in LEXER_PLACES:
        holder = data
        for key in place[:-1]:
            holder = holder[key]
        if holder[place[-1]] is not old and holder[place[-1]] != old:
            raise ValueError(f"unexpected value at {'.'.join(place)}")
        holder[place[-1]] = new


def cached_lark(grammar: str, lexer: type, **options: Any) -> Lark:
    """Lark(grammar, lexer=lexer, **options), its tables read from the disk cache when there."""

    def build() -> Lark:
        return Lark(grammar, lexer=lexer, **options)

    def dump(parser: Lark) -> bytes:
        data, memo = parser.memo_serialize([TerminalDef, Rule])
        _swap(data, lexer, LEXER_MARKER)
        return dump_json(plain({"data": data, "memo": memo}))

    def load(payload: bytes) -> Lark:
        stored = unplain(payload)
        _swap(stored["data"], LEXER_MARKER, lexer)
        try:
            parser: Lark = Lark._load_from_dict(stored["data"], stored["memo"])
        except Exception as exc:  # whatever lark makes of data it did not write: rebuild
            raise ValueError(f"lark cannot load the tables: {exc}") from None
        return parser

    kind = "grammar-" + hashlib.sha256(grammar.encode()).hexdigest()[:16]
    sources = [Path(__file__), Path(str(lark.__file__))]  # this format, and lark's version
    return cached(kind, sources, build, dump, load)
