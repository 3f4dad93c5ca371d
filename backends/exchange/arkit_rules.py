"""The usdz and ARKit rules of OpenUSD's compliance checker (usdUtils/complianceChecker.py, the code
behind `usdchecker --arkit`), written again here: the pip wheel usd-core 26 ships neither the
checker nor `usdchecker` (../shared/PLATFORM.md). One function per rule, named after the rule it
restates; each returns the failures it finds as text.

    failures = check_package("hull.usdz")      # [] when the package passes every rule
    failures = check("shot.usda", arkit=False)  # the base rules only (`usdchecker` without --arkit)
    python -m cnlmc.backends.exchange.arkit_rules [--no-arkit] FILE...   # prints failures, exit 1 if any

Base rules: byte alignment (64), no compression, no unresolvable dependency, stage metadata (upAxis
Y, metersPerUnit, defaultPrim), textures PNG/JPEG, prim encapsulation (connectable prims only
inside connectable containers, no gprim under a gprim), normal maps raw with scale 2 / bias -1,
MaterialBindingAPI applied where a binding is. ARKit rules: layers of core USD formats, the allowed
prim types, shaders with an `id` implementation source and a UsdPreviewSurface / UsdUVTexture /
UsdTransform2d / UsdPrimvarReader_* id whose connections are single and to shaders or materials,
bindings to real materials, only layer and image files in the package, nothing from outside it,
one usdc root layer that comes first. Prims are checked in every variant of every VariantSet.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

from pxr import Ar, Sdf, Tf, Usd, UsdGeom, UsdShade, UsdUtils

ALIGNMENT = 64
IMAGE_FORMATS = ("jpg", "png")
LAYER_FORMATS = ("usd", "usda", "usdc", "usdz")
PACKAGE_FILES = LAYER_FORMATS + IMAGE_FORMATS
EIGHT_BIT = ("bmp", "tga", "jpg", "png", "tif")
PRIM_TYPES = (
    "", "Scope", "Xform", "Camera", "Shader", "Material", "Mesh", "Sphere", "Cube", "Cylinder", "Cone",
    "Capsule", "GeomSubset", "Points", "SkelRoot", "Skeleton", "SkelAnimation", "BlendShape", "SpatialAudio",
)  # fmt: skip
SHADER_IDS = ("UsdPreviewSurface", "UsdUVTexture", "UsdTransform2d")
PRIMVAR_READER = "UsdPrimvarReader"

PrimRule = Callable[[Any], list[str]]


# ------------------------------------------------------------------------ the package


def byte_alignment(archive: Any, path: str) -> list[str]:
    return [
        f"file '{name}' in '{path}' has data at offset {archive.GetFileInfo(name).dataOffset}, not a multiple of 64"
        for name in archive.GetFileNames()
        if archive.GetFileInfo(name).dataOffset % ALIGNMENT
    ]


def compression(archive: Any, path: str) -> list[str]:
    return [
        f"file '{name}' in '{path}' is compressed (method {archive.GetFileInfo(name).compressionMethod})"
        for name in archive.GetFileNames()
        if archive.GetFileInfo(name).compressionMethod != 0
    ]


def file_extensions(archive: Any, path: str) -> list[str]:
    return [
        f"file '{name}' in '{path}' has an extension ARKit does not read"
        for name in archive.GetFileNames()
        if Ar.GetResolver().GetExtension(name).lower() not in PACKAGE_FILES
    ]


def root_layer_first(archive: Any, path: str) -> list[str]:
    names = archive.GetFileNames()
    if not names or not names[0].endswith(".usdc"):
        return [f"the first file in '{path}' is {names[0] if names else 'missing'}, not a .usdc layer"]
    return []


# -------------------------------------------------------------------------- the stage


def stage_metadata(stage: Any, arkit: bool = True) -> list[str]:
    """upAxis (Y for consumer content) and metersPerUnit authored, a valid defaultPrim."""
    failures = []
    if not stage.HasAuthoredMetadata(UsdGeom.Tokens.upAxis):
        failures.append("the stage does not specify an upAxis")
    elif arkit and UsdGeom.GetStageUpAxis(stage) != UsdGeom.Tokens.y:
        failures.append(f"the stage's upAxis is {UsdGeom.GetStageUpAxis(stage)}, not Y")
    if not stage.HasAuthoredMetadata(UsdGeom.Tokens.metersPerUnit):
        failures.append("the stage does not specify metersPerUnit")
    if not stage.GetDefaultPrim():
        failures.append("the stage has no valid defaultPrim")
    return failures


def one_layer(stage: Any) -> list[str]:
    on_disk = [layer for layer in stage.GetUsedLayers() if layer.realPath]
    failures = [] if len(on_disk) <= 1 else [f"the stage uses {len(on_disk)} layers, ARKit reads one usdc layer"]
    return failures + [
        f"layer '{layer.identifier}' has the format '{layer.GetFileFormat().formatId}'"
        for layer in on_disk
        if layer.GetFileFormat().formatId not in LAYER_FORMATS
    ]


def dependencies(path: str, opening_diagnostics: list[Any], inside_package: bool) -> list[str]:
    """Unresolvable asset paths and composition errors while opening; with `inside_package`
    (ARKit, on a usdz), every layer and asset also comes from inside the package."""
    layers, assets, unresolved = UsdUtils.ComputeAllDependencies(Sdf.AssetPath(path))
    failures = [f"unresolvable dependency '{p}'" for p in unresolved]
    failures += [
        d.commentary
        for d in opening_diagnostics
        if "_ReportErrors" in d.sourceFunction and "usd/stage.cpp" in d.sourceFileName
    ]
    if not inside_package:
        return failures
    outside = [layer.realPath for layer in layers if layer.realPath and not layer.realPath.startswith(path)]
    outside += [asset for asset in assets if not asset.startswith(path)]
    return failures + [f"'{p}' is outside the package '{path}'" for p in outside]


# ---------------------------------------------------------------------------- prims


def prim_type(prim: Any) -> list[str]:
    name = prim.GetTypeName()
    return [] if name in PRIM_TYPES else [f"prim <{prim.GetPath()}> has the type '{name}', which ARKit does not read"]


def texture_formats(allowed: tuple[str, ...]) -> PrimRule:
    """The rule: every asset input of a connectable prim names a texture of an `allowed` format."""

    def textures(prim: Any) -> list[str]:
        connectable = UsdShade.ConnectableAPI(prim)
        if not prim.GetTypeName() or not connectable:
            return []
        failures = []
        for shader_input in connectable.GetInputs():
            if shader_input.GetTypeName() != Sdf.ValueTypeNames.Asset:
                continue
            asset = shader_input.Get(Usd.TimeCode.EarliestTime())
            if asset and Ar.GetResolver().GetExtension(asset.path).lower() not in allowed:
                failures.append(f"texture <{shader_input.GetAttr().GetPath()}> @{asset.path}@ is not PNG or JPEG")
        return failures

    return textures


def encapsulation(prim: Any) -> list[str]:
    """No gprim under a gprim; a connectable prim only under connectable containers (or none)."""
    failures = []
    parent = prim.GetParent()
    if prim.IsA(UsdGeom.Boundable) and any(p.IsA(UsdGeom.Gprim) for p in ancestors(parent)):
        failures.append(f"gprim <{prim.GetPath()}> has a gprim ancestor")
    if not (prim.GetTypeName() and UsdShade.ConnectableAPI(prim)) or not parent:
        return failures
    parent_connectable = UsdShade.ConnectableAPI(parent) if parent.GetTypeName() else None
    if parent_connectable and not parent_connectable.IsContainer():
        failures.append(f"connectable <{prim.GetPath()}> is under a non-container {parent.GetTypeName()}")
    elif not parent_connectable and any(
        p.GetTypeName() and UsdShade.ConnectableAPI(p) for p in ancestors(parent.GetParent())
    ):
        failures.append(f"connectable <{prim.GetPath()}> has a non-connectable parent inside a connectable container")
    return failures


def ancestors(prim: Any) -> Iterator[Any]:
    while prim and prim.GetPath() != Sdf.Path.absoluteRootPath:
        yield prim
        prim = prim.GetParent()


def input_value(shader: Any, name: str) -> Any:
    found = shader.GetInput(name)
    return found.Get(Usd.TimeCode.EarliestTime()) if found else None


def normal_maps(prim: Any) -> list[str]:
    """A UsdUVTexture feeding UsdPreviewSurface's normal from an 8-bit image: raw, scale 2, bias -1."""
    if not prim.IsA(UsdShade.Shader) or UsdShade.Shader(prim).GetShaderId() != "UsdPreviewSurface":
        return []
    normal = UsdShade.Shader(prim).GetInput("normal")
    sources = UsdShade.Utils.GetValueProducingAttributes(normal) if normal else []
    if not sources or sources[0].GetPrim() == prim:
        return []
    texture = UsdShade.Shader(sources[0].GetPrim())
    if not texture or texture.GetShaderId() != "UsdUVTexture":
        return []
    where = texture.GetPath()
    asset = input_value(texture, "file")
    if not asset or not asset.resolvedPath:
        return [f"normal map <{where}> has no resolvable inputs:file"]
    if Ar.GetResolver().GetExtension(asset.resolvedPath).lower() not in EIGHT_BIT:
        return []
    failures = []
    if input_value(texture, "sourceColorSpace") != "raw":
        failures.append(f"normal map <{where}> does not set sourceColorSpace to raw")
    scale, bias = input_value(texture, "scale"), input_value(texture, "bias")
    if scale is None or bias is None or list(scale)[:3] != [2, 2, 2] or list(bias)[:3] != [-1, -1, -1]:
        failures.append(f"normal map <{where}> needs scale (2, 2, 2, 1) and bias (-1, -1, -1, 0)")
    return failures


def binding_rels(prim: Any) -> list[Any]:
    return [r for r in prim.GetRelationships() if r.GetName().startswith(UsdShade.Tokens.materialBinding)]


def binding_api(prim: Any) -> list[str]:
    """A prim with a material binding has MaterialBindingAPI applied."""
    if binding_rels(prim) and not prim.HasAPI(UsdShade.MaterialBindingAPI):
        return [f"prim <{prim.GetPath()}> has a material binding without MaterialBindingAPI"]
    return []


def binding_targets(prim: Any) -> list[str]:
    """ARKit: every direct binding targets a real Material."""
    return [
        f"binding <{rel.GetPath()}> targets no valid material"
        for rel in binding_rels(prim)
        if len(rel.GetTargets()) == 1 and not UsdShade.MaterialBindingAPI.DirectBinding(rel).GetMaterial()
    ]


def shaders(prim: Any) -> list[str]:
    """`id` implementation source, an id AR Quick Look knows, single connections to shaders/materials."""
    if not prim.IsA(UsdShade.Shader):
        return []
    shader = UsdShade.Shader(prim)
    failures = []
    if shader.GetImplementationSource() != UsdShade.Tokens.id:
        failures.append(f"shader <{prim.GetPath()}> has the implementation source {shader.GetImplementationSource()}")
    shader_id = shader.GetShaderId() or ""
    if shader_id not in SHADER_IDS and not shader_id.startswith(PRIMVAR_READER):
        failures.append(f"shader <{prim.GetPath()}> has the id '{shader_id}', which ARKit does not read")
    for shader_input in shader.GetInputs():
        connections = shader_input.GetAttr().GetConnections()
        if not connections:
            continue
        if len(connections) > 1:
            failures.append(f"input <{shader_input.GetAttr().GetPath()}> has {len(connections)} connections")
        source = shader_input.GetConnectedSource()
        if source is None:
            failures.append(f"input <{shader_input.GetAttr().GetPath()}> connects to a missing source")
        elif not (source[0].GetPrim().IsA(UsdShade.Shader) or source[0].GetPrim().IsA(UsdShade.Material)):
            failures.append(
                f"input <{shader_input.GetAttr().GetPath()}> connects to a {source[0].GetPrim().GetTypeName()}"
            )
    return failures


BASE_PRIM_RULES: tuple[PrimRule, ...] = (encapsulation, normal_maps, binding_api)
ARKIT_PRIM_RULES: tuple[PrimRule, ...] = (prim_type, shaders, binding_targets)


def check_prims(stage: Any, rules: tuple[PrimRule, ...]) -> list[str]:
    """The prim rules on every prim in every variant (selections are set in the session layer)."""
    stage.SetEditTarget(stage.GetSessionLayer())
    failures: list[str] = []
    for prim in visit(iter(Usd.PrimRange.Stage(stage, Usd.TraverseInstanceProxies()))):
        for rule in rules:
            failures += rule(prim)
    return sorted(set(failures))


def visit(prims: Any, skip: Any = None) -> Iterator[Any]:
    """Each prim of a PrimRange iterator; a prim with VariantSets once per combination of its
    selections, each time with its own subtree as that combination composes it."""
    for prim in prims:
        if skip is not None and prim == skip:
            continue
        names = list(prim.GetVariantSets().GetNames())
        if not names:
            yield prim
            continue
        prims.PruneChildren()
        for _ in selections(prim, names):
            yield prim
            yield from visit(iter(Usd.PrimRange(prim, Usd.TraverseInstanceProxies())), skip=prim)


def selections(prim: Any, names: list[str]) -> Iterator[None]:
    """Set every combination of the VariantSets `names` on `prim`, one after another."""
    variant_set = prim.GetVariantSets().GetVariantSet(names[0])
    for choice in variant_set.GetVariantNames():
        variant_set.SetVariantSelection(choice)
        if len(names) > 1:
            yield from selections(prim, names[1:])
        else:
            yield None


# --------------------------------------------------------------------------------- all


def check_package(path: str | Path) -> list[str]:
    """Every failure of the usdz at `path` under the base and ARKit rules ([] when it passes)."""
    return check(path, arkit=True)


def check(path: str | Path, arkit: bool = True) -> list[str]:
    """The failures of a USD file (.usda/.usdc/.usdz) under the base rules, and with `arkit` the
    ARKit rules too: `usdchecker FILE` and `usdchecker --arkit FILE` ([] when it passes)."""
    path = str(Path(path).resolve())
    package = path.lower().endswith(".usdz")
    failures = zip_failures(path, arkit) if package else []
    if arkit and not package and not path.endswith(".usdc"):
        failures.append(f"the root layer '{path}' is not a .usdc file")
    delegate = UsdUtils.CoalescingDiagnosticDelegate()
    try:
        stage = Usd.Stage.Open(path)
    except Tf.ErrorException as exc:  # e.g. a compressed layer, or no layer first
        return failures + [f"the file does not open as a stage: {' '.join(str(exc).split())}"]
    diagnostics = delegate.TakeUncoalescedDiagnostics()
    failures += stage_metadata(stage, arkit) + (one_layer(stage) if arkit else [])
    with Ar.ResolverContextBinder(stage.GetPathResolverContext()):
        failures += dependencies(path, diagnostics, arkit and package)
    rules = BASE_PRIM_RULES + (ARKIT_PRIM_RULES if arkit else ())
    if package or arkit:  # the checker tests texture formats only for packages and consumer content
        rules += (texture_formats(IMAGE_FORMATS if arkit else IMAGE_FORMATS + ("exr",)),)
    return failures + check_prims(stage, rules)


def zip_failures(path: str, arkit: bool) -> list[str]:
    archive = Sdf.ZipFile.Open(path)
    if not archive:
        return [f"'{path}' is not a zip package"]
    rules = (byte_alignment, compression) + ((file_extensions, root_layer_first) if arkit else ())
    return [failure for rule in rules for failure in rule(archive, path)]


def main(arguments: list[str]) -> int:
    """`[--no-arkit] FILE...`: print each failure; exit 1 if any."""
    arkit = "--no-arkit" not in arguments
    failed = 0
    for path in (a for a in arguments if a != "--no-arkit"):
        for failure in check(path, arkit):
            print(f"{path}: {failure}")
            failed = 1
    return failed


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
