"""Exchange backends: emit time per material (median) next to a floor, the same kind of
document built directly with each library's API (no IR mapping, no checks, no notes).

    .venv/bin/python bench/exchange_bench.py [--repeat 30]
"""

from __future__ import annotations

import argparse
import copy
import statistics
import time
import xml.etree.ElementTree as ET

from cnlmc.api import compile_source, emit

PHRASES = [
    "lightly brushed, blue anodized aluminum",
    "white varnished oak",
    "frosted glass",
    "deep red velvet",
    "clear-coated red car paint",
    "polished gold",
]


def single_material_irs() -> list[dict]:
    ir = compile_source("\n".join(PHRASES) + "\n").ir
    out = []
    for material in ir["materials"]:
        one = copy.deepcopy(ir)
        one["materials"] = [material]
        out.append(one)
    return out


def floor_materialx() -> str:
    import MaterialX as mx

    doc = mx.createDocument()
    shader = doc.addNode("open_pbr_surface", "SR_x", "surfaceshader")
    shader.setInputValue("base_color", mx.Color3(0.9, 0.9, 0.9), "color3")
    shader.setInputValue("base_metalness", 1.0, "float")
    shader.setInputValue("specular_color", mx.Color3(0.9, 0.9, 0.9), "color3")
    shader.setInputValue("specular_roughness", 0.3, "float")
    shader.setInputValue("specular_roughness_anisotropy", 0.4, "float")
    doc.addMaterialNode("M_x", shader).setDocString("x")
    return mx.writeToXmlString(doc)


def floor_usd() -> str:
    from pxr import Gf, Sdf, Usd, UsdShade

    stage = Usd.Stage.CreateInMemory()
    material = UsdShade.Material.Define(stage, "/Root/Looks/x")
    preview = UsdShade.Shader.Define(stage, "/Root/Looks/x/PreviewSurface")
    preview.CreateIdAttr("UsdPreviewSurface")
    preview.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(0.9, 0.9, 0.9))
    preview.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(1.0)
    preview.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.3)
    material.CreateSurfaceOutput().ConnectToSource(preview.CreateOutput("surface", Sdf.ValueTypeNames.Token))
    mx_shader = UsdShade.Shader.Define(stage, "/Root/Looks/x/SR_x")
    mx_shader.CreateIdAttr("ND_open_pbr_surface_surfaceshader")
    for name in ("base_color", "specular_color"):
        mx_shader.CreateInput(name, Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(0.9, 0.9, 0.9))
    for name in ("base_metalness", "specular_roughness", "specular_roughness_anisotropy"):
        mx_shader.CreateInput(name, Sdf.ValueTypeNames.Float).Set(0.5)
    material.CreateSurfaceOutput("mtlx").ConnectToSource(mx_shader.CreateOutput("out", Sdf.ValueTypeNames.Token))
    return stage.GetRootLayer().ExportToString()


def floor_mitsuba() -> str:
    scene = ET.Element("scene", version="3.0.0")
    outer = ET.SubElement(scene, "bsdf", type="twosided", id="x")
    bsdf = ET.SubElement(outer, "bsdf", type="roughconductor")
    ET.SubElement(bsdf, "string", name="distribution", value="ggx")
    for name, value in (("alpha_u", "0.11"), ("alpha_v", "0.07")):
        ET.SubElement(bsdf, "float", name=name, value=value)
    for name, value in (("eta", "1.5, 0.98, 0.6"), ("k", "7.6, 6.5, 5.3"), ("specular_reflectance", "0, 0, 1")):
        ET.SubElement(bsdf, "rgb", name=name, value=value)
    return ET.tostring(scene, encoding="unicode")


FLOORS = {"materialx": floor_materialx, "usd": floor_usd, "mitsuba": floor_mitsuba}
OPTIONS = {"materialx": {"maps": "none"}, "usd": {"maps": "none"}, "mitsuba": {"maps": "none"}}


def median_ms(fn, repeat: int) -> float:
    fn()  # warm caches (library loading, template compilation)
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=30)
    args = parser.parse_args()
    irs = single_material_irs()
    rows = []
    for target, floor in FLOORS.items():
        per_material = [median_ms(lambda ir=ir: emit(ir, target, OPTIONS[target]), args.repeat) for ir in irs]
        emit_ms = statistics.median(per_material)
        floor_ms = median_ms(floor, args.repeat)
        rows.append((target, emit_ms, min(per_material), max(per_material), floor_ms, emit_ms / floor_ms))
    print(f"{len(irs)} materials, median of {args.repeat} runs each, maps=none\n")
    print(f"{'target':<10} {'emit ms/material':>17} {'(min..max)':>16} {'direct API floor ms':>20} {'ratio':>7}")
    for target, emit_ms, lo, hi, floor_ms, ratio in rows:
        print(f"{target:<10} {emit_ms:>17.3f} {f'({lo:.2f}..{hi:.2f})':>16} {floor_ms:>20.3f} {ratio:>6.1f}x")


if __name__ == "__main__":
    main()
