"""The one image-size check (cnlmc.backends.image_size): an image whose header claims more than
MAX_PIXELS is refused before decoding, with the file and its size, through the preview's `--env`
and the AR photo alike (#13: a PNG header claiming 60000 x 60000 was an internal error)."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import pytest

from cnlmc.backends.image_size import MAX_PIXELS, ImageTooLarge, check_image_size, header_size
from tests.helpers import run_cnlmc

MESSAGE = "is 60000 x 60000 pixels (3600 megapixels); cnlmc reads images of at most 134 megapixels"


def png(width: int, height: int) -> bytes:
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"\0" * 7)) + chunk(b"IEND", b"")
    )


def jpeg(width: int, height: int) -> bytes:
    app0 = b"\xff\xe0" + struct.pack(">H", 16) + b"JFIF\0\x01\x01\0\0\x01\0\x01\0\0"
    sof = b"\xff\xc0" + struct.pack(">HBHHB", 11, 8, height, width, 1) + b"\x01\x11\x00"
    return b"\xff\xd8" + app0 + sof + b"\xff\xd9"


@pytest.fixture
def huge(tmp_path: Path) -> Path:
    path = tmp_path / "huge.png"
    path.write_bytes(png(60000, 60000))
    return path


@pytest.fixture
def phrase(tmp_path: Path) -> Path:
    path = tmp_path / "red.cnl"
    path.write_text("red plastic\n")
    return path


def test_the_size_is_read_from_the_header(tmp_path: Path) -> None:
    (tmp_path / "a.png").write_bytes(png(640, 480))
    (tmp_path / "b.jpg").write_bytes(jpeg(800, 600))
    assert header_size(tmp_path / "a.png") == (640, 480)
    assert header_size(tmp_path / "b.jpg") == (800, 600)
    check_image_size(tmp_path / "a.png")


def test_a_jpeg_header_too_large_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "big.jpg"
    path.write_bytes(jpeg(65000, 65000))
    with pytest.raises(ImageTooLarge, match=r"photo .*big\.jpg is 65000 x 65000 pixels"):
        check_image_size(path, "photo")


def test_the_limit_is_inclusive(tmp_path: Path) -> None:
    path = tmp_path / "edge.png"
    path.write_bytes(png(16384, MAX_PIXELS // 16384))
    check_image_size(path)
    path.write_bytes(png(16384, MAX_PIXELS // 16384 + 1))
    with pytest.raises(ImageTooLarge):
        check_image_size(path)


def test_preview_env_with_a_huge_header_is_a_usage_error(huge: Path, phrase: Path, tmp_path: Path) -> None:
    pytest.importorskip("OpenImageIO")
    pytest.importorskip("moderngl")
    done = run_cnlmc("preview", str(phrase), "--env", str(huge), "-o", str(tmp_path / "p.png"), "--size", "64")
    assert done.returncode == 2, done.stderr
    assert f"cnlmc: error: environment map {huge} {MESSAGE}" in done.stderr, done.stderr
    assert "internal error" not in done.stderr and not (tmp_path / "p.png").exists()


def test_ar_photo_with_a_huge_header_is_a_usage_error(huge: Path, phrase: Path, tmp_path: Path) -> None:
    pytest.importorskip("cv2")
    pytest.importorskip("moderngl")
    done = run_cnlmc("ar", str(huge), str(phrase), "-o", str(tmp_path / "a.png"))
    assert done.returncode == 2, done.stderr
    assert f"cnlmc: error: photo {huge} {MESSAGE}" in done.stderr, done.stderr
    assert "internal error" not in done.stderr and not (tmp_path / "a.png").exists()
