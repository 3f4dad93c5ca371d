"""Look at the Mitsuba volumetric reference (docs/subsurface.md): translucent materials on the
teapot (or a sphere), front-lit and backlit, through the mitsuba target's fragment (`form=fragment`).

    python bench/subsurface_look.py -o /tmp/look.png [--spp 64] [--size 160] [--mesh teapot] wax jade ...

Prints each render's time; writes one PNG row per lighting (front, back), a column per phrase.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

CONTENT = """<emitter type="constant"><rgb name="radiance" value="0.05, 0.05, 0.06"/></emitter>
    <shape type="rectangle">
        <transform name="to_world"><scale value="1.2"/><lookat origin="{light}" target="0, 0.1, 0" up="0, 1, 0"/></transform>
        <emitter type="area"><rgb name="radiance" value="{power}, {power}, {power}"/></emitter>
    </shape>
    <shape type="{shape_type}">
        {shape_props}
        <ref id="{ident}"/>{interior}
    </shape>"""
LIGHTS = {"front": ("1.8, 2.2, 3.0", 5.0), "back": ("0.0, 1.6, -2.4", 8.0)}


def mesh_file(folder: Path, name: str) -> str:
    from cnlmc.backends.preview.mesh_io import write_ply
    from cnlmc.backends.preview.meshes import fit, teapot

    path = folder / f"{name}.ply"
    if not path.exists():
        write_ply(fit(teapot(10), stand=False), path)
    return str(path)


def render(phrase: str, light: str, folder: Path, args: argparse.Namespace) -> tuple[np.ndarray, float]:
    import mitsuba as mi

    from cnlmc.api import compile_source, emit
    from cnlmc.backends.preview.subsurface_reference import probe_scene

    ir = compile_source(phrase).ir
    material = ir["materials"][0]
    xml = emit(ir, "mitsuba", {"form": "fragment", "unit_metres": str(args.unit)}).artifacts[0].content
    (folder / "materials.xml").write_text(xml)
    volume = material["model"].get("subsurface") == "volume"
    if args.mesh == "teapot":
        shape_type, props = "ply", f'<string name="filename" value="{mesh_file(folder, "teapot")}"/>'
    else:
        shape_type, props = "sphere", '<float name="radius" value="0.9"/>'
    origin, power = LIGHTS[light]
    content = CONTENT.format(
        light=origin,
        power=power,
        shape_type=shape_type,
        shape_props=props,
        ident=material["name"],
        interior=f'<ref name="interior" id="{material["name"]}_medium"/>' if volume else "",
    )
    text = probe_scene(
        content, origin="0, 0.9, 4.2", target="0, 0.05, 0", fov=34, size=args.size, spp=args.spp, max_depth=args.depth
    )
    (folder / "scene.xml").write_text(text)
    start = time.perf_counter()
    image = np.asarray(mi.render(mi.load_file(str(folder / "scene.xml"))))
    return image[..., :3], time.perf_counter() - start


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("phrases", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--depth", type=int, default=-1)
    parser.add_argument("--unit", type=float, default=0.08, help="metres per scene unit (0.08: a 16 cm teapot)")
    parser.add_argument("--mesh", choices=("teapot", "sphere"), default="teapot")
    parser.add_argument("--variant", default="llvm_ad_rgb")
    args = parser.parse_args(argv)
    import mitsuba as mi

    mi.set_variant(args.variant)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for light in LIGHTS:
            row = []
            for phrase in args.phrases:
                image, seconds = render(phrase, light, Path(tmp), args)
                print(f"{phrase!r:28} {light:5} {seconds:6.2f} s  mean {image.mean():.3f}")
                row.append(image)
            rows.append(np.concatenate(row, axis=1))
    picture = np.concatenate(rows, axis=0)
    srgb = np.where(picture <= 0.0031308, 12.92 * picture, 1.055 * np.clip(picture, 0, None) ** (1 / 2.4) - 0.055)
    mi.util.write_bitmap(args.output, mi.Bitmap(np.clip(srgb, 0, 1).astype(np.float32)), write_async=False)
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
