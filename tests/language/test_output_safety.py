"""The one output writer (cnlmc.output) through the real CLI: what -o may and may not write.

Non-regular destinations are refused (a FIFO, a link to one, a folder where a file goes; a
character device only through a unit test that proves the refusal comes before any write),
symlinks are written through, inputs are never overwritten, a multi-file result is all-or-nothing,
and every OS error is a clear usage error (exit 2) naming the path, never an internal error.
"""

from __future__ import annotations

import os
import stat
import subprocess
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cnlmc import output
from cnlmc.errors import UsageError
from tests.helpers import run_cnlmc

EXIT_USAGE = 2
SOURCE = "red plastic\n"
VARIANTS = "red or blue plastic\n"


@pytest.fixture
def source(tmp_path: Path) -> Path:
    path = tmp_path / "hull.cnl"
    path.write_text(SOURCE)
    return path


def refused(proc: subprocess.CompletedProcess[Any], *words: str) -> None:
    """Exit 2 with `cnlmc: error:` and every word on stderr; no internal error."""
    assert proc.returncode == EXIT_USAGE, proc.stderr
    stderr = proc.stderr
    assert "cnlmc: error:" in stderr and "internal error" not in stderr, stderr
    for word in words:
        assert word in stderr, stderr


def listing(folder: Path) -> dict[str, bytes | None]:
    """Every entry under `folder` (hidden temps included) with its bytes (None: not a file)."""
    return {
        str(p.relative_to(folder)): (p.read_bytes() if p.is_file() and not p.is_symlink() else None)
        for p in sorted(folder.rglob("*"))
    }


# ---------------------------------------------------------------- non-regular destinations


def test_a_fifo_is_refused_and_stays_a_fifo(tmp_path: Path, source: Path) -> None:
    fifo = tmp_path / "out.json"
    os.mkfifo(fifo)
    proc = run_cnlmc("compile", str(source), "-o", str(fifo), timeout=60)
    refused(proc, str(fifo), "FIFO", "not a regular file")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_a_symlink_to_a_fifo_is_refused_and_both_stay(tmp_path: Path, source: Path) -> None:
    fifo, link = tmp_path / "pipe", tmp_path / "out.json"
    os.mkfifo(fifo)
    link.symlink_to(fifo)
    proc = run_cnlmc("compile", str(source), "-o", str(link), timeout=60)
    refused(proc, str(link), "FIFO")
    assert link.is_symlink() and stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_a_character_device_is_refused_before_anything_is_written(monkeypatch: pytest.MonkeyPatch) -> None:
    """/dev/null itself, safely: every way the writer could touch the disk fails the test first."""

    def no_write(*args: object, **kwargs: object) -> None:
        raise AssertionError("the writer reached the disk before refusing a device")

    for name in ("_writer", "_commit", "_make_parents"):
        monkeypatch.setattr(output, name, no_write)
    monkeypatch.setattr(tempfile, "mkstemp", no_write)
    monkeypatch.setattr(os, "replace", no_write)
    with pytest.raises(UsageError, match="'/dev/null': it is a character device, not a regular file"):
        output.write_atomic(Path("/dev/null"), "{}")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_a_folder_where_the_file_goes_is_refused(tmp_path: Path) -> None:
    folder = tmp_path / "out.png"
    folder.mkdir()
    with pytest.raises(UsageError, match="out.png': it is a folder, not a regular file"):
        output.write_atomic(folder, b"png")
    assert folder.is_dir() and list(folder.iterdir()) == []


def test_preview_onto_a_folder_is_refused(tmp_path: Path, source: Path, gl_available: None) -> None:
    folder = tmp_path / "out.png"
    folder.mkdir()
    refused(run_cnlmc("preview", str(source), "-o", str(folder), "--size", "32"), str(folder), "a folder")
    assert folder.is_dir() and list(folder.iterdir()) == []


def test_a_symlinked_output_writes_through_and_stays_a_link(tmp_path: Path, source: Path) -> None:
    real, link = tmp_path / "real.json", tmp_path / "link.json"
    real.write_text("old")
    link.symlink_to(real.name)
    proc = run_cnlmc("compile", str(source), "-o", str(link))
    assert proc.returncode == 0, proc.stderr
    assert link.is_symlink() and os.readlink(link) == real.name
    assert real.read_text().lstrip().startswith("{")
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []


# ---------------------------------------------------------------- inputs are never overwritten


@pytest.mark.parametrize("target", ["ir", "glsl"])
def test_compile_never_overwrites_its_source(source: Path, target: str) -> None:
    proc = run_cnlmc("compile", str(source), "-t", target, "-o", str(source))
    refused(proc, "refusing to write", str(source), "input file")
    assert source.read_text() == SOURCE


@pytest.mark.parametrize("how", ["symlink", "hardlink", "relative"])
def test_the_source_is_recognised_through_any_path(tmp_path: Path, source: Path, how: str) -> None:
    other = tmp_path / "other.json"
    if how == "symlink":
        other.symlink_to(source)
    elif how == "hardlink":
        os.link(source, other)
    else:
        other = tmp_path / "sub" / ".." / source.name
        (tmp_path / "sub").mkdir()
    refused(run_cnlmc("compile", str(source), "-o", str(other)), "input file")
    assert source.read_text() == SOURCE


def test_preview_never_overwrites_its_source(source: Path, gl_available: None) -> None:
    proc = run_cnlmc("preview", str(source), "-o", str(source), "--size", "32")
    refused(proc, "refusing to write", str(source))
    assert source.read_text() == SOURCE


def test_bake_into_the_source_file_is_refused(source: Path) -> None:
    refused(run_cnlmc("bake", str(source), "-o", str(source)), "not a folder")
    assert source.read_text() == SOURCE


# ---------------------------------------------------------------- all-or-nothing


def test_a_directory_among_the_destinations_changes_nothing(tmp_path: Path) -> None:
    src = tmp_path / "v.cnl"
    src.write_text(VARIANTS)
    out = tmp_path / "gl"
    assert run_cnlmc("compile", str(src), "-t", "glsl", "-o", f"{out}/").returncode == 0
    written = sorted(p.name for p in out.iterdir())
    assert len(written) > 2
    for p in out.iterdir():
        p.write_text("old")
    blocker = out / written[-1]
    blocker.unlink()
    blocker.mkdir()
    before = listing(tmp_path)
    proc = run_cnlmc("compile", str(src), "-t", "glsl", "-o", f"{out}/")
    refused(proc, str(blocker), "folder")
    assert listing(tmp_path) == before  # nothing changed, no temp left


def test_a_rename_failing_midway_puts_every_file_back(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    names = ["a.glsl", "b.frag", "c.vert"]
    (tmp_path / "a.glsl").write_text("old a")
    (tmp_path / "b.frag").write_text("old b")  # c.vert does not exist yet
    before = listing(tmp_path)
    real_replace, calls = os.replace, list[str | Path]()

    def failing_replace(src: str | Path, dst: str | Path) -> None:
        calls.append(dst)
        if len(calls) == 2:  # the second destination's rename fails (a full disk, a race)
            raise OSError(28, "No space left on device", str(dst))
        real_replace(src, dst)

    monkeypatch.setattr(os, "replace", failing_replace)
    files = [(tmp_path / name, f"new {name}") for name in names]
    with pytest.raises(UsageError, match=r"b\.frag': No space left on device"):
        output.write_files(files)
    monkeypatch.setattr(os, "replace", real_replace)
    assert listing(tmp_path) == before


def test_a_failing_write_removes_its_temps_and_new_folders(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    real_writer, staged = output._writer, list[Path]()

    def failing_writer(data: bytes) -> Callable[[Path], None]:
        def write(temp: Path) -> None:  # the second file's write fails, its temp already made
            if staged:
                raise OSError(28, "No space left on device")
            staged.append(temp)
            real_writer(data)(temp)

        return write

    monkeypatch.setattr(output, "_writer", failing_writer)
    files = [(tmp_path / "new" / "a.json", "a"), (tmp_path / "new" / "deeper" / "b.json", "b")]
    with pytest.raises(UsageError, match=r"b\.json': No space left on device"):
        output.write_files(files)
    assert listing(tmp_path) == {}


# ---------------------------------------------------------------- OS errors are usage errors


@pytest.mark.skipif(os.geteuid() == 0, reason="root ignores folder permissions")
def test_a_read_only_folder_is_a_usage_error(tmp_path: Path, source: Path) -> None:
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        refused(run_cnlmc("compile", str(source), "-o", str(folder / "x.json")), "x.json", "Permission denied")
        assert list(folder.iterdir()) == []
    finally:
        folder.chmod(0o700)


def test_a_name_too_long_is_a_usage_error(tmp_path: Path, source: Path) -> None:
    long = tmp_path / ("a" * 300 + ".json")
    refused(run_cnlmc("compile", str(source), "-o", str(long)), "File name too long")
    refused(run_cnlmc("compile", str(source), "-t", "glsl", "-o", f"{tmp_path / ('b' * 300)}/"), "File name too long")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hull.cnl"]


def test_a_file_as_a_parent_folder_is_a_usage_error(tmp_path: Path, source: Path) -> None:
    refused(run_cnlmc("compile", str(source), "-o", str(source / "x.json")), "Not a directory")
    assert source.read_text() == SOURCE


def test_a_long_name_that_fits_gets_a_temp_that_fits(tmp_path: Path, source: Path) -> None:
    fits = tmp_path / ("a" * 250 + ".json")  # 255 bytes: the temp's name must not be longer
    assert run_cnlmc("compile", str(source), "-o", str(fits)).returncode == 0
    assert fits.read_text().lstrip().startswith("{")


@pytest.mark.oiio
def test_bake_is_all_or_nothing_across_materials(tmp_path: Path) -> None:
    pytest.importorskip("OpenImageIO")
    src = tmp_path / "two.cnl"
    src.write_text("heavily rusted iron\nhammered copper\n")
    out = tmp_path / "maps"
    out.mkdir()
    (out / "hammered_copper_normal.png").mkdir()  # the last material's map cannot be written
    before = listing(tmp_path)
    proc = run_cnlmc("bake", str(src), "-o", str(out), "--size", "16")
    refused(proc, "hammered_copper_normal.png", "a folder")
    assert listing(tmp_path) == before  # the first material's maps were not written either
    (out / "hammered_copper_normal.png").rmdir()
    assert run_cnlmc("bake", str(src), "-o", str(out), "--size", "16").returncode == 0
    assert len(list(out.iterdir())) == 4 and not [p for p in out.iterdir() if p.name.startswith(".")]


# ---------------------------------------------------------------- never outside the output folder


class Named:
    def __init__(self, name: str, content: str) -> None:
        self.name, self.content = name, content


@pytest.mark.parametrize("name", ["../escaped.json", "sub/../../escaped.json", "/tmp/escaped-by-cnlmc.json"])
def test_an_artifact_name_outside_the_output_folder_is_refused(tmp_path: Path, name: str) -> None:
    out = tmp_path / "a" / "out"
    out.mkdir(parents=True)
    artifacts = [Named("main.json", "{}"), Named(name, "{}")]
    with pytest.raises(UsageError, match="leads outside the output folder"):
        output.write_artifacts(artifacts, f"{out}/")
    assert list(out.iterdir()) == [] and not (tmp_path / "a" / "escaped.json").exists()
    assert not Path("/tmp/escaped-by-cnlmc.json").exists()


def test_a_staged_path_outside_the_root_is_refused(tmp_path: Path) -> None:
    root = tmp_path / "maps"
    with pytest.raises(UsageError, match="outside the output folder"), output.Staging(root=root) as staging:
        staging.add(root / "x_a" / ".." / ".." / "ESCAPED.png", lambda temp: temp.write_bytes(b"x"))
    assert list(tmp_path.iterdir()) == []


def test_a_hostile_lexicon_role_never_writes_outside(tmp_path: Path) -> None:
    lexicon = tmp_path / "words"
    lexicon.mkdir()
    (lexicon / "nouns.toml").write_text(
        '[evilwood]\naliases = []\nclass = "wood"\nmodel = "dielectric"\nroughness = 0.5\n'
        "base_color = [0.3, 0.2, 0.1]\nior = 1.5\n"
        'maps = { "a/../../../ESCAPED" = { graph = "wood", output = "color" } }\n'
        'source = "test"\ndoc = "a hostile entry"\nexample = "evilwood"\n'
    )
    src = tmp_path / "evil.cnl"
    src.write_text("evilwood\n")
    out = tmp_path / "x" / "y" / "maps"
    proc = run_cnlmc("bake", str(src), "-L", str(lexicon), "-o", str(out), "--size", "16")
    refused(proc, "a/../../../ESCAPED")
    assert not list(tmp_path.rglob("*ESCAPED*"))


# ---------------------------------------------------------------- names too long for a file


def test_a_300_character_material_name_gets_short_file_names(tmp_path: Path) -> None:
    src = tmp_path / "long.cnl"
    src.write_text("a" * 300 + ": gold\n" + "a" * 300 + "b: silver\n")
    out = tmp_path / "gl"
    proc = run_cnlmc("compile", str(src), "-t", "glsl", "-o", f"{out}/")
    assert proc.returncode == 0, proc.stderr
    names = sorted(p.name for p in out.iterdir())
    assert len(names) == 8 and all(len(n.encode()) <= 255 and n.startswith("a" * 100) for n in names)
    stems = {n.split(".", 1)[0] for n in names}  # one shortened stem per material, its suffixes kept
    assert len(stems) == 2 and {n.split(".", 1)[1] for n in names} == {"glsl", "frag", "vert", "glsl.json"}


def test_unicode_names_are_cut_on_a_character_boundary() -> None:
    from cnlmc.filenames import NAME_MAX, fit_file_name

    name = fit_file_name("名" * 200 + ".glsl.json")
    assert len(name.encode()) <= NAME_MAX and name.endswith(".glsl.json") and "~" in name
    assert fit_file_name("short.png") == "short.png"
