"""Batch builds of material catalogues (`cnlmc build`, `cnlmc.build(...)`; docs/build.md).

A catalogue (one .cnl file, or a folder of them) is compiled once to IR here; each material then
becomes one task per target (a `Task`: the material's own one-material IR document, the target and
its parsed options), run in a process pool, in this process, or on a Dask cluster. A task's key is
the SHA-256 of what its output is made from (the document, the target, the options, the cnlmc
version), so a material is rebuilt only when that changes. Every file goes through cnlmc.output.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .builder import BuildReport, build, build_report

__all__ = ["BuildReport", "build", "build_report"]


def __getattr__(name: str) -> Any:
    """The builder loads on first use, so `cnlmc --help` and a compile do not import it."""
    if name in __all__:
        from . import builder

        return getattr(builder, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
