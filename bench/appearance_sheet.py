"""The appearance sheet of docs/preview.md (issue #15, "a picture in docs/"): 24 everyday materials,
each as a triple of tiles side by side: the cnlmc preview (default tier) | Mitsuba 3 rendering the
exported scene (native plugins: glass, coats and sheen as Mitsuba implements them) | MaterialX's own
GLSL render of the exported .mtlx (when it can run here; see `materialx_column`). Same 10 cm sphere,
camera, studio environment, key light and tile size; the phrase under each triple.

    .venv/bin/python bench/appearance_sheet.py [--size 160] [--spp 64] [-o docs/appearance_sheet.png]
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PHRASES = (
    "clear glass",
    "frosted glass",
    "water",
    "clear acrylic",
    "black anodized aluminium",
    "blue anodized aluminum",
    "velvet",
    "navy blue velvet",
    "metallic car paint",
    "red car paint",
    "red brick",
    "hammered copper",
    "rusty iron",
    "black granite",
    "black marble",
    "white marble",
    "concrete",
    "white varnished oak",
    "brushed stainless steel",
    "gold",
    "gunmetal steel",
    "white porcelain",
    "tan leather",
    "green patina copper",
)
#: Materials per row of the sheet (each material is three tiles wide).
PER_ROW = 4


def to_rgba8(linear: np.ndarray, alpha: np.ndarray) -> np.ndarray:
    """Linear RGB (clipped) -> sRGB 8-bit over the sheet's 18 % grey (the same curve for every column)."""
    rgb = np.clip(linear, 0.0, 1.0) + (1.0 - alpha[..., None]) * 0.18
    srgb = np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * np.clip(rgb, 0.0031308, 1.0) ** (1 / 2.4) - 0.055)
    out = np.concatenate([srgb, np.ones_like(alpha)[..., None]], axis=-1)
    return (np.clip(out, 0.0, 1.0) * 255 + 0.5).astype(np.uint8)


def mitsuba_tile(material, scene, size: int, spp: int) -> np.ndarray:
    from cnlmc.backends.preview.mitsuba_scene import export_scene, render_scene

    with tempfile.TemporaryDirectory() as folder:
        image, _ = render_scene(export_scene(material, scene, folder, size, size, spp=spp), spp=spp)
    alpha = image[..., 3]
    return to_rgba8(image[..., :3], alpha)  # premultiplied RGB over grey: rgb + grey * (1 - alpha)


# ------------------------------------------------------------------ MaterialX's own GLSL render
#: FIS samples of the environment per pixel in MaterialX's shader (its own default is 16).
MATERIALX_ENV_SAMPLES = 64


def write_materialx_job(material, scene, folder: Path) -> None:
    """The exported .mtlx (+ baked images) and, once per sheet, the environment and the sphere."""
    from cnlmc.backends.base import as_document
    from cnlmc.backends.exchange import materialx

    folder.mkdir(parents=True, exist_ok=True)
    for artifact in materialx.emit(as_document({"materials": [material.to_ir()]}), {}).artifacts:
        path = folder / artifact.name
        path.parent.mkdir(parents=True, exist_ok=True)
        content = artifact.content
        path.write_bytes(content if isinstance(content, bytes) else content.encode())


def write_materialx_stage(scene, folder: Path) -> None:
    """env.hdr (radiance), env_irr.hdr (cosine-convolved / pi) in MaterialX's lat-long convention
    (u = atan2(x, -z) / 2pi + 0.5: ours rolled by half a turn), sphere.obj, camera.txt."""
    import cv2

    from cnlmc.backends.preview.environment import pixel_directions, pixel_solid_angles

    image = np.asarray(scene.env.image, np.float32) * scene.env_intensity
    cv2.imwrite(str(folder / "env.hdr"), np.roll(image, image.shape[1] // 2, axis=1)[..., ::-1])
    small = cv2.resize(image, (64, 32), interpolation=cv2.INTER_AREA).reshape(-1, 3)
    directions = pixel_directions(32, 64).reshape(-1, 3)
    solid = np.broadcast_to(np.asarray(pixel_solid_angles(32, 64)).reshape(32, -1), (32, 64)).reshape(-1)
    irradiance = (np.clip(directions @ directions.T, 0, None) * solid[None, :]) @ small / np.pi
    irradiance = np.roll(irradiance.reshape(32, 64, 3), 32, axis=1).astype(np.float32)
    cv2.imwrite(str(folder / "env_irr.hdr"), irradiance[..., ::-1])
    mesh = scene.mesh
    lines = [f"v {x:.7g} {y:.7g} {z:.7g}" for x, y, z in mesh.positions]
    lines += [f"vn {x:.7g} {y:.7g} {z:.7g}" for x, y, z in mesh.normals]
    lines += [f"vt {u:.7g} {v:.7g}" for u, v in mesh.uvs]
    lines += ["f " + " ".join(f"{i}/{i}/{i}" for i in face) for face in np.asarray(mesh.indices) + 1]
    (folder / "sphere.obj").write_text("\n".join(lines) + "\n")
    cam, key = scene.camera, scene.env.key
    values = [*(-key.unit), key.irradiance * scene.env_intensity, *cam.eye, *cam.target, *cam.up, cam.fov_y]
    (folder / "camera.txt").write_text(" ".join(f"{float(v):.9g}" for v in values))


def materialx_peer(stage: Path, size: int) -> None:
    """Runs under xvfb-run: MaterialX's GlslRenderer (FIS environment, one directional key light)
    renders stage/NN/materials.mtlx on stage/sphere.obj into stage/NN/render.npy."""
    import MaterialX as mx
    from MaterialX import PyMaterialXGenGlsl as mx_gen_glsl
    from MaterialX import PyMaterialXGenShader as mx_gen
    from MaterialX import PyMaterialXRender as mx_render
    from MaterialX import PyMaterialXRenderGlsl as mx_glsl

    values = [float(v) for v in (stage / "camera.txt").read_text().split()]
    library = mx.createDocument()
    search = mx.getDefaultDataSearchPath()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search, library)
    generator = mx_gen_glsl.GlslShaderGenerator.create()
    context = mx_gen.GenContext(generator)
    context.registerSourceCodeSearchPath(search)
    colour_management = mx_gen.DefaultColorManagementSystem.create(generator.getTarget())
    colour_management.loadLibrary(library)  # srgb_texture images decoded to linear, as MaterialXView does
    generator.setColorManagementSystem(colour_management)
    options = context.getOptions()
    options.targetColorSpaceOverride = "lin_rec709"
    options.hwSpecularEnvironmentMethod = mx_gen.HwSpecularEnvironmentMethod.SPECULAR_ENVIRONMENT_FIS
    options.hwMaxActiveLightSources = 1
    lights = mx.createDocument()
    lights.setDataLibrary(library)
    key = lights.addNode("directional_light", "key", "lightshader")
    key.setInputValue("direction", mx.Vector3(*values[0:3]))
    key.setInputValue("color", mx.Color3(1, 1, 1))
    key.setInputValue("intensity", values[3])
    light_handler = mx_render.LightHandler.create()
    light_handler.registerLights(lights, [key], context)
    light_handler.setLightSources([key])
    renderer = mx_glsl.GlslRenderer.create(size, size, mx_render.BaseType.FLOAT)
    renderer.initialize()
    images = mx_glsl.GLTextureHandler.create(mx_render.StbImageLoader.create())
    renderer.setImageHandler(images)
    renderer.setLightHandler(light_handler)
    light_handler.setEnvRadianceMap(images.acquireImage(mx.FilePath(str(stage / "env.hdr"))))
    light_handler.setEnvIrradianceMap(images.acquireImage(mx.FilePath(str(stage / "env_irr.hdr"))))
    light_handler.setEnvSampleCount(MATERIALX_ENV_SAMPLES)
    geometry = renderer.getGeometryHandler()
    geometry.addLoader(mx_render.TinyObjLoader.create())
    geometry.loadGeometry(mx.FilePath(str(stage / "sphere.obj")), False)
    eye, target, up = (mx.Vector3(*values[i : i + 3]) for i in (4, 7, 10))
    camera = renderer.getCamera()
    camera.setViewMatrix(mx_render.Camera.createViewMatrix(eye, target, up))
    near = 0.01
    top = near * float(np.tan(np.radians(values[13]) / 2))
    camera.setProjectionMatrix(mx_render.Camera.createPerspectiveMatrix(-top, top, -top, top, near, 100.0))
    done = ("render.hdr", "error.txt")  # a restarted peer goes on after the job it died on
    for job in sorted(p for p in stage.iterdir() if p.is_dir() and not any((p / n).exists() for n in done)):
        try:
            doc = mx.createDocument()
            mx.readFromXmlFile(doc, str(job / "materials.mtlx"))
            doc.setDataLibrary(library)
            images.setSearchPath(mx.FileSearchPath(str(job)))
            shader = generator.generate(job.name, doc.getMaterialNodes()[0], context)
            renderer.createProgram(shader)
            renderer.validateInputs()
            renderer.render()
            captured = renderer.captureImage(None)
            images.saveImage(mx.FilePath(str(job / "render.hdr")), captured, True)
        except Exception as error:  # reported on the tile, never hidden
            (job / "error.txt").write_text(f"{type(error).__name__}: {error}"[:200])
        print(job.name, flush=True)


def start_materialx(stage: Path, size: int):
    """The peer process under xvfb-run, or None (with the reason) when it cannot run here."""
    if shutil.which("xvfb-run") is None:
        return None, "xvfb-run not found"
    command = ["xvfb-run", "-a", sys.executable, __file__, "--materialx-peer", str(stage), "--size", str(size)]
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True), ""


def materialx_tile(job: Path, alpha: np.ndarray, size: int) -> np.ndarray:
    """The peer's render, masked by the sphere's coverage (same mesh and camera as the preview)."""
    import cv2

    if not (job / "render.hdr").exists():
        reason = (job / "error.txt").read_text() if (job / "error.txt").exists() else "no render"
        return missing_tile(size, "MaterialX render\nfailed:\n" + reason[:22] + "\n" + reason[22:44])
    rgb = cv2.imread(str(job / "render.hdr"), cv2.IMREAD_UNCHANGED)[..., ::-1].astype(np.float32)
    return to_rgba8(rgb * alpha[..., None], alpha)


def missing_tile(size: int, text: str) -> np.ndarray:
    """A plain tile that says the column could not be rendered (never a stand-in picture)."""
    import cv2

    tile = np.full((size, size, 4), (46, 46, 46, 255), np.uint8)
    for i, line in enumerate(text.split("\n")):
        cv2.putText(tile, line, (6, 20 + 16 * i), cv2.FONT_HERSHEY_SIMPLEX, 0.4, (200, 200, 200, 255), 1, cv2.LINE_AA)
    return tile


def triple(tiles: list[np.ndarray], phrase: str, gap: int = 2) -> np.ndarray:
    """Three labelled tiles side by side with the phrase in a strip under all three."""
    from cnlmc.backends.preview.sheet import label

    names = ("preview", "Mitsuba", "MaterialX")
    labelled = [label(tile, name) for tile, name in zip(tiles, names)]
    h = labelled[0].shape[0]
    spacer = np.full((h, gap, 4), (20, 20, 20, 255), np.uint8)
    row = np.hstack([labelled[0], spacer, labelled[1], spacer, labelled[2]])
    return label(row, phrase)


def cached_tile(path: Path, make) -> np.ndarray:
    """The tile saved at `path` by an earlier run with the same --stage, else make() (and save it)."""
    import cv2

    if path.exists():
        return cv2.cvtColor(cv2.imread(str(path), cv2.IMREAD_UNCHANGED), cv2.COLOR_BGRA2RGBA)
    tile = make()
    cv2.imwrite(str(path), cv2.cvtColor(tile, cv2.COLOR_RGBA2BGRA))
    return tile


def render_all(
    size: int, spp: int, stage: Path, materialx_timeout: float, phrases: tuple[str, ...] = PHRASES
) -> list[np.ndarray]:
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer, default_scene

    scene = default_scene("sphere", "studio", (size, size))
    scene.background = "transparent"
    materials = [compile_source(phrase + "\n").document.materials[0] for phrase in phrases]
    write_materialx_stage(scene, stage)
    for index, material in enumerate(materials):
        write_materialx_job(material, scene, stage / f"{index:02d}")
    pending = [stage / f"{i:02d}" for i in range(len(phrases)) if not (stage / f"{i:02d}" / "render.hdr").exists()]
    peer, reason = start_materialx(stage, size) if pending else (None, "")
    started = time.perf_counter()
    columns = []
    with Renderer(size, msaa=4) as renderer:
        for index, (phrase, material) in enumerate(zip(phrases, materials)):
            job = stage / f"{index:02d}"
            frame = renderer.render(material, scene=scene, hdr=True)
            alpha = frame.rgba[..., 3] / 255.0
            preview = to_rgba8(frame.hdr[..., :3], alpha)
            mitsuba = cached_tile(job / "mitsuba.png", lambda: mitsuba_tile(material, scene, size, spp))
            columns.append(([preview, mitsuba], alpha))
            print(f"{phrase:28s} preview + Mitsuba at {time.perf_counter() - started:6.1f} s", flush=True)
    if peer is not None:
        try:
            peer.wait(max(1.0, materialx_timeout - (time.perf_counter() - started)))
        except subprocess.TimeoutExpired:
            peer.terminate()
            reason = f"not rendered within {materialx_timeout:.0f} s"
    out = []
    for index, (phrase, (tiles, alpha)) in enumerate(zip(phrases, columns)):
        job = stage / f"{index:02d}"
        if (job / "render.hdr").exists() or (job / "error.txt").exists():
            third = materialx_tile(job, alpha, size)
        else:
            third = missing_tile(size, "MaterialX render:\n" + (reason or "not run"))
        out.append(triple([*tiles, third], phrase))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("-o", "--out", default=str(ROOT / "docs" / "appearance_sheet.png"))
    parser.add_argument("--stage", default="", help="a folder kept between runs (tiles and MaterialX renders reused)")
    parser.add_argument("--materialx-timeout", type=float, default=1800.0, help="seconds to wait for MaterialX")
    parser.add_argument("--materialx-peer", default="", help=argparse.SUPPRESS)
    parser.add_argument("--phrases", default="", help="';'-separated phrases instead of the 24 (a partial sheet)")
    args = parser.parse_args()
    if args.materialx_peer:
        materialx_peer(Path(args.materialx_peer), args.size)
        return
    from cnlmc.backends.preview.sheet import png_bytes, sheet
    from cnlmc.output import write_atomic

    with tempfile.TemporaryDirectory() as temporary:
        stage = Path(args.stage or temporary)
        stage.mkdir(parents=True, exist_ok=True)
        phrases = tuple(p.strip() for p in args.phrases.split(";") if p.strip()) or PHRASES
        triples = render_all(args.size, args.spp, stage, args.materialx_timeout, phrases)
    rows = [triples[i : i + PER_ROW] for i in range(0, len(triples), PER_ROW)]
    write_atomic(Path(args.out), png_bytes(sheet(rows, gap=8)))
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
