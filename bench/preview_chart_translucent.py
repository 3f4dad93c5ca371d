"""The preview chart's translucent class (issue #19): for wax, jade, skin II and V, milk, marble, soap
and a backlit leaf on the preview sphere in the studio, each preview tier's frame time (llvmpipe,
at 512x512) against its error (FLIP mean, RMSE of the tone-mapped image) vs Mitsuba's volumetric
reference of the same scene (backends/preview/subsurface_reference.py: the Mitsuba export's
boundary + homogeneous medium, or its thin sheet, `volpathmis`, --ref-spp), and Mitsuba's own
time/error curve (1, 4, 16, 64 spp against a second converged render, seed 7).

Mitsuba's time at 512^2 is measured at 1 spp and scaled by spp (a path tracer's time is linear in
its sample count; rendering 64 spp of a dense medium at 512^2 takes tens of minutes here).

    .venv/bin/python bench/preview_chart_translucent.py [--size 64] [--ref-spp 256]
    (also: bench/preview_chart.py --translucent)

Writes docs/preview_chart_translucent.csv and docs/preview_chart_translucent.png.
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
sys.path.insert(0, str(ROOT / "bench"))

from preview_chart import TIER_STYLE, TIERS, TIMING_SIZE, errors, tonemap  # noqa: E402

#: label -> (phrase, lighting): "front" the studio and its key light, "back" the key light behind
#: the object (30 degrees off the view axis, above), the studio around it
TRANSLUCENT = {
    "wax": ("wax", "front"),
    "jade": ("jade", "front"),
    "skin II": ("type II skin", "front"),
    "skin V": ("type V skin", "front"),
    "milk": ("milk", "front"),
    "marble": ("marble", "front"),
    "soap": ("soap", "front"),
    "leaf (backlit)": ("backlit leaf", "back"),
    "leaf sheet (backlit)": ("backlit leaf", "back"),
}
#: label -> mesh for the rows not on the sphere: a leaf is an open sheet (meshes.leaf); on the sphere
#: the same sheet is a closed shell whose cavity glows (docs/subsurface.md)
MESH = {"leaf sheet (backlit)": "leaf"}
MITSUBA_SPP = (1, 4, 16, 64)
GOAL_FLIP, GOAL_MS = 0.08, 1000.0 / 30.0
DEFAULT_TIER = "splitsum"


def material(phrase: str):
    from cnlmc.api import compile_source
    from cnlmc.material import Material

    return Material.from_ir(compile_source(phrase + "\n").ir["materials"][0])


def backlit_key(scene):
    """A key light behind the object: from the far side of the view axis, 30 degrees off it, raised."""
    from cnlmc.backends.preview.environment import Environment, KeyLight

    view = np.subtract(scene.camera.target, scene.camera.eye)
    view = view / np.linalg.norm(view)
    side = np.cross(view, [0.0, 1.0, 0.0])
    towards = view * np.cos(np.radians(30)) + (side / np.linalg.norm(side) + [0.0, 0.5, 0.0]) * np.sin(np.radians(30))
    return Environment(scene.env.name + " backlit", scene.env.image, KeyLight(tuple(towards), scene.env.key.irradiance))


def scene_for(renderer, lighting: str, mesh: str = "sphere"):
    scene = renderer.scene(mesh, "studio")
    if lighting == "back":
        scene = renderer.scene(mesh, backlit_key(scene))
    scene.background = "transparent"
    return scene


def mitsuba(body, scene, size: int, spp: int, seed: int, work: Path) -> tuple[np.ndarray, float]:
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    return render_subsurface(body, scene, work / f"s{size}_{spp}_{seed}", size, spp, seed)


def rows_for(label: str, body, scene, big, renderer, renderer512, size: int, ref_spp: int) -> list[dict]:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        ref, _ = mitsuba(body, scene, size, ref_spp, 0, work)
        ref_ldr = tonemap(ref)
        second, _ = mitsuba(body, scene, size, ref_spp, 7, work)
        flip, rmse = errors(ref_ldr, tonemap(second))
        rows.append(
            {"material": label, "method": "reference_noise", "ms": 0.0, "ms512": 0.0, "flip": flip, "rmse": rmse}
        )
        _, one512 = mitsuba(body, big, TIMING_SIZE, 1, 1, work)
        for spp in MITSUBA_SPP:
            img, seconds = mitsuba(body, scene, size, spp, 1, work)
            flip, rmse = errors(tonemap(second), tonemap(img))
            ms512 = one512 * spp * 1000
            rows.append(
                {
                    "material": label,
                    "method": f"mitsuba{spp}",
                    "ms": seconds * 1000,
                    "ms512": ms512,
                    "flip": flip,
                    "rmse": rmse,
                }
            )
    for tier in TIERS:
        frame = renderer.render(body, tier=tier, scene=scene, hdr=True)
        ms = renderer.frame_time(scene, body, tier, repeats=2)
        ms512 = renderer512.frame_time(big, body, tier, repeats=3)
        flip, rmse = errors(ref_ldr, tonemap(frame.hdr))
        rows.append({"material": label, "method": tier, "ms": ms, "ms512": ms512, "flip": flip, "rmse": rmse})
    return rows


def run(size: int, ref_spp: int, out_csv: Path, only: list[str] | None = None) -> list[dict]:
    from cnlmc.backends.preview.render import Renderer

    renderer, renderer512 = Renderer(size), Renderer(TIMING_SIZE, resources=None)
    rows: list[dict] = []
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, ["material", "method", "ms", "ms512", "flip", "rmse"])
        writer.writeheader()
        for label, (phrase, lighting) in TRANSLUCENT.items():
            if only and label not in only:
                continue
            body, mesh = material(phrase), MESH.get(label, "sphere")
            scene, big = scene_for(renderer, lighting, mesh), scene_for(renderer512, lighting, mesh)
            per = rows_for(label, body, scene, big, renderer, renderer512, size, ref_spp)
            writer.writerows(per)
            f.flush()
            rows += per
            print(f"{label:16s} " + " ".join(f"{r['method']}={r['flip']:.3f}" for r in per), flush=True)
    return rows


def retime(rows: list[dict], out_csv: Path) -> list[dict]:
    """The preview tiers' 512^2 frame times measured again (median of 5), with no Mitsuba render
    beside them, and a plain dielectric ("white plastic") timed in the same process as the peer."""
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer

    renderer = Renderer(TIMING_SIZE)
    peer = compile_source("white plastic\n").ir["materials"][0]
    for label, (phrase, lighting) in TRANSLUCENT.items():
        body, scene = material(phrase), scene_for(renderer, lighting, MESH.get(label, "sphere"))
        for r in rows:
            if r["material"] == label and r["method"] in TIERS:
                r["ms512"] = renderer.frame_time(scene, body, r["method"], repeats=5)
        plain = renderer.frame_time(scene, peer, DEFAULT_TIER, repeats=5)
        mine = next(r["ms512"] for r in rows if r["material"] == label and r["method"] == DEFAULT_TIER)
        print(f"{label:16s} {DEFAULT_TIER} {mine:6.1f} ms, white plastic {plain:6.1f} ms ({mine / plain:.2f}x)")
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, ["material", "method", "ms", "ms512", "flip", "rmse"])
        writer.writeheader()
        writer.writerows(rows)
    return rows


def read_rows(path: Path) -> list[dict]:
    with open(path) as f:
        return [dict(r, **{k: float(r[k]) for k in ("ms", "ms512", "flip", "rmse")}) for r in csv.DictReader(f)]


def print_table(rows: list[dict]) -> None:
    labels = list(dict.fromkeys(r["material"] for r in rows))
    methods = [m for m in dict.fromkeys(r["method"] for r in rows) if m != "reference_noise"]
    print(f"\nFLIP vs the volumetric reference (ref noise = FLIP between two reference seeds); ms at {TIMING_SIZE}^2")
    print(f"{'material':16s} {'noise':>6s} " + " ".join(f"{m:>10s}" for m in methods))
    for label in labels:
        per = {r["method"]: r for r in rows if r["material"] == label}
        print(
            f"{label:16s} {per['reference_noise']['flip']:6.3f} "
            + " ".join(f"{per[m]['flip']:10.3f}" for m in methods if m in per)
        )
    print(
        f"{'median ms512':23s} "
        + " ".join(f"{np.median([r['ms512'] for r in rows if r['method'] == m]):10.1f}" for m in methods)
    )
    default = [r for r in rows if r["method"] == DEFAULT_TIER]
    met = [r["material"] for r in default if r["flip"] <= GOAL_FLIP and r["ms512"] <= GOAL_MS]
    print(
        f"\ngoal (default tier {DEFAULT_TIER}: FLIP <= {GOAL_FLIP} at >= 30 fps at 512^2): {len(met)}/{len(default)} "
        f"({', '.join(met) or 'none'}); fps under load is a lower bound"
    )


def plot(rows: list[dict], size: int, ref_spp: int, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8.5, 5.4))
    methods = [m for m in dict.fromkeys(r["method"] for r in rows) if m != "reference_noise"]
    for method in methods:
        per = [r for r in rows if r["method"] == method]
        mitsuba_row = method.startswith("mitsuba")
        colour, marker = ("tab:red", "x") if mitsuba_row else TIER_STYLE.get(method, ("black", "o"))
        ax.scatter([r["ms512"] for r in per], [r["flip"] for r in per], s=12, alpha=0.35, color=colour, marker=marker)
        t, e = float(np.median([r["ms512"] for r in per])), float(np.mean([r["flip"] for r in per]))
        ax.scatter(
            [t],
            [e],
            s=90,
            color=colour,
            marker="o" if mitsuba_row else marker,
            edgecolor="black",
            zorder=3,
            label=None if mitsuba_row else method,
        )
        ax.annotate(method, (t, e), textcoords="offset points", xytext=(6, 5), fontsize=8)
    curve = [
        (
            np.median([r["ms512"] for r in rows if r["method"] == f"mitsuba{s}"]),
            np.mean([r["flip"] for r in rows if r["method"] == f"mitsuba{s}"]),
        )
        for s in MITSUBA_SPP
    ]
    ax.plot(*zip(*curve), color="tab:red", lw=1.5, label="Mitsuba volpathmis 1-64 spp")
    noise = np.mean([r["flip"] for r in rows if r["method"] == "reference_noise"])
    ax.axhline(GOAL_FLIP, color="black", lw=0.8, ls="--", label=f"goal FLIP {GOAL_FLIP}")
    ax.axhline(noise, color="tab:red", lw=0.8, ls=":", label=f"reference noise (two seeds) {noise:.3f}")
    ax.axvline(GOAL_MS, color="black", lw=0.8, ls="-.", label="30 fps")
    ax.set_xscale("log")
    ax.set_ylim(bottom=0)
    ax.set_xlabel(
        f"ms per {TIMING_SIZE}² frame, log (llvmpipe; Mitsuba llvm, 1 spp measured x spp; load: docs/subsurface.md)"
    )
    ax.set_ylabel(f"FLIP mean vs Mitsuba volumetric reference ({ref_spp} spp, {size}²)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="upper right")
    labels = ", ".join(TRANSLUCENT)
    fig.suptitle(f"translucent class: {labels}\nsmall: per material; large: mean FLIP at the median time", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=64, help="FLIP image size (with --from-csv: the label only)")
    parser.add_argument("--ref-spp", type=int, default=256, help="reference spp (with --from-csv: the label only)")
    parser.add_argument("--from-csv", action="store_true", help="re-plot docs/preview_chart_translucent.csv")
    parser.add_argument("--only", nargs="*", help="these materials (labels) only")
    parser.add_argument("--retime", action="store_true", help="with --from-csv: time the preview tiers again")
    parser.add_argument("--out", type=Path, default=ROOT / "docs", help="folder for the csv and png")
    args = parser.parse_args(argv)
    start = time.time()
    out_csv, out_png = args.out / "preview_chart_translucent.csv", args.out / "preview_chart_translucent.png"
    rows = read_rows(out_csv) if args.from_csv else run(args.size, args.ref_spp, out_csv, args.only)
    if args.retime:
        rows = retime(rows, out_csv)
    plot(rows, args.size, args.ref_spp, out_png)
    print_table(rows)
    print(f"\n({time.time() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
