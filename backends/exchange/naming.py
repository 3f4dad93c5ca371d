"""Names and free text in exchange documents: valid unique identifiers, XML-safe text."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from cnlmc.diagnostics import visible
from cnlmc.filenames import short_hash
from cnlmc.material import Material
from cnlmc.passes.variants import ascii_fold


def identifier(text: str, fallback: str = "material") -> str:
    """Any text -> [A-Za-z_][A-Za-z0-9_]*: accents folded ('ünïcødé' -> 'unicode'), everything
    else becomes '_'; a text with nothing ASCII left gets `fallback` and a short hash of it, so two
    such names never collide. (The name as written is shown beside it: `display_name`.)"""
    text = str(text)
    folded = ascii_fold(text).encode("ascii", "ignore").decode("ascii")
    name = re.sub(r"[^A-Za-z0-9_]+", "_", folded).strip("_")
    if not name:
        name = fallback if text.isascii() else f"{fallback}_{short_hash(text)}"
    return name if not name[0].isdigit() else f"_{name}"


def display_name(material: Material) -> str:
    """The material's name as written, when its identifier could not keep it ('' otherwise)."""
    return xml_text(material.label)


def described(material: Material) -> str:
    """'NAME AS WRITTEN: phrase' (or the phrase): a comment or doc string beside an identifier."""
    label = display_name(material)
    return f"{label}: {phrase_text(material)}" if label else phrase_text(material)


def unique_identifiers(names: Iterable[str], fallback: str = "material") -> list[str]:
    """Identifiers for a list of names, suffixed _2, _3 ... where two would collide."""
    seen: set[str] = set()
    out = []
    for name in names:
        base = identifier(name, fallback)
        candidate, n = base, 2
        while candidate in seen:
            candidate, n = f"{base}_{n}", n + 1
        seen.add(candidate)
        out.append(candidate)
    return out


class MaterialIdents:
    """The unique identifier of each material of one document (two materials may be equal,
    so a material is found by identity among the document's own objects). The search starts
    after the last material found: asked in document order, as the emit loop asks, each lookup
    is one step (not a scan: 10k materials took minutes)."""

    def __init__(self, materials: Sequence[Material]):
        self.pairs = list(zip(materials, unique_identifiers(m.name for m in materials)))
        self.next = 0

    def __getitem__(self, material: Material) -> str:
        count = len(self.pairs)
        for step in range(count):
            index = (self.next + step) % count
            candidate, ident = self.pairs[index]
            if candidate is material:
                self.next = index + 1
                return ident
        raise KeyError(material.name)


INVALID_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def xml_text(value: object) -> str:
    """Free text (a phrase, a name as written) for a doc string or comment: control characters
    (C0, DEL, C1, line separators, bidi overrides) become visible escapes such as `\\x9b`, as on
    the terminal (a file printed on stdout must not drive the terminal; XML 1.0 cannot hold C0
    at all), and lone surrogates are removed; the rest is escaped by whichever writer the
    backend uses (MaterialX's, pxr's, jinja2's autoescape)."""
    return INVALID_XML.sub("", visible(str(value), one_line=True))


def phrase_text(material: Material) -> str:
    return xml_text(material.phrase)
