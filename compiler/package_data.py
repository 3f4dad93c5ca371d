"""The folders of cnlmc's data packages on disk (cnlmc.stdlib, cnlmc.grammar).

Found from the package's own `__path__`: the folder importlib.resources.files gives for a package
installed as files (as pip and editable installs do), without the resource readers that its
first use imports (zipfile and half a dozen modules: about 8 ms of every cold start).
"""

from __future__ import annotations

import importlib
from pathlib import Path

__all__ = ["package_folder"]


def package_folder(package: str) -> Path:
    """The folder of `package` (a regular package of cnlmc's, e.g. 'cnlmc.stdlib')."""
    return Path(next(iter(importlib.import_module(package).__path__)))
