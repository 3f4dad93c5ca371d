"""A real full disk and a real read-only file system under the CLI (#13), and `sheet -o` checked first.

#13: "on a full disk the GLSL target stopped after 2 of 200 materials; bake exits 2 but leaves
earlier materials' maps. Read-only filesystem, full disk, a file as a parent folder -> internal
error, exit 70." tests/language/test_output_safety.py proves the writer's roll-back with a
failing os.replace; here the kernel says ENOSPC and EROFS: a small tmpfs is mounted for each test
(root with CAP_SYS_ADMIN, as CI runs; skipped elsewhere with the reason). Every run must exit 2
with the path and the kernel's reason, and leave the folder as it was: no file, no temp.
"""

from __future__ import annotations

import os
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.helpers import run_cnlmc

EXIT_USAGE = 2
MANY = "".join(f"m{n}: lightly brushed, blue anodized aluminum\n" for n in range(40))


def mount_tmpfs(folder: Path, *options: str) -> None:
    folder.mkdir()
    command = ["mount", "-t", "tmpfs", "-o", ",".join(options), "tmpfs", str(folder)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=30, check=False)
    except FileNotFoundError:
        pytest.skip("no mount command here")
    if done.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here (needs root with CAP_SYS_ADMIN): {done.stderr.strip()}")


@pytest.fixture
def small_disk(tmp_path: Path) -> Iterator[Path]:
    """A 64 KiB file system with 16 KiB free: a few files fit, 40 materials' shaders do not."""
    folder = tmp_path / "disk"
    mount_tmpfs(folder, "size=64k", "mode=0755")
    (folder / "filler").write_bytes(bytes(48 * 1024))
    try:
        yield folder
    finally:
        subprocess.run(["umount", "-l", str(folder)], check=False, capture_output=True)


@pytest.fixture
def read_only_disk(tmp_path: Path) -> Iterator[Path]:
    folder = tmp_path / "ro"
    mount_tmpfs(folder, "size=64k", "ro")
    try:
        yield folder
    finally:
        subprocess.run(["umount", "-l", str(folder)], check=False, capture_output=True)


def refused(proc: subprocess.CompletedProcess[Any], *words: str) -> None:
    assert proc.returncode == EXIT_USAGE, proc.stderr
    assert "cnlmc: error:" in proc.stderr and "internal error" not in proc.stderr, proc.stderr
    assert "Traceback" not in proc.stderr
    for word in words:
        assert word in proc.stderr, proc.stderr


def entries(folder: Path) -> list[str]:
    """Everything under `folder`, hidden temps and lock files included."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def test_glsl_of_40_materials_onto_a_full_disk_writes_nothing(tmp_path: Path, small_disk: Path) -> None:
    source = tmp_path / "many.cnl"
    source.write_text(MANY)
    (small_disk / "keep.txt").write_text("mine")
    proc = run_cnlmc("compile", str(source), "-t", "glsl", "-o", f"{small_disk}/")
    refused(proc, str(small_disk), "No space left on device")
    assert entries(small_disk) == ["filler", "keep.txt"]  # all or nothing: not 2 of 40


def test_the_streamed_ir_onto_a_full_disk_writes_nothing(tmp_path: Path, small_disk: Path) -> None:
    source = tmp_path / "many.cnl"
    source.write_text(MANY)
    out = small_disk / "many.ir.json"
    refused(run_cnlmc("compile", str(source), "-o", str(out)), "many.ir.json", "No space left on device")
    assert entries(small_disk) == ["filler"]


@pytest.mark.oiio
def test_bake_onto_a_full_disk_leaves_no_map(tmp_path: Path, small_disk: Path) -> None:
    pytest.importorskip("OpenImageIO")
    source = tmp_path / "two.cnl"
    source.write_text("heavily rusted iron\nhammered copper\n")
    refused(run_cnlmc("bake", str(source), "-o", str(small_disk), "--size", "128"), "cannot write", "Write error")
    assert entries(small_disk) == ["filler"]


@pytest.mark.parametrize("target", ["ir", "glsl"])
def test_a_read_only_file_system_is_a_usage_error(tmp_path: Path, read_only_disk: Path, target: str) -> None:
    source = tmp_path / "a.cnl"
    source.write_text("red plastic\n")
    refused(run_cnlmc("compile", str(source), "-t", target, "-o", str(read_only_disk / "x")), "Read-only file system")


def test_sheet_refuses_a_read_only_file_system(read_only_disk: Path) -> None:
    refused(run_cnlmc("sheet", "-o", str(read_only_disk / "sheet.png")), "sheet.png", "Read-only file system")
    assert entries(read_only_disk) == []


@pytest.mark.parametrize("kind", ["fifo", "folder", "under_a_file", "read_only"])
def test_sheet_checks_its_output_before_rendering(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], kind: str
) -> None:
    """#13: `cnlmc sheet` refused a bad -o only after seconds of rendering. Rendering here fails
    the test: the refusal must come first."""
    from cnlmc.backends.maps import commands
    from cnlmc.cli import main

    def rendered(*_args: object, **_kwargs: object) -> Path:
        raise AssertionError("the sheet was rendered before its output was checked")

    monkeypatch.setattr(commands, "render_contact_sheet", rendered)
    out = tmp_path / "sheet.png"
    if kind == "fifo":
        os.mkfifo(out)
    elif kind == "folder":
        out.mkdir()
    elif kind == "under_a_file":
        (tmp_path / "file").write_text("x")
        out = tmp_path / "file" / "sheet.png"
    else:
        if os.geteuid() == 0:
            pytest.skip("root may write into any folder (the read-only file system test covers it)")
        out.parent.chmod(0o500)
    try:
        assert main(["sheet", "-o", str(out), "--size", "16"]) == EXIT_USAGE
    finally:
        out.parent.chmod(0o700)
    stderr = capsys.readouterr().err
    assert "cnlmc: error: cannot write" in stderr and "internal error" not in stderr, stderr


# ---------------------------------------------------------------- duplicate names (#13)

DUPLICATES = "red or red plastic\ny: red or blue plastic\ny__red: steel\nheavily rusted iron\nheavily rusted iron\n"


def test_no_two_materials_share_a_name(tmp_path: Path) -> None:
    """#13: 'red or red plastic', or 'y: red or blue plastic' then 'y__red: steel', overwrote one
    another's files (GLSL, preview and bake said "wrote" twice for one file)."""
    import json

    source = tmp_path / "dup.cnl"
    source.write_text(DUPLICATES)
    proc = run_cnlmc("compile", str(source))
    assert proc.returncode == 0, proc.stderr
    names = [m["name"] for m in json.loads(proc.stdout)["materials"]]
    assert names == [
        "red_plastic__red",
        "red_plastic__red_2",
        "y__red",
        "y__blue",
        "y__red_2",
        "heavily_rusted_iron",
        "heavily_rusted_iron_2",
    ]
    out = tmp_path / "gl"
    proc = run_cnlmc("compile", str(source), "-t", "glsl", "-o", f"{out}/")
    assert proc.returncode == 0, proc.stderr
    wrote = [line for line in proc.stdout.splitlines() + proc.stderr.splitlines() if line.startswith("wrote ")]
    assert (
        len(wrote)
        == len(set(wrote))
        == len([p for p in out.rglob("*") if p.is_file() and not p.name.startswith(".")])
        > len(names)
    )
