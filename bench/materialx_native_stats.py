"""Measure the mean of the native MaterialX recipes' patterns with MaterialX's own TextureBaker:
the numbers in backends/exchange/materialx_native_stats.json. Needs xvfb-run.

    .venv/bin/python bench/materialx_native_stats.py OUT_FOLDER

Prints, per rust coverage, E[mask] (from the baked base_metalness = 1 - mask) and the rust part of
the colour per channel (the baked colour / f0 / the recipe's mean gain, less the clean metal's
share 1 - E[mask]), and E[veins] of marble and E[minerals] of granite."""

from __future__ import annotations

import copy
import json
import subprocess
import sys
from pathlib import Path

import MaterialX as mx
import numpy as np
import OpenImageIO as oiio

from cnlmc.api import compile_source, emit
from cnlmc.output import write_artifacts

COVERAGES = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.92, 0.95, 0.98, 0.99, 0.995]
SIZE = "256"


def material(phrase: str) -> dict:
    return compile_source(phrase + "\n").ir["materials"][0]


def baked_mean(folder: Path, name: str, shader_input: str) -> np.ndarray:
    path = folder / f"M_{name}_open_pbr_surface_{shader_input}.hdr"
    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3].reshape(-1, 3).mean(axis=0)


def multiply_value(doc, name: str) -> np.ndarray:
    found = [n for g in doc.getNodeGraphs() for n in g.getNodes("multiply") if n.getName() == name]
    return np.array(list(found[0].getInputValue("in2")))


def main(folder: Path) -> None:
    rust, marble, granite = (material(p) for p in ("rusty iron", "polished white marble", "polished granite"))
    materials = []
    for coverage in COVERAGES:
        m = copy.deepcopy(rust)
        m["name"] = f"rust_{int(coverage * 1000)}"
        for ref in m["maps"].values():
            ref["params"] = {"coverage": coverage}
        materials.append(m)
    ir = {**compile_source("rusty iron\n").ir, "materials": [*materials, marble, granite]}
    write_artifacts(emit(ir, "materialx", {"maps": "native", "map_size": "16"}).artifacts, str(folder) + "/")
    baker = Path(sys.executable).with_name("baketextures")
    command = ["xvfb-run", "-a", str(baker), "--hdr", "--width", SIZE, "--height", SIZE, "materials.mtlx", "b.mtlx"]
    subprocess.run(command, cwd=folder, check=True, capture_output=True)
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, str(folder / "materials.mtlx"))
    out: dict = {"rust": {}}
    for coverage, m in zip(COVERAGES, materials):
        name = m["name"]
        mask = 1 - baked_mean(folder, name, "base_metalness")[0]
        f0, gain = multiply_value(doc, f"{name}_base_color_f0"), multiply_value(doc, f"{name}_rust_color_mean")
        colour = baked_mean(folder, name, "base_color") / f0 / gain
        out["rust"][coverage] = [round(float(mask), 4), [round(float(c), 4) for c in colour - (1 - mask)]]
    base = np.array(marble["params"]["base_color"])
    gain = multiply_value(doc, "polished_white_marble_marble_color_mean")
    mean = baked_mean(folder, "polished_white_marble", "base_color") / gain
    out["marble_veins"] = round(float(((base - mean) / (base * 0.45))[0]), 4)
    base = np.array(granite["params"]["base_color"])
    gain = multiply_value(doc, "polished_granite_granite_color_mean")
    mean = baked_mean(folder, "polished_granite", "base_color") / gain
    out["granite_minerals"] = round(float(((mean - base * 0.15) / (base * 1.2))[0]), 4)
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("native_stats"))
