"""Keep numpy's OpenBLAS on one thread while a graph is evaluated.

The maps engine's matrix products are small (rank ~10-300), and on a busy 2-core machine
OpenBLAS worker threads spin-wait after each product, stealing the core the elementwise
numpy work needs (a wood bake ran ~2x slower with the default thread count).  Found with
ctypes in numpy's bundled library; when it cannot be found this is a no-op.
"""

from __future__ import annotations

import ctypes
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path

import numpy as np

SETTERS = ("scipy_openblas_set_num_threads64_", "openblas_set_num_threads64_", "openblas_set_num_threads")
GETTERS = ("scipy_openblas_get_num_threads64_", "openblas_get_num_threads64_", "openblas_get_num_threads")


def first_symbol(library, names):
    for name in names:
        function = getattr(library, name, None)
        if function is not None:
            return function
    return None


@lru_cache(maxsize=1)
def openblas_controls():
    """(get, set) thread-count functions of numpy's OpenBLAS, or None."""
    folder = Path(np.__file__).parent.parent / "numpy.libs"
    for path in sorted(folder.glob("*openblas*.so*")):
        try:
            library = ctypes.CDLL(str(path))
        except OSError:
            continue
        get, set_ = first_symbol(library, GETTERS), first_symbol(library, SETTERS)
        if get is not None and set_ is not None:
            get.restype, set_.argtypes = ctypes.c_int, [ctypes.c_int]
            return get, set_
    return None


@contextmanager
def single_threaded_blas():
    controls = openblas_controls()
    if controls is None:
        yield
        return
    get, set_ = controls
    previous = get()
    set_(1)
    try:
        yield
    finally:
        set_(previous)
