"""Fixtures of the build tests: a small catalogue, and one Dask LocalCluster for the module."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

#: a small catalogue: two materials use steel (the lexicon test changes steel), maps on most,
#: a refinement line and a variant group
CATALOG = """\
hull: brushed steel
floor: polished oak
  darker
rail: glossy steel
trim: polished gold
tile: red or blue plastic
"""
USES_STEEL = {"hull", "rail"}


@pytest.fixture
def catalog(tmp_path: Path) -> Path:
    path = tmp_path / "catalog.cnl"
    path.write_text(CATALOG, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def cluster() -> Iterator[Any]:
    """A Dask cluster on this machine: 2 worker processes, one thread each."""
    distributed = pytest.importorskip("distributed", reason="Dask is not installed (pip install -e '.[build]')")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
    ) as local:
        yield local
