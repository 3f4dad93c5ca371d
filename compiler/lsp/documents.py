"""The server's copy of each open document, kept exactly as the editor's.

Incremental edits are applied with the LSP spec's line ends (CRLF, LF, lone CR: `cnlmc.lines`),
not `str.splitlines`, which also breaks lines at form feed, U+2028 and friends: with that, an
edit after such a character landed on another line than the editor's and the two copies drifted
apart. Positions are read in the negotiated encoding; a column past a line's end means the line's
end and a line past the last means the end of the text (the spec's rule for ranges).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from lsprotocol import types

from .positions import LineIndex

Change = types.TextDocumentContentChangePartial | types.TextDocumentContentChangeWholeDocument


@dataclass
class Document:
    uri: str
    text: str
    version: int | None

    def apply(self, change: Change, encoding: str) -> None:
        """One content change of a didChange: a whole new text or a range replaced."""
        if isinstance(change, types.TextDocumentContentChangeWholeDocument):
            self.text = change.text
            return
        index = LineIndex(self.text, encoding)
        start = index.clamped_offset(change.range.start)
        end = max(start, index.clamped_offset(change.range.end))
        self.text = self.text[:start] + change.text + self.text[end:]


class DocumentStore:
    """The open documents by URI; closing one forgets it."""

    def __init__(self) -> None:
        self._open: dict[str, Document] = {}

    def open(self, uri: str, text: str, version: int | None) -> Document:
        document = self._open[uri] = Document(uri, text, version)
        return document

    def change(self, uri: str, version: int | None, changes: Sequence[Change], encoding: str) -> Document | None:
        """Apply a didChange; None for a document that is not open (the change is ignored)."""
        document = self._open.get(uri)
        if document is None:
            return None
        for change in changes:
            document.apply(change, encoding)
        document.version = version
        return document

    def close(self, uri: str) -> Document | None:
        return self._open.pop(uri, None)

    def get(self, uri: str) -> Document | None:
        return self._open.get(uri)

    def __contains__(self, uri: str) -> bool:
        return uri in self._open

    def __iter__(self) -> Iterator[str]:
        return iter(list(self._open))

    def __len__(self) -> int:
        return len(self._open)
