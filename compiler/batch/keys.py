"""Content keys of build tasks and file hashes: what decides whether a task is up to date."""

from __future__ import annotations

import hashlib
import json
from typing import Any

from cnlmc import __version__

#: the format of the records and the manifest; a change rebuilds everything (our choice: start at 1)
BUILD_FORMAT = 1


def canonical_json(value: Any) -> bytes:
    """One byte form per value: sorted keys, no spaces, UTF-8, NaN refused."""
    text = json.dumps(value, sort_keys=True, separators=(",", ":"), ensure_ascii=False, allow_nan=False)
    return text.encode("utf-8")


def task_key(document: Any, target: str, options: dict[str, Any]) -> str:
    """The key of one material on one target: everything its files are made from."""
    made_from = {
        "cnlmc": __version__,
        "format": BUILD_FORMAT,
        "document": document,
        "target": target,
        "options": options,
    }
    return hashlib.sha256(canonical_json(made_from)).hexdigest()


def content_hash(data: bytes) -> str:
    return "sha256:" + hashlib.sha256(data).hexdigest()
