"""Frame time of the preview's body term with its pre-integrated table as a texture (cnlm_sss_lut,
session 10) against session 9's uniform array (rebuilt by rewriting the look-up, as
tests/subsurface/test_lut_texture.py does), paired and interleaved in one process.

    .venv/bin/python bench/subsurface_table_bench.py [--size 512] [--frames 9] [--mesh teapot] wax jade milk

Prints per phrase the median ms of each form, their ratio and the largest pixel difference.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def main(argv: list[str] | None = None) -> int:
    from cnlmc.api import compile_source
    from cnlmc.backends.preview import gl, object_pass
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.subsurface import preintegrated_table
    from cnlmc.material import Material
    from tests.subsurface.test_lut_texture import with_array_look_up

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("phrases", nargs="*", default=["wax", "jade", "milk"])
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--mesh", default="teapot")
    args = parser.parse_args(argv)
    fragment, uniforms = gl.preview_fragment, object_pass.subsurface_uniforms
    table = preintegrated_table().values.ravel()
    object_pass.subsurface_uniforms = lambda *a: {**uniforms(*a), "pv_sss_lut": table}  # type: ignore[assignment]
    with Renderer(args.size) as texture, Renderer(args.size) as array:
        forms = {"texture": texture, "array": array}
        for phrase in args.phrases:
            material = Material.from_ir(compile_source(phrase + "\n").ir["materials"][0])
            scenes, images = {}, {}
            for name, renderer in forms.items():  # each program linked once, by its own renderer
                gl.preview_fragment = (lambda *a: with_array_look_up(fragment(*a))) if name == "array" else fragment  # type: ignore[assignment]
                scenes[name] = renderer.scene(args.mesh, "studio")
                images[name] = renderer.render(material, scene=scenes[name], tier="splitsum", hdr=True).hdr
            gl.preview_fragment = fragment  # type: ignore[assignment]
            times: dict[str, list[float]] = {name: [] for name in forms}
            for i in range(args.frames):
                for name in sorted(forms, reverse=bool(i % 2)):  # interleaved, alternating order
                    renderer = forms[name]
                    renderer.resources.make_current()
                    start = time.perf_counter()
                    renderer.draw(scenes[name], material, "splitsum")
                    renderer.ctx.finish()
                    times[name].append((time.perf_counter() - start) * 1000.0)
            tex, arr = (float(np.median(times[n])) for n in ("texture", "array"))
            diff = float(np.abs(images["texture"] - images["array"]).max())
            print(f"{phrase}: texture {tex:.1f} ms, array {arr:.1f} ms, ratio {tex / arr:.3f}, max |d| {diff:.2e}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
