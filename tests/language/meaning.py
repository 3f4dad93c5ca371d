"""Helpers of the meaning tests (issue #14): a phrase compiled with the standard lexicon, its
material, a change session, colours in OKLCh, whether two materials look the same, and whether a
phrase reads as another with a note."""

from __future__ import annotations

import math

from cnlmc.api import Session, compile_source, lexicon_for
from cnlmc.colour import linear_to_oklab

LEX = lexicon_for()


def compiled(text: str):
    return compile_source(text + "\n", "t.cnl", LEX)


def material(text: str) -> dict:
    result = compiled(text)
    assert result.ir["materials"], [d.message for d in result.diagnostics]
    return result.ir["materials"][-1]


def graphs(text: str) -> dict[str, str]:
    """Each map slot of the phrase's material and the graph that draws it."""
    return {slot: spec["graph"] for slot, spec in (material(text).get("maps") or {}).items()}


def lch(rgb: list[float]) -> tuple[float, float, float]:
    """OKLCh lightness, chroma and hue (degrees) of a linear RGB colour."""
    L, a, b = linear_to_oklab(rgb)
    return L, math.hypot(a, b), math.degrees(math.atan2(b, a)) % 360


def refined(phrase: str, *lines: str) -> Session:
    session = Session(phrase, LEX)
    for line in lines:
        session.refine(line)
    return session


def same_look(a: dict, b: dict, keys: tuple[str, ...] = ("base_color", "roughness", "anisotropy")) -> bool:
    return a["model"] == b["model"] and all(a["params"].get(k) == b["params"].get(k) for k in keys)


def reads_as(said: str, plain: str, note: str = "") -> None:
    """`said` compiles, with a diagnostic that says `note`, to the look of `plain`."""
    result = compiled(said)
    assert result.ok, [d.message for d in result.diagnostics]
    assert not note or any(note in d.message for d in result.diagnostics), [d.message for d in result.diagnostics]
    assert same_look(result.ir["materials"][0], material(plain))
