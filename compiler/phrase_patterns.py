"""Regular expressions over the phrase lists of the teaching tables (stdlib/data/teaching.toml)."""

from __future__ import annotations

import re
from collections.abc import Iterable

__all__ = ["alternatives"]


def alternatives(phrases: Iterable[str]) -> str:
    """A regex alternation of the phrases, longest first (so 'on top of' wins over 'on'), each a
    whole word sequence whose spaces match any run of white space."""
    ordered = sorted(set(phrases), key=len, reverse=True)
    return "|".join(re.escape(p).replace(r"\ ", r"\s+") for p in ordered)
