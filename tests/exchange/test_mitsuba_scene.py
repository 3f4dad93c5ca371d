"""The Mitsuba preview scene tells the truth: clear glass shows (a checkered backdrop behind the
spheres), and a `bsdf=cnlm` scene's header names a command that renders it."""

from __future__ import annotations

import os
import re
import shlex
import sys

import numpy as np
import pytest

from tests.helpers import require, run_cnlmc

mi = require("mitsuba", "mitsuba")
pytestmark = pytest.mark.mitsuba

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.exchange import mitsuba_cnlm  # noqa: E402

from .conftest import FAST, ir_of  # noqa: E402

SPHERE = re.compile(r'<shape type="sphere">.*?</shape>', re.S)


def render(xml: str, folder) -> np.ndarray:
    mi.set_variant("scalar_rgb")
    (folder / "probe.xml").write_text(xml)
    scene = mi.load_file(str(folder / "probe.xml"), spp=8, resx=48, resy=48)
    return np.asarray(mi.render(scene))


def test_clear_glass_is_visible_in_the_default_scene(tmp_path):
    """The glass sphere's pixels differ from what is behind it (the scene without the sphere):
    in a constant white world with nothing behind it, clear glass rendered as white on white."""
    xml = emit(ir_of("clear glass"), "mitsuba", FAST).artifacts[0].content
    assert "checkerboard" in xml
    with_glass = render(xml, tmp_path)
    without = render(SPHERE.sub("", xml), tmp_path)
    centre = (slice(16, 32), slice(16, 32))  # the sphere fills the middle of the frame
    difference = np.abs(with_glass[centre] - without[centre]).mean()
    assert difference > 0.05, difference
    assert without[centre].std() > 0.1  # the backdrop is checkered, not flat


def header_command(xml: str) -> list[str]:
    header = re.search(r"<!--(.*?)-->", xml, re.S).group(1)
    assert "mitsuba scene.xml" not in header.replace("`mitsuba scene.xml` cannot", "")  # no false advice
    command = re.search(r"Render it with: (python -m \S+ scene\.xml -o \S+)", header).group(1)
    return shlex.split(command)


def test_a_cnlm_scene_header_names_a_command_that_renders_it(tmp_path):
    try:
        mitsuba_cnlm.choose_variant()
    except mitsuba_cnlm.PluginError as exc:
        pytest.skip(str(exc))
    done = run_cnlmc(
        "compile", "-", "-t", "mitsuba", "--option", "bsdf=cnlm", "-o", str(tmp_path / "scene.xml"), stdin="red plastic"
    )
    assert done.returncode == 0, done.stderr
    argv = header_command((tmp_path / "scene.xml").read_text())
    assert argv[:2] == ["python", "-m"]
    argv = [sys.executable, *argv[1:], "-D", "spp=2", "-D", "resx=16", "-D", "resy=16"]
    import subprocess

    ran = subprocess.run(argv, cwd=tmp_path, capture_output=True, text=True, timeout=300, env=dict(os.environ))
    assert ran.returncode == 0, ran.stderr
    image = mi.Bitmap(str(tmp_path / "render.exr"))
    pixels = np.asarray(image)
    assert pixels.shape[:2] == (16, 16) and np.isfinite(pixels).all() and pixels.mean() > 0.05


def test_a_native_scene_header_still_says_mitsuba(tmp_path):
    xml = emit(ir_of("red plastic"), "mitsuba", FAST).artifacts[0].content
    assert "mitsuba scene.xml -D spp=256" in xml.split("-->")[0]


def test_the_render_command_reports_a_missing_scene(tmp_path):
    import subprocess

    ran = subprocess.run(
        [sys.executable, "-m", "cnlmc.backends.exchange.mitsuba_render", "missing.xml"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert ran.returncode == 2 and "no such scene file" in ran.stderr and "Traceback" not in ran.stderr
    assert not list(tmp_path.iterdir())
