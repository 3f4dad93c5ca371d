"""Names and free text in exchange documents: valid unique identifiers, XML-safe text."""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable, Sequence

from cnlmc.material import Material


def identifier(text: str, fallback: str = "material") -> str:
    """Any text -> [A-Za-z_][A-Za-z0-9_]*: accents folded, everything else becomes '_'."""
    folded = unicodedata.normalize("NFKD", str(text)).encode("ascii", "ignore").decode("ascii")
    name = re.sub(r"[^A-Za-z0-9_]+", "_", folded).strip("_") or fallback
    return name if not name[0].isdigit() else f"_{name}"


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
    so a material is found by identity among the document's own objects)."""

    def __init__(self, materials: Sequence[Material]):
        self.pairs = list(zip(materials, unique_identifiers(m.name for m in materials)))

    def __getitem__(self, material: Material) -> str:
        for candidate, ident in self.pairs:
            if candidate is material:
                return ident
        raise KeyError(material.name)


INVALID_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def xml_text(value: object) -> str:
    """Characters XML 1.0 cannot hold at all (even escaped) are removed; the rest is escaped
    by whichever writer the backend uses (MaterialX's, pxr's, jinja2's autoescape)."""
    return INVALID_XML.sub("", str(value))


def phrase_text(material: Material) -> str:
    return xml_text(material.phrase)
