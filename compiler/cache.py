"""A small on-disk cache for derived data (the parsed lexicon), keyed by its source files.

The key is the names, sizes and modification times of the source files plus the cnlmc
version; any change rebuilds. Unreadable or stale cache files are ignored, never trusted.
Set CNLMC_NO_CACHE=1 to bypass it. The folder is $XDG_CACHE_HOME/cnlmc (or ~/.cache/cnlmc).
"""

from __future__ import annotations

import hashlib
import os
import pickle
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TypeVar

from . import __version__


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "cnlmc"


T = TypeVar("T")


def _key(kind: str, sources: Iterable[Path]) -> str:
    digest = hashlib.sha256(f"{kind}:{__version__}".encode())
    for path in sources:
        st = path.stat()
        digest.update(f"{path}:{st.st_size}:{st.st_mtime_ns}".encode())
    return digest.hexdigest()[:32]


def cached(kind: str, sources: Iterable[Path], build: Callable[[], T]) -> T:
    """build() once per distinct set of source files; later calls read the pickle."""
    if os.environ.get("CNLMC_NO_CACHE"):
        return build()
    path = cache_dir() / f"{kind}-{_key(kind, sources)}.pickle"
    try:
        with open(path, "rb") as handle:
            value: T = pickle.load(handle)
            return value
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
        pass
    built = build()
    _store(path, built)
    return built


def _store(path: Path, value: object) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "wb") as handle:
            pickle.dump(value, handle, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(tmp, path)
    except OSError:
        pass  # a read-only home is fine: we just rebuild next time


def freeze_long_lived() -> None:
    """Move what is alive now (modules, a loaded lexicon, parser tables) out of the cyclic GC's way.

    For long-running entry points (the CLI's main, the language server), called once what they
    keep is loaded: a lexicon is thousands of long-lived containers that every full collection
    would traverse again. Reference counting still frees everything; only cyclic garbage that
    exists at this moment is kept. Set CNLMC_NO_GC_FREEZE=1 to leave the collector alone.
    """
    import atexit
    import gc

    if not os.environ.get("CNLMC_NO_GC_FREEZE"):
        gc.freeze()
        atexit.register(gc.unfreeze)  # let extension modules see their objects freed at exit
