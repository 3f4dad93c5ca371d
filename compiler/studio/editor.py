"""The editor's language features, computed by the language server's own functions (cnlmc.lsp):
diagnostics, semantic tokens, colour swatches, completion, hover and quick fixes, as JSON the
page's CodeMirror reads. Positions are LSP positions in UTF-16 code units (what JavaScript strings
count), so the page maps them to offsets as `doc.line(line + 1).from + character`."""

from __future__ import annotations

from typing import Any

from lsprotocol import types
from pygls.protocol import default_converter

from ..lexicon import Lexicon
from ..lsp import actions, colours, completion, hover, tokens
from ..lsp.diagnostics import LspDiagnostics
from ..lsp.incremental import Analyzer, Snapshot

JSONDict = dict[str, Any]
#: the document's name in diagnostics and edits (the studio edits one document per session)
URI = "studio:document.cnl"
ENCODING = "utf-16"


class EditorEngine:
    """One session's analysis: the language server's incremental analyzer (blocks cached by their
    text, so a keystroke recompiles the block it changed) and its diagnostics converter."""

    def __init__(self, lexicon: Lexicon) -> None:
        self.lexicon = lexicon
        self.analyzer = Analyzer(lexicon, "<studio>")
        self.diagnostic_converter = LspDiagnostics()
        self.converter = default_converter()
        self.snapshot: Snapshot | None = None

    def analyse(self, text: str) -> Snapshot:
        """The snapshot of `text` (kept: completion, hover and fixes then ask about the same text)."""
        if self.snapshot is None or self.snapshot.index.text != text:
            self.snapshot = self.analyzer.analyse(text, ENCODING)
        return self.snapshot

    def features(self, text: str) -> JSONDict:
        """Diagnostics, semantic tokens and colour swatches of the whole document."""
        snapshot = self.analyse(text)
        return {
            "diagnostics": self._with_fixes(self.diagnostic_converter.of(snapshot, URI), snapshot),
            "tokens": [list(token) for batch in tokens.token_batches(snapshot, self.lexicon) for token in batch],
            "token_types": tokens.TOKEN_TYPES,
            "colours": [self.converter.unstructure(c) for c in colours.document_colours(snapshot, self.lexicon)],
        }

    def _with_fixes(self, diagnostics: list[JSONDict], snapshot: Snapshot) -> list[JSONDict]:
        """Each diagnostic with its quick fixes (`fixes`: title, preferred, edits), as the
        language server's code actions offer them for its range."""
        lines = sorted({d["range"]["start"]["line"] for d in diagnostics})
        by_range: dict[str, list[JSONDict]] = {}
        for line in lines:
            where = types.Range(types.Position(line, 0), types.Position(line, 0))
            for action in actions.quick_fixes(snapshot, URI, where, self.lexicon):
                for diag in action.diagnostics or []:
                    by_range.setdefault(_range_key(self.converter.unstructure(diag.range)), []).append(
                        self._fix(action)
                    )
        return [{**d, "fixes": by_range.get(_range_key(d["range"]), [])} for d in diagnostics]

    def _fix(self, action: types.CodeAction) -> JSONDict:
        changes = (action.edit.changes or {}).get(URI, []) if action.edit else []
        return {
            "title": action.title,
            "preferred": bool(action.is_preferred),
            "edits": [{"range": self.converter.unstructure(e.range), "text": e.new_text} for e in changes],
        }

    def completion(self, text: str, line: int, character: int) -> list[JSONDict]:
        found = completion.complete(self.analyse(text), types.Position(line, character), self.lexicon)
        if found is None:
            return []
        return [self._item(item) for item in found.items]

    def _item(self, item: types.CompletionItem) -> JSONDict:
        edit = item.text_edit
        documentation = item.documentation
        return {
            "label": item.label,
            "detail": item.detail or "",
            "kind": types.CompletionItemKind(item.kind).name.lower() if item.kind else "text",
            "sort": item.sort_text or item.label,
            "range": self.converter.unstructure(edit.range) if isinstance(edit, types.TextEdit) else None,
            "doc": documentation.value if isinstance(documentation, types.MarkupContent) else "",
        }

    def hover(self, text: str, line: int, character: int) -> JSONDict | None:
        found = hover.hover(self.analyse(text), types.Position(line, character), self.lexicon)
        if found is None or not isinstance(found.contents, types.MarkupContent):
            return None
        where = self.converter.unstructure(found.range) if found.range else None
        return {"markdown": found.contents.value, "range": where}


def _range_key(where: JSONDict) -> str:
    start, end = where["start"], where["end"]
    return f"{start['line']}:{start['character']}-{end['line']}:{end['character']}"
