"""Scratch folders a killed process left in $TMPDIR are removed by the next one (issue 13:
a SIGKILL during an exchange bake left a cnlmc-maps-* folder behind)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from cnlmc.scratch import remove_dead_scratch, scratch_folder
from tests.helpers import run_cnlmc


def dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_only_dead_processes_scratch_of_that_kind_is_removed(tmp_path: Path) -> None:
    dead = tmp_path / f"cnlmc-maps-{dead_pid()}-abc"
    (dead / "inner").mkdir(parents=True)
    (dead / "inner" / "a.exr").write_bytes(b"x" * 100)
    alive = tmp_path / f"cnlmc-maps-{os.getpid()}-def"
    other_kind = tmp_path / f"cnlmc-other-{dead_pid()}-ghi"
    not_ours = tmp_path / "cnlmc-maps-notapid"
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "keep.txt").write_text("keep")
    linked = tmp_path / f"cnlmc-maps-{dead_pid()}-link"
    for folder in (alive, other_kind, not_ours):
        folder.mkdir()
    linked.symlink_to(outside)  # a link is never followed nor removed
    assert remove_dead_scratch("maps", tmp_path) == [dead]
    assert not dead.exists()
    assert alive.is_dir() and other_kind.is_dir() and not_ours.is_dir() and linked.is_symlink()
    assert (outside / "keep.txt").read_text() == "keep"


def test_a_scratch_folder_is_removed_at_the_end(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", None)
    with scratch_folder("maps") as folder:
        assert Path(folder).parent == tmp_path and Path(folder).name.startswith(f"cnlmc-maps-{os.getpid()}-")
    assert not Path(folder).exists()


def test_an_exchange_bake_removes_what_a_killed_bake_left(tmp_path: Path) -> None:
    scratch = tmp_path / "tmp"
    left = scratch / f"cnlmc-maps-{dead_pid()}-xyz"
    left.mkdir(parents=True)
    (left / "oak_base_color.png").write_bytes(b"\x89PNG" + b"0" * 1000)
    out = tmp_path / "out"
    run = run_cnlmc(
        "compile", "-", "--target", "materialx", "--option", "map_size=16", "-o", str(out / "oak.mtlx"),
        stdin="oak\n", env={**os.environ, "TMPDIR": str(scratch)},
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert not left.exists()
    assert list(scratch.iterdir()) == []
