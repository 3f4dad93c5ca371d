"""The studio's settings (studio.toml beside this module): limits, the CSP, the export table."""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import Any


@dataclass(frozen=True)
class ExportKind:
    """One export button: a registry target with its options, the download's file name."""

    key: str
    label: str
    target: str
    options: dict[str, Any]
    file: str
    zip: bool


@dataclass(frozen=True)
class Limits:
    max_document_bytes: int
    max_upload_bytes: int
    max_message_bytes: int
    max_history: int
    max_sessions: int
    max_completion_items: int
    max_shown_materials: int
    max_cached_payloads: int
    max_sent_parts: int
    max_utterance_seconds: int


@dataclass(frozen=True)
class Settings:
    limits: Limits
    content_security_policy: str
    exports: tuple[ExportKind, ...]
    chip_needs_property: frozenset[str]
    max_chips: int

    def export(self, key: str) -> ExportKind | None:
        return next((kind for kind in self.exports if kind.key == key), None)


@lru_cache(maxsize=1)
def studio_settings() -> Settings:
    """studio.toml, read once (immutable package data)."""
    data = tomllib.loads(resources.files("cnlmc.studio").joinpath("studio.toml").read_text("utf-8"))
    exports = tuple(
        ExportKind(row["key"], row["label"], row["target"], dict(row["options"]), row["file"], bool(row.get("zip")))
        for row in data["exports"]
    )
    chips = data["refinement_chips"]
    return Settings(
        limits=Limits(**data["limits"]),
        content_security_policy="; ".join(data["security"]["content_security_policy"]),
        exports=exports,
        chip_needs_property=frozenset(chips["needs_property"]),
        max_chips=int(chips["max_chips"]),
    )
