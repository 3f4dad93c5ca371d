"""What the studio's live view (static/view/view.js, class MaterialView) draws, as data: one
compiled material's payload and the named static assets (environments, meshes, the full-screen
passes). The work is the preview backend's (cnlmc.backends.preview.web): the same shader, tables,
environment and mesh as `cnlmc preview`, so the browser frame agrees with it (docs/studio.md, "View").

    payload = material_payload(ir["materials"][0], session_folder)   # JSON-serialisable
    data, content_type = static_asset("env/studio")                  # or None for an unknown name
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from cnlmc.output import safe_name, write_files


def material_payload(material_ir: dict[str, Any], files: Path) -> dict[str, Any]:
    """How to draw one compiled material (its IR object); baked maps go into `files` (through
    cnlmc.output, named by content: a map already there is not baked again)."""
    from cnlmc.backends.preview.web import WebScene

    root = Path(files)

    def write(named: list[tuple[str, bytes]]) -> None:
        write_files([(safe_name(name, root), data) for name, data in named], root=root)

    def exists(name: str) -> bool:
        return safe_name(name, root).is_file()

    return WebScene().material(material_ir, write, exists)


def static_asset(name: str) -> tuple[bytes, str] | None:
    """(bytes, content type) of `env/<studio|sky|sun>`, `mesh/<sphere|shader_ball|teapot>` or
    `shader/<fullscreen.vert|prefilter.frag|background.frag|tonemap.frag>`; None for any other name."""
    from cnlmc.backends.preview.web import WebScene

    scene = WebScene()
    try:
        return scene.asset(name)
    finally:
        scene.close()  # an environment missing from the disk cache was prefiltered in an OpenGL context
