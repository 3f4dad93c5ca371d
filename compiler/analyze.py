"""Semantic analysis: AST -> material states -> IR, by small passes in one ordered tuple."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import Any

from . import ast
from .back import WHOLE, reversed_change, taken_back
from .default_name import name_words
from .diagnostics import Diagnostic, error, warning
from .document import iter_items, parse_change_line, read_change_alone, read_without_removal
from .ir import JSONDict, document_ir, material_ir
from .lexicon import Lexicon
from .params import Params
from .passes.base import apply_noun
from .passes.coats import apply_coat_clause
from .passes.conformal_coat import lay_conformal_coats
from .passes.metal_tone import tone_toward_named_metal
from .passes.model import select_model
from .passes.ranges import check_values
from .passes.refine import apply_inline_refinements, apply_refinement_line
from .passes.subsurface import apply_subsurface, select_subsurface
from .passes.variants import expand, identifier
from .passes.words import apply_groups
from .removed import without_words
from .spans import Span
from .state import Context, MaterialState

BUILD_PASSES = (apply_noun, apply_groups, apply_subsurface, apply_coat_clause, apply_inline_refinements)
FINAL_PASSES = (tone_toward_named_metal, lay_conformal_coats, select_model, select_subsurface, check_values)


def attach_refinements(doc: ast.Document, lexicon: Lexicon) -> list[tuple[ast.Material, list[ast.Refinement]]]:
    """Pair each material line with the refinement lines below it."""
    pairs: list[tuple[ast.Material, list[ast.Refinement]]] = []
    kept = 0  # the change lines an 'undo' cannot take back: those before the material last changed
    for item in doc.items:
        if isinstance(item, ast.Material):
            pairs.append((item, []))
            kept = 0
        elif pairs and item.changes_material and (changed := changed_material(pairs[-1][0], item, lexicon)):
            pairs[-1] = (changed, pairs[-1][1] + after_change(item))  # 'make it walnut': the material above, now walnut
            kept = len(pairs[-1][1])
        elif pairs:
            add_refinement(pairs[-1][1], item, lexicon, doc.diagnostics, kept)
        else:
            material = orphan_line(item, lexicon, doc.diagnostics)
            if material is not None:
                pairs.append((material, []))
                kept = 0
    return pairs


def add_refinement(
    lines: list[ast.Refinement], item: ast.Refinement, lexicon: Lexicon, diags: list[Diagnostic], kept: int = 0
) -> None:
    """Append a change line to the material's; 'go back a bit' goes in as the change above,
    reversed (cnlmc.back), with the note that says so; 'undo' takes the last line back, down to the
    first `kept` (those before a change of material)."""
    if item.back == WHOLE:  # 'undo', 'scrap that': the line above goes, exactly
        diags.append(taken_back(item, lines.pop() if len(lines) > kept else None))
        return
    if item.back is not None:
        reversed_line, note = reversed_change(item, _change_above(lines), lexicon, parse_change_line)
        diags.append(note)
        item = reversed_line or item
    lines.append(item)


def _change_above(lines: list[ast.Refinement]) -> ast.Refinement | None:
    """The last change line that is no going back itself ('go back a bit' twice goes back twice
    from the same change); None when there is none."""
    return next((line for line in reversed(lines) if line.back is None), None)


def after_change(change: ast.Refinement) -> list[ast.Refinement]:
    """The comparatives said with a change ('go darker, more like walnut'): a refinement line of
    their own after it; [] for a change alone, and for a removal (its comparatives are its reading
    where there was nothing to take off: 'lose the shine' = less shine)."""
    if not change.items or change.removed:
        return []
    return [ast.Refinement(None, change.items, change.span, change.text)]


def changed_material(material: ast.Material, change: ast.Refinement, lexicon: Lexicon) -> ast.Material | None:
    """The material above changed to the one a change line names: of the same kind ('make it
    walnut' under 'white varnished oak') the new noun with the describing words and clauses of
    both (the line's after), its coat if it names one, the name and span kept; of another kind
    ('switch to brass' under red plastic) the new material itself. None where the named material is
    of another kind and is also a colour ('make it cream' under red plastic): the line then applies
    as the colour (its groups)."""
    if change.removed:
        return without_words(material, change.removed, lexicon)
    assert change.material is not None, "only a change to a material"
    new = change.material
    same_kind = _kind(new, lexicon) == _kind(material, lexicon)
    if not same_kind and change.groups:
        return None
    kept = material if same_kind else ast.Material(None, (), (), None, material.span, material.text)
    return ast.Material(
        material.name,
        (*_without_colour(kept.groups, new.groups), *new.groups),
        new.nouns,
        new.coat or kept.coat,
        material.span,
        material.text,
        (*kept.refinements, *new.refinements),
        (*kept.features, *new.features),
    )


def _without_colour(kept: tuple[ast.Group, ...], said: tuple[ast.Group, ...]) -> tuple[ast.Group, ...]:
    """The kept describing groups without their colours when the change names one ('more like a
    dark cherry' under pale oak: dark, not pale and dark); the adjectives stay."""
    if not any(g.colours for g in said):
        return kept
    out = []
    for group in kept:
        if not group.colours:
            out.append(group)
        elif group.adjectives:
            out.append(ast.Group("adjective", group.adverbs, (), group.adjectives, group.span))
    return tuple(out)


def _kind(material: ast.Material, lexicon: Lexicon) -> str:
    noun = material.nouns[0]
    entry = lexicon.entry("nouns", noun.key)
    return str(entry.get("class", noun.key)) if entry is not None else noun.key


def orphan_line(item: ast.Item, lexicon: Lexicon, diags: list[Diagnostic]) -> ast.Material | None:
    """A refinement line with no material above: a comparison of a colour describes its own
    material ('paler blue': cnlmc.implied, with a note), so does a clause ('with a subtle sheen' =
    paint with a subtle sheen: cnlmc.hedges), so do comparatives of a finish ('a glossier finish');
    any other gets W104."""
    if isinstance(item, ast.Refinement) and item.material is not None:
        return item.material  # 'switch to brass' first: brass
    if isinstance(item, ast.Refinement) and (item.items or item.features or item.coat is not None):
        from .hedges import first_line_clause, first_line_described, first_line_finish  # first-line: rare
        from .implied import first_line_comparison

        found = (
            first_line_comparison(item, lexicon)
            or first_line_clause(item, lexicon)
            or first_line_finish(item, lexicon)
            or first_line_described(item, lexicon)
        )
        if found is not None:
            diags.append(found[1])
            return found[0]
    if isinstance(item, ast.Refinement) and item.removed:  # 'no sheen' first: nothing to take it off
        plain = read_without_removal(item, lexicon)
        if plain is not None:
            diags[:] = [
                d for d in diags if not (d.code == "N101" and d.span is not None and _within(d.span, item.span))
            ]
            diags.extend(plain[1])
            return plain[0]
    if isinstance(item, ast.Refinement) and (alone := read_change_alone(item, lexicon)) is not None:
        diags[:] = [d for d in diags if not (d.code == "N101" and d.span is not None and _within(d.span, item.span))]
        diags.extend(alone[1])  # 'make it navy blue' first: navy blue, its material implied
        return alone[0]
    keeps_only = isinstance(item, ast.Refinement) and item.keeps_only  # 'thanks' alone
    if keeps_only:  # its note said 'nothing changes': the error says why nothing can
        diags[:] = [d for d in diags if not (d.span == item.span and d.code == "N101")]
    diags.append(nothing_to_keep(item) if keeps_only else orphan_refinement(item))
    return None


def _within(inner: Span, outer: Span) -> bool:
    """Whether `inner` lies on `outer`'s line, before its end (a note on a line's words)."""
    return inner.line == outer.line and outer.start - (outer.col - 1) <= inner.start and inner.end <= outer.end


def nothing_to_keep(item: ast.Item) -> Diagnostic:
    """'thanks', 'keep the grain' with no material above: nothing to keep, and no material named."""
    return error(
        item.span,
        "E003",
        "nothing to keep: the line names no material and there is none above it",
        ("write the material first, e.g. 'white varnished oak', then 'keep the grain'",),
    )


def orphan_refinement(item: ast.Item) -> Diagnostic:
    hint = "write the material first, e.g. 'blue anodized aluminum' then 'darker'"
    if isinstance(item, ast.Refinement) and item.groups and not item.items:  # 'make it navy blue' first
        line_start = item.span.start - (item.span.col - 1)
        said = " ".join(
            item.text[item.groups[0].span.start - line_start : item.groups[-1].span.end - line_start].split()
        )
        hint = f"write the material first, or its words alone: '{said}' (the material they describe is implied)"
    return warning(item.span, "W104", "a refinement needs a material above it", (hint,))


def material_name(material: ast.Material, used: dict[str, int]) -> str:
    """An identifier from the name or the words; repeats get _2, _3, ... (used: name -> count)."""
    return unique_name(base_name(material), used)


def base_name(material: ast.Material) -> str:
    """The identifier of the name, or of the words, before repeats are numbered."""
    return identifier(material.name.text if material.name else " ".join(name_words(material)))


def unique_name(name: str, used: dict[str, int]) -> str:
    """`name`, or `name_2`, `name_3`, ... where it was used before (used: name -> count, updated)."""
    unique = name
    while unique in used:
        used[name] += 1
        unique = f"{name}_{used[name]}"
    used[unique] = 1
    return unique


def build_states(
    material: ast.Material, refinements: list[ast.Refinement], ctx: Context, name: str, diags: list[Diagnostic]
) -> list[MaterialState]:
    states = []
    for selection, variant in expand(material, name, diags):
        if selection.nouns[0].unknown:
            continue
        state = MaterialState(
            _variant_name(name, variant), _phrase(material), selection, variant, label=_label(material)
        )
        for step in BUILD_PASSES:
            state = step(state, ctx)
        for refinement in refinements:
            apply_refinement_line(state, ctx, refinement)
        for step in FINAL_PASSES:
            state = step(state, ctx)
        states.append(state)
    return states


def _label(material: ast.Material) -> str:
    """The name as written ('名前 ünïcødé 🔥 Ω', 'Hull'), when its identifier could not keep it."""
    written = material.name.text.strip() if material.name else ""
    return written if written and identifier(written) != written else ""


def _variant_name(name: str, variant: dict[str, Any] | None) -> str:
    return f"{name}__{variant['name']}" if variant else name


def _phrase(material: ast.Material) -> str:
    """The line's words after its name: 'hull: oak' and a schedule code said without its colon
    ('PT-02 matt emulsion') alike."""
    text = material.text.strip()
    if not material.name:
        return text
    if ":" in text:
        return text.split(":", 1)[1].strip()
    return text[len(material.name.text) :].strip() if text.startswith(material.name.text) else text


def analyze(doc: ast.Document, ctx: Context) -> tuple[list[MaterialState], list[Diagnostic]]:
    """All material states of a document, and every diagnostic, sorted by position."""
    diags: list[Diagnostic] = []
    states = list(iter_states(doc, ctx, diags))
    return states, sort_diagnostics(diags)


def iter_states(doc: ast.Document, ctx: Context, diags: list[Diagnostic]) -> Iterator[MaterialState]:
    """Each material state in document order, made as it is asked for; `diags` gets the document's
    diagnostics first, then each state's new ones as it is made (variants of one phrase repeat the
    same warnings: each is reported once). Each material's syntax tree is let go once its states
    are made: a caller that keeps no state keeps no tree."""
    pairs = attach_refinements(doc, ctx.lexicon)  # may add W104 to the document's diagnostics
    diags += doc.diagnostics
    return _states(pairs, _error_lines(diags), ctx, diags)


def _error_lines(diags: list[Diagnostic]) -> set[int]:
    """The lines with an error (most documents have no diagnostic at all: no set comprehension run)."""
    if not diags:
        return set()
    return {d.span.line for d in diags if d.is_error and d.span}


def _states(
    pairs: list[tuple[ast.Material, list[ast.Refinement]]], bad_lines: set[int], ctx: Context, diags: list[Diagnostic]
) -> Iterator[MaterialState]:
    seen = set(diags)
    used: dict[str, int] = {}
    pairs.reverse()  # popped from the end: document order, and each pair let go once used
    while pairs:
        material, refinements = pairs.pop()
        if material.span.line in bad_lines:
            continue  # reported already; half-understood materials are not emitted
        if bad_lines and refinements:
            refinements = [r for r in refinements if r.span.line not in bad_lines]
        for state in build_states(material, refinements, ctx, material_name(material, used), diags):
            _report_new(state.diagnostics, seen, diags)
            yield _variant_named(state, used)


def _variant_named(state: MaterialState, used: dict[str, int]) -> MaterialState:
    """A variant's name made unique as a material's is ('red or red plastic': red_plastic__red,
    red_plastic__red_2; a later 'y__red: steel' after 'y: red or blue' is y__red_2): no two
    materials of a document share a name, so no target writes one file twice (#13)."""
    if state.variant is not None:
        state.name = unique_name(state.name, used)
    return state


def iter_material_irs(source: str, ctx: Context, diags: list[Diagnostic]) -> Iterator[JSONDict]:
    """Each material's IR in document order, made as it is asked for: the lines are parsed as they
    are reached, and each material's syntax tree and states are let go once its IR is made (what
    analyze_to_ir gives, and the same diagnostics). `diags` gets every diagnostic as it is found:
    sort_diagnostics(diags) once the iterator is exhausted."""
    convention = ctx.settings.get("alpha_convention", Params.alpha_convention)
    rounded_optics = ctx.lexicon.caches.rounded_optics
    for state in _streamed_states(source, ctx, diags):
        yield material_ir(state, convention, rounded_optics)


def _report_new(found: Iterable[Diagnostic], seen: set[Diagnostic], diags: list[Diagnostic]) -> None:
    """Append what was not reported yet (variants of one phrase repeat the same warnings)."""
    for d in found:
        if d not in seen:
            seen.add(d)
            diags.append(d)


def _streamed_states(source: str, ctx: Context, diags: list[Diagnostic]) -> Iterator[MaterialState]:
    seen: set[Diagnostic] = set()
    used: dict[str, int] = {}
    mark = 0
    for material, refinements in _material_groups(iter_items(source, ctx.lexicon, diags), diags, ctx.lexicon):
        seen.update(diags[mark:])  # the parser's since the last material: a state repeating one is not added
        for state in build_states(material, refinements, ctx, material_name(material, used), diags):
            _report_new(state.diagnostics, seen, diags)
            yield _variant_named(state, used)
        mark = len(diags)


def _material_groups(
    items: Iterator[tuple[ast.Item, bool]], diags: list[Diagnostic], lexicon: Lexicon
) -> Iterator[tuple[ast.Material, list[ast.Refinement]]]:
    """Each material without an error on its line, with the error-free refinement lines below it,
    once the next material (or the end) is reached; a material with an error is left out with its
    refinements (reported already), a refinement before any material gets W104."""
    material: ast.Material | None = None
    refinements: list[ast.Refinement] = []
    material_ok = False
    kept = 0  # the lines an 'undo' cannot take back: those before the material last changed
    for item, has_error in items:
        if isinstance(item, ast.Material):
            if material is not None and material_ok:
                yield material, refinements
            material, refinements, material_ok, kept = item, [], not has_error, 0
        elif material is None and has_error:
            diags.append(orphan_refinement(item))
        elif material is None:
            material = orphan_line(item, lexicon, diags)  # 'paler blue' first: its own material
            material_ok, kept = material is not None, 0
        elif not has_error and item.changes_material and (changed := changed_material(material, item, lexicon)):
            material = changed
            refinements += after_change(item)
            kept = len(refinements)
        elif not has_error:
            add_refinement(refinements, item, lexicon, diags, kept)
    if material is not None and material_ok:
        yield material, refinements


def sort_diagnostics(diags: list[Diagnostic]) -> list[Diagnostic]:
    if len(diags) < 2:  # most documents: nothing to order (a new list all the same, as sorted gives)
        return list(diags)
    return sorted(diags, key=lambda d: (d.span.line, d.span.col) if d.span else (0, 0))


def to_ir(states: list[MaterialState], diags: list[Diagnostic], ctx: Context) -> dict[str, Any]:
    convention = ctx.settings.get("alpha_convention", Params.alpha_convention)
    rounded_optics = ctx.lexicon.caches.rounded_optics
    materials = [material_ir(s, convention, rounded_optics) for s in states]
    return document_ir(materials, diags, ctx.filename, ctx.lexicon.sources)
