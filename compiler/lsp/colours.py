"""Document colours: swatches for colour phrases and materials' base colours; the colour
picker's answer is the nearest phrase ("dark slate blue") from the lexicon's colours and shades."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from lsprotocol import types

from ..colour import linear_to_srgb, srgb_to_linear
from ..lexicon import Lexicon
from ..passes.colours import resolve_colour, shade
from ..state import Context
from .incremental import Snapshot

MAX_PRESENTATIONS = 3
Lab = tuple[float, float, float]


def swatch(rgb: Sequence[float]) -> types.Color:
    red, green, blue = (linear_to_srgb(c) for c in rgb)
    return types.Color(red=red, green=green, blue=blue, alpha=1.0)


def document_colours(snapshot: Snapshot, lexicon: Lexicon) -> list[types.ColorInformation]:
    return [swatch for batch in colour_batches(snapshot, lexicon) for swatch in batch]


def colour_batches(snapshot: Snapshot, lexicon: Lexicon) -> Iterator[list[types.ColorInformation]]:
    """The swatches of each line, one list per line (the server runs them in time slices)."""
    ctx = Context(lexicon)
    for line in range(len(snapshot.index.lines)):
        out = []
        for phrase, start, end in snapshot.colours_on(line):
            if phrase.base is not None and not phrase.base.unknown:
                out.append(
                    types.ColorInformation(
                        snapshot.index.range_of(line, start, end), swatch(resolve_colour(phrase, ctx))
                    )
                )
        yield out + material_swatches(snapshot, line)


def material_swatches(snapshot: Snapshot, line: int) -> list[types.ColorInformation]:
    """The resolved base colour of the material on `line`, shown on its noun."""
    materials = snapshot.materials_on(line)
    nouns = [(w, col) for w, col in snapshot.words_on(line) if w.category == "nouns"]
    if not materials or not nouns or "base_color" not in materials[0]["params"]:
        return []
    out = []
    for (word, col), material in zip(nouns, materials):
        where = snapshot.index.range_of(line, col, col + len(word.text))
        out.append(types.ColorInformation(where, swatch(material["params"]["base_color"])))
    return out


def _lab(rgb: Sequence[float]) -> Lab:
    """CIE L*a*b* (D65) of a linear Rec.709 colour: distances there match what people see."""
    r, g, b = rgb
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    fx, fy, fz = (t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116 for t in (x, y, z))
    return 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)


def phrase_table(lexicon: Lexicon) -> tuple[tuple[str, Lab], ...]:
    """(phrase, Lab) for every named colour and every shade of it (made once per lexicon)."""
    caches = lexicon.caches
    if caches.colour_phrases is None:
        caches.colour_phrases = _phrase_table(lexicon)
    return caches.colour_phrases


def _phrase_table(lexicon: Lexicon) -> tuple[tuple[str, Lab], ...]:
    table = []
    shades = lexicon.all_of("shades")
    for key, entry in lexicon.all_of("colours").items():
        rgb = list(entry.get("rgb"))
        table.append((key, _lab(rgb)))
        for shade_key, shade_entry in shades.items():
            table.append((f"{shade_key} {key}", _lab(shade(list(rgb), shade_entry.get("ops")))))
    return tuple(table)


def nearest_phrases(color: types.Color, lexicon: Lexicon, limit: int = MAX_PRESENTATIONS) -> list[str]:
    target = _lab([srgb_to_linear(c) for c in (color.red, color.green, color.blue)])
    ranked = sorted(phrase_table(lexicon), key=lambda row: sum((a - b) ** 2 for a, b in zip(row[1], target)))
    phrases: list[str] = []
    for phrase, _lab_value in ranked:
        if phrase not in phrases:
            phrases.append(phrase)
        if len(phrases) == limit:
            break
    return phrases


def presentations(
    color: types.Color, where: types.Range, lexicon: Lexicon, replaces_colour: bool = True
) -> list[types.ColorPresentation]:
    """Colour picker answers: the nearest phrases, replacing the colour words (or, on a noun's
    swatch, inserted before the noun)."""
    out = []
    for phrase in nearest_phrases(color, lexicon):
        if replaces_colour:
            edit = types.TextEdit(where, phrase)
        else:
            edit = types.TextEdit(types.Range(where.start, where.start), phrase + " ")
        out.append(types.ColorPresentation(label=phrase, text_edit=edit))
    return out


def is_colour_range(snapshot: Snapshot, where: types.Range) -> bool:
    """Whether a swatch range covers colour words (not a material's noun)."""
    line = where.start.line
    if line >= len(snapshot.index.lines):
        return True
    found = snapshot.index.line_col(where.start)
    if found is None:
        return True
    return any(start == found[1] for _phrase, start, _end in snapshot.colours_on(line)) or not any(
        col == found[1] and w.category == "nouns" for w, col in snapshot.words_on(line)
    )
