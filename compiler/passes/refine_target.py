"""What a refinement acts on, and how strongly: the visible surface, the adverbs' weight, the words."""

from __future__ import annotations

from typing import Any

from .. import ast
from ..degrees import compose_weights
from ..diagnostics import Diagnostic, Severity
from ..params import COAT_PARAMS, PARAMS, ranges
from ..spans import Span
from ..state import Context, MaterialState
from ..tagged import written_words
from .bracket import Move, bracket_move

PARAM_RANGES = ranges(PARAMS)  # param -> (low, high), from the parameter table (immutable data)
COAT_RANGES = ranges(COAT_PARAMS)
SURFACE_PARAMS = ("roughness",)  # what one sees on the outermost layer: the coat's, when there is one


def surface(state: MaterialState, param: str) -> tuple[dict[str, Any], str, tuple[float, float] | None]:
    """(where the value lives, its provenance key, its range) for a parameter a refinement moves:
    gloss and roughness act on the coat when there is one (the surface one sees)."""
    if (
        param in SURFACE_PARAMS
        and state.coat is not None
        and param in state.coat
        and not state.coat.get("follows_base")
    ):
        return state.coat, f"coat.{param}", COAT_RANGES.get(param)
    return state.params, param, PARAM_RANGES.get(param)


def refine_weight(item: ast.RefineItem, ctx: Context) -> float:
    """The adverbs' weight on a refinement: 'much rougher' (2) two steps, 'slightly darker' (0.5) half;
    a chain composes as on adjectives (compiler/degrees.py): 'very slightly' is slighter than 'slightly'."""
    weights = [ctx.lexicon.require("adverbs", a.key).get("weight") for a in item.adverbs if not a.unknown]
    return compose_weights(weights)  # as on adjectives: 'very slightly' is slighter than 'slightly


def item_words(item: ast.RefineItem) -> tuple[ast.Word, ...]:
    target = item.target
    extra = target.words if isinstance(target, ast.Colour) else ((target,) if target else ())
    return (*item.adverbs, item.word, *extra)


def item_text(item: ast.RefineItem) -> str:
    """The refinement as written: 'slightly less glossy' ('silkier', read as 'more silky', as one word)."""
    return " ".join(written_words(list(item_words(item))))


def note(span: Span | None, code: str, message: str, hints: tuple[str, ...] = ()) -> Diagnostic:
    """A NOTE diagnostic: how a refinement was read (never a warning)."""
    return Diagnostic(span, Severity.NOTE, code, message, hints)


DIFFUSE_SIGMA = "diffuse_roughness"  # the Oren-Nayar sigma: roughness words move it too (passes/words.py)


def move_sigma_too(state: MaterialState, key: str, move: Move, words: tuple[ast.Word, ...], rule: str) -> None:
    """A roughness refinement of the base also moves the Oren-Nayar sigma of a surface that has one
    ('rougher' on concrete or velvet), by the same step read in radians, on its own bracket."""
    sigma = state.params.get(DIFFUSE_SIGMA, 0.0)
    if key != "roughness" or not (isinstance(sigma, (int, float)) and sigma > 0):
        return
    sigma_move = Move(move.direction, move.step, move.weight, PARAM_RANGES.get(DIFFUSE_SIGMA))
    new = bracket_move(state.brackets, DIFFUSE_SIGMA, sigma, sigma_move)
    state.record(DIFFUSE_SIGMA, new, f"{rule}, on the Oren-Nayar sigma too", words)


HIGHLIGHT_MARGIN = 0.05  # how far below the diffuse threshold a first highlight starts (our choice)


def highlight_shown(
    state: MaterialState, ctx: Context, key: str, before: Any, after: Any, words: tuple[ast.Word, ...], rule: str
) -> None:
    """'a little shinier' on linen or matte concrete: a roughness step down that would leave the
    material diffuse (roughness at or above settings.toml diffuse_threshold: no highlight is drawn)
    goes on to just below the threshold, so the change shows as a first, broad highlight."""
    threshold = float(ctx.settings.get("diffuse_threshold", 0.85))
    if key != "roughness" or not isinstance(before, (int, float)) or not isinstance(after, (int, float)):
        return
    if state.kind in ("conductor", "glass") or state.coat is not None:
        return  # drawn with a highlight at any roughness (passes/model.py): no threshold to pass
    if after >= before or after < threshold:
        return
    shown = threshold - HIGHLIGHT_MARGIN
    state.params["roughness"] = shown
    state.note(key, shown, f"{rule}, past the diffuse threshold {threshold:g} so a highlight shows", words)


def note_unmoved_number(state: MaterialState, item: ast.RefineItem, key: str, before: Any, after: Any) -> None:
    """A parameter a refinement could not move (it is at its range's end) says so in a note."""
    if not isinstance(before, (int, float)) or not isinstance(after, (int, float)) or abs(after - before) > 1e-6:
        return
    state.diagnostics.append(
        note(item.span, "N106", f"'{item_text(item)}' leaves {key} at {after:g}: the end of its range")
    )
