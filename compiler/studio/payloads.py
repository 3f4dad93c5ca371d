"""The view's payloads: STUDIO-VIEW's `material_payload` for each material shown (the contract in
docs/studio.md), asked for only when the view's module is installed. The server owns one
`ViewData` (one scene, one worker thread); each session owns a `PayloadCache` (payloads by the
material's content key, so an edit that keeps a look does not build it again) and a `SentParts`
(what its page holds already: a payload's shader and tables go once, then by their key)."""

from __future__ import annotations

import asyncio
import hashlib
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
                found = keyed(found)
            self.kept[key] = found
            out.append({**found, "name": material["name"], "phrase": material["phrase"]})
        while len(self.kept) > self.size:
            self.kept.popitem(last=False)
        return out

    def alphas(self) -> set[float]:
        return {float(a) for payload in self.kept.values() for a in payload.get("prefilter", {}).values()}


def part_key(*texts: str) -> str:
    """A payload part's key: a digest of its content (16 bytes of BLAKE2b, hex)."""
    digest = hashlib.blake2b(digest_size=16)
    for text in texts:
        digest.update(text.encode())
        digest.update(b"\0")
    return digest.hexdigest()


def keyed(payload: JSONDict) -> JSONDict:
    """The payload with its parts' keys: `shader` (vertex and fragment source) and each table's `key`."""
    tables = {name: {**table, "key": part_key(table["data"])} for name, table in payload["tables"].items()}
    return {**payload, "shader": part_key(payload["vertex"], payload["fragment"]), "tables": tables}


class SentParts:
    """The parts (shaders, tables) one page has been sent, by key, the most recent `size` kept: a
    payload whose shader or table the page has goes without it (its key says which), so an edit
    that keeps the shader sends uniforms, not its 10-30 KB of source again. A page that lacks a part
    (it keeps as many; a new page is a new session) asks for the edit again with `fresh`: `forget`."""

    def __init__(self, size: int) -> None:
        self.size = size
        self.sent: OrderedDict[str, None] = OrderedDict()

    def forget(self) -> None:
        self.sent.clear()

    def delta(self, payload: JSONDict) -> JSONDict:
        """The payload as this page needs it (parts it has sent as keys alone); they count as sent now."""
        out = dict(payload)
        if self.had(payload["shader"]):
            del out["vertex"], out["fragment"]
        out["tables"] = {
            name: {k: v for k, v in table.items() if k != "data"} if self.had(table["key"]) else table
            for name, table in payload["tables"].items()
        }
        return out

    def had(self, key: str) -> bool:
        """Whether the page has the part `key`; it has it from now on (the most recently used)."""
        known = self.sent.pop(key, False) is None
        self.sent[key] = None
        while len(self.sent) > self.size:
            self.sent.popitem(last=False)
        return known
