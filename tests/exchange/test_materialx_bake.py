"""MaterialX's own tools consume cnlmc's documents: `baketextures` (MaterialX's TextureBaker, GLSL,
under Xvfb) bakes every textured document, and the baked documents validate as `mxvalidate` does
(readFromXmlFile + validate against the standard libraries). Native procedural maps
(`maps=native`), baked by the same tool, keep the mean colour of cnlmc's own baked maps."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import require

mx = require("MaterialX", "materialx")
oiio = require("OpenImageIO", "OpenImageIO")
pytestmark = pytest.mark.materialx

from cnlmc.api import emit  # noqa: E402

from .conftest import FAST, PHRASES, all_sources, ir_of, write_artifacts  # noqa: E402

BAKETEXTURES = Path(sys.executable).with_name("baketextures")
if not BAKETEXTURES.exists() or not shutil.which("xvfb-run"):
    pytest.skip("MaterialX's baketextures or xvfb-run is missing", allow_module_level=True)

BAKE_SIZE = 64  # our choice: enough pixels for a stable mean, quick on llvmpipe


def signature(material: dict) -> tuple:
    """What decides a material's node graph: its model, its map roles and graphs, the α convention."""
    model, maps = material["model"], material["maps"]
    graphs = tuple(sorted((role, ref["graph"], ref["output"]) for role, ref in maps.items()))
    return model["base"], model["anisotropic"], material["params"].get("alpha_convention"), graphs


def textured_sources() -> list[str]:
    """Every textured phrase of the exchange tests, and one stdlib noun per node-graph signature
    (the 220 textured nouns share about 40: baking each takes MaterialX about a second)."""
    textured = [s for s in PHRASES if any(m["maps"] for m in ir_of(s)["materials"])]
    covered = {signature(m) for s in textured for m in ir_of(s)["materials"]}
    for source in all_sources():
        signatures = {signature(m) for m in ir_of(source)["materials"] if m["maps"]}
        if signatures - covered:
            textured.append(source)
            covered |= signatures
    return textured


def combined_ir(sources: list[str]) -> dict:
    """One document with every material of `sources`, names kept unique."""
    materials, seen = [], set()
    for source in sources:
        for material in ir_of(source)["materials"]:
            if material["name"] not in seen:
                seen.add(material["name"])
                materials.append(material)
    ir = ir_of(sources[0])
    return {**ir, "materials": materials}


def bake_with_materialx(folder: Path, size: int = BAKE_SIZE) -> list[Path]:
    """`xvfb-run baketextures --hdr materials.mtlx baked.mtlx` in `folder`; the baked documents."""
    done = subprocess.run(
        ["xvfb-run", "-a", str(BAKETEXTURES), "--hdr", "--width", str(size), "--height", str(size)]
        + ["materials.mtlx", "baked.mtlx"],
        cwd=folder,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Validation warnings" not in done.stdout, done.stdout  # the input document itself is valid
    return sorted(folder.glob("baked*.mtlx"))


def mxvalidate(path: Path) -> tuple[bool, str]:
    """What MaterialX's `mxvalidate` script does, in process."""
    library = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), library)
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, str(path))
    doc.setDataLibrary(library)
    return doc.validate()


@pytest.mark.parametrize("maps", ["bake", "native"])
def test_baketextures_then_mxvalidate_on_every_textured_document(maps, tmp_path):
    sources = textured_sources()
    assert len(sources) >= 10
    ir = combined_ir(sources)
    write_artifacts(emit(ir, "materialx", {**FAST, "maps": maps}).artifacts, tmp_path)
    baked = bake_with_materialx(tmp_path, size=16)
    assert len(baked) == len(ir["materials"])
    for path in baked:
        ok, message = mxvalidate(path)
        assert ok, f"{path.name}: {message}"
        assert "<image" in path.read_text()  # the maps were baked into images, not dropped


NATIVE_PHRASES = ("heavily rusted iron", "rusty iron", "polished white marble", "polished granite")
NATIVE_SIZE = 256  # the native graphs baked at the maps' own size


def baked_map_mean(folder: Path, name: str, doc) -> np.ndarray:
    """The mean linear colour of the base-colour PNG maps=bake writes, times the conductor tint f0
    the document multiplies it by (what the shader's base_color input averages to)."""
    pixels = oiio.ImageBuf(str(folder / "textures" / "materials.mtlx" / f"{name}_base_color.png"))
    linear = oiio.ImageBufAlgo.colorconvert(pixels, "sRGB", "linear").get_pixels(oiio.FLOAT)[..., :3]
    tint = [n for g in doc.getNodeGraphs() for n in g.getNodes("multiply") if n.getName() == f"{name}_base_color_f0"]
    f0 = np.array(list(tint[0].getInputValue("in2"))) if tint else np.ones(3)
    return linear.reshape(-1, 3).mean(axis=0) * f0


def test_native_maps_keep_the_baked_mean_colour(tmp_path):
    """maps=native evaluated by MaterialX's TextureBaker (the native nodes, per pixel) against the
    map cnlmc bakes for maps=bake: the mean base colour (linear) agrees within 5 % per channel.
    (Baking the maps=bake document with MaterialX is no reference: its image node filters the sRGB
    texels before decoding them, which darkens dark, contrasty maps by 3-30 % with the bake size.)"""
    ir = combined_ir(list(NATIVE_PHRASES))
    write_artifacts(emit(ir, "materialx", {"map_size": str(NATIVE_SIZE)}).artifacts, tmp_path / "bake")
    write_artifacts(emit(ir, "materialx", {"map_size": "16", "maps": "native"}).artifacts, tmp_path / "native")
    bake_with_materialx(tmp_path / "native", size=NATIVE_SIZE)
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, str(tmp_path / "bake" / "materials.mtlx"))
    for material in ir["materials"]:
        baked = baked_map_mean(tmp_path / "bake", material["name"], doc)
        native = mean_base_colour(tmp_path / "native", material["name"])
        relative = abs(native / baked - 1.0)
        assert relative.max() <= 0.05, (material["name"], baked.round(4), native.round(4))


def mean_base_colour(folder: Path, name: str):
    image = folder / f"M_{name}_open_pbr_surface_base_color.hdr"
    pixels = oiio.ImageBuf(str(image)).get_pixels(oiio.FLOAT)
    return pixels[..., :3].reshape(-1, 3).mean(axis=0)
