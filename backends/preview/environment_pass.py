"""The environment on the GPU: its radiance texture, the GGX-prefiltered levels, the irradiance
map and exact-alpha prefilters (EnvResources), how the object pass reads them
(bind_environment) and the background pass (the blurred environment behind the object)."""

from __future__ import annotations

from typing import Any

import numpy as np

from . import gl
from .environment import Environment
from .resources import Resources
from .scene import Scene
from .targets import Targets
from .tiers import Tier

PREFILTER_LEVELS = 5
PREFILTER_SAMPLES = 256
IRRADIANCE_SIZE, IRRADIANCE_SAMPLES = (64, 32), 2048


class EnvResources:
    """Environment textures: radiance (mip-mapped), GGX-prefiltered levels, and on demand the
    environment prefiltered at one alpha and the irradiance map (made in `resources`' context)."""

    def __init__(self, env: Environment, resources: Resources):
        self.env = env
        self.resources = resources
        self.radiance = resources.float_texture(env.image, repeat=(True, False))
        self.size = (env.image.shape[1], env.image.shape[0])
        self.mean = env.mean_radiance
        self.prefiltered = self._prefilter()
        self._at_alpha: dict = {}
        self._irradiance = None

    def prefiltered_at(self, alpha: float):
        """The environment prefiltered at exactly this GGX alpha (full resolution, one level;
        cached): the split-sum tier of a material whose alpha is uniform needs no mip blend."""
        key = round(float(alpha), 6)
        if key not in self._at_alpha:
            self._at_alpha[key] = self._prefilter_level(key)
        return self._at_alpha[key]

    @property
    def irradiance(self):
        """E(n) / pi as a small equirect texture (cosine-weighted prefilter), made on first use."""
        if self._irradiance is None:
            data = self._prefilter_pass(1.0, IRRADIANCE_SIZE, IRRADIANCE_SAMPLES, cosine=True)
            self._irradiance = self.resources.float_texture(data, mipmaps=False, repeat=(True, False))
        return self._irradiance

    def _prefilter_pass(self, alpha: float, size: tuple, samples: int, cosine: bool = False) -> np.ndarray:
        """One pass of prefilter.frag at `alpha` into a (h, w, 3) float32 array."""
        import moderngl

        ctx = self.resources.make_current()
        prog = self.resources.program(gl.shader_file("fullscreen.vert"), gl.shader_file("prefilter.frag"))
        vao = ctx.vertex_array(prog, [])
        self.radiance.use(0)
        gl.set_uniform(prog, "pv_env", 0)
        gl.set_uniform(prog, "pv_samples", samples)
        gl.set_uniform(prog, "pv_env_size", self.size)
        gl.set_uniform(prog, "pv_alpha", alpha)
        gl.set_uniform(prog, "pv_cosine", int(cosine))
        target = ctx.texture(size, 4, dtype="f4")
        fbo = ctx.framebuffer([target])
        fbo.use()
        ctx.viewport = (0, 0, *size)
        vao.render(moderngl.TRIANGLES, vertices=3)
        data = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32).reshape(size[1], size[0], 4)[..., :3]
        for item in (vao, fbo, target):
            item.release()
        return np.ascontiguousarray(data)

    def _prefilter_level(self, alpha: float):
        data = self._prefilter_pass(alpha, self.size, PREFILTER_SAMPLES)
        return self.resources.float_texture(data, mipmaps=False, repeat=(True, False))

    def _prefilter(self, samples: int = PREFILTER_SAMPLES):
        """The mip chain: level k holds the environment prefiltered at sqrt(alpha) = k / LEVELS."""
        tex = self.resources.float_texture(self.env.image, repeat=(True, False))
        for level in range(1, PREFILTER_LEVELS + 1):
            size = (max(self.size[0] >> level, 4), max(self.size[1] >> level, 2))
            data = self._prefilter_pass((level / PREFILTER_LEVELS) ** 2, size, samples)
            tex.write(data.tobytes(), level=level)
        return tex


def env_resources(resources: Resources, env: Environment) -> EnvResources:
    """The environment's textures in `resources`' context, made once per environment content."""
    return resources.once(("environment", env.content_key), lambda: EnvResources(env, resources))


def bind_environment(prog: Any, res: EnvResources, scene: Scene, tier: Tier, first_unit: int) -> int:
    """Bind the environment's textures from texture unit `first_unit` on and set the object
    program's environment uniforms; returns the next free unit."""
    units = {"pv_env": res.radiance, "pv_env_prefiltered": res.prefiltered}
    for offset, (name, tex) in enumerate(units.items()):
        tex.use(first_unit + offset)
        gl.set_uniform(prog, name, first_unit + offset)
    gl.set_uniform(prog, "pv_prefilter_levels", float(PREFILTER_LEVELS))
    gl.set_uniform(prog, "pv_env_intensity", scene.env_intensity)
    gl.set_uniform(prog, "pv_ambient", res.mean * scene.env_intensity)
    gl.set_uniform(prog, "pv_env_size", res.size)
    gl.set_uniform(prog, "pv_samples", max(tier.samples, 1))
    gl.set_uniform(prog, "pv_filtered", int(tier.filtered))
    return first_unit + len(units)


def draw_background(resources: Resources, t: Targets, scene: Scene, res: EnvResources) -> None:
    """The blurred environment seen through each pixel, into the targets' background texture
    (1/BACKGROUND_SCALE of the frame); leaves the viewport on the whole frame."""
    import moderngl

    ctx = resources.ctx
    prog, vao = resources.fullscreen("background.frag")
    res.radiance.use(0)
    gl.set_uniform(prog, "pv_env", 0)
    gl.set_uniform(prog, "pv_env_intensity", scene.env_intensity)
    gl.set_uniform(prog, "pv_background_lod", scene.background_lod)
    gl.set_uniform(prog, "pv_inverse_view_projection", np.linalg.inv(scene.camera.view_projection))
    ctx.disable(moderngl.DEPTH_TEST)
    t.background.use()
    ctx.viewport = (0, 0, *t.background_size)
    vao.render(moderngl.TRIANGLES, vertices=3)
    ctx.viewport = (0, 0, *t.size)
