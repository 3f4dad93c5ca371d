"""Speed vs accuracy of the preview tiers against a converged Mitsuba 3 reference of the same scene.

For every stdlib noun (and a few variants) on the preview sphere in the studio environment:
each tier's frame time (llvmpipe, median of 2 frames) and its error (FLIP mean, RMSE of the
tone-mapped sRGB image) against Mitsuba (`direct` integrator, REF_SPP samples per pixel);
Mitsuba itself at increasing spp for the time/error curve. Then a table of failure cases.

    .venv/bin/python bench/preview_chart.py [--size 256] [--ref-spp 256] [--quick]

Writes docs/preview_chart.png, docs/preview_chart.csv and docs/preview_failures.csv.
"""
from __future__ import annotations

import argparse
import csv
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
VARIANTS = {"anisotropic": "lightly brushed, blue anodized aluminum", "coat": "clear-coated red car paint",
            "rough": "rough iron", "mirror": "mirror chrome"}
TIERS = ("analytic", "splitsum", "mc16", "fis16", "mc64", "fis64")
VARIANT_TIERS = TIERS + ("mc256",)
MITSUBA_SPP = (1, 4, 16, 64)
#: failure case -> (phrase, environment, pixel region)
FAILURES = {
    "grazing angles (silhouette rim)": ("ceramic", "studio", "rim"),
    "roughness 0 / mirror": ("mirror chrome", "studio", "all"),
    "strong anisotropy": ("strongly brushed steel", "studio", "all"),
    "bright small light (sun)": ("blue plastic", "sun", "all"),
}


def tonemap(linear_rgba: np.ndarray, background: float = 0.18) -> np.ndarray:
    """The preview's tone map (tonemap.frag) in numpy, over a constant linear background."""
    a = np.clip(linear_rgba[..., 3:4], 0, 1)
    x = np.maximum(linear_rgba[..., :3], 0) * a + background * (1 - a)
    x = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055).astype(np.float32)


def errors(reference: np.ndarray, test: np.ndarray, mask: np.ndarray | None = None) -> tuple[float, float]:
    import flip_evaluator
    flip_map, mean, _ = flip_evaluator.evaluate(reference, test, "LDR")
    diff2 = np.mean((reference - test) ** 2, axis=2)
    if mask is not None:
        return float(np.asarray(flip_map).reshape(diff2.shape)[mask].mean()), float(np.sqrt(diff2[mask].mean()))
    return float(mean), float(np.sqrt(diff2.mean()))


def rim_mask(alpha: np.ndarray) -> np.ndarray:
    import cv2
    inside = (alpha > 0.5).astype(np.uint8)
    radius = max(2, int(np.sqrt(inside.sum() / np.pi) * 0.12))
    core = cv2.erode(inside, np.ones((2 * radius + 1, 2 * radius + 1), np.uint8))
    return (inside > 0) & (core == 0)


def materials() -> dict[str, dict]:
    from cnlmc.api import compile_source, lexicon_for
    out = {}
    for noun in sorted(lexicon_for().all_of("nouns")):
        out[noun] = compile_source(noun + "\n").ir["materials"][0]
    for label, phrase in VARIANTS.items():
        out[f"{label}: {phrase}"] = compile_source(phrase + "\n").ir["materials"][0]
    return out


def mitsuba_reference(material, scene, size, spp, work: Path, seed=0):
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    path = export_scene(material, scene, work, size, size, spp=spp)
    return render_scene(path, spp=spp, seed=seed)


def run(size: int, ref_spp: int, quick: bool, out_csv: Path) -> list[dict]:
    from cnlmc.backends.preview.render import Renderer, default_scene
    renderer = Renderer(size)
    rows = []
    mats = materials()
    if quick:
        mats = {k: v for i, (k, v) in enumerate(mats.items()) if i % 6 == 0 or ":" in k}
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, ["material", "method", "ms", "flip", "rmse"])
        writer.writeheader()
        for label, material in mats.items():
            scene = default_scene("sphere", "studio", (size, size))
            scene.background = "transparent"
            with tempfile.TemporaryDirectory() as tmp:
                ref, _ = mitsuba_reference(material, scene, size, ref_spp, Path(tmp))
                ref_ldr = tonemap(ref)
                for spp in MITSUBA_SPP:
                    img, seconds = mitsuba_reference(material, scene, size, spp, Path(tmp), seed=1)
                    flip, rmse = errors(ref_ldr, tonemap(img))
                    rows.append({"material": label, "method": f"mitsuba{spp}", "ms": seconds * 1000, "flip": flip, "rmse": rmse})
                    writer.writerow(rows[-1])
            for tier in (VARIANT_TIERS if ":" in label else TIERS):
                frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
                ms = renderer.frame_time(scene, material, tier, repeats=2)
                flip, rmse = errors(ref_ldr, tonemap(frame.hdr))
                rows.append({"material": label, "method": tier, "ms": ms, "flip": flip, "rmse": rmse})
                writer.writerow(rows[-1])
            f.flush()
            print(f"{label:48s} " + " ".join(f"{r['method']}={r['flip']:.3f}" for r in rows if r["material"] == label),
                  flush=True)
    return rows


def failures(size: int, ref_spp: int, out_csv: Path) -> list[dict]:
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer, default_scene
    renderer = Renderer(size)
    rows = []
    for case, (phrase, env, region) in FAILURES.items():
        material = compile_source(phrase + "\n").ir["materials"][0]
        scene = default_scene("sphere", env, (size, size))
        scene.background = "transparent"
        with tempfile.TemporaryDirectory() as tmp:
            ref, _ = mitsuba_reference(material, scene, size, ref_spp, Path(tmp))
        ref_ldr = tonemap(ref)
        mask = rim_mask(ref[..., 3]) if region == "rim" else None
        for tier in VARIANT_TIERS:
            frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
            flip, rmse = errors(ref_ldr, tonemap(frame.hdr), mask)
            rows.append({"case": case, "phrase": phrase, "tier": tier, "flip": flip, "rmse": rmse})
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, ["case", "phrase", "tier", "flip", "rmse"])
        writer.writeheader()
        writer.writerows(rows)
    return rows


def summarise(rows: list[dict]) -> dict[str, tuple[float, float, float]]:
    methods = {}
    for r in rows:
        methods.setdefault(r["method"], []).append(r)
    return {m: (float(np.median([r["ms"] for r in rs])), float(np.mean([r["flip"] for r in rs])),
                float(np.mean([r["rmse"] for r in rs]))) for m, rs in methods.items()}


def plot(summary: dict, rows: list[dict], size: int, ref_spp: int, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, key, index in ((axes[0], "FLIP mean", 1), (axes[1], "RMSE (sRGB)", 2)):
        for method, values in summary.items():
            per = [r for r in rows if r["method"] == method]
            colour = "tab:red" if method.startswith("mitsuba") else "tab:blue"
            ax.scatter([r["ms"] for r in per], [r["flip" if index == 1 else "rmse"] for r in per], s=6, alpha=0.25,
                       color=colour)
            ax.scatter([values[0]], [values[index]], s=60, color=colour, edgecolor="black", zorder=3)
            ax.annotate(method, (values[0], values[index]), textcoords="offset points", xytext=(5, 4), fontsize=8)
        spp = [m for m in summary if m.startswith("mitsuba")]
        ax.plot([summary[m][0] for m in spp], [summary[m][index] for m in spp], color="tab:red", lw=1)
        ax.set_xscale("log")
        ax.set_xlabel(f"frame time, ms ({size}x{size}, llvmpipe / Mitsuba scalar_rgb)")
        ax.set_ylabel(f"{key} vs Mitsuba {ref_spp} spp")
        ax.grid(alpha=0.3)
    fig.suptitle("cnlmc preview tiers: speed vs error (large dots: mean over materials, median time)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def default_tier(summary: dict, budget_ms: float) -> str:
    fits = [(v[1], m) for m, v in summary.items() if not m.startswith("mitsuba") and v[0] <= budget_ms]
    return min(fits)[1] if fits else "analytic"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--ref-spp", type=int, default=256)
    parser.add_argument("--quick", action="store_true", help="every sixth noun plus the variants")
    parser.add_argument("--budget-ms", type=float, default=250.0, help="interactive budget for the default tier")
    args = parser.parse_args(argv)
    docs = ROOT / "docs"
    start = time.time()
    rows = run(args.size, args.ref_spp, args.quick, docs / "preview_chart.csv")
    summary = summarise(rows)
    plot(summary, rows, args.size, args.ref_spp, docs / "preview_chart.png")
    print(f"\n{'method':10s} {'ms (median)':>12s} {'FLIP':>7s} {'RMSE':>7s}")
    for method, (ms, flip, rmse) in sorted(summary.items(), key=lambda kv: kv[1][0]):
        print(f"{method:10s} {ms:12.1f} {flip:7.4f} {rmse:7.4f}")
    choice = default_tier(summary, args.budget_ms)
    print(f"\ndefault tier: {choice} -- the lowest mean FLIP among tiers whose median frame time at "
          f"{args.size}x{args.size} fits {args.budget_ms:.0f} ms on llvmpipe")
    fail = failures(args.size, args.ref_spp, docs / "preview_failures.csv")
    print("\nwhere methods fail (FLIP mean; rim = silhouette ring only):")
    cases = list(dict.fromkeys(r["case"] for r in fail))
    print(f"{'case':34s} " + " ".join(f"{t:>8s}" for t in VARIANT_TIERS) + "  copes")
    for case in cases:
        per = {r["tier"]: r["flip"] for r in fail if r["case"] == case}
        cheapest_ok = next((t for t in VARIANT_TIERS if per[t] <= 1.25 * min(per.values())), "")
        print(f"{case:34s} " + " ".join(f"{per[t]:8.4f}" for t in VARIANT_TIERS) + f"  {cheapest_ok}")
    print(f"\n({time.time() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
