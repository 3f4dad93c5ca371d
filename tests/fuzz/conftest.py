"""Fixtures for the fuzz suites (#13): a synthetic AR photo made once per session.

The fuzz helpers themselves (documents, options, the sandboxed CLI runner) are in
tests/fuzz/cli_fuzz.py; each suite keeps its own hypothesis budget (derandomized, bounded).
"""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def marker_photo(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A small PNG photo of a table with the AR marker on it (cv2 needed; skipped without)."""
    cv2 = pytest.importorskip("cv2", reason="OpenCV is not installed (pip install -e '.[ar]')")
    import numpy as np

    from cnlmc.backends.ar.synthetic import synthetic_photo

    photo, _K, _truth = synthetic_photo(
        np.array((3.0, 0.0, 0.0)), np.array((0.0, 0.0, 0.35)), width=160, height=120, seed=1
    )
    path = tmp_path_factory.mktemp("ar") / "photo.png"
    assert cv2.imwrite(str(path), photo)
    return path
