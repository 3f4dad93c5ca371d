"""Fixtures for the GLSL backend tests: the real consumers (glslangValidator, moderngl on EGL).

Tests skip with a clear message only when a tool is truly absent."""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from functools import cache
from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.backends import glsl

GLSLANG = shutil.which("glslangValidator")


@cache
def material_of(phrase: str) -> dict:
    result = compile_source(phrase + "\n")
    assert result.ir["materials"], f"{phrase!r} compiled to no material: {result.ir['diagnostics']}"
    return result.ir["materials"][0]


def emit_material(material: dict, **options) -> dict[str, str]:
    """Emit one material; returns {file suffix: text}, e.g. 'frag', 'vert', 'glsl', 'json' (the
    baked map images, 8x8 here unless `map_size` says otherwise, are left out)."""
    ir = {"ir_version": 1, "materials": [material], "diagnostics": []}
    result = glsl.emit(ir, {"map_size": "8", **{k: str(v) for k, v in options.items()}})
    return {a.name.split(".", 1)[1]: a.content for a in result.artifacts if isinstance(a.content, str)}


def emit_phrase(phrase: str, **options) -> dict[str, str]:
    return emit_material(material_of(phrase), **options)


def run_glslang(sources: list[tuple[str, str]]) -> list[tuple[str, int, str]]:
    """Validate (filename, text) pairs with glslangValidator in parallel: (name, exit code, output)."""
    folder = Path(tempfile.mkdtemp(prefix="cnlm_glslang_"))

    def one(item):
        name, text = item
        path = folder / name
        path.write_text(text)
        done = subprocess.run([GLSLANG, str(path)], capture_output=True, text=True)
        return name, done.returncode, done.stdout + done.stderr

    with ThreadPoolExecutor(max_workers=4) as pool:
        return list(pool.map(one, sources))


@pytest.fixture(scope="session")
def glslang():
    if GLSLANG is None:
        pytest.skip("glslangValidator is not installed (apt-get install glslang-tools)")
    return GLSLANG
