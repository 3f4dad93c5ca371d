"""The dark-metals sheet of docs/bsdf.md (issue #15 item 2): black anodized aluminium, blue anodized
aluminum, gunmetal steel, matte black metal, gold and red car paint on the 10 cm preview sphere in
the studio environment; top row the preview (`fis64`), bottom row Mitsuba 3 rendering the exported
scene (native plugins, 64 spp).

    .venv/bin/python bench/dark_metals_sheet.py [--size 176] [-o docs/dark_metals.png]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PHRASES = (
    "black anodized aluminium",
    "blue anodized aluminum",
    "gunmetal steel",
    "matte black metal",
    "gold",
    "red car paint",
)


def to_rgba8(linear: np.ndarray, alpha: np.ndarray) -> np.ndarray:
    """Linear RGB (clipped) -> sRGB 8-bit over the sheet's grey."""
    rgb = np.clip(linear, 0.0, 1.0) + (1.0 - alpha[..., None]) * 0.18
    srgb = np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * np.clip(rgb, 0.0031308, 1.0) ** (1 / 2.4) - 0.055)
    out = np.concatenate([srgb, np.ones_like(alpha)[..., None]], axis=-1)
    return (np.clip(out, 0.0, 1.0) * 255 + 0.5).astype(np.uint8)


def tiles(size: int) -> list[list[np.ndarray]]:
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.render import Renderer, default_scene
    from cnlmc.backends.preview.sheet import label

    scene = default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    top, bottom = [], []
    with Renderer(size, msaa=4) as renderer:
        for phrase in PHRASES:
            material = compile_source(phrase + "\n").document.materials[0]
            frame = renderer.render(material, tier="fis64", scene=scene, hdr=True)
            top.append(label(to_rgba8(frame.hdr[..., :3], frame.rgba[..., 3] / 255.0), f"preview: {phrase}"))
            with tempfile.TemporaryDirectory() as folder:
                image, _ = render_scene(export_scene(material, scene, folder, size, size, spp=64), spp=64)
            alpha = image[..., 3]
            rgb = image[..., :3] / np.maximum(alpha, 1e-6)[..., None] * alpha[..., None]
            bottom.append(label(to_rgba8(rgb, alpha), f"Mitsuba: {phrase}"))
    return [top, bottom]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=176)
    parser.add_argument("-o", "--out", default=str(ROOT / "docs" / "dark_metals.png"))
    args = parser.parse_args()
    from cnlmc.backends.preview.sheet import png_bytes, sheet
    from cnlmc.output import write_atomic

    write_atomic(Path(args.out), png_bytes(sheet(tiles(args.size))))
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
