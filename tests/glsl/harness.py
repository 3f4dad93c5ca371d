"""Evaluate an emitted `cnlm_bsdf` on the GPU for given directions and compare with
`cnlmc.bsdf.evaluate`.

Directions go in as two RGBA32F data textures (wo, wi), one pair per pixel; a full-screen
triangle calls cnlm_bsdf (or cnlm_btdf)(n = +z, t = +x, wo, wi) and writes RGBA32F."""

from __future__ import annotations

import numpy as np

SIDE = 64  # 4096 direction pairs per material

VERTEX = """#version 330 core
in vec2 in_vert;
void main() { gl_Position = vec4(in_vert, 0.0, 1.0); }
"""

FRAGMENT_MAIN = """
uniform sampler2D cnlm_test_wo;
uniform sampler2D cnlm_test_wi;
uniform mat3 cnlm_test_frame;  // the local frame in "world" space (identity: n = +z, t = +x)
out vec4 cnlm_test_out;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 wo = texelFetch(cnlm_test_wo, p, 0).xyz;
    vec3 wi = texelFetch(cnlm_test_wi, p, 0).xyz;
    mat3 r = cnlm_test_frame;
    cnlm_test_out = vec4(ENTRY(r[2], r[0], r * wo, r * wi, vec2(0.5)), 1.0);
}
"""


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _hemisphere(rng, n, mu_low=0.0, mu_high=1.0):
    mu = rng.uniform(mu_low, mu_high, n)
    phi = rng.uniform(0, 2 * np.pi, n)
    s = np.sqrt(1 - mu * mu)
    return np.stack([s * np.cos(phi), s * np.sin(phi), mu], -1)


def _near_mirror(rng, wo, spread):
    """wi = reflect(wo) tilted by up to `spread` radians: samples the specular peak."""
    wi = wo * np.array([-1.0, -1.0, 1.0])
    jitter = rng.normal(size=wi.shape) * spread[:, None]
    wi = _unit(wi + jitter)
    wi[:, 2] = np.abs(wi[:, 2])
    return _unit(wi)


def direction_pairs(seed: int = 7) -> tuple[np.ndarray, np.ndarray]:
    """SIDE² (wo, wi) pairs, float32-exact: uniform, grazing (cos down to 1e-6), the specular
    peak of α = 1e-3 and wider lobes, exact mirror pairs and below-horizon pairs."""
    rng = np.random.default_rng(seed)
    n = SIDE * SIDE
    q = n // 8
    wo_parts, wi_parts = [], []
    wo_parts.append(_hemisphere(rng, 3 * q))
    wi_parts.append(_hemisphere(rng, 3 * q))
    wo_parts.append(_hemisphere(rng, q, 1e-6, 2e-2))
    wi_parts.append(_hemisphere(rng, q))  # grazing view
    wo_parts.append(_hemisphere(rng, q))
    wi_parts.append(_hemisphere(rng, q, 1e-6, 2e-2))  # grazing light
    for spread in (3e-3, 0.2):
        wo = _hemisphere(rng, q // 2, 0.05, 1.0)
        wo_parts.append(wo)
        wi_parts.append(_near_mirror(rng, wo, rng.uniform(0, spread, q // 2)))
    wo = _hemisphere(rng, q // 2, 0.02, 1.0)
    wo_parts.append(wo)
    wi_parts.append(wo * np.array([-1.0, -1.0, 1.0]))  # exact mirror
    rest = n - sum(len(p) for p in wo_parts)
    wo = _hemisphere(rng, rest)
    wo_parts.append(wo)
    wi_parts.append(-wo[::-1])  # below the horizon: must be 0
    wo = np.concatenate(wo_parts).astype(np.float32)
    wi = np.concatenate(wi_parts).astype(np.float32)
    return wo.reshape(SIDE, SIDE, 3), wi.reshape(SIDE, SIDE, 3)


class Evaluator:
    """Compiles library sources into evaluation programs (cached by source) and runs them."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.programs: dict[str, object] = {}
        self.fbo = ctx.framebuffer(color_attachments=[ctx.texture((SIDE, SIDE), 4, dtype="f4")])
        self.quad = ctx.buffer(np.array([-1, -1, 3, -1, -1, 3], dtype="f4").tobytes())

    def program(self, library: str, entry: str = "cnlm_bsdf"):
        key = (library, entry)
        if key not in self.programs:
            source = "#version 330 core\n" + library + FRAGMENT_MAIN.replace("ENTRY", entry)
            self.programs[key] = self.ctx.program(vertex_shader=VERTEX, fragment_shader=source)
        return self.programs[key]

    def _texture(self, dirs):
        rgba = np.concatenate([dirs, np.zeros(dirs.shape[:-1] + (1,), np.float32)], -1)
        tex = self.ctx.texture((SIDE, SIDE), 4, rgba.astype("f4").tobytes(), dtype="f4")
        tex.filter = (self.ctx.NEAREST, self.ctx.NEAREST)
        return tex

    def evaluate(self, library: str, uniforms: list[dict], wo, wi, frame=None, entry: str = "cnlm_bsdf") -> np.ndarray:
        """``entry``(n, t, v, l, uv) per pixel: cnlm_bsdf, or cnlm_btdf for glass."""
        prog = self.program(library, entry)
        prog["cnlm_test_frame"].value = tuple(
            np.asarray(np.eye(3) if frame is None else frame, np.float64).T.ravel()
        )  # column-major
        for u in uniforms:
            if u["name"] in prog:
                value = u["value"]
                prog[u["name"]].value = tuple(value) if isinstance(value, list) else value
        tex_o, tex_i = self._texture(wo), self._texture(wi)
        tex_o.use(0)
        tex_i.use(1)
        prog["cnlm_test_wo"].value, prog["cnlm_test_wi"].value = 0, 1
        vao = self.ctx.vertex_array(prog, [(self.quad, "2f", "in_vert")])
        self.fbo.use()
        self.fbo.clear(0.0, 0.0, 0.0, 0.0)
        vao.render(vertices=3)
        out = np.frombuffer(self.fbo.read(components=4, dtype="f4"), np.float32).reshape(SIDE, SIDE, 4)
        vao.release()
        tex_o.release()
        tex_i.release()
        return out[..., :3]


def relative_error(gpu: np.ndarray, ref: np.ndarray, floor: float = 1e-3) -> tuple[float, tuple]:
    """Max |gpu - ref| / |ref| over entries with |ref| > floor, and where it happens."""
    mask = np.abs(ref) > floor
    if not mask.any():
        return 0.0, ()
    err = np.where(mask, np.abs(gpu - ref) / np.where(mask, np.abs(ref), 1.0), 0.0)
    where = np.unravel_index(np.argmax(err), err.shape)
    return float(err[where]), where


def _refracted(w, ior):
    """Smooth refraction of w through the plane z = 0 (outside index 1 above, ``ior`` below);
    the zero vector under total internal reflection."""
    eta = np.where(w[:, 2] > 0, ior, 1.0 / ior)  # index behind / index on w's side
    ct2 = 1.0 - (1.0 - w[:, 2] ** 2) / eta**2
    t = -w / eta[:, None]
    t[:, 2] = -np.sign(w[:, 2]) * np.sqrt(np.maximum(ct2, 0.0))
    return np.where((ct2 >= 0)[:, None], t, 0.0)


def transmission_pairs(ior: float = 1.5, seed: int = 11) -> tuple[np.ndarray, np.ndarray]:
    """SIDE² (wo, wi) pairs for cnlm_btdf, float32-exact, with both sides of the interface as
    the view side: uniform opposite-side pairs, grazing view / light (|cos| down to 1e-6),
    the refraction peak (spreads 1e-3 and 0.2 rad, and exact), views from inside beyond the
    critical angle (total internal reflection region), same-side pairs and in-plane
    directions (both must give exactly 0)."""
    rng = np.random.default_rng(seed)
    n = SIDE * SIDE
    q = n // 8

    def flip_some(w):
        sign = np.where(rng.uniform(size=len(w)) < 0.5, -1.0, 1.0)
        return w * np.stack([np.ones_like(sign), np.ones_like(sign), sign], -1)

    def opposite(wo, wi):
        wi = wi.copy()
        wi[:, 2] = -np.sign(wo[:, 2]) * np.abs(wi[:, 2])
        return wi

    wo_parts, wi_parts = [], []
    wo = flip_some(_hemisphere(rng, 2 * q))
    wo_parts.append(wo)
    wi_parts.append(opposite(wo, _hemisphere(rng, 2 * q)))
    wo = flip_some(_hemisphere(rng, q // 2, 1e-6, 2e-2))
    wo_parts.append(wo)
    wi_parts.append(opposite(wo, _hemisphere(rng, q // 2)))  # grazing view
    wo = flip_some(_hemisphere(rng, q // 2))
    wo_parts.append(wo)
    wi_parts.append(opposite(wo, _hemisphere(rng, q // 2, 1e-6, 2e-2)))  # grazing light
    for spread in (1e-3, 0.2):
        wo = flip_some(_hemisphere(rng, q, 0.05, 1.0))
        t = _refracted(wo, ior)
        ok = np.any(t != 0, axis=1)
        wo, t = wo[ok], t[ok]
        wi = _unit(t + rng.normal(size=t.shape) * rng.uniform(0, spread, len(t))[:, None])
        wo_parts.append(wo)
        wi_parts.append(opposite(wo, wi))
    wo = flip_some(_hemisphere(rng, q // 2, 0.05, 1.0))
    t = _refracted(wo, ior)
    ok = np.any(t != 0, axis=1)
    wo_parts.append(wo[ok])
    wi_parts.append(t[ok])  # exact refraction
    mu_c = np.sqrt(1.0 - 1.0 / ior**2)
    wo = _hemisphere(rng, q, 1e-3, mu_c) * np.array([1.0, 1.0, -1.0])  # inside, beyond critical
    wo_parts.append(wo)
    wi_parts.append(_hemisphere(rng, q))
    wo = flip_some(_hemisphere(rng, q // 2))
    wo_parts.append(wo)
    wi_parts.append(-opposite(wo, _hemisphere(rng, q // 2)))  # same side: 0
    wo = flip_some(_hemisphere(rng, 64))
    wi = opposite(wo, _hemisphere(rng, 64))
    wi[:32, 2] = 0.0
    wo[32:, 2] = 0.0  # in the plane: 0
    wo_parts.append(_unit(wo))
    wi_parts.append(_unit(wi))
    wo, wi = np.concatenate(wo_parts), np.concatenate(wi_parts)
    rest = n - len(wo)
    extra = flip_some(_hemisphere(rng, rest))
    wo = np.concatenate([wo, extra]).astype(np.float32)
    wi = np.concatenate([wi, opposite(extra, _hemisphere(rng, rest))]).astype(np.float32)
    return wo.reshape(SIDE, SIDE, 3), wi.reshape(SIDE, SIDE, 3)
