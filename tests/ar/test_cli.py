"""`cnlmc ar` and `cnlmc preview` as a user runs them."""

import numpy as np
import pytest

from tests.helpers import require
from tests.helpers import run_cnlmc as cnlmc

from .conftest import MARKER_LENGTH, POSES

cv2 = require("cv2", "ar")
pytestmark = pytest.mark.cv2


@pytest.fixture(scope="module")
def photo(tmp_path_factory):
    from cnlmc.backends.ar.synthetic import synthetic_photo

    rvec, tvec = (np.array(v, float) for v in POSES["oblique"])
    image, _K, _truth = synthetic_photo(rvec, tvec, marker_length=MARKER_LENGTH, seed=1)
    path = tmp_path_factory.mktemp("ar") / "photo.png"
    cv2.imwrite(str(path), image)
    return path


def test_marker_command_writes_a_detectable_marker(tmp_path):
    out = tmp_path / "marker.png"
    r = cnlmc("ar", "--marker", str(out))
    assert r.returncode == 0, r.stderr
    gray = cv2.imread(str(out), cv2.IMREAD_GRAYSCALE)
    detector = cv2.aruco.ArucoDetector(cv2.aruco.getPredefinedDictionary(cv2.aruco.DICT_4X4_50))
    _corners, ids, _ = detector.detectMarkers(gray)
    assert ids is not None and ids.ravel().tolist() == [0]


def test_ar_places_a_phrase_on_the_photo(tmp_path, photo):
    out = tmp_path / "out.png"
    r = cnlmc("ar", str(photo), "blue anodized aluminum", "-o", str(out), "--option", f"marker_length={MARKER_LENGTH}")
    assert r.returncode == 0, r.stderr
    before, after = cv2.imread(str(photo)), cv2.imread(str(out))
    assert before.shape == after.shape
    changed = np.any(before != after, axis=2)
    assert 0.001 < changed.mean() < 0.5  # an object was drawn, the photo is still there


def test_ar_without_a_marker_is_a_clear_error_and_writes_nothing(tmp_path):
    blank = tmp_path / "blank.png"
    cv2.imwrite(str(blank), np.full((120, 160, 3), 200, np.uint8))
    out = tmp_path / "out.png"
    r = cnlmc("ar", str(blank), "polished gold", "-o", str(out))
    assert r.returncode == 1
    assert "no marker found in blank.png" in r.stderr and "cnlmc ar --marker" in r.stderr
    assert not out.exists() and "Traceback" not in r.stderr


def test_ar_with_a_bad_phrase_reports_it(tmp_path, photo):
    r = cnlmc("ar", str(photo), "polished glod", "-o", str(tmp_path / "o.png"))
    assert r.returncode == 1
    assert "unknown word 'glod'" in r.stderr


def test_preview_command_renders_a_png(tmp_path):
    src = tmp_path / "m.cnl"
    src.write_text("red or blue anodized aluminum\n")
    out = tmp_path / "p.png"
    r = cnlmc("preview", str(src), "-o", str(out), "--size", "64", "--mesh", "sphere")
    assert r.returncode == 0, r.stderr
    image = cv2.imread(str(out))
    assert image is not None and image.shape[0] >= 64
    r = cnlmc("preview", str(src), "-o", str(out), "--mesh", "dodecahedron")
    assert r.returncode == 2 and "dodecahedron" in r.stderr
