"""The headless OpenGL context (moderngl on EGL) and caches of what is costly to build:
programs (compiling on llvmpipe takes seconds), textures and vertex arrays."""

from __future__ import annotations

import hashlib
from functools import lru_cache
from pathlib import Path

import jinja2
import numpy as np

SHADERS = Path(__file__).parent / "shaders"
IBL_FILES = {"ambient": "ibl_ambient.glsl", "splitsum": "ibl_splitsum.glsl", "sampled": "ibl_sampled.glsl"}


class PreviewUnavailable(RuntimeError):
    """No OpenGL 3.3 context can be created here (no EGL / Mesa)."""


@lru_cache(maxsize=1)
def context():
    """One process-wide standalone EGL context (GL 3.3+ core)."""
    try:
        import moderngl

        return moderngl.create_context(standalone=True, backend="egl", require=330)
    except Exception as exc:  # pragma: no cover - depends on the machine
        raise PreviewUnavailable(
            f"preview: cannot create an OpenGL context on EGL ({exc}); "
            "install libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri"
        ) from None


def current():
    """The preview's context, made current on this thread first: another GL context (an
    engine's, a test's) may have been made current since ours was created."""
    ctx = context()
    ctx.__enter__()  # makes it current; no matching exit: it stays current for our calls
    return ctx


@lru_cache(maxsize=1)
def templates() -> jinja2.Environment:
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


def preview_fragment(name: str, library: str, plan: dict, ibl: str) -> str:
    return (
        templates()
        .get_template("preview.frag.j2")
        .render(name=name, library=library, plan=plan, ibl=ibl, IBL_FILES=IBL_FILES)
    )


_PROGRAMS: dict = {}


def program(vertex: str, fragment: str):
    """A linked program, cached by the hash of its sources (compile errors carry the log)."""
    key = hashlib.sha256((vertex + "\0" + fragment).encode()).hexdigest()
    if key not in _PROGRAMS:
        _PROGRAMS[key] = current().program(vertex_shader=vertex, fragment_shader=fragment)
    return _PROGRAMS[key]


def set_uniform(prog, name: str, value) -> None:
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


def float_texture(array: np.ndarray, mipmaps: bool = True, repeat: tuple = (True, True)):
    """A float32 texture from (H, W[, C]) with row 0 at v = 0, trilinear and mip-mapped."""
    import moderngl

    array = np.ascontiguousarray(array, np.float32)
    components = 1 if array.ndim == 2 else array.shape[2]
    tex = current().texture((array.shape[1], array.shape[0]), components, array.tobytes(), dtype="f4")
    tex.repeat_x, tex.repeat_y = repeat
    if mipmaps:
        tex.build_mipmaps()
        tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    else:
        tex.filter = (moderngl.LINEAR, moderngl.LINEAR)
    return tex
