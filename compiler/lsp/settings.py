"""The server's settings (initializationOptions and workspace/didChangeConfiguration), checked.

    {"cnlmc": {"debounceMs": 120, "inlayHints": true, "lexicon": ["de", "./my-words"]}}

A value of the wrong type or out of range is not silently ignored: the setting keeps its old
value (a number out of range is clamped) and the problem is returned, for the server to show
the user (window/showMessage) as well as to log.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from ..lexicon_schema import did_you_mean

DEFAULT_DEBOUNCE_MS = 120
MAX_DEBOUNCE_MS = 5000  # a longer wait would read as "the server never answers"
KNOWN = ("debounceMs", "inlayHints", "lexicon")


@dataclass(frozen=True)
class Settings:
    debounce_ms: float = DEFAULT_DEBOUNCE_MS
    inlay_hints: bool = True
    lexicon: tuple[str, ...] | None = None  # None: unchanged


def read_settings(raw: Any, current: Settings) -> tuple[Settings, list[str]]:
    """The settings `raw` asks for, starting from `current`, and what was wrong with it."""
    if raw is None:
        return replace(current, lexicon=None), []
    if not isinstance(raw, dict):
        return replace(current, lexicon=None), [f"cnlmc settings must be an object, not {type(raw).__name__}"]
    raw = raw.get("cnlmc", raw)
    if not isinstance(raw, dict):
        return replace(current, lexicon=None), ["the 'cnlmc' setting must be an object"]
    problems: list[str] = []
    settings = replace(current, lexicon=None)
    if "debounceMs" in raw:
        settings = replace(settings, debounce_ms=_debounce(raw["debounceMs"], current.debounce_ms, problems))
    if "inlayHints" in raw:
        if isinstance(raw["inlayHints"], bool):
            settings = replace(settings, inlay_hints=raw["inlayHints"])
        else:
            problems.append(f"cnlmc.inlayHints must be true or false, not {raw['inlayHints']!r}")
    if "lexicon" in raw:
        value = raw["lexicon"]
        if isinstance(value, list) and all(isinstance(v, str) for v in value):
            settings = replace(settings, lexicon=tuple(value))
        else:
            problems.append('cnlmc.lexicon must be a list of lexicon names or folders, e.g. ["de", "./words"]')
    for key in raw:
        if key not in KNOWN:
            hint = did_you_mean(key, KNOWN) or f" (known: {', '.join(KNOWN)})"
            problems.append(f"unknown setting cnlmc.{key}{hint}")
    return settings, problems


def _debounce(value: Any, old: float, problems: list[str]) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
        problems.append(f"cnlmc.debounceMs must be a number of milliseconds (0 to {MAX_DEBOUNCE_MS}), not {value!r}")
        return old
    if not 0 <= value <= MAX_DEBOUNCE_MS:
        clamped = min(max(float(value), 0.0), MAX_DEBOUNCE_MS)
        problems.append(f"cnlmc.debounceMs is {value!r}: it must be 0 to {MAX_DEBOUNCE_MS} ms; using {clamped:g}")
        return clamped
    return float(value)
