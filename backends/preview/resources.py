"""What renderers make once and reuse, and who owns it: `Resources` holds one OpenGL context and
every object made in it (linked programs, textures, buffers, vertex arrays, framebuffers), plus
the CPU-side material shaders and albedo tables they are made from.

Everything is cached by what it is made from, never by object identity: programs by their
source text, environment textures by `Environment.content_key`, mesh buffers by `Mesh.key`,
a material's shader, maps and tables by the material's content and the options. It all lives
as long as the Resources object (renderers that share one share its caches) and goes with
`release()`, which frees the context and everything in it."""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from typing import Any, TypeVar

from ..glsl.render import ShaderWriter
from . import gl
from .albedo_tables import TableCache

T = TypeVar("T")


def source_key(*sources: str) -> str:
    """The digest programs are cached by: their shader sources."""
    return hashlib.sha256("\0".join(sources).encode()).hexdigest()


class Resources:
    """One GL context and what is made in it, each once (see the module docstring)."""

    def __init__(self) -> None:
        self.ctx = gl.create_context()
        self.tables = TableCache()
        self.shader_writer = ShaderWriter()  # the GLSL backend's templates and snippets, loaded once
        self._made: dict[tuple, Any] = {}
        self._warm: set[tuple] = set()

    def make_current(self) -> Any:
        """The context, made current on this thread first: another GL context (an engine's, a
        test's, another renderer's) may have been made current since."""
        self.ctx.__enter__()  # no matching exit: it stays current for our calls
        return self.ctx

    def once(self, key: tuple, make: Callable[[], T]) -> T:
        """The object made for `key` (a tuple of content keys whose first item names the kind),
        made by `make()` the first time it is asked for."""
        if key not in self._made:
            self._made[key] = make()
        made: T = self._made[key]
        return made

    def program(self, vertex: str, fragment: str) -> Any:
        """A linked program, cached by its sources (compile errors carry the log)."""
        key = ("program", source_key(vertex, fragment))
        return self.once(key, lambda: self.make_current().program(vertex_shader=vertex, fragment_shader=fragment))

    def fullscreen(self, fragment_file: str, define: str = "") -> tuple[Any, Any]:
        """(program, vertex array) of a full-screen pass over the package's `fragment_file`;
        `define` names a preprocessor symbol defined for this variant (llvmpipe runs both sides of
        every branch, even on a uniform: a variant that leaves work out must be its own program)."""

        def make() -> tuple[Any, Any]:
            source = gl.shader_file(fragment_file)
            if define:
                version, rest = source.split("\n", 1)
                source = f"{version}\n#define {define}\n{rest}"
            prog = self.program(gl.shader_file("fullscreen.vert"), source)
            return prog, self.make_current().vertex_array(prog, [])

        return self.once(("fullscreen", fragment_file, define), make)

    def float_texture(self, array: Any, mipmaps: bool = True, repeat: tuple = (True, True)) -> Any:
        """A new (uncached) float texture in this context: see gl.float_texture."""
        return gl.float_texture(self.make_current(), array, mipmaps, repeat)

    def first_use(self, key: tuple) -> bool:
        """True the first time `key` is seen (a frame whose programs and uploads are not made yet)."""
        if key in self._warm:
            return False
        self._warm.add(key)
        return True

    def release(self) -> None:
        """Free the context and everything made in it; the object cannot be used afterwards."""
        self._made.clear()
        self._warm.clear()
        self.ctx.release()
