"""OpenGL helpers of the preview: a headless context (moderngl on EGL), the shader sources
shipped with the package, uniforms and float textures. What is made in a context is cached by
`resources.Resources`, which owns the context."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

import jinja2
import numpy as np

SHADERS = Path(__file__).parent / "shaders"
IBL_FILES = {"ambient": "ibl_ambient.glsl", "splitsum": "ibl_splitsum.glsl", "sampled": "ibl_sampled.glsl"}


class PreviewUnavailable(RuntimeError):
    """No OpenGL 3.3 context can be created here (no EGL / Mesa)."""


def create_context() -> Any:
    """A new standalone EGL context (GL 3.3+ core), made current."""
    try:
        import moderngl

        settings: dict[str, Any] = {"standalone": True, "backend": "egl", "require": 330}
        return moderngl.create_context(**settings)
    except Exception as exc:  # pragma: no cover - depends on the machine
        raise PreviewUnavailable(
            f"preview: cannot create an OpenGL context on EGL ({exc}); "
            "install libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri"
        ) from None


@lru_cache(maxsize=1)
def templates() -> jinja2.Environment:
    """The loader of the package's shader templates (immutable package data: one per process)."""
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(SHADERS)),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )


def shader_file(name: str) -> str:
    return (SHADERS / name).read_text("utf-8")


def preview_fragment(name: str, library: str, plan: Any, ibl: str) -> str:
    return (
        templates()
        .get_template("preview.frag.j2")
        .render(name=name, library=library, plan=plan, ibl=ibl, IBL_FILES=IBL_FILES)
    )


def set_uniform(prog: Any, name: str, value: Any) -> None:
    """Write a uniform if the program uses it (matrices are given row-major, numpy style)."""
    if name not in prog:
        return
    member = prog[name]
    arr = np.asarray(value, np.float32)
    if getattr(member, "array_length", 1) > 1:
        member.write(np.ascontiguousarray(arr).tobytes())
    elif arr.ndim == 2:
        member.write(np.ascontiguousarray(arr.T).tobytes())
    elif isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        member.value = int(value)
    elif arr.ndim == 0:
        member.value = float(arr)
    else:
        member.value = tuple(float(x) for x in arr)


def float_texture(ctx: Any, array: np.ndarray, mipmaps: bool = True, repeat: tuple = (True, True)) -> Any:
    """A float32 texture in `ctx` from (H, W[, C]) with row 0 at v = 0, trilinear and mip-mapped."""
    import moderngl

    array = np.ascontiguousarray(array, np.float32)
    components = 1 if array.ndim == 2 else array.shape[2]
    tex = ctx.texture((array.shape[1], array.shape[0]), components, array.tobytes(), dtype="f4")
    tex.repeat_x, tex.repeat_y = repeat
    if mipmaps:
        tex.build_mipmaps()
        tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    else:
        tex.filter = (moderngl.LINEAR, moderngl.LINEAR)
    return tex
