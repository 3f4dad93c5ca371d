"""Drawing the object: its program (the material's shader in the tier's template), the mesh's
buffers and vertex array, the material's textures and the environment bound, then the draw."""

from __future__ import annotations

from typing import Any

import numpy as np

from cnlmc.material import Material

from ..glsl.options import GlslOptions
from . import gl
from .environment_pass import EnvResources, bind_environment
from .flakes import flake_uniforms
from .glass import glass_uniforms, internal_paths
from .material_textures import map_textures, split_textures
from .mesh import Mesh
from .resources import Resources, source_key
from .scene import Scene
from .shader import MaterialShader
from .sheen import sheen_uniforms
from .subsurface import lut_image, subsurface_uniforms
from .tiers import Tier

VERTEX_ATTRIBUTES = (("in_position", 3), ("in_normal", 3), ("in_tangent", 3), ("in_uv", 2))


def vertex_layout(prog: Any) -> tuple[str, list[str]]:
    """The buffer format for Mesh.interleaved(); attributes the program does not use are skipped."""
    parts, names = [], []
    for name, size in VERTEX_ATTRIBUTES:
        if name in prog:
            parts.append(f"{size}f")
            names.append(name)
        else:
            parts.append(f"{size * 4}x")
    return " ".join(parts), names


def object_program(resources: Resources, shader: MaterialShader, tier: Tier) -> tuple[str, Any]:
    """(source key, program) of the object pass for this shader and tier kind, linked once."""

    def link() -> tuple[str, Any]:
        vertex = gl.shader_file("preview.vert")
        fragment = gl.preview_fragment(shader.name, shader.library, shader.plan, tier.ibl)
        return source_key(vertex, fragment), resources.program(vertex, fragment)

    return resources.once(("object program", shader.key, tier.ibl), link)


def mesh_buffers(resources: Resources, mesh: Mesh) -> tuple[Any, Any]:
    """(vertex buffer, index buffer) of the mesh, uploaded once per mesh content."""
    ctx = resources.ctx
    return resources.once(
        ("mesh", mesh.key),
        lambda: (ctx.buffer(mesh.interleaved().tobytes()), ctx.buffer(mesh.indices.astype("u4").tobytes())),
    )


def object_vertex_array(resources: Resources, program_key: str, prog: Any, mesh: Mesh) -> Any:
    """The mesh's vertex array for one program, made once."""

    def make() -> Any:
        vbo, ibo = mesh_buffers(resources, mesh)
        layout, names = vertex_layout(prog)
        return resources.ctx.vertex_array(prog, [(vbo, layout, *names)], index_buffer=ibo, index_element_size=4)

    return resources.once(("vertex array", program_key, mesh.key), make)


def subsurface_table(resources: Resources) -> Any:
    """The body term's pre-integrated table as a one-channel float32 texture, made once per context
    (read with texelFetch: snippets/subsurface.glsl)."""

    def upload() -> Any:
        tex = resources.float_texture(lut_image(), mipmaps=False, repeat=(False, False))
        tex.filter = (resources.ctx.NEAREST, resources.ctx.NEAREST)
        return tex

    return resources.once(("subsurface table",), upload)


def draw_object(
    resources: Resources,
    scene: Scene,
    material: Material,
    shader: MaterialShader,
    tier: Tier,
    res: EnvResources,
    model: np.ndarray,
    options: GlslOptions,
) -> None:
    """The object, shaded by the tier, into the current framebuffer (depth tested; back faces
    culled on a closed mesh, where they are never seen)."""
    import moderngl

    ctx = resources.ctx
    program_key, prog = object_program(resources, shader, tier)
    textures = dict(map_textures(resources, material, shader.samplers))
    if tier.ibl == "splitsum":
        textures.update(split_textures(resources, material, shader.plan, res, options))
    if shader.plan.subsurface:
        textures["pv_env_irradiance"] = res.irradiance  # the body's diffuse light (subsurface.glsl.j2)
        textures["cnlm_sss_lut"] = subsurface_table(resources)
    if material.model.base == "glass":  # what a rough ball keeps inside (transmission.glsl.j2)
        ior = float(material.params.ior)
        textures["pv_glass_paths"] = resources.once(
            ("glass paths", ior), lambda: resources.float_texture(internal_paths(ior), False, (False, False))
        )
    for unit, (name, tex) in enumerate(textures.items()):
        tex.use(unit)
        gl.set_uniform(prog, name, unit)
    bind_environment(prog, res, scene, tier, len(textures))
    cam = scene.camera
    gl.set_uniform(prog, "pv_model", model)
    gl.set_uniform(prog, "pv_normal_matrix", np.linalg.inv(model[:3, :3]).T)
    gl.set_uniform(prog, "pv_view_projection", cam.view_projection)
    gl.set_uniform(prog, "pv_camera_position", cam.position)
    gl.set_uniform(prog, "pv_key_direction", scene.env.key.unit)
    gl.set_uniform(prog, "pv_key_irradiance", [scene.env.key.irradiance * scene.env_intensity] * 3)
    if material.model.base == "glass":
        for name, value in glass_uniforms(scene.mesh, model, material.params.transmission_depth, scene.glass).items():
            gl.set_uniform(prog, name, value)
    for name, value in sheen_uniforms(material).items():
        gl.set_uniform(prog, name, value)
    for name, value in flake_uniforms(material, scene.mesh).items():
        gl.set_uniform(prog, name, value)
    for name, value in subsurface_uniforms(material, scene.mesh, model).items():
        gl.set_uniform(prog, name, value)
    ctx.enable(moderngl.DEPTH_TEST)
    if scene.mesh.closed:
        ctx.enable(moderngl.CULL_FACE)
    object_vertex_array(resources, program_key, prog, scene.mesh).render(moderngl.TRIANGLES)
    ctx.disable(moderngl.CULL_FACE)
