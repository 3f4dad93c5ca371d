"""Textures on disk through the real CLI: each document owns `textures/<main file name>/`, so two
documents in one folder never share a texture; a re-compile removes its own stale textures (its
manifest) and never a file it did not write; names too long for a file are shortened."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cnlmc.filenames import NAME_MAX
from cnlmc.manifest import MANIFEST_NAME
from tests.helpers import require, run_cnlmc

require("MaterialX", "materialx")
require("OpenImageIO", "maps")
pytestmark = pytest.mark.oiio

SMALL = ("--option", "map_size=16")


def compile_to(tmp_path: Path, phrase: str, out: Path, target: str = "materialx", *extra: str) -> str:
    source = tmp_path / f"{out.name}.cnl"
    source.write_text(phrase + "\n")
    done = run_cnlmc("compile", str(source), "-t", target, "-o", str(out), *SMALL, *extra)
    assert done.returncode == 0, done.stderr
    return done.stderr


def files_under(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def referenced(document: Path) -> list[str]:
    """The texture paths a .mtlx document names."""
    text = document.read_text()
    return [part.split('"')[0] for part in text.split('value="')[1:] if part.split('"')[0].endswith(".png")]


def test_two_documents_in_one_folder_keep_their_own_textures(tmp_path: Path) -> None:
    out = tmp_path / "out"
    compile_to(tmp_path, "white varnished oak", out / "first.mtlx")
    first = files_under(out)
    compile_to(tmp_path, "walnut", out / "second.mtlx")
    after = files_under(out)
    assert {k: v for k, v in after.items() if k in first} == first  # the oak is still oak
    assert referenced(out / "first.mtlx") and all(
        p.startswith("textures/first.mtlx/") for p in referenced(out / "first.mtlx")
    )
    assert all(p.startswith("textures/second.mtlx/") for p in referenced(out / "second.mtlx"))
    for document in ("first.mtlx", "second.mtlx"):
        assert all((out / path).is_file() for path in referenced(out / document))


def test_one_stem_three_formats_do_not_collide(tmp_path: Path) -> None:
    out = tmp_path / "out"
    compile_to(tmp_path, "white varnished oak", out / "wood.mtlx")
    compile_to(tmp_path, "white varnished oak", out / "wood.usda", "usd")
    compile_to(tmp_path, "white varnished oak", out / "wood.xml", "mitsuba")
    folders = sorted(p.name for p in (out / "textures").iterdir())
    assert folders == ["wood.mtlx", "wood.usda", "wood.xml"]
    assert (
        "./textures/wood.usda/" in (out / "wood.usda").read_text()
        or "textures/wood.usda/" in (out / "wood.usda").read_text()
    )
    assert "textures/wood.xml/" in (out / "wood.xml").read_text()


def test_a_recompile_removes_its_stale_textures_and_nothing_else(tmp_path: Path) -> None:
    out = tmp_path / "out"
    compile_to(tmp_path, "white varnished oak", out / "wood.mtlx")
    own = out / "textures" / "wood.mtlx"
    oak = sorted(p.name for p in own.iterdir() if not p.name.startswith("."))
    assert oak == ["white_varnished_oak_base_color.png", "white_varnished_oak_roughness.png"]
    assert sorted(json.loads((own / MANIFEST_NAME).read_text())["files"]) == oak
    (own / "mine.png").write_bytes(b"the user's own file")
    compile_to(tmp_path, "heavily rusted iron", out / "wood.mtlx")
    names = sorted(p.name for p in own.iterdir() if not p.name.startswith("."))
    assert "mine.png" in names and not any(name.startswith("white_varnished_oak") for name in names)
    assert any(name.startswith("heavily_rusted_iron") for name in names)
    compile_to(tmp_path, "red plastic", out / "wood.mtlx")  # no textures any more
    assert files_under(out / "textures") == {"wood.mtlx/mine.png": b"the user's own file"}
    (own / "mine.png").unlink()
    compile_to(tmp_path, "heavily rusted iron", out / "wood.mtlx")
    compile_to(tmp_path, "red plastic", out / "wood.mtlx")
    assert sorted(p.name for p in out.iterdir()) == ["wood.mtlx"]  # empty texture folders go too


def test_a_folder_output_names_its_textures_after_the_main_file(tmp_path: Path) -> None:
    out = tmp_path / "out"
    compile_to(tmp_path, "white varnished oak", Path(f"{out}/"), "mitsuba")
    assert sorted(p.name for p in (out / "textures").iterdir()) == ["scene.xml"]


LONG = "a" * 300


@pytest.mark.parametrize("target", ["materialx", "usd", "mitsuba"])
def test_a_300_character_name_gets_short_file_names(tmp_path: Path, target: str) -> None:
    out = tmp_path / "out"
    compile_to(tmp_path, f"{LONG}: heavily rusted iron", out / "long.doc", target)
    names = [p.name for p in out.rglob("*")]
    assert names and all(len(name.encode()) <= NAME_MAX for name in names)
    assert any(name.startswith("a" * 100) and "~" in name for name in names)


def test_bake_with_a_300_character_name(tmp_path: Path) -> None:
    source = tmp_path / "long.cnl"
    source.write_text(f"{LONG}: heavily rusted iron\n{LONG}x: hammered copper\n")
    done = run_cnlmc("bake", str(source), "-o", str(tmp_path / "maps"), "--size", "16")
    assert done.returncode == 0, done.stderr
    names = sorted(p.name for p in (tmp_path / "maps").iterdir())
    assert all(len(n.encode()) <= NAME_MAX and n.startswith("a" * 100) for n in names)
    roles = sorted(n.split("~", 1)[1].split("_", 1)[1] for n in names)  # the role stays readable
    assert roles == ["base_color.png", "mask.png", "normal.png", "roughness.png"]


def test_mitsuba_keeps_the_name_as_written_in_the_id_comment(tmp_path: Path) -> None:
    compile_to(tmp_path, "名前 ünïcødé 🔥 Ω: red plastic", tmp_path / "out" / "u.xml", "mitsuba")
    xml = (tmp_path / "out" / "u.xml").read_text()
    assert "<!-- unicode: 名前 ünïcødé 🔥 Ω: red plastic -->" in xml and 'id="unicode"' in xml
