"""Hover: a word's lexicon doc and effects; a material line's resolved material (as `explain`)."""

from __future__ import annotations

from typing import Any

from lsprotocol import types

from .. import ast
from ..colour import linear_to_hex
from ..explain import explain_material
from ..lexicon import Lexicon
from .entries import entry_markdown
from .incremental import Snapshot
from .lines import LineWord, line_words, word_at
from .markdown import code_block, code_span, prose, strong


def hover(snapshot: Snapshot, position: types.Position, lexicon: Lexicon) -> types.Hover | None:
    found = snapshot.index.line_col(position)
    if found is None:
        return None
    line, col = found
    word = word_at(line_words(snapshot, line, lexicon), col)
    sections = []
    if word is not None:
        sections.append(word_section(word, lexicon))
    sections += [material_section(m) for m in line_materials(snapshot, line)]
    sections = [s for s in sections if s]
    if not sections:
        return None
    where = snapshot.index.range_of(line, word.start, word.end) if word else None
    return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, "\n\n---\n\n".join(sections)), where)


def line_materials(snapshot: Snapshot, line: int) -> list[dict[str, Any]]:
    """The materials a line describes; a refinement line shows the material it refines."""
    on_line = snapshot.materials_on(line)
    if on_line:
        return on_line
    item, block = snapshot.item_on(line)
    if block is None or not isinstance(item, ast.Refinement):
        return []
    return list(block.result.materials)


def word_section(word: LineWord, lexicon: Lexicon) -> str:
    if word.category == "unknown":
        suggestions = lexicon.suggest(word.text) if word.text[:1].isalpha() else []
        hint = f" — did you mean {', '.join(code_span(s) for s in suggestions)}?" if suggestions else ""
        return f"{strong(word.text)} — not in the lexicon{hint}"
    entry = lexicon.entry(word.category, word.key)
    if entry is not None:
        return entry_markdown(entry, word.text)
    if word.category == "name":
        return f"{strong(word.text)} — material name"
    return ""


def material_section(material: dict[str, Any]) -> str:
    params = material["params"]
    summary = [strong(str(material["name"]))]
    if "base_color" in params:
        summary.append(f"colour {code_span(linear_to_hex(params['base_color']))}")
    if "roughness" in params:
        summary.append(prose(f"roughness {params['roughness']:.3g}"))
    return " · ".join(summary) + "\n\n" + code_block(explain_material(material))
