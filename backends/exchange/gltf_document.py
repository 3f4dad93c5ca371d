"""Assembling one glTF 2.0 asset with pygltflib: one binary buffer (geometry, and the images in a
.glb), accessors, one repeat sampler, textures, materials, meshes, nodes and KHR_materials_variants.

    builder = GltfBuilder(embed_images=True)
    geometry = builder.add_geometry(preview_geometry("sphere", 0.2))
    index = builder.add_material(material, textures, thickness=0.2)
    builder.add_object("hull", geometry, [(index, None)], (0, 0, 0))
    glb_bytes = builder.glb()

Everything is written in the order it is added, so equal inputs give equal bytes.
"""

from __future__ import annotations

import base64
import json
from collections.abc import Mapping, Sequence
from typing import Any
from urllib.parse import quote

import numpy as np
import pygltflib as gltf

from cnlmc.material import Material

from ..base import Artifact
from ..maps.library import metres_per_unit
from . import gltf_material
from .gltf_mesh import PreviewGeometry
from .naming import phrase_text

GENERATOR = "cnlmc"
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
REPEAT, LINEAR, LINEAR_MIPMAP_LINEAR = 10497, 9729, 9987
VARIANTS = "KHR_materials_variants"
TRANSFORM = "KHR_texture_transform"
#: the maps a packed image is made from, in the order their graph's unit is taken from
PACKED_FROM = {"metallic_roughness": ("roughness", "metallic")}
#: texture slot of pbrMetallicRoughness or the material, by baked role
SLOTS = {"base_color": "baseColorTexture", "metallic_roughness": "metallicRoughnessTexture", "normal": "normalTexture"}


class GltfBuilder:
    """One asset under construction (the object owns its buffer and its lists)."""

    def __init__(self, embed_images: bool):
        self.embed_images = embed_images
        self.doc = gltf.GLTF2(asset=gltf.Asset(generator=GENERATOR, version="2.0"))
        self.blob = bytearray()
        self.images: dict[str, int] = {}  # artifact name -> image index
        self.variant_names: list[str] = []
        self.used: set[str] = set()

    # ------------------------------------------------------------------------ buffers

    def add_view(self, data: bytes, target: int | None = None) -> int:
        self.blob.extend(b"\0" * (-len(self.blob) % 4))
        view = gltf.BufferView(buffer=0, byteOffset=len(self.blob), byteLength=len(data), target=target)
        self.blob.extend(data)
        self.doc.bufferViews.append(view)
        return len(self.doc.bufferViews) - 1

    def add_accessor(self, array: np.ndarray, kind: str, target: int, bounds: bool = False) -> int:
        component = (
            FLOAT if array.dtype == np.float32 else (UNSIGNED_SHORT if array.dtype == np.uint16 else UNSIGNED_INT)
        )
        view = self.add_view(np.ascontiguousarray(array).tobytes(), target)
        accessor = gltf.Accessor(bufferView=view, componentType=component, count=len(array), type=kind)
        if bounds:
            accessor.min = [float(v) for v in array.min(0)]
            accessor.max = [float(v) for v in array.max(0)]
        self.doc.accessors.append(accessor)
        return len(self.doc.accessors) - 1

    def add_geometry(self, geometry: PreviewGeometry) -> gltf.Primitive:
        """The geometry's accessors, as a primitive without a material (meshes share them)."""
        attributes = gltf.Attributes(
            POSITION=self.add_accessor(geometry.positions, gltf.VEC3, ARRAY_BUFFER, bounds=True),
            NORMAL=self.add_accessor(geometry.normals, gltf.VEC3, ARRAY_BUFFER),
            TANGENT=self.add_accessor(geometry.tangents, gltf.VEC4, ARRAY_BUFFER),
            TEXCOORD_0=self.add_accessor(geometry.uvs, gltf.VEC2, ARRAY_BUFFER),
        )
        flat = geometry.indices.reshape(-1)
        small = len(geometry.positions) < 65535
        indices = self.add_accessor(flat.astype(np.uint16 if small else np.uint32), gltf.SCALAR, ELEMENT_ARRAY_BUFFER)
        return gltf.Primitive(attributes=attributes, indices=indices, mode=gltf.TRIANGLES)

    # ----------------------------------------------------------------------- textures

    def texture(self, image: Artifact) -> int:
        if image.name not in self.images:
            if self.embed_images:
                content = image.content if isinstance(image.content, bytes) else image.content.encode()
                entry = gltf.Image(bufferView=self.add_view(content), mimeType="image/png")
            else:
                entry = gltf.Image(uri=quote(image.name))
            self.doc.images.append(entry)
            self.images[image.name] = len(self.doc.images) - 1
        if not self.doc.samplers:
            self.doc.samplers.append(
                gltf.Sampler(magFilter=LINEAR, minFilter=LINEAR_MIPMAP_LINEAR, wrapS=REPEAT, wrapT=REPEAT)
            )
        self.doc.textures.append(gltf.Texture(sampler=0, source=self.images[image.name]))
        return len(self.doc.textures) - 1

    # ---------------------------------------------------------------------- materials

    def add_material(
        self, material: Material, images: Mapping[str, Artifact], thickness: float, uv_metres: float | None = None
    ) -> int:
        """The material with its baked images (role -> image: base_color, metallic_roughness, normal).
        `uv_metres`: metres one UV unit spans on the mesh; each map then gets a KHR_texture_transform
        scale so it shows at its real size (its graph's metres per texture unit)."""
        factors = gltf_material.core(material)
        exts = gltf_material.extensions(material, thickness)
        pbr = gltf.PbrMetallicRoughness(**factors)
        entry = gltf.Material(name=material.name, pbrMetallicRoughness=pbr, extensions=exts)
        entry.extras = {"cnlmc": {"phrase": phrase_text(material)}}
        for role, image in images.items():
            index = self.texture(image)
            transform = self.real_size(material, role, uv_metres)
            if role == "base_color":
                pbr.baseColorTexture = gltf.TextureInfo(index=index, extensions=transform)
                if material.model.base != "conductor":  # the map is the colour; on a metal it tints f0
                    pbr.baseColorFactor = [1.0, 1.0, 1.0, 1.0]
            elif role == "metallic_roughness":
                pbr.metallicRoughnessTexture = gltf.TextureInfo(index=index, extensions=transform)
                pbr.metallicFactor = 1.0 if "metallic" in material.maps else pbr.metallicFactor
                pbr.roughnessFactor = 1.0 if "roughness" in material.maps else pbr.roughnessFactor
            elif role == "normal":
                entry.normalTexture = gltf.NormalMaterialTexture(index=index, scale=1.0, extensions=transform)
        self.used.update(exts)
        self.doc.materials.append(entry)
        return len(self.doc.materials) - 1

    def real_size(self, material: Material, role: str, uv_metres: float | None) -> dict[str, Any]:
        """{KHR_texture_transform: {scale}} that shows the map of `role` at its graph's real size on
        a mesh whose UV unit spans `uv_metres`; {} when either is unknown or the scale is 1."""
        refs = [material.maps[r] for r in PACKED_FROM.get(role, (role,)) if r in material.maps]
        unit = metres_per_unit(refs[0].graph) if refs else None
        if uv_metres is None or not unit or abs(uv_metres / unit - 1.0) < 1e-6:
            return {}
        self.used.add(TRANSFORM)
        scale = round(uv_metres / unit, 6)
        return {TRANSFORM: {"scale": [scale, scale]}}

    def add_variant(self, name: str) -> int:
        """The variant called `name` (variants are global in glTF: one name switches every object
        that has an alternative of that name, e.g. 'red' on both 'red or green glass' and
        'red or blue plastic')."""
        if name not in self.variant_names:
            self.variant_names.append(name)
        return self.variant_names.index(name)

    # ------------------------------------------------------------------------- scene

    def add_object(
        self,
        name: str,
        geometry: gltf.Primitive,
        materials: Sequence[tuple[int, int | None]],
        translation: Sequence[float],
    ) -> None:
        """A node with a mesh showing the first material; (material, variant) pairs with a variant
        become the primitive's KHR_materials_variants mappings."""
        primitive = gltf.Primitive(
            attributes=geometry.attributes, indices=geometry.indices, mode=gltf.TRIANGLES, material=materials[0][0]
        )
        mappings = [{"material": m, "variants": [v]} for m, v in materials if v is not None]
        if mappings:
            primitive.extensions = {VARIANTS: {"mappings": mappings}}
        self.doc.meshes.append(gltf.Mesh(name=name, primitives=[primitive]))
        node = gltf.Node(name=name, mesh=len(self.doc.meshes) - 1, translation=[float(t) for t in translation])
        self.doc.nodes.append(node)

    def finish(self) -> None:
        self.doc.scenes = [gltf.Scene(name=GENERATOR, nodes=list(range(len(self.doc.nodes))))]
        self.doc.scene = 0
        if self.variant_names and self.doc.meshes:
            self.doc.extensions = {VARIANTS: {"variants": [{"name": n} for n in self.variant_names]}}
            self.used.add(VARIANTS)
        self.doc.extensionsUsed = sorted(self.used)
        self.blob.extend(b"\0" * (-len(self.blob) % 4))

    # ------------------------------------------------------------------------ output

    def glb(self) -> bytes:
        self.finish()
        if self.blob:
            self.doc.buffers = [gltf.Buffer(byteLength=len(self.blob))]
            self.doc.set_binary_blob(bytes(self.blob))
        data = self.doc.save_to_bytes()
        return b"".join(data) if isinstance(data, list) else bytes(data)

    def gltf_json(self) -> str:
        """The .gltf text: the buffer as a base64 data URI, images by relative URI."""
        self.finish()
        if self.blob:
            uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode("ascii")
            self.doc.buffers = [gltf.Buffer(byteLength=len(self.blob), uri=uri)]
        return json.dumps(json.loads(self.doc.to_json()), indent=1, ensure_ascii=False) + "\n"
