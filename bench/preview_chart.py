"""Speed vs accuracy of the preview tiers against a converged Mitsuba 3 reference of the same scene.

For every stdlib noun (and a few variants) on the preview sphere in the studio environment:
each tier's frame time (llvmpipe, median of 2 frames, at --size and at 512x512, the size the
chart plots and the speed-up goal uses; Mitsuba timed at both sizes too) and its error (FLIP
mean, RMSE of the tone-mapped sRGB image) against Mitsuba (`direct` integrator, REF_SPP samples
per pixel, llvm_ad_rgb) rendering the same material with cnlmc's own BSDF (the `cnlm` plugin,
backends/exchange/mitsuba_cnlm.py; glass: native roughdielectric, its exact match). Mitsuba itself at
increasing spp with its native plugins (what a Mitsuba user renders; warm, timed) against its
own converged native render gives the time/error curve; the row `native_model` is the distance
between Mitsuba's native approximation and cnlmc's model (the Mitsuba backend's fidelity).
Then a table of failure cases.

    .venv/bin/python bench/preview_chart.py [--size 256] [--ref-spp 256] [--quick]

Writes docs/preview_chart.png, docs/preview_chart.csv and docs/preview_failures.csv.
"""

from __future__ import annotations

import argparse
import csv
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
#: the chart's nouns and variants (label -> phrase): data, bench/data/preview_chart.toml
CHART_MATERIALS = ROOT / "bench" / "data" / "preview_chart.toml"
TIERS = ("analytic", "splitsum", "mc16", "fis16", "mc64", "fis64")
VARIANT_TIERS = TIERS + ("mc256",)
MITSUBA_SPP = (1, 4, 16, 64)
#: the issue's frame size for times: every method is also timed at 512x512 (column ms512);
#: errors are measured at --size (the converged reference at 512^2 would take 2 hours).
TIMING_SIZE = 512
#: failure case -> (phrase, environment, pixel region)
FAILURES = {
    "grazing angles, dielectric (rim)": ("ceramic", "studio", "rim"),
    "grazing angles, metal (rim)": ("gold", "studio", "rim"),
    "roughness 0 / mirror": ("mirror chrome", "studio", "all"),
    "strong anisotropy": ("strongly brushed steel", "studio", "all"),
    "bright small light (sun)": ("blue plastic", "sun", "all"),
    "rough transmission (frosted)": ("frosted glass", "studio", "all"),
    "flake sparkle (metallic paint)": ("metallic car paint", "studio", "all"),
}


def tonemap(linear_rgba: np.ndarray, background: float = 0.18) -> np.ndarray:
    """The preview's tone map (tonemap.frag) in numpy, over a constant linear background. Both
    renderers' colour is premultiplied by coverage (Mitsuba's film and the preview's target:
    zero where nothing was drawn), so the background is added under the uncovered part only."""
    a = np.clip(linear_rgba[..., 3:4], 0, 1)
    x = np.maximum(linear_rgba[..., :3], 0) + background * (1 - a)
    x = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055).astype(np.float32)


def errors(reference: np.ndarray, test: np.ndarray, mask: np.ndarray | None = None) -> tuple[float, float]:
    import flip_evaluator

    flip_map, mean, _ = flip_evaluator.evaluate(reference, test, "LDR", applyMagma=False)
    diff2 = np.mean((reference - test) ** 2, axis=2)
    if mask is not None:
        return float(np.asarray(flip_map).reshape(diff2.shape)[mask].mean()), float(np.sqrt(diff2[mask].mean()))
    return float(mean), float(np.sqrt(diff2.mean()))


def rim_mask(alpha: np.ndarray) -> np.ndarray:
    """The grazing ring: inside the silhouette, outside 88 % of the radius, without the 2 pixels
    at the silhouette itself (whose error is the anti-aliasing, not the shading)."""
    import cv2

    inside = (alpha > 0.5).astype(np.uint8)
    radius = max(2, int(np.sqrt(inside.sum() / np.pi) * 0.12))
    core = cv2.erode(inside, np.ones((2 * radius + 1, 2 * radius + 1), np.uint8))
    shell = cv2.erode(inside, np.ones((5, 5), np.uint8))
    return (shell > 0) & (core == 0)


def chart_materials() -> tuple[list[str], dict[str, str]]:
    """(nouns, variants label -> phrase) of the chart (bench/data/preview_chart.toml)."""
    with open(CHART_MATERIALS, "rb") as f:
        data = tomllib.load(f)
    return list(data["nouns"]), dict(data["variants"])


def materials() -> dict[str, dict]:
    from cnlmc.api import compile_source, lexicon_for

    nouns, variants = chart_materials()
    known = set(lexicon_for().all_of("nouns"))
    out = {}  # the variants first: a run cut short still has the rows
    for label, phrase in variants.items():
        out[f"{label}: {phrase}"] = compile_source(phrase + "\n").ir["materials"][0]
    for noun in sorted(n for n in nouns if n in known):
        out[noun] = compile_source(noun + "\n").ir["materials"][0]
    return out


def mitsuba_render(material, scene, size, spp, work: Path, seed=0, bsdf="native", warm=False):
    """(linear RGBA, seconds) of the preview scene in Mitsuba (llvm_ad_rgb); the cnlm plugin
    renders in chunks of CNLM_CHUNK spp (bounded memory: it runs on numpy), averaged."""
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene

    path = export_scene(material, scene, work / bsdf, size, size, spp=spp, bsdf=bsdf)
    image, seconds = 0.0, 0.0
    for index, chunk in enumerate(spp_chunks(spp, CNLM_CHUNK if bsdf == "cnlm" else spp)):
        part, t = render_scene(path, spp=chunk, seed=seed * 1000 + index, variant="vectorized", warm=warm)
        image, seconds = image + part * (chunk / spp), seconds + t
    return image, seconds


#: spp per cnlm-plugin render: a square power of two, which the exported ldsampler needs
#: (it rounds any other count up: 32 would render 64).
CNLM_CHUNK = 16


def spp_chunks(spp: int, chunk: int = CNLM_CHUNK) -> list[int]:
    return [chunk] * (spp // chunk) + ([spp % chunk] if spp % chunk else [])


def mitsuba_reference(material, scene, size, spp, work: Path, seed=0):
    """The converged reference: cnlmc's BSDF in Mitsuba."""
    return mitsuba_render(material, scene, size, spp, work, seed, bsdf="cnlm")


FIELDS = ["material", "method", "ms", "ms512", "flip", "rmse", "run"]


def run(
    size: int,
    ref_spp: int,
    quick: bool,
    out_csv: Path,
    out_png: Path | None = None,
    times_from: Path | None = None,
    reverse: bool = False,
    glass_spp: int | None = None,
    skip: int = 0,
    curves: bool = True,
    only: int | None = None,
    glass: str = "all",
) -> list[dict]:
    """Measure every chart material. `times_from` (a previous chart's CSV): measure only the
    errors of the tiers against the reference, and take the frame times, Mitsuba's spp curve and
    the native_model row from that run (column `run`: "now" or that file's name) -- for a
    machine too loaded for timings to mean anything."""
    from cnlmc.backends.preview.render import Renderer, default_scene

    renderer = Renderer(size)
    renderer512 = None  # made when something is timed
    earlier = read_rows(times_from) if times_from else []
    rows = []
    mats = materials()
    mats = dict(list(mats.items())[skip : None if only is None else skip + only])
    if reverse:  # a second process from the other end (--reverse --csv ...; then --merge)
        mats = dict(reversed(list(mats.items())))
    if quick:
        mats = {k: v for i, (k, v) in enumerate(mats.items()) if i % 6 == 0 or ":" in k}
    if glass != "all":  # a part for the glass rows alone, or all but them (--glass; then --merge)
        mats = {k: v for k, v in mats.items() if (v["model"]["base"] == "glass") == (glass == "only")}
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, FIELDS)
        writer.writeheader()
        for label, material in mats.items():
            if material["model"].get("subsurface"):  # the translucent class: bench/preview_chart_translucent.py
                continue
            scene = default_scene("sphere", "studio", (size, size))
            scene.background = "transparent"
            with tempfile.TemporaryDirectory() as tmp:
                spp = glass_spp if glass_spp and material["model"]["base"] == "glass" else ref_spp
                ref, _ = mitsuba_reference(material, scene, size, spp, Path(tmp))
                ref_ldr = tonemap(ref)
                before = [r for r in earlier if r["material"] == label]
                if before and times_from:
                    new = [dict(r, run=r.get("run") or times_from.name) for r in before if not _is_tier(r["method"])]
                else:  # measured now (a material the earlier run did not have, too)
                    new = mitsuba_curve(label, material, scene, size, ref_spp, ref_ldr, Path(tmp)) if curves else []
                    renderer512 = renderer512 or Renderer(TIMING_SIZE)
            for row in new:
                rows.append(row)
                writer.writerow(row)
            for tier in VARIANT_TIERS if ":" in label else TIERS:
                frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
                flip, rmse = errors(ref_ldr, tonemap(frame.hdr))
                ms, ms512 = tier_times(renderer, renderer512 if not before else None, scene, material, tier, before)
                rows.append(
                    {
                        "material": label,
                        "method": tier,
                        "ms": ms,
                        "ms512": ms512,
                        "flip": flip,
                        "rmse": rmse,
                        "run": "now",
                    }
                )
                writer.writerow(rows[-1])
            f.flush()
            print(
                f"{label:48s} " + " ".join(f"{r['method']}={r['flip']:.3f}" for r in rows if r["material"] == label),
                flush=True,
            )
            if out_png is not None:  # a partial run still leaves a chart
                plot(summarise(rows), rows, size, ref_spp, out_png)
    return rows


def _is_tier(method: str) -> bool:
    return method in VARIANT_TIERS


def tier_times(renderer, renderer512, scene, material, tier, before: list[dict]) -> tuple[float, float]:
    """(ms at the chart's size, ms at 512^2): measured (median of 2 warm frames) when renderer512
    is given, else the earlier run's (`before`: its rows of this material)."""
    if renderer512 is None:
        old = next((r for r in before if r["method"] == tier), None)
        return (old["ms"], old["ms512"]) if old else (0.0, 0.0)
    from cnlmc.backends.preview.render import default_scene

    big = default_scene("sphere", "studio", (TIMING_SIZE, TIMING_SIZE))
    big.background = "transparent"
    return renderer.frame_time(scene, material, tier, repeats=2), renderer512.frame_time(big, material, tier, repeats=2)


def mitsuba_curve(label, material, scene, size, ref_spp, ref_ldr, work: Path) -> list[dict]:
    """The native_model row and Mitsuba's own time/error curve (native plugins, 1..64 spp,
    against its converged native render; timed warm at size and at 512^2)."""
    from cnlmc.backends.preview.render import default_scene

    big = default_scene("sphere", "studio", (TIMING_SIZE, TIMING_SIZE))
    big.background = "transparent"
    native_ref, _ = mitsuba_render(material, scene, size, ref_spp, work, seed=7)
    native_ldr = tonemap(native_ref)
    flip, rmse = errors(ref_ldr, native_ldr)
    rows = [
        {"material": label, "method": NATIVE_MODEL, "ms": 0.0, "ms512": 0.0, "flip": flip, "rmse": rmse, "run": "now"}
    ]
    for spp in MITSUBA_SPP:
        img, seconds = mitsuba_render(material, scene, size, spp, work, seed=1, warm=True)
        _, seconds512 = mitsuba_render(material, big, TIMING_SIZE, spp, work / "big", seed=1, warm=True)
        flip, rmse = errors(native_ldr, tonemap(img))
        rows.append(
            {
                "material": label,
                "method": f"mitsuba{spp}",
                "ms": seconds * 1000,
                "ms512": seconds512 * 1000,
                "flip": flip,
                "rmse": rmse,
                "run": "now",
            }
        )
    return rows


SELF_REFERENCE = "mc1024"
NATIVE_MODEL = "native_model"


def failures(size: int, ref_spp: int, out_csv: Path) -> list[dict]:
    """Each failure case against Mitsuba (`flip`, `rmse`) and against the preview's own
    converged tier mc1024 (`flip_self`): the second isolates the tier's approximation from the
    model differences between cnlm_bsdf and Mitsuba's plugins."""
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
        own = tonemap(renderer.render(material, tier=SELF_REFERENCE, scene=scene, hdr=True).hdr)
        for tier in VARIANT_TIERS:
            test = tonemap(renderer.render(material, tier=tier, scene=scene, hdr=True).hdr)
            flip, rmse = errors(ref_ldr, test, mask)
            flip_self, _ = errors(own, test, mask)
            rows.append(
                {"case": case, "phrase": phrase, "tier": tier, "flip": flip, "rmse": rmse, "flip_self": flip_self}
            )
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, ["case", "phrase", "tier", "flip", "rmse", "flip_self"])
        writer.writeheader()
        writer.writerows(rows)
    return rows


REALTIME = ("analytic", "splitsum")


def material_class(material: dict) -> str:
    model = material["model"]
    if model.get("subsurface"):
        return "translucent"
    if model["base"] == "glass":  # the goal for glass, frosted glass and water: FLIP <= 0.05
        return "transparent"
    if model.get("coat"):
        return "coated"
    if model.get("anisotropic"):
        return "anisotropic"
    if material.get("maps"):
        return "textured"
    return {"diffuse": "diffuse", "conductor": "metal"}.get(model["base"], "dielectric")


def equal_error_ms(rows: list[dict], flip: float, time_key: str = "ms") -> float:
    """Mitsuba's time for this error: log-log interpolation along its spp curve (extrapolated
    with error ~ 1/sqrt(spp) below the 64-spp error); `time_key` "ms512": its times at 512^2."""
    curve = sorted(((r[time_key], r["flip"]) for r in rows if r["method"].startswith("mitsuba")), key=lambda c: c[0])
    if not curve:  # a material the earlier run (--times-from) did not have
        return float("nan")
    for (t0, e0), (t1, e1) in zip(curve, curve[1:]):
        if e1 <= flip <= e0:
            w = np.log(e0 / flip) / np.log(e0 / e1) if e0 > e1 else 0.0
            return float(np.exp(np.log(t0) + w * np.log(t1 / t0)))
    if flip > curve[0][1]:
        return curve[0][0]
    return curve[-1][0] * (curve[-1][1] / flip) ** 2


def goals(rows: list[dict], classes: dict[str, str]) -> list[dict]:
    """Per material: the best real-time tier, its FLIP, the goal (0.02 for untextured smooth and
    rough isotropic materials, else 0.05), Mitsuba's time for the same error and the speed-up."""
    out = []
    for label in dict.fromkeys(r["material"] for r in rows):
        per = [r for r in rows if r["material"] == label]
        best = min((r for r in per if r["method"] in REALTIME), key=lambda r: r["flip"])
        cls = classes.get(label, "?")
        limit = 0.02 if cls in ("dielectric", "metal", "diffuse") else 0.05
        mitsuba_ms = equal_error_ms(per, best["flip"])
        timed512 = all(r.get("ms512", 0.0) > 0 for r in per if r["method"].startswith("mitsuba")) and best["ms512"] > 0
        mitsuba_ms512 = equal_error_ms(per, best["flip"], "ms512") if timed512 else float("nan")
        native = next((r["flip"] for r in per if r["method"] == NATIVE_MODEL), float("nan"))
        out.append(
            {
                "material": label,
                "class": cls,
                "tier": best["method"],
                "flip": best["flip"],
                "goal": limit,
                "met": best["flip"] <= limit,
                "ms": best["ms"],
                "ms512": best.get("ms512", 0.0),
                "mitsuba_ms": mitsuba_ms,
                "speedup": mitsuba_ms / best["ms"] if best["ms"] > 0 else float("nan"),
                "mitsuba_ms512": mitsuba_ms512,
                "speedup512": mitsuba_ms512 / best["ms512"] if timed512 else float("nan"),
                "native_model": native,
            }
        )
    return out


def print_goals(table: list[dict]) -> None:
    print(
        f"\n{'material':48s} {'class':12s} {'tier':9s} {'FLIP':>6s} {'goal':>5s} {'ms':>6s} {'Mitsuba':>8s} "
        f"{'x':>6s} {'ms512':>6s} {'Mitsuba512':>10s} {'x512':>6s} {'native':>6s}"
    )
    for g in table:
        print(
            f"{g['material']:48s} {g['class']:12s} {g['tier']:9s} {g['flip']:6.3f} {g['goal']:5.2f} {g['ms']:6.1f} "
            f"{g['mitsuba_ms']:8.0f} {g['speedup']:6.1f} {g['ms512']:6.1f} {g['mitsuba_ms512']:10.0f} "
            f"{g['speedup512']:6.1f} {g['native_model']:6.3f}{'' if g['met'] else '  (FLIP goal missed)'}"
        )
    by = {}
    for g in table:
        by.setdefault(g["class"], []).append(g)
    print("\nclass        n  FLIP goal met  median speed-up 256^2 / 512^2  >= 100x at 512^2  tiers")
    for cls, gs in sorted(by.items()):
        tiers = ", ".join(f"{t} {sum(g['tier'] == t for g in gs)}" for t in REALTIME if any(g["tier"] == t for g in gs))
        print(
            f"{cls:12s} {len(gs):2d}  {sum(g['met'] for g in gs):2d}/{len(gs):<2d}          "
            f"{np.nanmedian([g['speedup'] for g in gs]):8.1f} / {np.nanmedian([g['speedup512'] for g in gs]):6.1f}"
            f"          {sum(g['speedup512'] >= 100 for g in gs):2d}/{len(gs):<2d}        {tiers}"
        )


def merge(parts: list[Path], out_csv: Path) -> None:
    """One chart CSV from runs that measured parts of it (a material's rows from the first part
    that has all its tiers), in the chart's material order."""
    found: dict[str, list[dict]] = {}
    for part in parts:
        with open(part) as f:
            rows = list(csv.DictReader(f))
        for label in dict.fromkeys(r["material"] for r in rows):
            mine = [r for r in rows if r["material"] == label]
            if label not in found and {"analytic", "splitsum", "fis64"} <= {r["method"] for r in mine}:
                found[label] = mine
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, FIELDS)
        writer.writeheader()
        for label in materials():
            writer.writerows(found.get(label, []))


def read_rows(path: Path) -> list[dict]:
    with open(path) as f:
        return [
            dict(r, ms=float(r["ms"]), ms512=float(r.get("ms512") or 0.0), flip=float(r["flip"]), rmse=float(r["rmse"]))
            for r in csv.DictReader(f)
        ]


def print_failures(fail: list[dict]) -> None:
    print(f"\nwhere methods fail (FLIP mean vs Mitsuba / vs the preview's {SELF_REFERENCE}; rim = grazing ring only):")
    cases = list(dict.fromkeys(r["case"] for r in fail))
    print(f"{'case':34s} " + " ".join(f"{t:>13s}" for t in VARIANT_TIERS) + "  copes")
    for case in cases:
        per = {r["tier"]: r for r in fail if r["case"] == case}
        best = min(r["flip"] for r in per.values())
        cheapest_ok = next((t for t in VARIANT_TIERS if per[t]["flip"] <= 1.25 * best), "")
        print(
            f"{case:34s} "
            + " ".join(f"{per[t]['flip']:6.3f}/{per[t]['flip_self']:6.3f}" for t in VARIANT_TIERS)
            + f"  {cheapest_ok}"
        )


def time_key(rows: list[dict]) -> str:
    """ "ms512" when every method was timed at 512^2 (the issue's frame size), else "ms"."""
    timed = [r for r in rows if r["method"] != NATIVE_MODEL and np.isfinite(r.get("ms512", 0.0))]  # nan: untimed
    return "ms512" if timed and all(r.get("ms512", 0.0) > 0 for r in timed) else "ms"


def summarise(rows: list[dict]) -> dict[str, tuple[float, float, float]]:
    """method -> (median time at the chart's timing size, mean FLIP, mean RMSE)."""
    key = time_key(rows)
    methods = {}
    for r in rows:
        if r["method"] != NATIVE_MODEL:
            methods.setdefault(r["method"], []).append(r)
    return {
        m: (
            float(np.nanmedian([r[key] for r in rs])),
            float(np.mean([r["flip"] for r in rs])),
            float(np.mean([r["rmse"] for r in rs])),
        )
        for m, rs in methods.items()
    }


TIER_STYLE = {
    "analytic": ("tab:gray", "v"),
    "splitsum": ("tab:blue", "o"),
    "mc16": ("tab:orange", "s"),
    "fis16": ("tab:green", "D"),
    "mc64": ("tab:purple", "s"),
    "fis64": ("tab:olive", "D"),
    "mc256": ("tab:brown", "P"),
}


def plot(summary: dict, rows: list[dict], size: int, ref_spp: int, path: Path) -> None:
    """Time (log x) against error: one marker style per tier (small: per material, large: mean
    error at the median time), Mitsuba at 1...64 spp as a red line."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    timing = time_key(rows)
    timed_at = TIMING_SIZE if timing == "ms512" else size
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    for ax, key, index in ((axes[0], "flip", 1), (axes[1], "rmse", 2)):
        for method, values in summary.items():
            per = [r for r in rows if r["method"] == method]
            mitsuba = method.startswith("mitsuba")
            colour, marker = ("tab:red", "x") if mitsuba else TIER_STYLE.get(method, ("black", "o"))
            ax.scatter([r[timing] for r in per], [r[key] for r in per], s=10, alpha=0.3, color=colour, marker=marker)
            ax.scatter(
                [values[0]],
                [values[index]],
                s=90,
                color=colour,
                marker=marker if not mitsuba else "o",
                edgecolor="black",
                zorder=3,
                label=None if mitsuba else method,
            )
            ax.annotate(method, (values[0], values[index]), textcoords="offset points", xytext=(6, 5), fontsize=8)
        spp = sorted((m for m in summary if m.startswith("mitsuba")), key=lambda m: int(m[7:]))
        ax.plot(
            [summary[m][0] for m in spp],
            [summary[m][index] for m in spp],
            color="tab:red",
            lw=1.5,
            label="Mitsuba 1-64 spp",
        )
        if key == "flip":
            ax.axhline(0.05, color="black", lw=0.8, ls="--")
            ax.axhline(0.02, color="black", lw=0.8, ls=":")
        ax.set_xscale("log")
        ax.set_ylim(bottom=0)
        ax.set_xlabel(f"ms per {timed_at}² frame, log (llvmpipe; Mitsuba llvm_ad_rgb); errors at {size}²")
        ax.set_ylabel(("FLIP mean" if key == "flip" else "RMSE, tone-mapped sRGB") + " vs the Mitsuba reference")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8, loc="upper right")
    materials = len({r["material"] for r in rows})
    fig.suptitle(
        f"cnlmc preview tiers vs Mitsuba: {materials} materials (small: per material; large: mean error, "
        "median time; dashed: FLIP 0.05, dotted: 0.02)\ntiers against Mitsuba rendering the complete material (cnlm "
        "plugin: layers, sheen, flakes; glass path-traced, rough glass compensated);\nMitsuba's curve against its "
        "own converged native render",
        fontsize=10,
    )
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def default_tier(summary: dict, budget_ms: float) -> str:
    fits = [(v[1], m) for m, v in summary.items() if not m.startswith("mitsuba") and v[0] <= budget_ms]
    return min(fits)[1] if fits else "analytic"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--ref-spp", type=int, default=256)
    parser.add_argument("--quick", action="store_true", help="every sixth noun plus the variants")
    parser.add_argument("--budget-ms", type=float, default=33.3, help="interactive budget for the default tier")
    parser.add_argument("--failures-only", action="store_true", help="only the failure cases")
    parser.add_argument("--skip-failures", action="store_true", help="no failure cases")
    parser.add_argument("--from-csv", action="store_true", help="re-plot and summarise docs/preview_chart.csv")
    parser.add_argument(
        "--times-from",
        type=Path,
        default=None,
        help="measure errors only; frame times, Mitsuba's curve and native_model from this earlier chart CSV",
    )
    parser.add_argument(
        "--translucent", action="store_true", help="the translucent class (preview_chart_translucent.py)"
    )
    parser.add_argument("--csv", type=Path, default=None, help="write the chart's rows here (default docs/)")
    parser.add_argument("--reverse", action="store_true", help="measure the materials last to first")
    parser.add_argument("--glass-spp", type=int, default=None, help="the reference's spp for glass (path traced)")
    parser.add_argument("--no-curves", action="store_true", help="no Mitsuba spp curve where none is taken over")
    parser.add_argument("--only", type=int, default=None, help="measure only ONLY materials (after --skip)")
    parser.add_argument(
        "--skip", type=int, default=0, help="leave out the first SKIP materials (another part has them)"
    )
    parser.add_argument(
        "--glass", choices=("all", "only", "none"), default="all", help="measure only the glass rows, or all but them"
    )
    parser.add_argument("--merge", type=Path, nargs="+", default=None, help="merge part CSVs into docs/ and plot")
    args = parser.parse_args(argv)
    if args.translucent:
        from preview_chart_translucent import main as translucent_main

        return translucent_main([])
    docs = ROOT / "docs"
    start = time.time()
    if args.merge:
        merge(args.merge, docs / "preview_chart.csv")
        args.from_csv = True
    if args.from_csv:
        rows = read_rows(docs / "preview_chart.csv")
        plot(summarise(rows), rows, args.size, args.ref_spp, docs / "preview_chart.png")
        print_goals(goals(rows, {k: material_class(m) for k, m in materials().items()}))
        return 0
    if not args.skip_failures:
        print_failures(failures(args.size, args.ref_spp, docs / "preview_failures.csv"))
    if args.failures_only:
        return 0
    out_csv = args.csv or docs / "preview_chart.csv"
    out_png = docs / "preview_chart.png" if args.csv is None else None
    rows = run(
        args.size,
        args.ref_spp,
        args.quick,
        out_csv,
        out_png,
        args.times_from,
        args.reverse,
        args.glass_spp,
        args.skip,
        not args.no_curves,
        args.only,
        args.glass,
    )
    if args.csv is not None:  # a part: --merge plots the whole
        return 0
    summary = summarise(rows)
    plot(summary, rows, args.size, args.ref_spp, docs / "preview_chart.png")
    timed_at = TIMING_SIZE if time_key(rows) == "ms512" else args.size
    print(
        f"\n{'method':10s} {f'ms {timed_at}^2':>12s} {'FLIP':>7s} {'RMSE':>7s}   (median time, mean error at {args.size}^2)"
    )
    for method, (ms, flip, rmse) in sorted(summary.items(), key=lambda kv: kv[1][0]):
        print(f"{method:10s} {ms:12.1f} {flip:7.4f} {rmse:7.4f}")
    print_goals(goals(rows, {k: material_class(m) for k, m in materials().items()}))
    choice = default_tier(summary, args.budget_ms)
    print(
        f"\ndefault tier: {choice} -- the lowest mean FLIP among tiers whose median frame time at "
        f"{timed_at}x{timed_at} fits {args.budget_ms:.0f} ms on llvmpipe"
    )
    print(f"\n({time.time() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
