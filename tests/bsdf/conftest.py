"""Fixtures for the reference-BSDF tests: the shared reference data (../shared/data)."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

DATA_DIR = Path(__file__).parents[2].parent / "shared" / "data"


def _require_data() -> Path:
    if not DATA_DIR.is_dir():
        pytest.skip(f"reference data folder {DATA_DIR} is absent (expected ../shared/data)")
    return DATA_DIR


@pytest.fixture(scope="session")
def data_dir() -> Path:
    return _require_data()


@pytest.fixture(scope="session")
def accuracy_checks(data_dir) -> dict:
    return json.loads((data_dir / "brdf_accuracy_checks.json").read_text())


@pytest.fixture(scope="session")
def metals(data_dir) -> list[dict]:
    return json.loads((data_dir / "metals_rgb.json").read_text())["metals"]


def read_angular_csv(path: Path):
    """(theta_deg (n,), rgb (n, 3)) from a *_angular_reflectance_srgb.csv file."""
    with path.open() as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].startswith("#")]
    values = np.array([[float(x) for x in r] for r in rows[1:]])
    return values[:, 0], values[:, 1:4]


@pytest.fixture(scope="session")
def angular_reference(data_dir):
    """key → (theta_deg, rgb) for every metal's spectral reference curve."""
    out = {}
    for path in sorted((data_dir / "spectral").glob("*_angular_reflectance_srgb.csv")):
        out[path.name.removesuffix("_angular_reflectance_srgb.csv")] = read_angular_csv(path)
    return out
