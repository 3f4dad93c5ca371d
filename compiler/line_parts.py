"""A refinement line of parts set off by commas, each said its own way ('deeper, more of a
burgundy', 'bit darker, less shine please', 'warmer, keep the finish'): each part is read as a line
of its own where it stands (cnlmc.document), and the parts join into one refinement; a part that is
only courtesy ('same colour', 'please') is read past. Runs only for a line that failed as a whole,
and only when every part is a refinement; one part may change the material when the others are
comparatives ('go darker, more like walnut': walnut, then darker)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from . import ast
from .diagnostics import Diagnostic, Severity
from .lexicon import Lexicon
from .removal import TAKEN_OFF_NOTE
from .removed import much_less, step_away, without_words
from .spans import Span
from .suggest import teaching
from .tagged import NOTE_CODE

__all__ = ["PART_MARKS", "by_parts", "material_then_comparatives", "part_cuts"]

#: the marks that set parts apart
PART_MARKS = frozenset((",", ";"))
#: what a removal part takes off as 'much less' of it where the material has none of the word: a
#: property ('oak, no grain') or a colour ('wood floor, not orange': its hue moved away from orange)
TAKEN_AS_LESS = frozenset(("properties", "colours"))

#: reads the line's text from start to end (columns) as a line of its own, its problems to the list
Reader = Callable[[int, int, list[Diagnostic]], "ast.Item | None"]


def by_parts(text: str, line: int, offset: int, read: Reader) -> tuple[ast.Refinement, list[Diagnostic]] | None:
    """The line as one refinement of its parts and the parts' notes, or None (one part, an empty
    part, or a part that is no refinement or has an error)."""
    cuts = part_cuts(text)
    if len(cuts) < 3:
        return None
    complained = any(_complaint(text[a + 1 : b]) for a, b in zip(cuts, cuts[1:]))
    parts = _parts_read(
        cuts, text, line, offset, read, lambda w: _courtesy(w) or (complained and _echo(w)), _remark_or_likeness
    )
    if parts is None:
        return None
    nodes, notes = parts
    turned = [_part_around(text, n.span.start - offset) for n in nodes if _no_change(n, text, offset)]
    if turned and len(turned) < len(nodes):  # 'lighter, not jet black', 'keep that pink, ...': read past
        nodes = [n for n in nodes if _part_around(text, n.span.start - offset) not in turned]
        notes = [d for d in notes if d.span is None or not any(a <= d.span.start - offset < b for a, b in turned)]
        notes += [_read_past(text[a:b], a, line, offset) for a, b in turned]
    found = [n for n in nodes if isinstance(n, ast.Refinement) and not n.removed]
    if len(found) != len(nodes):
        return None
    changes = [p for p in found if p.material is not None]
    if not found or len(changes) > 1 or (changes and not _comparatives_beside(found, changes[0])):
        return None
    return (_with_change(found, changes[0], text) if changes else _joined(found, text)), notes


def material_then_comparatives(
    text: str, line: int, offset: int, read: Reader, lexicon: Lexicon
) -> tuple[ast.Material, list[Diagnostic]] | None:
    """'walnut, a bit darker', 'reddish brown, maybe a bit darker': a material, then parts that are
    comparatives only, is the material moved by them in turn (its inline comparatives, applied after
    its describing words), and the parts' notes; None for any other line. A part that takes words
    off ('oak, no grain', 'varnished oak, no varnish') takes them off the material, or is its
    comparatives where the material has none of them, as the same change line would be
    (cnlmc.removed)."""
    cuts = part_cuts(text)
    if len(cuts) < 3:
        return None
    first: list[Diagnostic] = []
    material = read(0, cuts[1], first)
    if not isinstance(material, ast.Material) or any(d.is_error for d in first):
        return None
    parts = _parts_read(cuts[1:], text, line, offset, read, _courtesy)
    if parts is None or not parts[0] or not all(_comparatives_only(n) or _removal(n) for n in parts[0]):
        return None
    if any(_comparatives_only(n) and _bare_like(n, text, offset) for n in parts[0]):
        return None
    moved = material
    warned: list[Diagnostic] = []
    stepped: list[tuple[Span, str]] = []  # the parts read as a step away (and their colours), not taken off
    for node in parts[0]:
        assert isinstance(node, ast.Refinement)
        said = _removal_said(node, text, offset)
        if node.removed and _colour_said_again(node.removed, moved, lexicon):  # 'soft black, not jet black'
            items = tuple(step_away(w, said) for w in node.removed)
            moved = replace(moved, span=moved.span.to(node.span), text=text, refinements=(*moved.refinements, *items))
            stepped.append((node.span, ", ".join(f"'{w.text}'" for w in node.removed)))
            continue
        taken_off = without_words(moved, node.removed, lexicon) if node.removed else None
        if taken_off is not None:  # 'varnished oak, no varnish': the word goes
            moved = replace(taken_off, span=moved.span.to(node.span), text=text)
        else:  # 'walnut, a bit darker'; 'oak, no grain' = much less grain, as the change line 'no grain' is
            items = node.items or tuple(much_less(w, said) for w in node.removed if w.category in TAKEN_AS_LESS)
            if not items:  # 'white paint, no texture', 'oak, no knots': as said already, a note
                listed = ", ".join(dict.fromkeys(f"'{w.text}'" for w in node.removed))
                message = f"the material has no {listed}: none to take off, as said"
                warned.append(Diagnostic(node.span, Severity.NOTE, NOTE_CODE, message))
            moved = replace(moved, span=moved.span.to(node.span), text=text, refinements=(*moved.refinements, *items))
    kept = [_as_step_away(d, stepped, text, offset) for d in parts[1]]
    return moved, [*first, *kept, *warned]


def _as_step_away(diag: Diagnostic, stepped: list[tuple[Span, str]], text: str, offset: int) -> Diagnostic:
    """The removal's own note of a part read as a step away instead, said again over the same
    words ("read 'not jet black' as a step away from 'jet black'"); any other diagnostic as it is."""
    at = diag.span
    if at is None or diag.severity is not Severity.NOTE or TAKEN_OFF_NOTE not in diag.message:
        return diag
    listed = next((colours for part, colours in stepped if at.start <= part.end and part.start <= at.end), None)
    if listed is None:
        return diag
    said = " ".join(text[at.start - offset : at.end - offset].split())
    message = f"read '{said}' as a step away from {listed}: the colour said before is that colour already"
    return replace(diag, message=message)


def _colour_said_again(removed: tuple[ast.Word, ...], material: ast.Material, lexicon: Lexicon) -> bool:
    """Whether each word turned down is a colour the material already names, by another name or the
    same ('soft black, not jet black', 'white but not stark white'): not the colour taken off, but
    its extreme turned down, a step away from it."""
    named = [c.base.key for g in material.groups for c in g.colours if c.base is not None]
    if not removed or not named or any(w.category != "colours" for w in removed):
        return False
    rgb = {key: lexicon.require("colours", key).get("rgb") for key in {*named, *(w.key for w in removed)}}
    return all(any(rgb[w.key] == rgb[key] for key in named) for w in removed)


def _removal_said(node: ast.Refinement, text: str, offset: int) -> ast.Word | None:
    """The removal phrase of a part as written ('no', 'without the', 'lose the' of 'can we lose the
    grain'): the word that names the lessening in the material's default name (oak_no_grain, not
    grain_grain_grain)."""
    from .removal import removal_phrase

    if not node.removed:
        return None
    end = node.removed[0].span.start - offset
    start = max(text.rfind(mark, 0, end) for mark in PART_MARKS) + 1
    found = removal_phrase(text[start:end] + " ")
    if found is None:
        return None
    at, written = start + found[0], text[start + found[0] : start + found[1]]
    return ast.Word(
        written, "less", "refinements", Span(offset + at, offset + at + len(written), node.span.line, at + 1)
    )


def _removal(node: ast.Item) -> bool:
    """A part that takes words off ('no grain', 'without the varnish'), with its reading as
    comparatives for a material that has none of them ('much less grain')."""
    return isinstance(node, ast.Refinement) and bool(node.removed) and node.material is None


def part_cuts(text: str) -> list[int]:
    """Where the parts of a line end: -1, each part mark, the line's length."""
    return [-1, *(i for i, ch in enumerate(text) if ch in PART_MARKS), len(text)]


def _parts_read(
    cuts: list[int],
    text: str,
    line: int,
    offset: int,
    read: Reader,
    read_past: Callable[[str], bool],
    past_if_unread: Callable[[str], bool] = lambda _written: False,
) -> tuple[list[ast.Item], list[Diagnostic]] | None:
    """Each part between the cuts read as a line of its own, and the notes (a part `read_past`
    says is courtesy, a remark or an echo gets a note only, as does one `past_if_unread` says may
    be read past when it does not read); None for an empty part, or one that does not read or has
    an error."""
    nodes: list[ast.Item] = []
    notes: list[Diagnostic] = []
    for start, end in zip(cuts, cuts[1:]):
        written = text[start + 1 : end]
        if not written.strip():
            return None
        if read_past(written):
            notes.append(_read_past(written, start + 1, line, offset))
            continue
        said: list[Diagnostic] = []
        node = read(start + 1, end, said)
        if node is None or any(d.is_error for d in said) or isinstance(node, ast.Material):  # a remark is no material
            if not past_if_unread(written):
                return None
            notes.append(_read_past(written, start + 1, line, offset))
            continue
        nodes.append(node)
        notes += said
    return nodes, notes


def _no_change(node: ast.Item, text: str, offset: int) -> bool:
    """A part that keeps the material ('keep that pink': cnlmc.kept) or turns a colour down."""
    return (isinstance(node, ast.Refinement) and node.keeps_only) or _turned_down(node, text, offset)


def _turned_down(node: ast.Item, text: str, offset: int) -> bool:
    """A part that says only which colour it should not be ('not jet black', read as taking the
    colour off): beside a part that says what it should be, it is read past."""
    if not isinstance(node, ast.Refinement) or not node.removed or node.items or node.material is not None:
        return False
    if not all(w.category == "colours" for w in node.removed):
        return False
    start = _part_around(text, node.span.start - offset)[0]
    before = text[start : node.span.start - offset].lower().split()
    if before[:1] and before[0] in teaching()["politeness"]["remark_breaks"]:  # 'lighter, but not white'
        before = before[1:]
    return " ".join(before) in teaching()["removal"]["negations"]


def _part_around(text: str, at: int) -> tuple[int, int]:
    """Where the part (between part marks) that holds column `at` (0-based) starts and ends."""
    start = max(text.rfind(mark, 0, at) for mark in PART_MARKS) + 1
    ends = [i for i in (text.find(mark, at) for mark in PART_MARKS) if i >= 0]
    return start, min(ends, default=len(text))


def _comparatives_only(node: ast.Item) -> bool:
    """A part of comparatives and nothing else ('a bit darker', 'less yellow': a colour step moves
    the material as the change line would, passes/refine.py); not a bare 'like' before a colour
    ('paint, like navy' is no step towards navy: it stays an error)."""
    return (
        isinstance(node, ast.Refinement)
        and bool(node.items)
        and not (node.groups or node.coat or node.features or node.material or node.removed)
    )


def _bare_like(node: ast.Item, text: str, offset: int) -> bool:
    """A part whose colour step is a bare 'like' as written ('paint, like navy': no step towards
    navy; it stays an error)."""
    assert isinstance(node, ast.Refinement)
    written = [text[item.word.span.start - offset : item.word.span.end - offset].lower() for item in node.items]
    return any(isinstance(item.target, ast.Colour) and said == "like" for item, said in zip(node.items, written))


def _courtesy(written: str) -> bool:
    table = teaching()["politeness"]
    said = " ".join(written.lower().split())
    return any(said in table[kind] for kind in ("leading", "trailing", "changes_at_end", "alone"))


def _remark_or_likeness(written: str) -> bool:
    """A part that does not read as a change of its own and only remarks on the material as it is
    ('it looks plasticky', 'keep that pink', 'people will slip': teaching.toml [politeness] remarks)
    or likens the change to something ('like an old crackle glaze': [hedges] likeness), beside the
    part that changes it: read past. A part that reads ('it's too shiny' in a document, 'keep the
    grain but make it darker') is a change and stays one."""
    table = teaching()["politeness"]
    said = f" {' '.join(written.lower().split())} "
    joined = (*table["remark_breaks"], *(change for change in table["changes"] if " " in change))
    if any(f" {word} " in said for word in joined):
        return False  # 'leave the grain but make it darker': a change it could not read keeps its error
    return _opens_with(written, table["remarks"]) or _opens_with(written, teaching()["hedges"]["likeness"])


def _opens_with(written: str, openers: list[str]) -> bool:
    said = " ".join(written.lower().split())
    return any(said.startswith(opener + " ") for opener in openers)


def _complaint(written: str) -> bool:
    """Whether a part asks for less of something, as a complaint reads ('less shiny', 'much less
    red': teaching.toml [politeness] complaints): an idiom beside it only echoes it."""
    table = teaching()["politeness"]
    said = " ".join(written.lower().split())
    readings = {*table["complaints"].values(), *table["opened_complaints"].values()}
    return any(said.startswith(f"{reading} ") for reading in readings)


def _echo(written: str) -> bool:
    """'can we knock it back a bit' beside 'too shiny' (read 'less shiny'): a verb-and-'it' idiom
    (teaching.toml [politeness] idioms) with only courtesy and degree words around it, which echoes
    the complaint beside it."""
    table = teaching()["politeness"]
    words = [w.strip(".,!?;:") for w in written.lower().split()]
    words = _without_edges(words, table["leading"], at_start=True)
    if " ".join(words) in table["idioms"]:  # 'tone the colour down': its particle is the idiom's own
        return True
    words = _without_edges(words, [*table["trailing"], *table["degree_tails"]], at_start=False)
    said = " ".join(w for w in words if w not in table["echo_read_past"])  # 'back': the tagger reads it past
    return said in table["idioms"] or said in table["echoes"]


def _without_edges(words: list[str], phrases: list[str] | tuple[str, ...], at_start: bool) -> list[str]:
    """The words without listed phrases at one edge, taken repeatedly (longest first)."""
    listed = sorted(set(phrases), key=lambda p: -len(p.split()))
    changed = True
    while changed and words:
        changed = False
        for phrase in listed:
            n = len(phrase.split())
            edge = words[:n] if at_start else words[-n:]
            if n < len(words) and " ".join(edge) == phrase:
                words = words[n:] if at_start else words[:-n]
                changed = True
                break
    return words


def _read_past(written: str, start: int, line: int, offset: int) -> Diagnostic:
    """The note of a courtesy part, on its words as written (their unknown-word errors go with it)."""
    first = start + len(written) - len(written.lstrip())
    said = written.strip()
    span = Span(offset + first, offset + first + len(said), line, first + 1)
    return Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read past '{said}'")


def _comparatives_beside(parts: list[ast.Refinement], change: ast.Refinement) -> bool:
    """Whether the other parts of a line with a change are comparatives only ('go darker, more like
    walnut'): they apply after the change (cnlmc.analyze.after_change)."""
    return all(p.items and not (p.groups or p.coat or p.features) for p in parts if p is not change)


def _with_change(parts: list[ast.Refinement], change: ast.Refinement, text: str) -> ast.Refinement:
    span: Span = parts[0].span.to(parts[-1].span)
    items = tuple(i for p in parts if p is not change for i in p.items)
    return ast.Refinement(None, items, span, text, change.coat, change.features, change.groups, change.material)


def _joined(parts: list[ast.Refinement], text: str) -> ast.Refinement:
    coat = next((p.coat for p in parts if p.coat is not None), None)
    span: Span = parts[0].span.to(parts[-1].span)
    return ast.Refinement(
        None,
        tuple(i for p in parts for i in p.items),
        span,
        text,
        coat,
        tuple(f for p in parts for f in p.features),
        tuple(g for p in parts for g in p.groups),
    )
