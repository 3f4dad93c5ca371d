"""What a frame shows: the mesh, the camera, the environment and how the background is drawn."""

from __future__ import annotations

from dataclasses import dataclass

from .camera import Camera, framing_camera
from .environment import Environment, environment
from .mesh import Mesh
from .meshes import fit, mesh_by_name, sphere_for_pixels


@dataclass
class Scene:
    mesh: Mesh
    camera: Camera
    env: Environment
    background: str = "env"  # "env" (blurred environment), "transparent", "none"
    background_lod: float = 3.0
    exposure: float = 1.0
    env_intensity: float = 1.0
    glass: str = "auto"  # "solid", "thin" (a sheet) or "auto" (by mesh.closed): how glass transmits (glass.py)


def scene_mesh(name: str, size: tuple[int, int]) -> Mesh:
    """The named mesh (or file) fitted for a frame of `size`; the built-in sphere is tessellated
    for its size on screen (the framing fits it inside min(size) pixels: radius below half)."""
    if name == "sphere":
        return sphere_for_pixels(0.5 * min(size))
    return fit(mesh_by_name(name))


def default_scene(mesh: str | Mesh = "sphere", env: str | Environment = "studio", size=(512, 512)) -> Scene:
    """The framed preview scene, its mesh and environment made anew when named
    (Renderer.scene keeps them)."""
    mesh = scene_mesh(mesh, size) if isinstance(mesh, str) else mesh
    env = environment(env) if isinstance(env, str) else env
    lo, hi = mesh.bounds
    return Scene(mesh, framing_camera(lo, hi, aspect=size[0] / size[1]), env)
