"""MERL fits vs our phrases, rendered: each of the 50 MERL materials of ../shared/data/merl_fits/ on
the same sphere under the same light, from its published fit (Löw 2012 Cook–Torrance E2,
bench/merl_model.py) and from the phrase a person would type for it (bench/calibration.py
MERL_PHRASES, compiled; its IR evaluated by cnlmc.bsdf with its sheen), compared with FLIP.

Scene (our choice: a plain studio look that shows both the body colour and the highlight):
orthographic view of a unit sphere along −z, SIZE² pixels with 2×2 supersampling; one directional
light of irradiance 1 from L = normalise(−0.5, 0.6, 0.62) (upper left, in front), plus a uniform
white environment of radiance AMBIENT = 0.1 (its reflection is L_a · A(μo), A the directional albedo
tabulated on 16 μ values by cnlmc.bsdf's MIS integrator, the same for both models); black background.

Exposure: the fits are in MERL's camera RGB with their own scale, so each image is scaled so that the
mean luminance (Rec. 709 weights) over the sphere's pixels is 0.18 (default; `--exposure p99`: its
99th percentile is 0.8), then clipped to [0, 1] and sRGB-encoded; FLIP (flip-evaluator, LDR, 67 ppd)
is averaged over the sphere's pixels only (the background is equal and would dilute it). Camera RGB
is read as linear sRGB, unconverted. A second FLIP column compares the two images' luma only (the
same encoded images, hue and chroma removed): it separates gloss and shading from colour.

    .venv/bin/python bench/merl_render.py                 # table, medians, writes docs/merl_worst10.png
    .venv/bin/python bench/merl_render.py --size 96 --no-sheet --exposure p99
    .venv/bin/python bench/merl_render.py --surface-gamut pointer   # also in Pointer's gamut; docs/merl_pointer.png
Exit status 2 when the shared data folder is missing.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import calibration as cal  # bench/calibration.py: the MERL phrases, the .fit parser, compile_phrase
from merl_model import LowCookTorrance, parse_low_fits

ROOT = Path(__file__).resolve().parents[1]
LIGHT = np.array([-0.5, 0.6, 0.62]) / np.linalg.norm([-0.5, 0.6, 0.62])
AMBIENT = 0.1
MEAN_LUMINANCE = 0.18
P99_LUMINANCE = 0.8
LUMA = np.array([0.2126, 0.7152, 0.0722])
MU_TABLE = np.linspace(0.02, 1.0, 16)
GOAL = 0.2

Brdf = Callable[[np.ndarray, np.ndarray], np.ndarray]


class Sphere:
    """The pixels of an orthographic unit sphere, with a local frame (normal +z) per covered pixel."""

    def __init__(self, size: int, supersample: int = 2) -> None:
        self.size, self.ss = size, supersample
        n = size * supersample
        c = (np.arange(n) + 0.5) / n * 2.0 - 1.0
        x, y = np.meshgrid(c, -c)
        r2 = x * x + y * y
        self.mask = r2 < 1.0
        normal = np.stack([x, y, np.sqrt(np.clip(1.0 - r2, 0.0, 1.0))], axis=-1)[self.mask]
        tangent = np.cross([0.0, 1.0, 0.0], normal)
        tangent /= np.maximum(np.linalg.norm(tangent, axis=-1, keepdims=True), 1e-12)
        self.frame = np.stack([tangent, np.cross(normal, tangent), normal], axis=-2)  # rows t, b, n
        self.coverage = self.mask.reshape(size, supersample, size, supersample).mean(axis=(1, 3))

    def local(self, world: np.ndarray) -> np.ndarray:
        """A world direction (3,) in every pixel's local frame, (P, 3)."""
        return np.einsum("pij,j->pi", self.frame, world)

    def render(self, brdf: Brdf, albedo_of_mu: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:
        """Linear RGB (size, size, 3): key light plus the uniform environment, box-filtered."""
        wo = self.local(np.array([0.0, 0.0, 1.0]))
        wi = self.local(LIGHT)
        key = brdf(wo, wi) * np.clip(wi[:, 2], 0.0, None)[:, None]
        radiance = key + AMBIENT * albedo_of_mu(wo[:, 2])
        n = self.size * self.ss
        full = np.zeros((n, n, 3))
        full[self.mask] = np.nan_to_num(radiance, nan=0.0, posinf=0.0)
        return full.reshape(self.size, self.ss, self.size, self.ss, 3).mean(axis=(1, 3))


def albedo_table(brdf: Brdf, lobes: Sequence[tuple[float, float]]) -> Callable[[np.ndarray], np.ndarray]:
    """A(μ) of `brdf`, integrated on MU_TABLE and interpolated linearly."""
    from cnlmc.bsdf import albedo_mis, dir_from_mu

    table = np.asarray(albedo_mis(brdf, dir_from_mu(MU_TABLE), list(lobes), 1024))
    return lambda mu: np.stack([np.interp(mu, MU_TABLE, table[:, k]) for k in range(3)], axis=-1)


def fit_image(sphere: Sphere, fit: LowCookTorrance) -> np.ndarray:
    alpha = min(max(fit.roughness, 1e-3), 1.0)  # Beckmann m ≈ GGX α for sampling only
    return sphere.render(fit.evaluate, albedo_table(fit.evaluate, [(alpha, alpha)]))


def ours_image(sphere: Sphere, material: dict[str, Any]) -> np.ndarray:
    from cnlmc.bsdf.evaluate import lobe_alphas
    from cnlmc.bsdf.inputs import as_material
    from cnlmc.bsdf.sheen import evaluate_sheened

    m = as_material(material)
    brdf: Brdf = lambda o, i: evaluate_sheened(m, o, i)
    lobes = [(float(np.mean(a[0])), float(np.mean(a[1]))) for a in lobe_alphas(m) if a is not None]
    return sphere.render(brdf, albedo_table(brdf, lobes))


def exposed(image: np.ndarray, coverage: np.ndarray, exposure: str = "mean") -> np.ndarray:
    """Scaled so the sphere's mean luminance is MEAN_LUMINANCE ("mean") or its 99th percentile is
    P99_LUMINANCE ("p99"), clipped, sRGB-encoded (FLIP's LDR input)."""
    luminance = image[coverage > 0.999] @ LUMA
    if exposure == "p99":
        scale = P99_LUMINANCE / max(float(np.percentile(luminance, 99)), 1e-12)
    else:
        scale = MEAN_LUMINANCE / max(float(luminance.mean()), 1e-12)
    scaled = np.clip(image * scale, 0.0, 1.0)
    return np.where(scaled <= 0.0031308, 12.92 * scaled, 1.055 * scaled ** (1 / 2.4) - 0.055)


def flip(reference: np.ndarray, test: np.ndarray, coverage: np.ndarray) -> tuple[float, np.ndarray]:
    """Mean FLIP over the sphere and the magma error map (uint8-ready floats in [0, 1])."""
    import flip_evaluator

    errors, _, _ = flip_evaluator.evaluate(
        reference.astype(np.float32), test.astype(np.float32), "LDR", applyMagma=False
    )
    error = np.asarray(errors, np.float64).reshape(reference.shape[:2])
    inside = coverage > 0.999
    return float(error[inside].mean()), error


def grey(srgb: np.ndarray) -> np.ndarray:
    """The encoded image's luma in all three channels: FLIP on it sees gloss and shading, not hue."""
    return np.repeat((srgb @ LUMA)[..., None], 3, axis=-1)


def magma(error: np.ndarray) -> np.ndarray:
    """A compact magma-like ramp (black → purple → orange → pale yellow) for the error map."""
    stops = np.array([[0.0, 0.0, 0.02], [0.33, 0.07, 0.43], [0.72, 0.21, 0.47], [0.98, 0.56, 0.36], [0.99, 0.99, 0.75]])
    t = np.clip(error, 0.0, 1.0) * (len(stops) - 1)
    i = np.minimum(t.astype(int), len(stops) - 2)
    f = (t - i)[..., None]
    return stops[i] * (1 - f) + stops[i + 1] * f


def rgba8(srgb: np.ndarray) -> np.ndarray:
    out = np.concatenate([np.clip(srgb, 0.0, 1.0), np.ones(srgb.shape[:2] + (1,))], axis=-1)
    return (out * 255 + 0.5).astype(np.uint8)


def score(ref: np.ndarray, ours: np.ndarray, coverage: np.ndarray) -> dict[str, Any]:
    """FLIP of our encoded image against the fit's, in colour and on luma only."""
    value, error_map = flip(ref, ours, coverage)
    return {"flip": value, "flip_grey": flip(grey(ref), grey(ours), coverage)[0], "map": error_map, "ours_png": ours}


def compare_all(data: Path, size: int, exposure: str = "mean", gamut: str = "none") -> list[dict[str, Any]]:
    """Each MERL material's row; with gamut "pointer" also row["pointer"]: the score with our pigment
    colours mapped into Pointer's gamut (bench/surface_gamut.py), and row["mapped"]: whether they moved."""
    fits = parse_low_fits(data / "merl_fits" / cal.FITS["low"])
    sphere = Sphere(size)
    rows = []
    for name in sorted(fits):
        phrase, _ = cal.MERL_PHRASES.get(name, (name.replace("-", " "), False))
        material, error = cal.compile_phrase(phrase)
        row: dict[str, Any] = {"name": name, "phrase": phrase, "error": error}
        if material is not None:
            ref = exposed(fit_image(sphere, fits[name]), sphere.coverage, exposure)
            ours = exposed(ours_image(sphere, material), sphere.coverage, exposure)
            row |= score(ref, ours, sphere.coverage) | {"fit_png": ref}
            if gamut == "pointer":
                row |= pointer_score(sphere, material, ref, ours, exposure)
        rows.append(row)
        scores = f"{cal.fmt(row.get('flip', float('nan'))):>7}{cal.fmt(row.get('flip_grey', float('nan'))):>7}"
        if "pointer" in row:
            moved = "" if row["mapped"] else "  (in gamut)"
            scores += f"{cal.fmt(row['pointer']['flip']):>9}{cal.fmt(row['pointer']['flip_grey']):>7}{moved}"
        print(f"  {name:<26}{phrase:<32}{scores}", flush=True)
    return rows


def pointer_score(
    sphere: Sphere, material: dict[str, Any], ref: np.ndarray, ours: np.ndarray, exposure: str
) -> dict[str, Any]:
    """The row's score with the pigment colours in Pointer's gamut (the same image when none moved)."""
    from surface_gamut import in_surface_gamut

    mapped = in_surface_gamut(material)
    if mapped == material:
        return {"mapped": False, "pointer": score(ref, ours, sphere.coverage)}
    image = exposed(ours_image(sphere, mapped), sphere.coverage, exposure)
    return {"mapped": True, "pointer": score(ref, image, sphere.coverage)}


def write_sheet(rows: list[dict[str, Any]], path: Path) -> None:
    from cnlmc.backends.preview.sheet import label, png_bytes, sheet
    from cnlmc.output import write_atomic

    worst = sorted((r for r in rows if "flip" in r), key=lambda r: -r["flip"])[:10]
    tiles = [
        [
            label(rgba8(r["fit_png"]), f"fit: {r['name']}"),
            label(rgba8(r["ours_png"]), f"ours: {r['phrase']}"),
            label(rgba8(magma(r["map"])), f"FLIP {r['flip']:.3f}"),
        ]
        for r in worst
    ]
    write_atomic(path, png_bytes(sheet(tiles)))
    print(f"wrote {path}")


def write_pointer_sheet(rows: list[dict[str, Any]], path: Path) -> None:
    """fit | ours as compiled | ours in Pointer's gamut | FLIP map of the latter, for the ten materials
    whose FLIP the mapping changed most (better or worse), worst as compiled first."""
    from cnlmc.backends.preview.sheet import label, png_bytes, sheet
    from cnlmc.output import write_atomic

    changed = sorted((r for r in rows if r.get("mapped")), key=lambda r: -abs(r["pointer"]["flip"] - r["flip"]))
    moved = sorted(changed[:10], key=lambda r: -r["flip"])
    tiles = [
        [
            label(rgba8(r["fit_png"]), f"fit: {r['name']}"),
            label(rgba8(r["ours_png"]), f"ours {r['flip']:.3f}"),
            label(rgba8(r["pointer"]["ours_png"]), f"Pointer {r['pointer']['flip']:.3f}"),
            label(rgba8(magma(r["pointer"]["map"])), "FLIP map (Pointer)"),
        ]
        for r in moved
    ]
    write_atomic(path, png_bytes(sheet(tiles)))
    print(f"wrote {path}")


def summarise(title: str, scored: list[dict[str, Any]], total: int) -> None:
    """Median, mean, max, the count within the goal, the luma-only median and the worst ten."""
    scores = [r["flip"] for r in scored]
    median = statistics.median(scores)
    print(
        f"  {title}: compared {len(scores)}/{total}; FLIP median {median:.3f}, mean {statistics.fmean(scores):.3f}, "
        f"max {max(scores):.3f}; <= {GOAL}: {sum(s <= GOAL for s in scores)}; goal median <= {GOAL}: {median <= GOAL}"
    )
    greys = [r["flip_grey"] for r in scored]
    print(f"    FLIP on luma only (gloss and shading, colour removed): median {statistics.median(greys):.3f}")
    worst = sorted(scored, key=lambda r: -r["flip"])[:10]
    print("    worst ten: " + ", ".join(f"{r['name']} {r['flip']:.3f}" for r in worst))


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=cal.DATA, help="the shared data folder (default ../shared/data)")
    ap.add_argument("--size", type=int, default=128, help="image side in pixels (default 128)")
    ap.add_argument("--sheet", type=Path, help="the sheet (default docs/merl_worst10.png; docs/merl_pointer.png)")
    ap.add_argument("--exposure", choices=("mean", "p99"), default="mean", help="the exposure normalisation")
    ap.add_argument(
        "--surface-gamut",
        choices=("none", "pointer"),
        default="none",
        help="pointer: also score our phrases with their pigment colours in Pointer's gamut (bench/surface_gamut.py)",
    )
    ap.add_argument("--no-sheet", action="store_true", help="print the numbers only")
    args = ap.parse_args(argv)
    if not (args.data / "merl_fits").is_dir():
        print(f"error: {args.data / 'merl_fits'} not found; pass --data DIR (the shared data folder)")
        return 2
    columns = "RGB, luma only" + ("; the same in Pointer's gamut" if args.surface_gamut == "pointer" else "")
    print(f"MERL: FLIP (fit | ours, exposure {args.exposure}, LDR, sphere pixels); columns: {columns}")
    rows = compare_all(args.data, args.size, args.exposure, args.surface_gamut)
    scored = [r for r in rows if "flip" in r]
    summarise("as compiled", scored, len(rows))
    if args.surface_gamut == "pointer":
        print(f"  pigment colours moved into Pointer's gamut: {sum(r['mapped'] for r in scored)}/{len(scored)}")
        summarise("in Pointer's gamut", [r["pointer"] | {"name": r["name"]} for r in scored], len(rows))
    if not args.no_sheet:
        if args.surface_gamut == "pointer":
            write_pointer_sheet(rows, args.sheet or ROOT / "docs" / "merl_pointer.png")
        else:
            write_sheet(rows, args.sheet or ROOT / "docs" / "merl_worst10.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
