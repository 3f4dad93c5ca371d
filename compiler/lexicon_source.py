"""One lexicon file's text and where its keys are: errors say FILE:LINE:COL of the key at fault.

tomllib gives no positions, so `key_positions` scans the text once (only when an error needs
one): table headers, `key = value` lines, and the keys and list items inside inline tables and
arrays, each recorded under its full path, e.g. ("brushed", "effects", 1, "value"). The scanner
is forgiving: on text it does not understand it stops, and a path it did not see falls back to
its nearest recorded parent, then to the file's first line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .lines import LineTable

Path_ = tuple[str | int, ...]  # a key path inside one file: table keys (str) and list indices (int)

BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")
VALUE_TOKEN = re.compile(r"[^\s,\]}#]+")  # a number, boolean or date: whatever runs up to a separator
MAX_DEPTH = 64  # deeper nesting is not scanned (tomllib refuses far less already)


def dotted(path: Path_) -> str:
    """("clear coat", "ior") -> '"clear coat".ior'; ("brushed", "effects", 1) -> 'brushed.effects[1]'."""
    out = ""
    for part in path:
        if isinstance(part, int):
            out += f"[{part}]"
            continue
        name = part if BARE_KEY.fullmatch(part) else '"' + part.replace("\\", "\\\\").replace('"', '\\"') + '"'
        out += f".{name}" if out else name
    return out


@dataclass
class Positions:
    """Key path -> offset of its first appearance; `duplicates` holds paths assigned twice."""

    found: dict[Path_, int] = field(default_factory=dict)
    duplicates: list[tuple[Path_, int]] = field(default_factory=list)

    def assign(self, path: Path_, offset: int) -> None:
        if path in self.found:
            self.duplicates.append((path, offset))
        else:
            self.found[path] = offset


class _Scanner:
    """A small reader of TOML's shape (not its values): enough to know where each key is."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.i = 0
        self.positions = Positions()

    def scan(self) -> Positions:
        table: Path_ = ()
        array_tables: dict[Path_, int] = {}
        while self._skip_blank_lines():
            start = self.i
            if self.text.startswith("[[", start):
                self.i += 2
                keys = self._key()
                index = array_tables[keys] = array_tables.get(keys, -1) + 1
                table = (*keys, index)
                self.positions.found.setdefault(table, start)
                self.positions.found.setdefault(keys, start)
            elif self.text[start] == "[":
                self.i += 1
                table = self._key()
                self.positions.assign(table, start)
            else:
                keys = self._key()
                self._expect("=")
                self.positions.assign((*table, *keys), start)
                self._value((*table, *keys), 0)
            self._rest_of_line()
        return self.positions

    # ------------------------------------------------------------- lexical helpers

    def _skip_blank_lines(self) -> bool:
        """Skip white space, line ends and comments; False at the end of the text."""
        text = self.text
        while self.i < len(text):
            c = text[self.i]
            if c in " \t\r\n":
                self.i += 1
            elif c == "#":
                self._comment()
            else:
                return True
        return False

    def _space(self, newlines: bool = False) -> None:
        text = self.text
        while self.i < len(text):
            c = text[self.i]
            if c in " \t" or (newlines and c in "\r\n"):
                self.i += 1
            elif newlines and c == "#":
                self._comment()
            else:
                return

    def _comment(self) -> None:
        end = self.text.find("\n", self.i)
        self.i = len(self.text) if end < 0 else end

    def _rest_of_line(self) -> None:
        self._space()
        if self.i < len(self.text) and self.text[self.i] == "#":
            self._comment()
        if self.i < len(self.text) and self.text[self.i] not in "\r\n":
            raise ValueError("unexpected text after a value")

    def _expect(self, char: str) -> None:
        self._space()
        if not self.text.startswith(char, self.i):
            raise ValueError(f"expected {char!r}")
        self.i += 1

    def _key(self) -> tuple[str, ...]:
        parts = [self._simple_key()]
        while True:
            self._space()
            if not self.text.startswith(".", self.i):
                break
            self.i += 1
            parts.append(self._simple_key())
        self._space()
        if self.text.startswith("]", self.i):  # the end of a [table] or [[array]] header
            self.i += 2 if self.text.startswith("]]", self.i) else 1
        return tuple(parts)

    def _simple_key(self) -> str:
        self._space()
        if self.i < len(self.text) and self.text[self.i] in "\"'":
            return self._string()
        match = BARE_KEY.match(self.text, self.i)
        if match is None:
            raise ValueError("expected a key")
        self.i = match.end()
        return match.group()

    def _string(self) -> str:
        quote = self.text[self.i]
        if self.text.startswith(quote * 3, self.i):
            end = self.text.find(quote * 3, self.i + 3)
            if end < 0:
                raise ValueError("unterminated string")
            while self.text.startswith(quote, end + 3):  # up to two quotes may end the content
                end += 1
            body, self.i = self.text[self.i + 3 : end], end + 3
            return body
        j = self.i + 1
        while j < len(self.text) and self.text[j] != quote and self.text[j] != "\n":
            j += 2 if quote == '"' and self.text[j] == "\\" else 1
        if j >= len(self.text) or self.text[j] != quote:
            raise ValueError("unterminated string")
        raw, self.i = self.text[self.i + 1 : j], j + 1
        return raw.replace('\\"', '"').replace("\\\\", "\\") if quote == '"' else raw

    # ------------------------------------------------------------- values

    def _value(self, path: Path_, depth: int) -> None:
        if depth > MAX_DEPTH:
            raise ValueError("nested too deeply")
        self._space()
        c = self.text[self.i : self.i + 1]
        if c == "{":
            self._inline_table(path, depth)
        elif c == "[":
            self._array(path, depth)
        elif c in ("'", '"'):
            self._string()
        else:
            match = VALUE_TOKEN.match(self.text, self.i)
            if match is None:
                raise ValueError("expected a value")
            self.i = match.end()

    def _inline_table(self, path: Path_, depth: int) -> None:
        self.i += 1
        self._space()
        while not self.text.startswith("}", self.i):
            start = self.i
            keys = self._key()
            self._expect("=")
            self.positions.assign((*path, *keys), start)
            self._value((*path, *keys), depth + 1)
            self._space()
            if self.text.startswith(",", self.i):
                self.i += 1
                self._space()
            elif not self.text.startswith("}", self.i):
                raise ValueError("expected ',' or '}'")
        self.i += 1

    def _array(self, path: Path_, depth: int) -> None:
        self.i += 1
        index = 0
        self._space(newlines=True)
        while not self.text.startswith("]", self.i):
            self.positions.found.setdefault((*path, index), self.i)
            self._value((*path, index), depth + 1)
            self._space(newlines=True)
            if self.text.startswith(",", self.i):
                self.i += 1
                index += 1
                self._space(newlines=True)
            elif not self.text.startswith("]", self.i):
                raise ValueError("expected ',' or ']'")
        self.i += 1


def key_positions(text: str) -> Positions:
    """Where each key of a TOML text is (offsets); as much as could be scanned."""
    scanner = _Scanner(text)
    try:
        return scanner.scan()
    except (ValueError, IndexError):
        return scanner.positions


class SourceText:
    """A lexicon file's name and text, with positions found on first need."""

    def __init__(self, name: str, text: str) -> None:
        self.name = name
        self.text = text
        self._positions: Positions | None = None
        self._lines: LineTable | None = None

    @property
    def positions(self) -> Positions:
        if self._positions is None:
            self._positions = key_positions(self.text)
        return self._positions

    def line_col(self, offset: int) -> tuple[int, int]:
        """1-based line and column of an offset."""
        if self._lines is None:
            self._lines = LineTable(self.text)
        line, column = self._lines.position(offset)
        return line, column + 1

    def locate(self, path: Path_) -> tuple[int, int]:
        """1-based (line, column) of the key at `path`, or of its nearest parent the scan found."""
        found = self.positions.found
        for end in range(len(path), 0, -1):
            offset = found.get(path[:end])
            if offset is not None:
                return self.line_col(offset)
        return 1, 1

    def where(self, path: Path_) -> str:
        """'FILE:LINE:COL' of a key."""
        line, column = self.locate(path)
        return f"{self.name}:{line}:{column}"
