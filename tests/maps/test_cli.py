"""The map commands as a user runs them: cnlmc bake, --target maps, cnlmc sheet."""

import numpy as np
import pytest

from tests.helpers import require
from tests.helpers import run_cnlmc as cnlmc

oiio = require("OpenImageIO", "maps")
pytestmark = pytest.mark.oiio


def read(path):
    image = oiio.ImageInput.open(str(path))
    pixels, spec = image.read_image(), image.spec()
    image.close()
    return np.asarray(pixels), spec


def test_bake_writes_only_the_maps_a_material_needs(tmp_path):
    r = cnlmc(
        "bake",
        "-",
        "-o",
        str(tmp_path),
        "--size",
        "64",
        stdin="deck: white varnished oak\nhull: polished steel\nrusty iron\n",
    )
    assert r.returncode == 0, r.stderr
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == [
        "deck_base_color.png",
        "deck_roughness.png",
        "rusty_iron_base_color.png",
        "rusty_iron_mask.png",
        "rusty_iron_roughness.png",
    ]
    assert "hull: uniform, no maps to bake" in r.stderr
    pixels, spec = read(tmp_path / "deck_base_color.png")
    assert pixels.shape == (64, 64, 3) and spec.getattribute("oiio:ColorSpace")


def test_bake_exr_and_a_seed_changes_the_pattern(tmp_path):
    for seed in ("1", "2"):
        r = cnlmc(
            "bake",
            "-",
            "-o",
            str(tmp_path / seed),
            "--size",
            "32",
            "--format",
            "exr-half",
            "--seed",
            seed,
            stdin="marble\n",
        )
        assert r.returncode == 0, r.stderr
    a, _ = read(tmp_path / "1" / "marble_base_color.exr")
    b, _ = read(tmp_path / "2" / "marble_base_color.exr")
    assert a.shape == (32, 32, 3) and not np.array_equal(a, b)


def test_bake_refuses_absurd_sizes():
    r = cnlmc("bake", "-", "-o", "/tmp/never", "--size", "100000", stdin="oak\n")
    assert r.returncode == 2
    assert "map size 100000 is out of range: use a power of two from 8 to 8192" in r.stderr


def test_target_maps_gives_the_same_images_as_bake(tmp_path):
    r = cnlmc("compile", "-", "-t", "maps", "-o", str(tmp_path / "t") + "/", "--option", "size=32", stdin="oak\n")
    assert r.returncode == 0, r.stderr
    r = cnlmc("bake", "-", "-o", str(tmp_path / "b"), "--size", "32", stdin="oak\n")
    for name in ("oak_base_color.png", "oak_roughness.png"):
        assert np.array_equal(read(tmp_path / "t" / name)[0], read(tmp_path / "b" / name)[0])


def test_sheet_writes_a_png(tmp_path):
    out = tmp_path / "sheet.png"
    r = cnlmc("sheet", "-o", str(out), "--size", "16")
    assert r.returncode == 0, r.stderr
    pixels, spec = read(out)
    assert spec.width > 16 * 4 and spec.height > 16 * 10


@pytest.mark.parametrize("size", ["0", "-1", "1", "3000"])
def test_sheet_refuses_a_tile_size_out_of_range(tmp_path, size):
    """#13: 0, -1 and 1 were internal errors; 3000 used 9.5 GB."""
    out = tmp_path / "sheet.png"
    r = cnlmc("sheet", "-o", str(out), "--size", size)
    assert r.returncode == 2 and f"tile size {size} is out of range: use 16 to 1024 pixels" in r.stderr, r.stderr
    assert not out.exists()


def test_bake_of_uniform_materials_leaves_no_folder_behind(tmp_path):
    src = tmp_path / "plain.cnl"
    src.write_text("red plastic\n")
    done = cnlmc("bake", str(src), "-o", str(tmp_path / "maps"))
    assert done.returncode == 0 and "uniform, no maps to bake" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain.cnl"]  # no folder, no lock file


def test_the_progress_bar_writes_to_the_stderr_of_its_call(monkeypatch):
    """Its stream is this call's stderr, not the one at import (a closed one in an embedding run)."""
    import io
    import sys

    from cnlmc.backends.maps.commands import ProgressBar

    replaced = io.StringIO()
    monkeypatch.setattr(sys, "stderr", replaced)
    assert ProgressBar().stream is replaced
