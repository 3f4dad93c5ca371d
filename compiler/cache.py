"""A small on-disk cache for derived data (the parsed lexicon), keyed by its source files.

What is stored is plain data (JSON: dicts, lists, strings, numbers, booleans), never code or
pickled objects: loading a cache file cannot run anything, and the caller rebuilds its objects
from the data through explicit constructors. Each file is

    cnlmc-cache 2 sha256=<64 hex digits>\\n<JSON payload>

where the digest covers the format line's version, the entry's name and the payload. A file
that fails any check (not a regular file, too large, a wrong header, a digest mismatch, JSON
that does not parse, data the caller's decoder refuses) is ignored and rebuilt, never trusted.

The key is the names, sizes and modification times of the source files plus the cnlmc version;
any change makes a new entry. The folder is $XDG_CACHE_HOME/cnlmc (or ~/.cache/cnlmc), made
private to the user (mode 0700, files 0600); a folder owned by someone else or writable by group
or others is not used at all. After each write the folder is trimmed to
CNLMC_CACHE_MAX_BYTES (default 32 MiB), least recently used first; leftover temporary files
older than an hour and pickled caches of older versions (*.pickle, *.lark-cache) are deleted. Set
CNLMC_NO_CACHE=1 to bypass the cache.
"""

from __future__ import annotations

import gc
import hashlib
import hmac
import json
import os
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, TypeVar

from . import __version__
from .errors import UsageError
from .inputs import read_bytes  # bounded, refuses FIFOs and devices

T = TypeVar("T")

FORMAT = "cnlmc-cache 2"
SUFFIX = ".cache.json"
TEMP_PREFIX = ".tmp-"
LEGACY_SUFFIXES = (".pickle", ".lark-cache")  # pickles (they ran code on load): removed, never read
DEFAULT_MAX_BYTES = 32 * 1024 * 1024
MAX_BYTES_VARIABLE = "CNLMC_CACHE_MAX_BYTES"
STALE_TEMP_SECONDS = 3600


class Corrupt(Exception):
    """A cache file that fails verification (ignored, then rebuilt)."""


class CacheDamaged(UsageError):
    """A part of a verified cache entry that is decoded only when it is used (a stored lexicon
    entry's fields) fails its check: the run stops and says which folder to delete (exit 2)."""


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "cnlmc"


def max_cache_bytes() -> int:
    text = os.environ.get(MAX_BYTES_VARIABLE, "")
    try:
        return max(0, int(text)) if text else DEFAULT_MAX_BYTES
    except ValueError:
        return DEFAULT_MAX_BYTES


def source_key(kind: str, sources: Iterable[Path]) -> str | None:
    """A key for this set of source files, or None when one cannot be looked at (no caching then:
    building reports the problem)."""
    digest = hashlib.sha256(f"{kind}:{__version__}:{FORMAT}".encode())
    try:
        for path in sources:
            st = os.stat(path)
            digest.update(f"{path}:{st.st_size}:{st.st_mtime_ns}\0".encode())
    except (OSError, ValueError):
        return None
    return digest.hexdigest()[:32]


def _digest(name: str, payload: bytes) -> str:
    return hashlib.sha256(f"{FORMAT}\n{name}\n".encode() + payload).hexdigest()


def encode(name: str, payload: bytes) -> bytes:
    """A cache file's bytes: the format line with the payload's digest, then the payload."""
    return f"{FORMAT} sha256={_digest(name, payload)}\n".encode() + payload


def decode(name: str, blob: bytes) -> bytes:
    """The payload of a cache file's bytes; Corrupt unless the header and the digest check out."""
    header, newline, payload = blob.partition(b"\n")
    prefix = f"{FORMAT} sha256=".encode()
    if not newline or not header.startswith(prefix):
        raise Corrupt("not a cache file of this version")
    expected = header[len(prefix) :].decode("ascii", "replace")
    if not hmac.compare_digest(expected, _digest(name, payload)):
        raise Corrupt("checksum mismatch")
    return payload


def dump_json(data: object) -> bytes:
    """Plain data (dicts, lists, strings, finite numbers, booleans, None) as compact UTF-8 JSON."""
    return json.dumps(data, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")


def load_json(payload: bytes) -> Any:
    """dump_json's data back; ValueError for anything else (NaN and Infinity included)."""
    try:
        return json.loads(payload, parse_constant=_refuse_constant)
    except RecursionError:
        raise ValueError("nested too deeply") from None


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a finite number")


class DiskCache:
    """The cache folder: read verified entries, write atomically, trim to a size."""

    def __init__(self, folder: Path | None = None, max_bytes: int | None = None) -> None:
        self.folder = cache_dir() if folder is None else folder
        self.max_bytes = max_cache_bytes() if max_bytes is None else max_bytes

    def path(self, name: str) -> Path:
        return self.folder / f"{name}{SUFFIX}"

    def private(self) -> bool:
        """Whether the folder is this user's own and no one else may write in it (owner, no group or
        other write bit): only then are its files trusted to be what cnlmc wrote (as ssh does)."""
        try:
            info = os.stat(self.folder)
        except OSError:
            return False
        owner = getattr(os, "getuid", None)
        return (owner is None or info.st_uid == owner()) and not info.st_mode & 0o022

    def load(self, name: str) -> bytes:
        """The stored payload, or Corrupt (also for a missing or unreadable file)."""
        path = self.path(name)
        if not self.private():
            raise Corrupt(f"{self.folder} is not private to this user: not used")
        try:
            blob = read_bytes(str(path), limit=max(self.max_bytes, 1), what="cache file")
        except UsageError as exc:  # missing, unreadable, not a regular file, too large: rebuild
            raise Corrupt(str(exc)) from None
        payload = decode(name, blob)
        try:
            os.utime(path)  # recently used: evicted last
        except OSError:
            pass
        return payload

    def store(self, name: str, payload: bytes) -> None:
        """Write atomically (a private temporary file renamed over the entry), then trim the folder.
        A folder that cannot be written is fine: the next run rebuilds."""
        import tempfile  # only a miss writes

        blob = encode(name, payload)
        if len(blob) > self.max_bytes:
            return
        try:
            self.folder.mkdir(mode=0o700, parents=True, exist_ok=True)
            if not self.private():
                return
            fd, tmp = tempfile.mkstemp(dir=self.folder, prefix=TEMP_PREFIX, suffix=SUFFIX)
            try:
                with os.fdopen(fd, "wb") as handle:
                    handle.write(blob)
                os.replace(tmp, self.path(name))
            except BaseException:
                _remove(Path(tmp))
                raise
        except OSError:
            return
        self.evict()

    def evict(self) -> None:
        """Delete stale temporaries and old formats, then the least recently used entries until
        the folder's cache files total at most max_bytes."""
        entries = []
        now = time.time()
        try:
            listing = list(os.scandir(self.folder))
        except OSError:
            return
        for item in listing:
            try:
                if not item.is_file(follow_symlinks=False):
                    continue
                info = item.stat(follow_symlinks=False)
            except OSError:
                continue
            if item.name.endswith(LEGACY_SUFFIXES):
                _remove(Path(item.path))
            elif item.name.startswith(TEMP_PREFIX):
                if now - info.st_mtime > STALE_TEMP_SECONDS:
                    _remove(Path(item.path))
            elif item.name.endswith(SUFFIX):
                entries.append((info.st_mtime, info.st_size, item.path))
        total = sum(size for _mtime, size, _path in entries)
        for _mtime, size, path in sorted(entries):
            if total <= self.max_bytes:
                break
            _remove(Path(path))
            total -= size


def _remove(path: Path) -> None:
    try:
        path.unlink()
    except OSError:
        pass


def cached(
    kind: str, sources: Iterable[Path], build: Callable[[], T], dump: Callable[[T], bytes], load: Callable[[bytes], T]
) -> T:
    """build() once per distinct set of source files; later calls rebuild the value with
    load(payload) from the verified cache file. dump and load are the caller's codec of plain
    data (dump_json / load_json and explicit constructors; never pickle): load raises ValueError,
    TypeError, KeyError or OSError on a payload it does not accept, and the value is rebuilt."""
    if os.environ.get("CNLMC_NO_CACHE"):
        return build()
    key = source_key(kind, sources)
    if key is None:
        return build()
    cache, name = DiskCache(), f"{kind}-{key}"
    try:
        with collection_paused():
            return load(cache.load(name))
    except (Corrupt, ValueError, TypeError, KeyError, IndexError, AttributeError, OSError):
        pass
    with collection_paused():
        built = build()
    try:
        payload = dump(built)
    except (ValueError, TypeError):
        return built  # not plain data (a NaN, say): not cached
    cache.store(name, payload)
    return built


class collection_paused:  # used as the context manager function it was
    """The cyclic garbage collector off while cached data is decoded or built (then back on, if it
    was): thousands of long-lived containers and no cycles to collect, so each collection the
    allocations would trigger only traverses them again (a tenth of a cold start's lexicon load).
    A class, not a generator function: entered for every phrase compiled (#14 speed)."""

    __slots__ = ("was_enabled",)

    def __enter__(self) -> None:
        self.was_enabled = gc.isenabled()
        gc.disable()

    def __exit__(self, *exc: object) -> None:
        if self.was_enabled:
            gc.enable()


def freeze_long_lived(unfreeze_at_exit: bool = True) -> None:
    """Move what is alive now (modules, a loaded lexicon, parser tables) out of the cyclic GC's way.

    For long-running entry points (the CLI's main, the language server), called once what they
    keep is loaded: a lexicon is thousands of long-lived containers that every full collection
    would traverse again. Reference counting still frees everything; only cyclic garbage that
    exists at this moment is kept. Set CNLMC_NO_GC_FREEZE=1 to leave the collector alone.
    `unfreeze_at_exit`: give them back to the collector at exit, so that the extension modules
    loaded by then see their objects freed (the interpreter's last collection then traverses
    everything: ~5 % of a cold `cnlmc compile`, which has loaded none and passes False).
    """
    if not os.environ.get("CNLMC_NO_GC_FREEZE"):
        gc.freeze()
        if unfreeze_at_exit:
            import atexit

            atexit.register(gc.unfreeze)
