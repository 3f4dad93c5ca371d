"""The view's payloads: STUDIO-VIEW's `material_payload` for each material shown (the contract in
docs/studio.md), asked for only when the view's module is installed. The server owns one
`ViewData` (one scene, one worker thread); each session owns a `PayloadCache` (payloads by the
material's content key, so an edit that keeps a look does not build it again)."""

from __future__ import annotations

import asyncio
import importlib
from collections import OrderedDict
from pathlib import Path
from types import ModuleType
from typing import Any

from ..material import Material

VIEW_MODULE = "cnlmc.studio.view_payload"
JSONDict = dict[str, Any]


class ViewData:
    """The view's Python side, imported once by its owner (the server); None when absent."""

    def __init__(self) -> None:
        try:
            self.module: ModuleType | None = importlib.import_module(VIEW_MODULE)
        except ImportError:
            self.module = None
        self.scene: Any = self.module.ViewScene() if self.module is not None else None

    def payload(self, material: JSONDict, files: Path) -> JSONDict | None:
        if self.scene is None:
            return None
        found: JSONDict = self.scene.payload(material, files)
        return found

    async def static_asset(self, name: str) -> tuple[bytes, str] | None:
        """Built on the scene's own thread: the event loop waits for it without blocking."""
        if self.scene is None:
            return None
        found: tuple[bytes, str] | None = await asyncio.wrap_future(self.scene.asset(name))
        return found

    def close(self) -> None:
        if self.scene is not None:
            self.scene.close()
            self.scene = None


def content_key(material: JSONDict) -> str:
    """The material's look (model, params, maps; not its name): Material.key."""
    return Material.from_ir(material).key


class PayloadCache:
    """One session's payloads by content key, the most recently used `size` kept; the alphas
    their environments are prefiltered at are the only ones the server builds for the page."""

    def __init__(self, view: ViewData, size: int) -> None:
        self.view = view
        self.size = size
        self.kept: OrderedDict[str, JSONDict] = OrderedDict()

    def payloads(self, materials: list[JSONDict], files: Path) -> list[JSONDict]:
        out = []
        for material in materials:
            key = content_key(material)
            found = self.kept.pop(key, None)
            if found is None:
                found = self.view.payload(material, files)
                if found is None:
                    return []
            self.kept[key] = found
            out.append({**found, "name": material["name"], "phrase": material["phrase"]})
        while len(self.kept) > self.size:
            self.kept.popitem(last=False)
        return out

    def alphas(self) -> set[float]:
        return {float(a) for payload in self.kept.values() for a in payload.get("prefilter", {}).values()}
