"""File names that fit: any text -> a name under NAME_MAX bytes, readable where it can be.

    fit_name("a" * 300, suffix="_base_color.png")  -> "aaa...aaa~5f3a9c1e_base_color.png" (255 bytes)

A name that fits is returned unchanged. A longer one keeps a readable prefix, then `~` and 8
hex digits of the SHA-256 of the name (so two long names that share their prefix never collide;
the files of one stem, `x.glsl` and `x.frag`, share it), then the suffix; it is cut on a
character boundary, never inside a UTF-8 sequence.
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
    tail = f"~{short_hash(name)}{suffix}"  # the name's hash: siblings with one stem share it
    room = limit - len(tail.encode("utf-8", "surrogatepass"))
    if room <= 0:
        raise ValueError(f"a suffix of {len(suffix)} characters leaves no room in a {limit}-byte name")
    return _cut(name, room) + tail


#: the longest suffix (".glsl.json", "_base_color.png") a shortened name keeps whole
MAX_KEPT_SUFFIX = 32


def fit_file_name(name: str) -> str:
    """A file name that fits: unchanged when it does, else its stem shortened (fit_name) to the
    same length whatever its suffixes (`.glsl`, `.glsl.json`: kept readable), so the files of one
    stem still share it."""
    if len(name.encode("utf-8", "surrogatepass")) <= NAME_MAX:
        return name
    dot = name.find(".", 1)
    suffix = name[dot:] if dot > 0 and len(name[dot:].encode("utf-8", "surrogatepass")) <= MAX_KEPT_SUFFIX else ""
    stem = name[: len(name) - len(suffix)]
    return fit_name(stem, NAME_MAX - MAX_KEPT_SUFFIX) + suffix  # one stem for x.glsl, x.frag, x.glsl.json
