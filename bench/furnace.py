"""White furnace per target (issue #15 item 6): the mean sphere radiance under a uniform white
environment (radiance 1, no key light) in the preview and in Mitsuba, against the IR's albedo.

For a sphere seen by an orthographic camera under a white sky the pixel at view cosine mu shows
the directional albedo A(mu), so the disc's mean is 2 * integral A(mu) mu dmu: the IR's number,
from the numpy reference (`cnlmc.bsdf.albedo`). The preview's camera is a perspective one at the
framing distance, close to orthographic. Prints one row per material: IR, preview, Mitsuba, and
the relative differences; `--all` takes every stdlib noun plus coats and variants.

    .venv/bin/python bench/furnace.py [--all] [--size 96] [--spp 64]
"""

from __future__ import annotations

import argparse
import sys
import tempfile

import numpy as np

REPRESENTATIVE = [
    "white plastic",
    "white paper",
    "gold",
    "silver",
    "brushed aluminium",
    "white varnished oak",
    "steel with a clear coat",
    "red car paint",
    "black anodized aluminium",
    "blue anodized aluminum",
    "gunmetal steel",
    "matte black metal",
    "white powder-coated steel",
    "rough iron",
]
GAUSS_POINTS = 24


def material_of(phrase: str):
    from cnlmc.api import compile_source

    result = compile_source(phrase + "\n")
    if not result.ir["materials"]:
        raise ValueError(f"{phrase!r}: {[d.message for d in result.diagnostics]}")
    return result.document.materials[0]


def ir_albedo(material, n_samples: int = 1024) -> np.ndarray:
    """2 * integral_0^1 A(mu) mu dmu, RGB, by Gauss-Legendre in mu: the orthographic disc's mean."""
    from cnlmc.bsdf import albedo

    x, w = np.polynomial.legendre.leggauss(GAUSS_POINTS)
    mu = 0.5 * (x + 1.0)
    a = albedo(material, mu, n_samples=n_samples)
    return (w * mu) @ a


def view_cosines(scene, size: int) -> np.ndarray:
    """cos(theta_o) per pixel centre (size, size), NaN where the ray misses the scene's sphere."""
    cam = scene.camera
    eye, target = np.asarray(cam.eye, float), np.asarray(cam.target, float)
    lo, hi = (np.asarray(b, float) for b in scene.mesh.bounds)
    centre, radius = (lo + hi) / 2, float(np.max(hi - lo)) / 2
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, cam.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half = np.tan(np.radians(cam.fov_y) / 2)
    t = (np.arange(size) + 0.5) / size * 2 - 1
    sx, sy = np.meshgrid(t * half * cam.aspect, -t * half)
    d = forward + sx[..., None] * right + sy[..., None] * up
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    oc = eye - centre
    b = d @ oc
    disc = b * b - (oc @ oc - radius * radius)
    hit = disc > 0
    dist = -b[hit] - np.sqrt(disc[hit])
    normal = (eye + dist[:, None] * d[hit] - centre) / radius
    out = np.full((size, size), np.nan)
    out[hit] = np.clip(np.einsum("ij,ij->i", normal, -d[hit]), 0.0, 1.0)
    return out


def ir_image(material, mus: np.ndarray, n_samples: int = 1024) -> np.ndarray:
    """The IR's radiance per pixel under the white sky: A(mu) at each pixel's view cosine, RGB."""
    from cnlmc.bsdf import albedo

    grid = np.linspace(0.0, 1.0, 33) ** 2  # dense near grazing, where A changes fastest
    grid[0] = 1e-3
    a = albedo(material, grid, n_samples=n_samples)
    return np.stack([np.interp(np.nan_to_num(mus), grid, a[:, c]) for c in range(3)], axis=-1)


def agreement(ir: np.ndarray, mus: np.ndarray, rgb: np.ndarray, coverage: np.ndarray) -> tuple[float, float]:
    """(IR mean, target mean) luminance over the pixels fully inside the sphere in both (edge
    pixels are part background in a rasterizer, a tessellated rim differs from the true sphere)."""
    inside = (coverage > 0.999) & np.isfinite(mus)
    return luminance(ir[inside].mean(axis=0)), luminance(rgb[inside].mean(axis=0))


def white_scene(size: int):
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight
    from cnlmc.backends.preview.render import default_scene

    env = Environment("white", np.ones((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(irradiance=0.0))
    scene = default_scene("sphere", env, (size, size))
    scene.background = "transparent"  # alpha = the sphere's coverage
    return scene


def preview_image(renderer, scene, material, tier: str) -> tuple[np.ndarray, np.ndarray]:
    """(linear RGB, coverage) of the preview under the white sky."""
    frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
    return frame.hdr[..., :3], frame.rgba[..., 3] / 255.0


def mitsuba_image(scene, material, size: int, spp: int) -> tuple[np.ndarray, np.ndarray]:
    """(linear RGB, coverage) of the exported Mitsuba scene under the white sky."""
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene

    with tempfile.TemporaryDirectory() as folder:
        path = export_scene(material, scene, folder, size, size, spp=spp)
        image, _ = render_scene(path, spp=spp)
    alpha = image[..., 3]
    return image[..., :3] / np.maximum(alpha, 1e-6)[..., None], alpha


def luminance(rgb) -> float:
    return float(np.dot(rgb, [0.2126, 0.7152, 0.0722]))


def measure(phrases, size: int, spp: int, tier: str, mitsuba: bool = True):
    from cnlmc.backends.preview.render import Renderer

    scene = white_scene(size)
    mus = view_cosines(scene, size)
    with Renderer(size, msaa=4) as renderer:
        for phrase in phrases:
            m = material_of(phrase)
            ir = ir_image(m, mus)
            ir_pv, pv = agreement(ir, mus, *preview_image(renderer, scene, m, tier))
            ir_mi, mi = agreement(ir, mus, *mitsuba_image(scene, m, size, spp)) if mitsuba else (ir_pv, float("nan"))
            yield phrase, ir_pv, pv, (mi * ir_pv / ir_mi if ir_mi > 0 else mi)  # ultra-black paints: IR 0


def every_phrase() -> list[str]:
    from cnlmc.api import lexicon_for

    lex = lexicon_for()
    nouns = sorted(lex.all_of("nouns"))
    coats = [f"white plastic with a {c}" for c in sorted(lex.all_of("coats"))]
    variants = ["polished gold", "rough gold", "brushed steel", "matte white plastic", "glossy red plastic"]
    return [*nouns, *coats, *variants]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true", help="every stdlib noun plus coats and variants")
    parser.add_argument("--size", type=int, default=96)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--tier", default="fis64")
    args = parser.parse_args(argv)
    phrases = every_phrase() if args.all else REPRESENTATIVE
    print(f"{'material':36s} {'IR':>7s} {'preview':>8s} {'Mitsuba':>8s} {'pv/IR':>7s} {'mi/IR':>7s}")
    for phrase, ir, pv, mi in measure(phrases, args.size, args.spp, args.tier):
        scale = 1.0 / ir if ir > 0 else float("nan")
        print(f"{phrase[:36]:36s} {ir:7.3f} {pv:8.3f} {mi:8.3f} {pv * scale:7.3f} {mi * scale:7.3f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
