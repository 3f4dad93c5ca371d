"""A build with a target that needs OpenGL: each pool worker makes its own EGL context (workers
start from a fresh process, never from a fork of one holding a context), and the pictures are the
bytes a serial build renders."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from cnlmc.api import build


def test_previews_in_a_pool_are_the_serial_pictures(gl_available, tmp_path):
    oiio = pytest.importorskip("OpenImageIO", reason="OpenImageIO is not installed (pip install -e '.[preview]')")
    catalog = tmp_path / "c.cnl"
    catalog.write_text("velvet: navy blue velvet\nred: glossy red plastic\n", encoding="utf-8")
    serial = build(catalog, tmp_path / "serial", ["preview"], size=32, jobs=1)
    pool = build(catalog, tmp_path / "pool", ["preview"], size=32, jobs=2)
    assert serial == pool
    for name in ("velvet", "red"):
        picture = Path(tmp_path / "pool" / name / "preview" / f"{name}.png")
        assert picture.read_bytes() == (tmp_path / "serial" / name / "preview" / f"{name}.png").read_bytes()
    pixels = oiio.ImageBuf(str(tmp_path / "pool" / "velvet" / "preview" / "velvet.png")).get_pixels(oiio.FLOAT)
    centre = pixels[12:20, 12:20, :3].reshape(-1, 3).mean(axis=0)
    assert centre[2] > centre[0] and centre[2] > centre[1]  # navy blue velvet is blue
    red = oiio.ImageBuf(str(tmp_path / "pool" / "red" / "preview" / "red.png")).get_pixels(oiio.FLOAT)
    assert np.mean(red[12:20, 12:20, 0]) > np.mean(red[12:20, 12:20, 2])
