"""Helpers shared by the test folders: the CLI as a user runs it, one phrase per model kind.

Fixtures (OpenGL contexts, golden files) live in tests/conftest.py; plain functions and
tables live here, imported as ``from tests.helpers import run_cnlmc``.
"""

from __future__ import annotations

import importlib
import importlib.util
import subprocess
import sys
from collections.abc import Callable, Mapping
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

#: The repository's root (examples/, tests/, pyproject.toml).
ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

#: One phrase per IR model kind and feature, so a target or pass meets every row of the
#: capability tables: base models, diffuse lobes, distributions, coats, maps, variants.
PHRASE_BY_MODEL: Mapping[str, str] = {
    "diffuse": "weathered concrete",
    "diffuse_oren_nayar": "navy blue velvet",
    "dielectric": "glossy red plastic",
    "dielectric_oren_nayar": "terracotta",
    "anisotropic_dielectric": "brushed plastic",
    "conductor": "polished gold",
    "mirror": "mirror chrome",
    "anisotropic_ward": "lightly brushed, blue anodized aluminum",
    "glass": "frosted glass",
    "coat": "oak with a glossy white varnish",
    "tinted_coat": "steel with a red lacquer",
    "maps": "heavily rusted iron",
    "normal_map": "hammered copper",
    "variants": "red or blue plastic",
}


def run_cnlmc(
    *args: str,
    stdin: str | bytes | None = None,
    timeout: float = 300,
    cwd: str | Path | None = None,
    env: Mapping[str, str] | None = None,
) -> subprocess.CompletedProcess[Any]:
    """Run ``python -m cnlmc ARGS`` in a fresh process, as a user would, and capture its output.

    Text in, text out; give ``stdin`` as bytes to get bytes back (for input that is not text).
    """
    return subprocess.run(
        [sys.executable, "-m", "cnlmc", *args],
        input=stdin,
        capture_output=True,
        text=not isinstance(stdin, bytes),
        timeout=timeout,
        cwd=cwd,
        env=env,
        check=False,
    )


def require(module: str, extra: str) -> ModuleType:
    """Import an optional dependency, or skip the calling module with how to install it."""
    imported: ModuleType = pytest.importorskip(
        module, reason=f"{module} is not installed (pip install -e '.[{extra}]')"
    )
    return imported


class Goldens:
    """Golden files: compared by default; with ``pytest --update-goldens`` each one the test
    would reject is rewritten instead (write-if-different), and the rewritten paths are kept
    for the end-of-run report. ``refreeze`` asks the exchange goldens to recompile their frozen IR."""

    def __init__(self, updating: bool = False, refreeze: bool = False) -> None:
        self.updating = updating or refreeze
        self.refreeze = refreeze
        self.rewritten: list[Path] = []

    def check(self, path: Path, produced: bytes, agrees: Callable[[bytes], None]) -> None:
        """``agrees(existing_bytes)`` asserts that the golden file accepts what was produced."""
        if not self.updating:
            assert path.exists(), f"golden file {path} is missing; write it with: pytest --update-goldens"
            agrees(path.read_bytes())
            return
        if path.exists():
            try:
                agrees(path.read_bytes())
                return
            except AssertionError:
                pass
        self.write(path, produced)

    def check_text(self, path: Path, text: str, message: str) -> None:
        """The golden file holds exactly ``text`` (UTF-8)."""

        def agrees(existing: bytes) -> None:
            assert text == existing.decode("utf-8"), message

        self.check(path, text.encode("utf-8"), agrees)

    def write(self, path: Path, data: bytes) -> bool:
        """Write ``data`` unless the file already holds exactly it; True when it was rewritten."""
        if path.exists() and path.read_bytes() == data:
            return False
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
        self.rewritten.append(path)
        return True


def load_module(name: str, path: Path) -> ModuleType:
    """A script or bench file (not a package module) imported by path, registered under `name`
    in sys.modules (dataclasses look their module up there)."""
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None, path
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def bench_modules(*names: str) -> tuple[ModuleType, ...]:
    """Modules of bench/ imported by name (bench/ on the path while they load, so they find each
    other as they do when run as scripts)."""
    folder = str(Path(__file__).resolve().parents[1] / "bench")
    sys.path.insert(0, folder)
    try:
        return tuple(importlib.import_module(name) for name in names)
    finally:
        sys.path.remove(folder)
