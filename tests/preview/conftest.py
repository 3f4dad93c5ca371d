"""Fixtures for the preview tests: one renderer per session, whose resources (its GL context,
programs cached per material, so every material compiles once) other renderers share."""

from __future__ import annotations

from functools import cache

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.material import Material

SMALL = 64


@cache
def material_of(phrase: str) -> Material:
    """The phrase's material, typed (what the preview reads)."""
    result = compile_source(phrase + "\n")
    assert result.ir["materials"], f"{phrase!r}: {result.ir['diagnostics']}"
    return result.document.materials[0]


def stdlib_nouns() -> list[str]:
    return sorted(lexicon_for().all_of("nouns"))


@pytest.fixture(scope="session")
def renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SMALL, msaa=4) as made:
        yield made


@pytest.fixture(scope="session")
def scene():
    from cnlmc.backends.preview.render import default_scene

    scene = default_scene("sphere", "studio", (SMALL, SMALL))
    scene.background = "transparent"  # alpha = coverage of the object
    return scene
