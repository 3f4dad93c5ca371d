"""Fixtures for the preview tests: one EGL context and renderer per session (programs are
cached per material, so every material compiles once)."""

from __future__ import annotations

from functools import cache

import pytest

from cnlmc.api import compile_source, lexicon_for

SMALL = 64


@cache
def material_of(phrase: str) -> dict:
    result = compile_source(phrase + "\n")
    assert result.ir["materials"], f"{phrase!r}: {result.ir['diagnostics']}"
    return result.ir["materials"][0]


def stdlib_nouns() -> list[str]:
    return sorted(lexicon_for().all_of("nouns"))


@pytest.fixture(scope="session")
def renderer():
    try:
        from cnlmc.backends.preview.gl import context

        context()
    except Exception as exc:  # pragma: no cover - machine without EGL
        pytest.skip(f"no OpenGL on EGL here: {exc}")
    from cnlmc.backends.preview.render import Renderer

    return Renderer(SMALL, msaa=4)


@pytest.fixture(scope="session")
def scene():
    from cnlmc.backends.preview.render import default_scene

    scene = default_scene("sphere", "studio", (SMALL, SMALL))
    scene.background = "transparent"  # alpha = coverage of the object
    return scene
