"""Our wood bake next to MaterialX's own TextureBaker baking a wood-like procedural graph.

    .venv/bin/python bench/maps_vs_materialx.py [--size 1024] [--runs 5]

The MaterialX document (MX_WOOD below) mirrors stdlib/graphs/wood.toml: rings from a
fract() of v bent by fractal noise, power 4 ring profile, stretched fibre noise,
colour = mix of two browns, roughness = mix of two values, normal = heighttonormal.
TextureBaker renders through OpenGL and needs an X display, so it runs in a subprocess
under `xvfb-run -a` (Mesa llvmpipe on this machine: the CPU does the GPU's work).
It always writes its images; so the peer is compared with our bake *and* with our bake
plus writing the same three maps as 8-bit PNG.  Prints numbers, asserts nothing.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

MX_WOOD = """<?xml version="1.0"?>
<materialx version="1.39">
  <nodegraph name="NG_wood">
    <texcoord name="uv" type="vector2" />
    <multiply name="bend_uv" type="vector2"><input name="in1" type="vector2" nodename="uv" /><input name="in2" type="vector2" value="0.667, 2" /></multiply>
    <fractal2d name="bend" type="float"><input name="texcoord" type="vector2" nodename="bend_uv" /><input name="octaves" type="integer" value="3" /><input name="amplitude" type="float" value="0.5" /></fractal2d>
    <separate2 name="uv_split" type="multioutput"><input name="in" type="vector2" nodename="uv" /></separate2>
    <multiply name="ring_v" type="float"><input name="in1" type="float" nodename="uv_split" output="outy" /><input name="in2" type="float" value="9" /></multiply>
    <multiply name="bend_amount" type="float"><input name="in1" type="float" nodename="bend" /><input name="in2" type="float" value="1.6" /></multiply>
    <add name="ring_phase" type="float"><input name="in1" type="float" nodename="ring_v" /><input name="in2" type="float" nodename="bend_amount" /></add>
    <fract name="rings" type="float"><input name="in" type="float" nodename="ring_phase" /></fract>
    <power name="ring_profile" type="float"><input name="in1" type="float" nodename="rings" /><input name="in2" type="float" value="4" /></power>
    <subtract name="latewood" type="float"><input name="in1" type="float" value="1" /><input name="in2" type="float" nodename="ring_profile" /></subtract>
    <multiply name="fibre_uv" type="vector2"><input name="in1" type="vector2" nodename="uv" /><input name="in2" type="vector2" value="2, 48" /></multiply>
    <fractal2d name="fibre_noise" type="float"><input name="texcoord" type="vector2" nodename="fibre_uv" /><input name="octaves" type="integer" value="3" /><input name="diminish" type="float" value="0.6" /></fractal2d>
    <multiply name="fibres" type="float"><input name="in1" type="float" nodename="fibre_noise" /><input name="in2" type="float" value="0.5" /></multiply>
    <add name="fibres_centred" type="float"><input name="in1" type="float" nodename="fibres" /><input name="in2" type="float" value="0.5" /></add>
    <multiply name="figure_dark" type="float"><input name="in1" type="float" nodename="latewood" /><input name="in2" type="float" nodename="fibres_centred" /></multiply>
    <mix name="figure" type="float"><input name="fg" type="float" nodename="figure_dark" /><input name="bg" type="float" nodename="latewood" /><input name="mix" type="float" value="0.5" /></mix>
    <mix name="color" type="color3"><input name="fg" type="color3" value="0.48, 0.28, 0.13" /><input name="bg" type="color3" value="0.21, 0.12, 0.055" /><input name="mix" type="float" nodename="figure" /></mix>
    <mix name="roughness" type="float"><input name="fg" type="float" value="0.51" /><input name="bg" type="float" value="0.63" /><input name="mix" type="float" nodename="figure" /></mix>
    <heighttonormal name="bump" type="vector3"><input name="in" type="float" nodename="figure" /><input name="scale" type="float" value="0.4" /></heighttonormal>
    <output name="out_color" type="color3" nodename="color" />
    <output name="out_roughness" type="float" nodename="roughness" />
    <output name="out_normal" type="vector3" nodename="bump" />
  </nodegraph>
  <standard_surface name="SR_wood" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG_wood" output="out_color" />
    <input name="specular_roughness" type="float" nodegraph="NG_wood" output="out_roughness" />
    <input name="normal" type="vector3" nodegraph="NG_wood" output="out_normal" />
  </standard_surface>
  <surfacematerial name="M_wood" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_wood" />
  </surfacematerial>
</materialx>
"""


def median_ms(function, runs: int) -> tuple[float, float]:
    """(median, first-call) milliseconds; the first call is timed separately (warm-up)."""
    start = time.perf_counter()
    function()
    first = (time.perf_counter() - start) * 1000
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times), first


def materialx_document():
    import MaterialX as mx

    library = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), library)
    doc = mx.createDocument()
    mx.readFromXmlString(doc, MX_WOOD)
    doc.importLibrary(library)
    valid, message = doc.validate()
    if not valid:
        raise RuntimeError(f"MX_WOOD does not validate: {message}")
    return doc


def bake_with_texture_baker(size: int, out_dir: str):
    """One TextureBaker bake of M_wood at size^2 (8-bit images, written to out_dir)."""
    import MaterialX as mx
    import MaterialX.PyMaterialXRender as mx_render
    import MaterialX.PyMaterialXRenderGlsl as mx_glsl

    doc = materialx_document()
    baker = mx_glsl.TextureBaker.create(size, size, mx_render.BaseType.UINT8)
    baker.setOutputImagePath(mx.FilePath(out_dir))
    baker.setOptimizeConstants(False)
    baker.setAverageImages(False)
    baked = baker.bakeMaterialToDoc(doc, mx.getDefaultDataSearchPath(), "M_wood", [], "wood")
    return baked


def peer_main(size: int, runs: int) -> None:
    """Runs under xvfb-run: prints one JSON line with the TextureBaker timings."""
    with tempfile.TemporaryDirectory() as out:
        median, first = median_ms(lambda: bake_with_texture_baker(size, out), runs)
        images = sorted(f for f in os.listdir(out))
    print(json.dumps({"median_ms": median, "first_ms": first, "images": images}))


def run_peer(size: int, runs: int) -> dict:
    """TextureBaker in a subprocess under xvfb-run; {'error': ...} when it cannot run."""
    if shutil.which("xvfb-run") is None:
        return {"error": "xvfb-run not found (apt-get install -y xvfb xauth)"}
    command = ["xvfb-run", "-a", sys.executable, __file__, "--peer", "--size", str(size), "--runs", str(runs)]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    lines = [line for line in result.stdout.splitlines() if line.startswith("{")]
    if result.returncode != 0 or not lines:
        return {"error": f"exit {result.returncode}: {(result.stderr or result.stdout).strip()[-2000:]}"}
    return json.loads(lines[-1])


def ours(size: int, runs: int) -> dict:
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from maps_bench import WOOD

    from cnlmc.backends.maps import bake, write_maps

    material = {"base_color": [0.42, 0.24, 0.11]}
    bake_ms, _ = median_ms(lambda: bake(WOOD, material, size, 0), runs)
    with tempfile.TemporaryDirectory() as out:
        both_ms, _ = median_ms(lambda: write_maps(bake(WOOD, material, size, 0), out, fmt="png8", stem="wood"), runs)
    return {"bake_ms": bake_ms, "bake_write_png8_ms": both_ms}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--peer", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.peer:
        peer_main(args.size, args.runs)
        return
    print(
        f"cpu count {os.cpu_count()}, load average {os.getloadavg()[0]:.2f}, size {args.size}^2, median of {args.runs}"
    )
    mine = ours(args.size, args.runs)
    print(f"cnlmc maps bake wood color+normal+roughness:      {mine['bake_ms']:8.1f} ms")
    print(f"cnlmc maps bake + write 3 png8:                   {mine['bake_write_png8_ms']:8.1f} ms")
    peer = run_peer(args.size, args.runs)
    if "error" in peer:
        print(f"MaterialX TextureBaker could not run: {peer['error']}")
        return
    print(
        f"MaterialX TextureBaker (GLSL, llvmpipe, Xvfb), bake + write {len(peer['images'])} images "
        f"{peer['images']}: {peer['median_ms']:8.1f} ms (first bake {peer['first_ms']:.0f} ms)"
    )
    print(f"ratio TextureBaker / cnlmc bake:         {peer['median_ms'] / mine['bake_ms']:6.1f}x")
    print(f"ratio TextureBaker / cnlmc bake + write: {peer['median_ms'] / mine['bake_write_png8_ms']:6.1f}x")


if __name__ == "__main__":
    main()
