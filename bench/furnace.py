"""White furnace per target (issue #15 item 6): the mean sphere radiance under a uniform white
environment (radiance 1, no key light) in the preview, Mitsuba and MaterialX's own GLSL render,
against the IR's albedo.

Under a white sky a sphere's pixel at view cosine mu shows the directional albedo A(mu). The IR's
number is A(mu) from the numpy reference (`cnlmc.bsdf.flakes.albedo_full`: flakes and sheen
included) at each pixel's own mu, from the camera's real rays (`view_cosines`: the preview's
perspective camera, 10 cm sphere), over the pixels fully inside the sphere in both images; so the
camera model is in the IR's number, not an error term (`--camera` prints how far the orthographic
disc mean 2 int A mu dmu is from it). What the sphere shows decides the IR's material:
- a textured material: the mean of its baked maps' texels (colour, roughness) as the constant
  parameters (A is linear in the colour; roughness varies little within a map);
- glass: reflected plus transmitted light, R(mu) + T(mu) T_in a / (1 - R_in a) (T_in/R_in the
  inside interface at the refracted angle, its inter-reflections summed; a the Beer-Lambert
  transmittance along one chord of the 10 cm ball, 2 R cos(theta_t), the same for every chord of
  the ray): lossless clear glass shows ~1;
- a volume: the surface model's A, whose base colour is the medium's colour (the dipole's total
  diffuse reflectance Rd) under the IR's interface: the classical dipole BSSRDF's (1 - F(mu)) Rd
  (1 - F_avg) plus the interface's own reflection; a colour map (marble's veins) is not in the
  medium, so not in the number. Mitsuba renders the medium itself (`volpathmis`);
- a thin sheet, lit from both sides: the Kubelka-Munk slab's R + T (reflected and let through), under
  the same interface (`sheet_material`).
Prints one row per material (IR, preview, Mitsuba, MaterialX, the ratios, the kind) and the
counts within 5 % per target; `--all` takes every stdlib noun plus coats and variants.

    .venv/bin/python bench/furnace.py [--all] [--size 96] [--spp 64] [--materialx N] [--camera]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from collections.abc import Collection
from dataclasses import dataclass, field, replace
from pathlib import Path

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
    "clear glass",
    "frosted glass",
    "velvet",
    "metallic car paint",
    "acacia",
]
GAUSS_POINTS = 24
TOLERANCE = 0.05  # the issue's: within 5 % of the IR
MAP_SIZE, MAP_SEED = 256, 0  # the exports' defaults (exchange options map_size, seed)
TARGETS = ("preview", "Mitsuba", "MaterialX")


def material_of(phrase: str):
    from cnlmc.api import compile_source

    result = compile_source(phrase + "\n")
    if not result.ir["materials"]:
        raise ValueError(f"{phrase!r}: {[d.message for d in result.diagnostics]}")
    return result.document.materials[0]


# ------------------------------------------------------------------------ the IR's side


def kind_of(material) -> str:
    """The row's model kind: what decides which mapping each target uses."""
    model, p = material.model, material.params
    if model.subsurface:
        return model.subsurface
    if model.base == "glass":
        return "glass"
    if material.maps and {"base_color", "roughness"} & set(material.maps):
        return "textured"
    if p.flake_color is not None and p.flake_density > 0:
        return "flakes"
    if p.sheen_color is not None and max(p.sheen_color) > 0:
        return "sheen"
    if model.coat:
        return "coat/" + model.base
    return model.base + ("/aniso" if model.anisotropic else "")


def shown_material(material):
    """The constant material a textured one shows on average: its baked colour and roughness maps'
    texel means in place of the constants (the sphere shows the maps, not the IR's constants)."""
    from cnlmc.backends.maps.service import bake_arrays
    from cnlmc.material import Material

    roles = {"base_color", "roughness"} & set(material.maps)
    if not roles:
        return material
    arrays = bake_arrays(material, MAP_SIZE, MAP_SEED, roles)
    ir = material.to_ir()
    params = dict(ir["params"])
    if "base_color" in arrays:
        params["base_color"] = [float(v) for v in arrays["base_color"].reshape(-1, 3).mean(axis=0)]
    if "roughness" in arrays:
        params["roughness"] = float(arrays["roughness"].mean())
        params.pop("alpha", None)  # derived again from the mean roughness
    return Material.from_ir({**ir, "params": params, "maps": {}})


def glass_curve(material, grid: np.ndarray) -> np.ndarray:
    """A glass sphere's A(mu) under the white sky, RGB: R + T T_in a / (1 - R_in a) (module doc)."""
    from cnlmc.backends.preview.meshes import SPHERE_DIAMETER_M
    from cnlmc.bsdf.transmission import absorption, interface_albedo

    ior = float(material.params.ior)
    alpha = float(np.sqrt(np.prod(material.params.alpha)))
    r_out, t_out = interface_albedo(grid, ior, alpha)
    mu_in = np.sqrt(np.maximum(1.0 - (1.0 - grid**2) / ior**2, 0.0))
    r_in, t_in = interface_albedo(mu_in, 1.0 / ior, alpha)
    chord = SPHERE_DIAMETER_M * mu_in  # every chord of a ray inside a sphere has this length
    kept = absorption(material, chord)
    through = (t_out * t_in)[:, None] * kept / np.maximum(1.0 - r_in[:, None] * kept, 1e-6)
    return r_out[:, None] + through


def albedo_curve(material, grid: np.ndarray, n_samples: int = 1024) -> np.ndarray:
    """The IR's A(mu) at `grid`, RGB (len(grid), 3), of what the sphere shows (module doc)."""
    from cnlmc.bsdf.flakes import albedo_full

    if material.model.base == "glass" and not material.model.subsurface:
        return glass_curve(material, grid)
    if material.model.subsurface == "thin":
        return albedo_full(sheet_material(material), grid, n_samples)
    if material.model.subsurface == "volume":  # the medium's colour: a colour map is not in the medium
        return albedo_full(replace(material, maps={}), grid, n_samples)
    return albedo_full(shown_material(material), grid, n_samples)


def sheet_material(material):
    """A thin sheet under the white sky, lit from both sides: what the sheet reflects plus what comes
    through from behind, the Kubelka-Munk slab's R + T at the IR's thickness (its medium: the IR's
    subsurface colour and radius), both under the same interface ((1 - F(mu)) out, (1 - F_avg) in; A
    is linear in the colour): the surface model with R + T as its colour."""
    from cnlmc.bsdf.subsurface import medium_of, slab

    params, sub = material.params, material.params.subsurface
    medium = medium_of(sub.color, sub.radius, float(sub.anisotropy), float(params.ior))
    reflected, through = slab(medium, float(sub.thickness))
    colour = tuple(float(v) for v in np.clip(reflected + through, 0.0, 1.0))
    return replace(shown_material(material), params=replace(params, base_color=colour))


def ir_albedo(material, n_samples: int = 1024) -> np.ndarray:
    """2 * integral_0^1 A(mu) mu dmu, RGB, by Gauss-Legendre in mu: the orthographic disc's mean."""
    x, w = np.polynomial.legendre.leggauss(GAUSS_POINTS)
    mu = 0.5 * (x + 1.0)
    return (w * mu) @ albedo_curve(material, mu, n_samples)


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
    grid = np.linspace(0.0, 1.0, 33) ** 2  # dense near grazing, where A changes fastest
    grid[0] = 1e-3
    a = albedo_curve(material, grid, n_samples)
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


# ------------------------------------------------------------------------ the targets


def preview_image(renderer, scene, material, tier: str) -> tuple[np.ndarray, np.ndarray]:
    """(linear RGB, coverage) of the preview under the white sky."""
    frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
    return frame.hdr[..., :3], frame.rgba[..., 3] / 255.0


def mitsuba_image(scene, material, size: int, spp: int) -> tuple[np.ndarray, np.ndarray]:
    """(linear RGB, coverage) of the exported Mitsuba scene under the white sky; a volume or a thin
    sheet as the export writes it, with the volume path tracer (`subsurface_reference`: the medium as
    the sphere's interior, `volpathmis`; the surface integrator sees the boundary alone)."""
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    with tempfile.TemporaryDirectory() as folder:
        if material.model.subsurface:
            image, _ = render_subsurface(material, scene, folder, size, spp)
        else:
            path = export_scene(material, scene, folder, size, size, spp=spp)
            image, _ = render_scene(path, spp=spp)
    alpha = image[..., 3]
    return image[..., :3] / np.maximum(alpha, 1e-6)[..., None], alpha


def sheet_driver():
    """bench/appearance_sheet.py: its MaterialX driver (job and stage files, the xvfb-run peer)."""
    from importlib.util import module_from_spec, spec_from_file_location

    name = "appearance_sheet_bench"
    if name not in sys.modules:
        spec = spec_from_file_location(name, Path(__file__).with_name("appearance_sheet.py"))
        assert spec is not None and spec.loader is not None
        sys.modules[name] = module_from_spec(spec)
        spec.loader.exec_module(sys.modules[name])
    return sys.modules[name]


class MaterialXRenders:
    """MaterialX's own GLSL render (MaterialXRenderGlsl under xvfb-run) of each exported .mtlx on
    the same sphere, camera and white sky, through the appearance sheet's driver; started first,
    it renders while the preview and Mitsuba do (one peer process, every job in `stage`).

    A job costs 4-130 s of wall time here (llvmpipe, shared cores): the bench waits as long as jobs
    keep finishing (`STALL_S` without one ends the wait), and a peer that dies on a job (a driver
    crash) is restarted after it, the job marked with the exit status; every other job renders."""

    STALL_S = 900.0  # no job finished for this long: the peer is stuck
    RESTARTS = 8

    def __init__(self, scene, materials, size: int, stage: Path):
        driver = sheet_driver()
        self.stage, self.size, self.count = stage, size, len(materials)
        driver.write_materialx_stage(scene, stage)
        for index, material in enumerate(materials):
            driver.write_materialx_job(material, scene, self.job(index))
        self.peer, self.reason = driver.start_materialx(stage, size)

    def job(self, index: int) -> Path:
        return self.stage / f"{index:04d}"

    def finished(self) -> int:
        return sum(
            (self.job(i) / "render.hdr").exists() or (self.job(i) / "error.txt").exists() for i in range(self.count)
        )

    def wait(self, log=print) -> None:
        """Until every job has a render or an error (restarting a dead peer), or STALL_S pass idle."""
        restarts, last, changed = 0, -1, time.monotonic()
        while self.peer is not None and self.finished() < self.count:
            done = self.finished()
            if done != last:
                last, changed = done, time.monotonic()
            if time.monotonic() - changed > self.STALL_S:
                self.peer.terminate()
                self.reason = f"no MaterialX job finished within {self.STALL_S:.0f} s"
                return
            code = self.peer.poll()
            if code is None:
                time.sleep(1.0)
                continue
            left = [i for i in range(self.count) if not (self.job(i) / "render.hdr").exists()]
            left = [i for i in left if not (self.job(i) / "error.txt").exists()]
            if not left or restarts >= self.RESTARTS:
                return
            (self.job(left[0]) / "error.txt").write_text(f"the MaterialX peer died on this job (exit {code})")
            log(f"  MaterialX peer exited {code} on job {left[0]}: restarted", file=sys.stderr, flush=True)
            self.peer, self.reason = sheet_driver().start_materialx(self.stage, self.size)
            restarts += 1
        if self.peer is not None:
            self.peer.wait()

    def image(self, index: int) -> np.ndarray | None:
        """Linear RGB (size, size, 3), or None where it did not render (`error` says why)."""
        import cv2

        path = self.job(index) / "render.hdr"
        if not path.exists():
            return None
        return cv2.imread(str(path), cv2.IMREAD_UNCHANGED)[..., ::-1].astype(np.float64)

    def error(self, index: int) -> str:
        path = self.job(index) / "error.txt"
        return path.read_text() if path.exists() else self.reason or "no render"


def luminance(rgb) -> float:
    return float(np.dot(rgb, [0.2126, 0.7152, 0.0722]))


# ------------------------------------------------------------------------ rows


@dataclass
class Row:
    phrase: str
    kind: str
    ir: float
    values: dict[str, float] = field(default_factory=dict)  # target -> its mean, scaled to the IR's pixels

    def ratio(self, target: str) -> float:
        value = self.values.get(target, float("nan"))
        return value / self.ir if self.ir > 0 else float("nan")

    def within(self, target: str) -> bool:
        return bool(abs(self.ratio(target) - 1.0) <= TOLERANCE)


def scaled(ir_ref: float, pair: tuple[float, float]) -> float:
    """A target's mean on its own pixel set, scaled to the reference pixel set's IR (coverage differs
    a little between rasterizers; ultra-black paints have IR 0: unscaled)."""
    ir, value = pair
    return value * ir_ref / ir if ir > 0 else value


def spread(kinds: list[str], count: int) -> list[int]:
    """Up to `count` row indices, a stratified sample: each kind gets count / kinds rows (what a small
    kind leaves goes to the others), evenly spaced through its rows (alphabetical: not only its
    first letters). MaterialX's GLSL render costs 4-130 s of wall time a material on llvmpipe
    here, so --all renders a sample."""
    queues: dict[str, list[int]] = {}
    for index, kind in enumerate(kinds):
        queues.setdefault(kind, []).append(index)
    shares = dict.fromkeys(queues, 0)
    left = min(count, len(kinds))
    while left > 0:  # round-robin shares, so small kinds give their surplus to the others
        for kind, queue in queues.items():
            if left > 0 and shares[kind] < len(queue):
                shares[kind] += 1
                left -= 1
    chosen: list[int] = []
    for kind, queue in queues.items():
        n = shares[kind]
        chosen += [queue[int((j + 0.5) * len(queue) / n)] for j in range(n)] if n else []
    return sorted(chosen)


def measure(
    phrases,
    size: int,
    spp: int,
    tier: str,
    mitsuba: bool = True,
    materialx: int | Collection[str] = 1 << 30,
    log=print,
) -> list[Row]:
    """One Row per phrase: the IR and each target under the white sky (see the module doc);
    MaterialX renders at most `materialx` of them (a number: spread over the model kinds), or the
    phrases named (a collection)."""
    from cnlmc.backends.preview.render import Renderer

    scene = white_scene(size)
    mus = view_cosines(scene, size)
    materials = [material_of(phrase) for phrase in phrases]
    if isinstance(materialx, int):
        rendered = spread([kind_of(m) for m in materials], materialx)
    else:
        rendered = [i for i, phrase in enumerate(phrases) if phrase in materialx]
    rows, coverages = [], []
    with tempfile.TemporaryDirectory() as folder:
        chosen = [materials[i] for i in rendered]
        peer = MaterialXRenders(scene, chosen, size, Path(folder)) if chosen else None
        started = time.perf_counter()
        with Renderer(size, msaa=4) as renderer:
            for phrase, m in zip(phrases, materials):
                ir = ir_image(m, mus)
                coverage = np.isfinite(mus).astype(float)  # until the preview gives its own
                row = Row(phrase, kind_of(m), agreement(ir, mus, ir, coverage)[0])
                try:
                    rgb, coverage = preview_image(renderer, scene, m, tier)
                    row.ir, row.values["preview"] = agreement(ir, mus, rgb, coverage)
                except Exception as error:  # a target that fails on one row is reported, the rest go on
                    log(f"  preview {phrase}: {type(error).__name__}: {error}", file=sys.stderr, flush=True)
                if mitsuba:
                    try:
                        pair = agreement(ir, mus, *mitsuba_image(scene, m, size, spp))
                        row.values["Mitsuba"] = scaled(row.ir, pair)
                    except Exception as error:
                        log(f"  Mitsuba {phrase}: {type(error).__name__}: {error}", file=sys.stderr, flush=True)
                rows.append(row)
                coverages.append((ir, coverage))
                log(f"  {phrase[:36]:36s} at {time.perf_counter() - started:7.1f} s", file=sys.stderr, flush=True)
        if peer is not None:
            peer.wait(log)
            for index, row_index in enumerate(rendered):
                row, (ir, coverage) = rows[row_index], coverages[row_index]
                image = peer.image(index)
                if image is None:
                    log(f"  MaterialX {row.phrase}: {peer.error(index)[:120]}", file=sys.stderr, flush=True)
                    continue
                row.values["MaterialX"] = scaled(row.ir, agreement(ir, mus, image, coverage))
    return rows


def every_phrase() -> list[str]:
    from cnlmc.api import lexicon_for

    lex = lexicon_for()
    nouns = sorted(lex.all_of("nouns"))
    coats = [f"white plastic with a {c}" for c in sorted(lex.all_of("coats"))]
    variants = ["polished gold", "rough gold", "brushed steel", "matte white plastic", "glossy red plastic"]
    return [*nouns, *coats, *variants]


def print_rows(rows: list[Row]) -> None:
    head = " ".join(f"{t:>9s}" for t in TARGETS) + " " + " ".join(f"{t[:2] + '/IR':>7s}" for t in TARGETS)
    print(f"{'material':36s} {'kind':16s} {'IR':>7s} {head}")
    for row in rows:
        values = " ".join(f"{row.values.get(t, float('nan')):9.3f}" for t in TARGETS)
        ratios = " ".join(f"{row.ratio(t):7.3f}" for t in TARGETS)
        print(f"{row.phrase[:36]:36s} {row.kind[:16]:16s} {row.ir:7.3f} {values} {ratios}")


def print_counts(rows: list[Row]) -> None:
    """Per target: rows within 5 %, above 1 (a bug), and the same per model kind."""
    print(f"\nwithin {TOLERANCE:.0%} of the IR, of {len(rows)} rows:")
    for target in TARGETS:
        measured = [r for r in rows if target in r.values]
        above = [r.phrase for r in measured if r.values[target] > 1.0 + 0.01]
        line = f"  {target:9s} {sum(r.within(target) for r in measured):4d} / {len(measured)}"
        print(line + f"   above 1: {len(above)} {above[:6]}")
    kinds = sorted({r.kind for r in rows})
    print(f"\n{'kind':16s} {'rows':>5s} " + " ".join(f"{t:>9s}" for t in TARGETS))
    for kind in kinds:
        of_kind = [r for r in rows if r.kind == kind]
        counts = " ".join(f"{sum(r.within(t) for r in of_kind):9d}" for t in TARGETS)
        print(f"{kind:16s} {len(of_kind):5d} {counts}")


def print_camera(phrases: list[str], size: int) -> None:
    """The orthographic disc mean (2 int A mu dmu) against the per-pixel IR mean of the camera."""
    scene = white_scene(size)
    mus = view_cosines(scene, size)
    inside = np.isfinite(mus)
    print(f"camera: pixel mu from {np.nanmin(mus):.3f}; orthographic mean / camera's pixel mean")
    for phrase in phrases:
        m = material_of(phrase)
        ortho, pixels = luminance(ir_albedo(m)), luminance(ir_image(m, mus)[inside].mean(axis=0))
        print(f"  {phrase[:36]:36s} {ortho:7.3f} {pixels:7.3f} {ortho / pixels:7.3f}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true", help="every stdlib noun plus coats and variants")
    parser.add_argument("--phrases", default="", help="';'-separated phrases instead")
    parser.add_argument("--size", type=int, default=96)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--tier", default="fis64")
    parser.add_argument(
        "--materialx", type=int, default=-1, help="rows MaterialX renders (default: all, 40 with --all)"
    )
    parser.add_argument("--camera", action="store_true", help="the camera model's effect on the IR's mean")
    args = parser.parse_args(argv)
    phrases = [p.strip() for p in args.phrases.split(";") if p.strip()]
    phrases = phrases or (every_phrase() if args.all else REPRESENTATIVE)
    if args.camera:
        print_camera(phrases, args.size)
        return 0
    count = args.materialx if args.materialx >= 0 else (40 if args.all else len(phrases))
    rows = measure(phrases, args.size, args.spp, args.tier, materialx=count)
    print_rows(rows)
    print_counts(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
