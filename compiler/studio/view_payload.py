"""What the studio's live view (static/view/view.js, class MaterialView) draws, as data: one
compiled material's payload and the named static assets (environments, meshes, the full-screen
passes). The work is the preview backend's (cnlmc.backends.preview.web): the same shader, tables,
environment and mesh as `cnlmc preview`, so the browser frame agrees with it (docs/studio.md, "View").

    payload = material_payload(ir["materials"][0], session_folder)   # JSON-serialisable
    data, content_type = static_asset("env/studio")                  # or None for an unknown name

A server keeps one `ViewScene` instead: one WebScene (its tables, GLSL templates, OpenGL context)
used on one worker thread of its own, so builds never run on the event loop nor side by side.
"""

from __future__ import annotations

from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import Any

from cnlmc.output import safe_name, write_files


def material_payload(material_ir: dict[str, Any], files: Path) -> dict[str, Any]:
    """How to draw one compiled material (its IR object); baked maps go into `files` (through
    cnlmc.output, named by content: a map already there is not baked again)."""
    from cnlmc.backends.preview.web import WebScene

    scene = WebScene()
    try:
        return _payload(scene, material_ir, files)
    finally:
        scene.close()


def _payload(scene: Any, material_ir: dict[str, Any], files: Path) -> dict[str, Any]:
    root = Path(files)

    def write(named: list[tuple[str, bytes]]) -> None:
        write_files([(safe_name(name, root), data) for name, data in named], root=root)

    def exists(name: str) -> bool:
        return safe_name(name, root).is_file()

    found: dict[str, Any] = scene.material(material_ir, write, exists)
    return found


def static_asset(name: str) -> tuple[bytes, str] | None:
    """(bytes, content type) of `env/<studio|sky|sun>`, `mesh/<sphere|shader_ball|teapot>` or
    `shader/<fullscreen.vert|prefilter.frag|background.frag|tonemap.frag>`; None for any other name."""
    from cnlmc.backends.preview.web import WebScene

    scene = WebScene()
    try:
        return scene.asset(name)
    finally:
        scene.close()  # an environment missing from the disk cache was prefiltered in an OpenGL context


class ViewScene:
    """The server's one WebScene, made on first need and used only on its own worker thread (one
    build at a time: the OpenGL context is current there); `close` releases it."""

    def __init__(self) -> None:
        self.worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cnlmc-view")
        self.scene: Any = None

    def _scene(self) -> Any:
        if self.scene is None:
            from cnlmc.backends.preview.web import WebScene

            self.scene = WebScene()
        return self.scene

    def payload(self, material_ir: dict[str, Any], files: Path) -> dict[str, Any]:
        """material_payload, on the scene's thread (the caller waits)."""
        return self.worker.submit(lambda: _payload(self._scene(), material_ir, files)).result()

    def asset(self, name: str) -> Future[tuple[bytes, str] | None]:
        """static_asset's answer, built on the scene's thread (await it with asyncio.wrap_future)."""
        return self.worker.submit(lambda: self._scene().asset(name))

    def close(self) -> None:
        def release() -> None:
            if self.scene is not None:
                self.scene.close()
                self.scene = None

        self.worker.submit(release).result()
        self.worker.shutdown(wait=True)
