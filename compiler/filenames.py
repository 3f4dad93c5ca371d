"""File names that fit: any text -> a name under NAME_MAX bytes, readable where it can be.

    fit_name("a" * 300, suffix="_base_color.png")  -> "aaa...aaa~5f3a9c1e_base_color.png" (255 bytes)

A name that fits is returned unchanged. A longer one keeps a readable prefix, then `~` and 8
hex digits of the SHA-256 of the whole name (so two long names that share their prefix never
collide), then the suffix; it is cut on a character boundary, never inside a UTF-8 sequence.
"""

from __future__ import annotations

import hashlib

#: the longest file name most file systems take (ext4, XFS, APFS, NTFS in UTF-16 units): bytes in UTF-8
NAME_MAX = 255
HASH_DIGITS = 8


def short_hash(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()[:HASH_DIGITS]


def _cut(text: str, max_bytes: int) -> str:
    """The longest prefix of `text` that takes at most `max_bytes` bytes in UTF-8."""
    data = text.encode("utf-8", "surrogatepass")[:max_bytes]
    return data.decode("utf-8", "ignore")


def fit_name(name: str, limit: int = NAME_MAX, suffix: str = "") -> str:
    """`name + suffix` if it fits in `limit` bytes, else a readable prefix of `name`, `~`, a
    short hash of the whole, and `suffix`."""
    whole = name + suffix
    if len(whole.encode("utf-8", "surrogatepass")) <= limit:
        return whole
    tail = f"~{short_hash(whole)}{suffix}"
    room = limit - len(tail.encode("utf-8", "surrogatepass"))
    if room <= 0:
        raise ValueError(f"a suffix of {len(suffix)} characters leaves no room in a {limit}-byte name")
    return _cut(name, room) + tail
