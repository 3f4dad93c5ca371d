"""Fixtures for the AR tests: synthetic photos of a marker at known poses."""

from __future__ import annotations

import numpy as np
import pytest

#: (rvec, tvec) of the marker in camera coordinates: frontal-ish, oblique, rotated, far.
POSES = {
    "oblique": ((2.2, 0.35, -0.2), (0.01, 0.03, 0.45)),
    "frontal": ((3.0, 0.0, 0.0), (0.0, 0.0, 0.35)),
    "turned": ((1.9, -0.6, 0.9), (-0.05, 0.02, 0.5)),
    "far": ((2.4, 0.1, 0.3), (0.08, -0.04, 0.9)),
}
MARKER_LENGTH = 0.1


@pytest.fixture(scope="session")
def gold():
    from cnlmc.api import compile_source

    return compile_source("polished gold\n").ir


@pytest.fixture(params=sorted(POSES))
def posed_photo(request):
    from cnlmc.backends.ar.synthetic import synthetic_photo

    rvec, tvec = (np.array(v, float) for v in POSES[request.param])
    photo, K, truth = synthetic_photo(rvec, tvec, marker_length=MARKER_LENGTH, seed=1)
    return {"name": request.param, "photo": photo, "K": K, "truth": truth, "rvec": rvec, "tvec": tvec}
