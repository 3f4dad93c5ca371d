"""Errors raised by the procedural map engine."""

from __future__ import annotations

import difflib


class MapError(ValueError):
    """A map request that cannot be honoured; the message is meant for users."""


class GraphSchemaError(MapError):
    """A graph file that does not follow the schema; the message names file and key."""


def did_you_mean(word: str, choices) -> str:
    """Return ' (did you mean 'x'?)' for the closest choice, or ''."""
    close = difflib.get_close_matches(word, sorted(choices), n=1, cutoff=0.5)
    return f" (did you mean '{close[0]}'?)" if close else ""
