"""Target name -> backend module, imported only when that target runs.

A backend module provides NAME, DESCRIPTION, CAPABILITIES and emit(ir, options) -> [Artifact].
Third-party targets register through the entry point group 'cnlmc.backends'.
"""

from __future__ import annotations

import difflib
import importlib
from dataclasses import dataclass

BUILTIN_BACKENDS = {
    "ir": "cnlmc.backends.ir_json",
    "glsl": "cnlmc.backends.glsl",
    "materialx": "cnlmc.backends.exchange.materialx",
    "usd": "cnlmc.backends.exchange.usd",
    "mitsuba": "cnlmc.backends.exchange.mitsuba",
    "maps": "cnlmc.backends.maps.target",
    "preview": "cnlmc.backends.preview",
}


@dataclass(frozen=True)
class Artifact:
    """One output file: a name relative to the output folder, and its content."""

    name: str
    content: str | bytes
    kind: str = "text"


class UnknownTarget(LookupError):
    def __init__(self, name: str, known: list[str]):
        close = difflib.get_close_matches(name, known, n=1)
        hint = f"; did you mean '{close[0]}'?" if close else ""
        super().__init__(f"unknown target '{name}' (known: {', '.join(known)}){hint}")


def available(include_plugins: bool = True) -> dict[str, str]:
    table = dict(BUILTIN_BACKENDS)
    if include_plugins:
        from importlib.metadata import entry_points  # slow to import: only when asked

        for ep in entry_points(group="cnlmc.backends"):
            table.setdefault(ep.name, ep.value)
    return table


class TargetUnavailable(LookupError):
    """The target exists but cannot load here (a missing optional dependency)."""


def get_backend(name: str):
    table = available(include_plugins=name not in BUILTIN_BACKENDS)
    if name not in table:
        raise UnknownTarget(name, sorted(table))
    try:
        return importlib.import_module(table[name])
    except ImportError as exc:
        raise TargetUnavailable(
            f"target '{name}' cannot load: {exc}; install it with: pip install 'cnlmc[{name}]'"
        ) from None
