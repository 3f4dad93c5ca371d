"""Signals and concurrent writers, with real processes: a bake killed mid-write leaves nothing
behind (SIGTERM/SIGHUP/SIGINT: cleaned at once, exit 128 + n; SIGKILL: cleaned by the next writer),
and two bakes into one folder never mix (the folder lock: the second waits, or fails clearly).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest

from cnlmc import output
from cnlmc.errors import UsageError
from cnlmc.folder_lock import LOCK_NAME, TEMP_MARK, FolderLock, remove_stale_temps
from tests.helpers import run_cnlmc

pytestmark = pytest.mark.oiio
pytest.importorskip("OpenImageIO")

#: many materials with maps: a bake that runs long enough (a minute and more) to be interrupted
#: between two of them, even when this test's process gets the CPU late; the tests stop it as soon
#: as its first maps are staged (100 lines took ~3 s on a fast machine: a starved test signalled a
#: bake that had already finished)
SLOW = "heavily rusted iron\n" * 1000
KEEP = b"a file that was there before"


def start_bake(source: Path, out: Path, *extra: str, env: dict[str, str] | None = None) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "cnlmc", "bake", str(source), "-o", str(out), *extra],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        preexec_fn=_default_dispositions,
    )


def _default_dispositions() -> None:
    """The bake starts with the default handlers even when the test run ignores a signal (`nohup`
    sets SIGHUP to ignored, and cnlmc rightly keeps an ignored signal ignored)."""
    for signum in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
        signal.signal(signum, signal.SIG_DFL)


def wait_for(found: Callable[[], bool], proc: subprocess.Popen[str], what: str, limit: float = 240) -> None:
    deadline = time.monotonic() + limit
    while not found():
        if proc.poll() is not None:
            pytest.fail(f"the bake ended before {what}: {proc.communicate()}")
        if time.monotonic() > deadline:
            proc.kill()
            pytest.fail(f"no {what} after {limit} s")
        time.sleep(0.02)


def temps(folder: Path) -> list[Path]:
    return [p for p in folder.iterdir() if TEMP_MARK in p.name] if folder.is_dir() else []


def entries(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


@pytest.fixture
def slow_source(tmp_path: Path) -> Path:
    path = tmp_path / "many.cnl"
    path.write_text(SLOW)
    return path


@pytest.fixture
def out(tmp_path: Path) -> Path:
    folder = tmp_path / "maps"
    folder.mkdir()
    (folder / "keep.txt").write_bytes(KEEP)
    return folder


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_a_signal_mid_bake_removes_the_temps_and_exits_128_plus_n(slow_source: Path, out: Path, signum: int) -> None:
    proc = start_bake(slow_source, out, "--size", "256")
    wait_for(lambda: bool(temps(out)), proc, "staged map")
    proc.send_signal(signum)
    _, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 128 + signum, stderr
    name = signal.Signals(signum).name
    assert stderr.strip().splitlines()[-1].startswith(f"cnlmc: interrupted by {name}: nothing was written"), stderr
    assert "Traceback" not in stderr and "internal error" not in stderr
    assert entries(out) == {"keep.txt": KEEP}  # no temp, no lock file, no map


def test_temps_of_a_killed_bake_are_removed_by_the_next_writer(slow_source: Path, out: Path, tmp_path: Path) -> None:
    proc = start_bake(slow_source, out, "--size", "256")
    wait_for(lambda: bool(temps(out)), proc, "staged map")
    proc.kill()  # SIGKILL: nothing runs in the process any more
    proc.communicate(timeout=60)
    left = temps(out)
    assert left and all(f".{TEMP_MARK}.{proc.pid}." in p.name for p in left)  # the temps carry the pid
    small = tmp_path / "one.cnl"
    small.write_text("hammered copper\n")
    done = run_cnlmc("bake", str(small), "-o", str(out), "--size", "16")
    assert done.returncode == 0, done.stderr
    assert entries(out).keys() == {"keep.txt", "hammered_copper_normal.png"}  # stale temps and lock gone


def test_a_second_writer_into_a_locked_folder_fails_clearly(out: Path, tmp_path: Path) -> None:
    small = tmp_path / "one.cnl"
    small.write_text("hammered copper\n")
    holder = FolderLock(out, wait=0)  # this test's process is the first writer
    holder.acquire()
    try:
        env = {**os.environ, "CNLMC_LOCK_WAIT": "0.5"}
        second = run_cnlmc("bake", str(small), "-o", str(out), "--size", "16", env=env)
    finally:
        holder.release()
    assert second.returncode == 2, second.stderr
    assert f"cannot write into '{out}': another cnlmc (process {os.getpid()}) is writing there" in second.stderr
    assert "waited 0.5 s" in second.stderr and "CNLMC_LOCK_WAIT" in second.stderr
    assert "internal error" not in second.stderr
    assert entries(out) == {"keep.txt": KEEP}


def test_a_second_bake_waits_for_the_first(slow_source: Path, out: Path, tmp_path: Path) -> None:
    first = start_bake(slow_source, out, "--size", "512")
    try:
        wait_for(lambda: bool(temps(out)), first, "staged map")
        small = tmp_path / "one.cnl"
        small.write_text("hammered copper\n")
        second = start_bake(small, out, "--size", "16")
        time.sleep(4.0)  # long enough to start, compile and bake; then it waits for the lock
        assert first.poll() is None, "the first bake ended too soon for this test"
        assert second.poll() is None, second.communicate()  # still waiting for the lock
        assert not (out / "hammered_copper_normal.png").exists()
    finally:
        first.send_signal(signal.SIGTERM)
        first.communicate(timeout=120)
    assert second.wait(timeout=240) == 0, second.communicate()
    assert entries(out).keys() == {"keep.txt", "hammered_copper_normal.png"}


def test_two_bakes_into_one_folder_do_not_mix(tmp_path: Path, out: Path) -> None:
    source = tmp_path / "two.cnl"
    source.write_text("heavily rusted iron\nhammered copper\n")
    reference = tmp_path / "reference"
    assert run_cnlmc("bake", str(source), "-o", str(reference), "--size", "64", "--seed", "2").returncode == 0
    first = start_bake(source, out, "--size", "64", "--seed", "1")
    wait_for(lambda: (out / LOCK_NAME).exists(), first, "lock")
    second = start_bake(source, out, "--size", "64", "--seed", "2")  # waits for the first, then writes
    assert first.wait(timeout=240) == 0 and second.wait(timeout=240) == 0, second.communicate()
    maps = {name: data for name, data in entries(out).items() if name != "keep.txt"}
    assert maps == entries(reference)  # every map from the second run, none from the first


# ---------------------------------------------------------------- the writer's API


def test_a_lock_held_in_this_process_makes_a_writer_wait_then_fail(tmp_path: Path) -> None:
    lock = FolderLock(tmp_path, wait=0)
    lock.acquire()
    try:
        with pytest.raises(UsageError, match=rf"another cnlmc \(process {os.getpid()}\) is writing there"):
            FolderLock(tmp_path, wait=0.1).acquire()
    finally:
        lock.release()
    assert list(tmp_path.iterdir()) == []  # the lock file goes with the lock
    output.write_atomic(tmp_path / "a.json", "{}")
    assert [p.name for p in tmp_path.iterdir()] == ["a.json"]


def test_only_the_temps_of_dead_writers_are_removed(tmp_path: Path) -> None:
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    dead_pid = int(dead.stdout)
    stale = tmp_path / f".a.png.{TEMP_MARK}.{dead_pid}.abcdefgh.png"
    live = tmp_path / f".b.png.{TEMP_MARK}.{os.getpid()}.abcdefgh.png"
    other = tmp_path / ".not-ours.tmp"
    for path in (stale, live, other):
        path.write_bytes(b"x")
    assert remove_stale_temps(tmp_path) == [stale]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([live.name, other.name])


def test_a_signal_in_process_discards_the_staging_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "old.json").write_text("old")
    with pytest.raises(SystemExit) as raised, output.Staging() as staging:
        staging.add(tmp_path / "old.json", lambda temp: temp.write_text("new"))
        staging.add(tmp_path / "new.json", lambda temp: temp.write_text("new"))
        os.kill(os.getpid(), signal.SIGTERM)  # handled at the next bytecode: raises Interrupted
        staging.commit()
    assert raised.value.code == 128 + signal.SIGTERM
    assert "cnlmc: interrupted by SIGTERM: nothing was written" in capsys.readouterr().err
    assert entries(tmp_path) == {"old.json": b"old"}
    assert signal.getsignal(signal.SIGTERM) == signal.SIG_DFL  # the default handler is back


def test_a_signal_right_after_a_rename_is_rolled_back(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from cnlmc.interrupts import Interrupted

    for name in ("a.glsl", "b.frag"):
        (tmp_path / name).write_text(f"old {name}")
    real_replace, calls = os.replace, []

    def replace_then_signal(src: str | Path, dst: str | Path) -> None:
        real_replace(src, dst)
        calls.append(dst)
        if len(calls) == 2:  # a signal arrives just after the second rename returned
            raise Interrupted(signal.SIGTERM)

    monkeypatch.setattr(os, "replace", replace_then_signal)
    files = [(tmp_path / name, f"new {name}") for name in ("a.glsl", "b.frag", "c.vert")]
    with pytest.raises(Interrupted):
        output.write_files(files)
    monkeypatch.setattr(os, "replace", real_replace)
    assert entries(tmp_path) == {"a.glsl": b"old a.glsl", "b.frag": b"old b.frag"}


def test_a_signal_right_after_a_temp_is_created_leaves_no_temp(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The temp is staged before it exists: a signal the moment the file appears (before `add`
    returns) is cleaned up like any other (with mkstemp, that moment's temp was left behind)."""
    real_close = os.close

    def close_then_signal(fd: int) -> None:
        real_close(fd)
        if any(TEMP_MARK in p.name for p in tmp_path.iterdir()):
            os.kill(os.getpid(), signal.SIGTERM)  # raises Interrupted at the next bytecode

    with pytest.raises(SystemExit) as raised, output.Staging() as staging:
        monkeypatch.setattr(os, "close", close_then_signal)
        staging.add(tmp_path / "a.json", lambda temp: temp.write_text("never"))
    monkeypatch.undo()
    assert raised.value.code == 128 + signal.SIGTERM
    assert "nothing was written" in capsys.readouterr().err
    assert entries(tmp_path) == {}


def test_the_image_library_is_loaded_before_any_signal_guard(tmp_path: Path) -> None:
    """A SIGTERM during the first import of OpenImageIO (a nanobind extension) aborted the process
    (SIGABRT, temps left: a fresh clone's CI); bake loads it before its staging guards signals."""
    source = tmp_path / "one.cnl"
    source.write_text("hammered copper\n")
    code = (
        "import sys; from cnlmc import interrupts; from cnlmc.cli import main\n"
        "seen = []\n"
        "enter = interrupts.SignalGuard.__enter__\n"
        "def recording(self):\n"
        "    seen.append('OpenImageIO' in sys.modules)\n"
        "    return enter(self)\n"
        "interrupts.SignalGuard.__enter__ = recording\n"
        f"code = main(['bake', {str(source)!r}, '-o', {str(tmp_path / 'maps')!r}, '--size', '16'])\n"
        "print(code, seen)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.stdout.split(" ", 1)[0] == "0", done.stderr
    seen = done.stdout.split(" ", 1)[1].strip()
    assert seen.startswith("[True") and "False" not in seen, (seen, done.stderr)
