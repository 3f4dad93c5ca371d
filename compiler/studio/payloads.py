"""The view's payloads: STUDIO-VIEW's `material_payload` for each material (the contract in
docs/studio.md), asked for only when the view's module is installed."""

from __future__ import annotations

import importlib
from pathlib import Path
from types import ModuleType
from typing import Any

VIEW_MODULE = "cnlmc.studio.view_payload"


class ViewData:
    """The view's Python side, imported once by its owner (the server); None when absent."""

    def __init__(self) -> None:
        try:
            self.module: ModuleType | None = importlib.import_module(VIEW_MODULE)
        except ImportError:
            self.module = None

    def payloads(self, materials: list[dict[str, Any]], files: Path) -> list[Any]:
        if self.module is None:
            return []
        return [self.module.material_payload(material, files) for material in materials]

    def static_asset(self, name: str) -> tuple[bytes, str] | None:
        if self.module is None:
            return None
        found: tuple[bytes, str] | None = self.module.static_asset(name)
        return found
