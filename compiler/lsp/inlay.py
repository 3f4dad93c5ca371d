"""Inlay hints: the resolved roughness and colour after each material line."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from lsprotocol import types

from ..colour import linear_to_hex
from .incremental import Snapshot


def material_label(material: dict[str, Any]) -> str:
    params = material["params"]
    parts = []
    if "roughness" in params:
        parts.append(f"roughness {params['roughness']:.3g}")
    if "base_color" in params:
        parts.append(linear_to_hex(params["base_color"]))
    label = " · ".join(parts) or material["model"]["base"]
    variant = material.get("variant")
    return f"{variant['name']}: {label}" if variant else label


def inlay_hints(snapshot: Snapshot, where: types.Range) -> list[types.InlayHint]:
    return [hint for batch in hint_batches(snapshot, where) for hint in batch]


def hint_batches(snapshot: Snapshot, where: types.Range) -> Iterator[list[types.InlayHint]]:
    """The hint of each line in `where`, one list per line (the server runs them in time slices)."""
    last = min(where.end.line, len(snapshot.index.lines) - 1)
    for line in range(max(0, where.start.line), last + 1):
        materials = snapshot.materials_on(line)
        if not materials:
            yield []
            continue
        item, block = snapshot.item_on(line)
        at = snapshot.index.line_end(line)
        if item is not None and block is not None:
            at = snapshot.index.position(block.offset + item.span.end)
        label = "→ " + " | ".join(material_label(m) for m in materials)
        yield [types.InlayHint(position=at, label=label, padding_left=True)]
