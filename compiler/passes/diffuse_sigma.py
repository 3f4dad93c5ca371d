"""Roughness words on the Oren-Nayar sigma of a diffuse surface (docs/language.md "Degrees and
order"): a relative formula moves sigma in radians, a level by the ratio it moved the roughness or
to at least its own sigma, and a surface the words make diffuse gets sigma = atan(roughness^2)."""

from __future__ import annotations

from typing import Any

from .. import ast
from ..degrees import knee_step, sigma_of_roughness, weighted_formula, word_level
from ..params import PARAMS, ranges
from ..state import Context, MaterialState

Effect = dict[str, Any]
Words = tuple[ast.Word, ...]

PARAM_BOUNDS = ranges(PARAMS)  # param -> (low, high): where a weighted formula saturates
DIFFUSE_SIGMA = "diffuse_roughness"  # the Oren-Nayar sigma that roughness words also move


def move_sigma(
    state: MaterialState,
    ctx: Context,
    effect: Effect,
    weight: float,
    rule: str,
    words: Words,
    roughness: tuple[float, float],
) -> None:
    """A roughness word also acts on the Oren-Nayar sigma of a surface that has one (rough concrete):
    a relative formula (mul, add) with its numbers read as radians of facet-slope spread; a level
    (set) by the ratio it moved the roughness ('glossy concrete'), or, where the roughness did not
    move (a cloth is already beyond 'matte'), as at least the level's own sigma ('very matte
    cotton'); saturating in sigma's range. A surface the words make diffuse gets its sigma from
    the roughness they reached ('very matte plastic')."""
    sigma = state.params.get(DIFFUSE_SIGMA, 0.0)
    if not sigma > 0:
        _sigma_from_words(state, ctx, roughness[1], rule, words)
        return
    bounds = PARAM_BOUNDS[DIFFUSE_SIGMA]
    if effect["op"] == "set":
        value = _sigma_for_level(sigma, effect, weight, roughness)
        if value is None:
            return
    else:
        value = weighted_formula(effect["op"], sigma, effect.get("value"), weight, effect.get("amount"), bounds)
    state.params[DIFFUSE_SIGMA] = value
    state.note(DIFFUSE_SIGMA, value, f"{rule}, on the Oren-Nayar sigma too", words)


def _sigma_for_level(sigma: float, effect: Effect, weight: float, roughness: tuple[float, float]) -> float | None:
    before, after = roughness
    if before > 0 and after != before:
        return knee_step(sigma, sigma * (after / before - 1.0), PARAM_BOUNDS[DIFFUSE_SIGMA])
    level = effect.get("value")
    if not isinstance(level, (float, int)) or after != before:
        return None
    own = word_level(float(level), weight, PARAM_BOUNDS["roughness"])
    if own is None:
        return None
    target = sigma_of_roughness(own)
    return target if target > sigma else None


def _sigma_from_words(state: MaterialState, ctx: Context, roughness: float, rule: str, words: Words) -> None:
    """The words made a dielectric diffuse (past the settings' diffuse threshold): its sigma follows."""
    if state.kind in ("conductor", "glass") or state.coat is not None:
        return
    if roughness < ctx.settings.get("diffuse_threshold", 0.85):
        return
    value = sigma_of_roughness(roughness)
    state.params[DIFFUSE_SIGMA] = value
    state.note(DIFFUSE_SIGMA, value, f"{rule}, made diffuse: Oren-Nayar sigma = atan(roughness^2)", words)
