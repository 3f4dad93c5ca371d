"""The preview chart's timing on a GPU (issue #15): the speed-up of the preview over Mitsuba at
equal error, where both run on the same GPU.

Two steps, because the chart's errors need the `cnlm` reference (numpy, hours on a CPU) and the
timing needs the GPU:

    measure (on the GPU machine; EGL on its driver, Mitsuba's cuda_ad_rgb):
        python bench/preview_chart_gpu.py measure --out DIR [--budget-s 330] [--variant cuda_ad_rgb]
    report (here; reads the measured CSV and the CPU chart's errors, docs/preview_chart.csv):
        .venv/bin/python bench/preview_chart_gpu.py report DIR [DIR ...]

`measure` writes DIR/gpu_times.csv (every chart material: each preview tier's frame time at 512²,
median of --repeats warm frames after a warm-up, `ctx.finish()` included; Mitsuba's native render
at 1, 4, 16, 64 spp at 512², timed warm, and its error at the chart's error size against its own
converged native render, measured there as on the CPU), DIR/gpu_frames.npz (each material's
`splitsum` frame and Mitsuba's 64-spp image at the error size: `report` checks that the GPU draws
what llvmpipe and the LLVM variant draw, so the CPU chart's errors hold for the GPU frames) and
DIR/gpu_device.txt (the GL renderer, the Mitsuba variant, the time it took). The real-time tiers
and Mitsuba's curve are measured for every material first; the sampled tiers follow while
--budget-s lasts (the CSV is written as it goes: a run cut short keeps what it measured).

`report` prints the speed-up at equal error per material and class (the CPU chart's method:
the best real-time tier's FLIP, Mitsuba's time for that FLIP along its spp curve, log-log) and
writes docs/preview_chart_gpu.csv. Both speed-ups, on the GPU and on the CPU (the chart's times),
use the curve's errors measured here at the tiers' error size (128²): the CPU chart's curve was
measured at 256², where the same render's FLIP is lower (about half at 4 spp).
"""

from __future__ import annotations

import argparse
import csv
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from preview_chart import (  # bench/ is not a package: found through sys.path above
    MITSUBA_SPP,
    NATIVE_MODEL,
    REALTIME,
    TIERS,
    TIMING_SIZE,
    VARIANT_TIERS,
    equal_error_ms,
    errors,
    material_class,
    materials,
    read_rows,
    tonemap,
)

ROOT = Path(__file__).resolve().parents[1]
FIELDS = ["material", "method", "ms512", "flip"]
#: the CPU chart's error size and its Mitsuba curve's converged native render (spp, seed)
ERROR_SIZE = 128
NATIVE_REF = (256, 7)
CURVE_SEED = 1


def chart() -> dict[str, dict]:
    """The chart's materials (the translucent class has its own chart)."""
    return {k: v for k, v in materials().items() if not v["model"].get("subsurface")}


def tiers_of(label: str) -> tuple[str, ...]:
    return VARIANT_TIERS if ":" in label else TIERS


# --- measure (on the GPU machine) -----------------------------------------------------------


class Log:
    """The CSV rows and the device notes, written as they come."""

    def __init__(self, out: Path):
        out.mkdir(parents=True, exist_ok=True)
        self.out = out
        self.file = open(out / "gpu_times.csv", "w", newline="")
        self.writer = csv.DictWriter(self.file, FIELDS)
        self.writer.writeheader()
        self.notes: list[str] = []

    def row(self, material: str, method: str, ms512: float, flip: float = float("nan")) -> None:
        self.writer.writerow({"material": material, "method": method, "ms512": ms512, "flip": flip})
        self.file.flush()

    def note(self, text: str) -> None:
        print(text, flush=True)
        self.notes.append(text)
        (self.out / "gpu_device.txt").write_text("\n".join(self.notes) + "\n")


def open_preview(log: Log):
    """(renderer at 512², renderer at the error size sharing its context) or None."""
    try:
        from cnlmc.backends.preview.render import Renderer

        big = Renderer(TIMING_SIZE)
        small = Renderer(ERROR_SIZE, resources=big.resources)
        info = big.ctx.info
        log.note(f"GL: {info.get('GL_RENDERER')} / {info.get('GL_VERSION')} ({info.get('GL_VENDOR')})")
        return big, small
    except Exception as exc:  # the report says what could not be measured
        log.note(f"GL: unavailable ({exc})")
        return None


def scenes():
    from cnlmc.backends.preview.render import default_scene

    out = {}
    for size in (TIMING_SIZE, ERROR_SIZE):
        scene = default_scene("sphere", "studio", (size, size))
        scene.background = "transparent"
        out[size] = scene
    return out


def time_tiers(log: Log, renderers, scene, label: str, material: dict, tiers, repeats: int, gpu_time: bool) -> None:
    """Each tier's frame time (wall clock, `ctx.finish()` included: what a caller waits); with
    `gpu_time`, also the GPU's own time of the frame's passes (a GL timer query), row `TIER:gpu`."""
    big, _ = renderers
    for tier in tiers:
        log.row(label, tier, big.frame_time(scene, material, tier, repeats=repeats))
        if gpu_time:
            log.row(label, f"{tier}{GPU_SIDE}", gpu_frame_time(big, scene, material, tier, repeats))


GPU_SIDE = ":gpu"


def gpu_frame_time(renderer, scene, material: dict, tier: str, repeats: int) -> float:
    """Median GPU time (ms) of one warm frame's draw calls, by a GL_TIME_ELAPSED query."""
    query = renderer.ctx.query(time=True)
    times = []
    for _ in range(repeats):
        with query:
            renderer.draw(scene, material, tier, None)
        times.append(query.elapsed / 1e6)
    return float(np.median(times))


def mitsuba_curve(log: Log, variant: str, material: dict, label: str, scene_of, work: Path) -> np.ndarray:
    """Mitsuba's native render at each spp: the time at 512² (warm) and the error at the error
    size against its converged native render; returns the 64-spp image at the error size."""
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene, sampler_for

    exported: dict[tuple[int, str], Path] = {}  # one export (textures baked once) per size and sampler

    def render(size: int, spp: int, seed: int, warm: bool):
        key = (size, sampler_for(spp))
        if key not in exported:
            exported[key] = export_scene(material, scene_of[size], work / f"{size}_{key[1]}", size, size, spp=spp)
        return render_scene(exported[key], spp=spp, seed=seed, variant=variant, warm=warm)

    reference, _ = render(ERROR_SIZE, NATIVE_REF[0], NATIVE_REF[1], False)
    reference_ldr = tonemap(reference)
    image = reference
    for spp in MITSUBA_SPP:
        _, seconds = render(TIMING_SIZE, spp, CURVE_SEED, True)
        image, _ = render(ERROR_SIZE, spp, CURVE_SEED, False)
        log.row(label, f"mitsuba{spp}", seconds * 1000.0, errors(reference_ldr, tonemap(image))[0])
    return image


def measure(out: Path, budget_s: float, repeats: int, variant: str, quick: bool, gpu_time: bool, skip: int) -> int:
    start = time.perf_counter()
    log = Log(out)
    renderers = open_preview(log)
    mats = dict(list(chart().items())[skip:])
    if quick:
        mats = {k: v for i, (k, v) in enumerate(mats.items()) if i % 6 == 0 or ":" in k}
    scene_of = scenes()
    mitsuba_ok = variant != "none" and check_mitsuba(log, variant)
    frames: dict[str, np.ndarray] = {}
    for label, material in mats.items():  # first: what the speed-up needs, for every material
        if renderers:
            time_tiers(log, renderers, scene_of[TIMING_SIZE], label, material, REALTIME, repeats, gpu_time)
            frame = renderers[1].render(material, tier="splitsum", scene=scene_of[ERROR_SIZE], hdr=True).hdr
            frames[f"splitsum/{label}"] = np.asarray(frame, np.float16)
        if mitsuba_ok:
            with tempfile.TemporaryDirectory() as tmp:
                image = mitsuba_curve(log, variant, material, label, scene_of, Path(tmp))
            frames[f"mitsuba64/{label}"] = np.asarray(image, np.float16)
        print(f"{time.perf_counter() - start:6.0f} s  {label}", flush=True)
        if time.perf_counter() - start > budget_s:
            log.note(f"stopped at the budget ({budget_s:.0f} s) after {label}")
            break
    np.savez_compressed(out / "gpu_frames.npz", **frames)
    log.note(f"real-time tiers and Mitsuba: {time.perf_counter() - start:.0f} s")
    for label, material in mats.items() if renderers else ():  # then the sampled tiers, while time lasts
        if time.perf_counter() - start > budget_s:
            log.note(f"sampled tiers stopped at the budget before {label}")
            break
        sampled = [t for t in tiers_of(label) if t not in REALTIME]
        time_tiers(log, renderers, scene_of[TIMING_SIZE], label, material, sampled, repeats, gpu_time)
    log.note(f"done in {time.perf_counter() - start:.0f} s")
    return 0


def check_mitsuba(log: Log, variant: str) -> bool:
    try:
        import drjit as dr
        import mitsuba as mi

        if variant.startswith("llvm") and "DRJIT_LIBLLVM_PATH" not in os.environ:
            from cnlmc.backends.exchange.mitsuba_cnlm import LLVM_LIBRARY

            os.environ["DRJIT_LIBLLVM_PATH"] = LLVM_LIBRARY
        mi.set_variant(variant)
        log.note(f"Mitsuba {mi.__version__} {variant}, Dr.Jit {dr.__version__}")
        return True
    except Exception as exc:
        log.note(f"Mitsuba {variant}: unavailable ({exc})")
        return False


# --- report (here) -------------------------------------------------------------------------


def read_gpu(path: Path) -> list[dict]:
    with open(path) as f:
        return [dict(r, ms512=float(r["ms512"]), flip=float(r["flip"] or "nan")) for r in csv.DictReader(f)]


def speedups(gpu: list[dict], cpu: list[dict], classes: dict[str, str]) -> list[dict]:
    """Per material: the best real-time tier by the CPU chart's FLIP, its GPU frame time, and
    Mitsuba's GPU time for that FLIP along its GPU-measured curve."""
    out = []
    for label in dict.fromkeys(r["material"] for r in gpu):
        tiers = {r["method"]: r for r in cpu if r["material"] == label and r["method"] in REALTIME}
        timed = {r["method"]: r["ms512"] for r in gpu if r["material"] == label}
        curve = [dict(r, ms=r["ms512"]) for r in gpu if r["material"] == label and r["method"].startswith("mitsuba")]
        if not tiers or not curve or not all(t in timed for t in tiers):
            continue
        best = min(tiers.values(), key=lambda r: r["flip"])
        mitsuba_ms = equal_error_ms(curve, best["flip"])
        ms = timed[best["method"]]
        cpu_times = {r["method"]: r["ms512"] for r in cpu if r["material"] == label}
        cpu_curve = [dict(r, ms=cpu_times.get(r["method"], float("nan"))) for r in curve]  # the same errors
        cpu_mitsuba = equal_error_ms(cpu_curve, best["flip"])
        out.append(
            {
                "material": label,
                "class": classes.get(label, "?"),
                "tier": best["method"],
                "flip": best["flip"],
                "ms512_gpu": ms,
                "mitsuba_ms512_gpu": mitsuba_ms,
                "speedup_gpu": mitsuba_ms / ms,
                "ms512_cpu": best["ms512"],
                "mitsuba_ms512_cpu": cpu_mitsuba,
                "speedup_cpu": cpu_mitsuba / best["ms512"] if best["ms512"] > 0 else float("nan"),
            }
        )
    return out


def frame_agreement(frames_path: Path, mats: dict[str, dict]) -> list[tuple[str, float, float]]:
    """(material, FLIP of the GPU's splitsum frame against llvmpipe's, FLIP of Mitsuba's GPU
    64-spp image against the LLVM variant's with the same seed)."""
    from cnlmc.backends.preview.render import Renderer

    frames = np.load(frames_path)
    scene_of = scenes()
    renderer = Renderer(ERROR_SIZE)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for label, material in mats.items():
            gl = mitsuba = float("nan")
            if f"splitsum/{label}" in frames:
                cpu = renderer.render(material, tier="splitsum", scene=scene_of[ERROR_SIZE], hdr=True).hdr
                gl = errors(tonemap(cpu), tonemap(frames[f"splitsum/{label}"].astype(np.float32)))[0]
            if f"mitsuba64/{label}" in frames:
                image = llvm_image(material, scene_of[ERROR_SIZE], Path(tmp) / "m")
                mitsuba = errors(tonemap(image), tonemap(frames[f"mitsuba64/{label}"].astype(np.float32)))[0]
            rows.append((label, gl, mitsuba))
    return rows


def llvm_image(material: dict, scene, work: Path) -> np.ndarray:
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene

    path = export_scene(material, scene, work, ERROR_SIZE, ERROR_SIZE, spp=64)
    return render_scene(path, spp=64, seed=CURVE_SEED, variant="vectorized")[0]


def merged(folders: list[Path]) -> list[dict]:
    """The rows of several measured folders: a (material, method) from the first that has it."""
    seen: set[tuple[str, str]] = set()
    rows = []
    for folder in folders:
        for r in read_gpu(folder / "gpu_times.csv"):
            if (r["material"], r["method"]) not in seen:
                seen.add((r["material"], r["method"]))
                rows.append(r)
    return rows


def report(folders: list[Path], out_csv: Path) -> int:
    """The speed-ups from measured folders (the first's rows win; later ones add what it lacks)."""
    gpu = merged(folders)
    cpu = read_rows(ROOT / "docs" / "preview_chart.csv")
    mats = chart()
    table = speedups(gpu, cpu, {k: material_class(m) for k, m in mats.items()})
    for folder in folders:
        print(f"{folder}:\n{(folder / 'gpu_device.txt').read_text()}")
    print_speedups(table)
    print_tier_medians(gpu, cpu)
    frames = folders[0] / "gpu_frames.npz"
    if frames.exists():
        agree = frame_agreement(frames, {k: mats[k] for k in dict.fromkeys(r["material"] for r in gpu)})
        gl = [a[1] for a in agree if np.isfinite(a[1])]
        mit = [a[2] for a in agree if np.isfinite(a[2])]
        print(f"\nGPU vs CPU frames, FLIP at {ERROR_SIZE}² over {len(agree)} materials:")
        print(f"  preview splitsum (NVIDIA EGL vs llvmpipe): median {np.median(gl):.4f}, max {np.max(gl):.4f}")
        print(f"  Mitsuba 64 spp, same seed (cuda vs llvm):  median {np.median(mit):.4f}, max {np.max(mit):.4f}")
        worst = sorted(agree, key=lambda a: -a[1])[:3]
        print("  largest preview differences: " + ", ".join(f"{a[0]} {a[1]:.4f}" for a in worst))
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    return 0


def print_speedups(table: list[dict]) -> None:
    print(
        f"{'material':48s} {'class':12s} {'tier':9s} {'FLIP':>6s} {'GPU ms':>7s} {'Mitsuba':>8s} {'x GPU':>7s} {'x CPU':>7s}"
    )
    for g in table:
        print(
            f"{g['material']:48s} {g['class']:12s} {g['tier']:9s} {g['flip']:6.3f} {g['ms512_gpu']:7.2f} "
            f"{g['mitsuba_ms512_gpu']:8.2f} {g['speedup_gpu']:7.1f} {g['speedup_cpu']:7.1f}"
        )
    by: dict[str, list[dict]] = {}
    for g in table:
        by.setdefault(g["class"], []).append(g)
    print("\nclass         n  median x GPU  median x CPU  >= 100x on the GPU")
    for cls, gs in sorted(by.items()) + [("all", table)]:
        print(
            f"{cls:12s} {len(gs):2d}  {np.nanmedian([g['speedup_gpu'] for g in gs]):12.1f}  "
            f"{np.nanmedian([g['speedup_cpu'] for g in gs]):12.1f}  {sum(g['speedup_gpu'] >= 100 for g in gs):2d}/{len(gs)}"
        )


def print_tier_medians(gpu: list[dict], cpu: list[dict]) -> None:
    print("\nmethod      median ms at 512²: GPU (wall; GPU side)   CPU (the chart)   ratio (wall)")
    for method in VARIANT_TIERS + tuple(f"mitsuba{s}" for s in MITSUBA_SPP):
        g = [r["ms512"] for r in gpu if r["method"] == method]
        side = [r["ms512"] for r in gpu if r["method"] == method + GPU_SIDE]
        c = [r["ms512"] for r in cpu if r["method"] == method and r["ms512"] > 0 and r["method"] != NATIVE_MODEL]
        if g and c:
            gpu_side = f"{np.median(side):6.2f}" if side else "     -"
            print(
                f"{method:10s} {np.median(g):14.2f} ({len(g)}); {gpu_side} {np.median(c):16.1f} "
                f"{np.median(c) / np.median(g):12.0f}x"
            )


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="step", required=True)
    m = sub.add_parser("measure", help="time the chart on this machine's GPU")
    m.add_argument("--out", type=Path, required=True)
    m.add_argument("--budget-s", type=float, default=330.0, help="stop measuring after this long")
    m.add_argument("--repeats", type=int, default=20, help="warm frames per tier (median)")
    m.add_argument(
        "--variant", default="cuda_ad_rgb", help="Mitsuba's variant (llvm_ad_rgb to try it here; none: no Mitsuba)"
    )
    m.add_argument("--quick", action="store_true", help="every sixth noun plus the variants")
    m.add_argument("--gpu-time", action="store_true", help="also each tier's GPU time (GL timer query)")
    m.add_argument("--skip", type=int, default=0, help="leave out the first SKIP chart materials")
    r = sub.add_parser("report", help="speed-ups from a measured folder and the CPU chart")
    r.add_argument("measured", type=Path, nargs="+", help="measured folders; the first's rows win")
    r.add_argument("--csv", type=Path, default=ROOT / "docs" / "preview_chart_gpu.csv")
    args = parser.parse_args(argv)
    if args.step == "measure":
        return measure(args.out, args.budget_s, args.repeats, args.variant, args.quick, args.gpu_time, args.skip)
    return report(args.measured, args.csv)


if __name__ == "__main__":
    sys.exit(main())
