"""The one output writer: every file cnlmc writes goes through here.

What it guarantees:

- **Atomic files.** A file is written to a hidden temp beside its destination
  (`.NAME.XXXXXXXX.tmp`) and renamed over it: a destination appears whole or not at all, and an
  existing file survives a failure unchanged.
- **All-or-nothing results.** `write_artifacts` first writes every file of a result to its temp,
  then renames them all; when anything fails (a full disk, a read-only folder, a file where a
  folder is expected, a name too long, ...) every temp it made is removed, the files already
  renamed are put back as they were (kept as hard links until the end), and no destination is
  changed.
- **Only regular files are written.** A destination that exists and is not a regular file (a
  device node such as /dev/null, a FIFO, a socket, a folder where a file is expected) is refused
  before anything is written.
- **Symlinks are written through.** An output path that is a symlink updates the file the link
  points to (resolved to the end of the chain); the link itself stays a link. A link to a
  non-regular file is refused like the file itself.
- **Inputs are never overwritten.** The commands pass the files they read (`protect=`); a
  destination that is one of them (the same file, through any path, link or hard link) is refused.
- **Nothing outside the output folder.** An artifact name that is absolute or climbs out of the
  output folder ('..') is refused, as is a staged path outside a Staging's `root`.
- **One writer per folder, no temps left behind.** Each folder written to is locked while its files
  are staged and committed (cnlmc.folder_lock); temps carry the writer's process id, and a writer
  removes the temps of dead writers in the folders it locks. SIGTERM, SIGHUP and SIGINT during a
  write discard it and exit 128 + the signal's number (cnlmc.interrupts).
- **An output owns its textures.** The files of a result inside its own folder
  (`textures/<main file name>/`) are listed in a manifest there; the next write of that output
  removes the ones it no longer has, and never a file it did not write (cnlmc.manifest).

Every refusal and every OS error is a `UsageError` naming the path and the reason: the CLI prints
`cnlmc: error: ...` and exits 2.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path, PurePosixPath
from typing import BinaryIO, Protocol

from .errors import UsageError
from .filenames import fit_file_name
from .folder_lock import FolderLock, backup_name, temp_prefix
from .interrupts import SignalGuard
from .manifest import MANIFEST_NAME, manifest_text, owned_folder, prune, read_manifest, remove_stale

#: a temp keeps its destination's suffix (image writers choose the format by it) up to this length
MAX_TEMP_SUFFIX = 16
#: the write buffer of a streamed file (write_streamed)
STREAM_BUFFER = 1 << 16


class Artifact(Protocol):
    """What is written: a file name relative to the output, and its content (a backend's Artifact)."""

    @property
    def name(self) -> str: ...

    @property
    def content(self) -> str | bytes: ...


def usual_mode() -> int:
    """The mode a plain open() would give a new file under the current umask."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def os_error(path: Path | str, exc: OSError) -> UsageError:
    """An OS error as the usage error the CLI prints: the path and the reason."""
    reason = exc.strerror or (errno.errorcode.get(exc.errno, "") if exc.errno else "") or str(exc)
    return UsageError(f"cannot write '{path}': {reason}")


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def _input_stats(protect: Iterable[str | Path]) -> list[tuple[str, os.stat_result]]:
    stats = []
    for path in protect:
        if str(path) in ("", "-"):
            continue
        with contextlib.suppress(OSError):
            stats.append((str(path), os.stat(path)))
    return stats


def destination(path: Path | str, protect: Iterable[str | Path] = ()) -> Path:
    """The file a write to `path` changes (a symlink resolved to its target), after the checks:
    it is a regular file or does not exist yet, and it is none of the `protect`ed inputs.
    Raises UsageError naming `path` otherwise. Writes nothing."""
    shown = Path(path)
    try:
        real = Path(os.path.realpath(shown))
        info: os.stat_result | None = os.stat(real)
    except FileNotFoundError:
        info = None
    except OSError as exc:
        raise os_error(shown, exc) from None
    if info is None:
        return real
    if not stat.S_ISREG(info.st_mode):
        raise UsageError(f"cannot write '{shown}': it is {_kind(info.st_mode)}, not a regular file")
    for name, other in _input_stats(protect):
        if (info.st_dev, info.st_ino) == (other.st_dev, other.st_ino):
            raise UsageError(f"refusing to write '{shown}': it is the input file '{name}'")
    return real


def writable_destination(path: Path | str, protect: Iterable[str | Path] = ()) -> Path:
    """destination(path, protect), and a new file can be made where it goes: the nearest folder
    above it that exists is a folder this process may write into. For a command that works
    before it writes (a contact sheet renders for seconds): a bad -o is refused before the work
    (UsageError naming the path and the reason), not after. Writes nothing."""
    real = destination(path, protect)
    probe = real.parent
    while not os.path.lexists(probe) and probe.parent != probe:
        probe = probe.parent
    if not probe.is_dir():
        raise os_error(path, OSError(errno.ENOTDIR, os.strerror(errno.ENOTDIR)))
    if not os.access(probe, os.W_OK | os.X_OK):
        code = errno.EROFS if os.statvfs(probe).f_flag & os.ST_RDONLY else errno.EACCES
        raise os_error(path, OSError(code, os.strerror(code)))
    return real


def _make_parents(folder: Path, made: list[Path]) -> None:
    """Create `folder` and its missing parents, recording each folder made (to remove on failure)."""
    missing = []
    probe = folder
    while not os.path.lexists(probe):
        missing.append(probe)
        if probe.parent == probe:
            break
        probe = probe.parent
    for part in reversed(missing):
        part.mkdir()
        made.append(part)


def _commit(staged: Sequence[tuple[Path, Path, Path]]) -> None:
    """Rename every temp over its destination; on a failure (or a signal), put back the ones
    already renamed. Each rename is recorded before it runs, so a signal between the rename and
    the next line still finds it: putting back a rename that did not happen changes nothing."""
    done: list[tuple[Path, Path | None, bool]] = []
    backups: list[Path] = []
    try:
        for tmp, real, shown in staged:
            existed, backup = os.path.lexists(real), None
            if len(staged) > 1 and existed:
                backup = real.parent / backup_name(real.name)
                backup.unlink(missing_ok=True)
                try:
                    os.link(real, backup)  # the old file, kept until every rename succeeded
                    backups.append(backup)
                except OSError:
                    backup = None  # no hard links here: this file cannot be put back
            done.append((real, backup, existed))
            try:
                os.replace(tmp, real)
            except OSError as exc:
                done.pop()
                raise os_error(shown, exc) from None
    except BaseException:
        _put_back(done)
        raise
    finally:
        for backup in backups:
            backup.unlink(missing_ok=True)


def _put_back(done: Sequence[tuple[Path, Path | None, bool]]) -> None:
    """Undo renames, last first: the old file back from its backup, a new file removed."""
    for real, backup, existed in reversed(done):
        with contextlib.suppress(OSError):
            if backup is not None:
                os.replace(backup, real)
            elif not existed:
                real.unlink(missing_ok=True)


def inside(root: Path, path: Path) -> bool:
    """Whether `path` names something in `root` or below, as written ('..' resolved lexically)."""
    rest = os.path.relpath(os.path.abspath(path), os.path.abspath(root))
    return rest != ".." and not rest.startswith(".." + os.sep)


def safe_name(name: str, root: Path) -> Path:
    """`root / name` for an artifact name that stays in `root`, each part too long for a file
    name shortened (cnlmc.filenames.fit_file_name); UsageError for an absolute name or one that
    climbs out ('..')."""
    parts = PurePosixPath(name).parts
    if not name or PurePosixPath(name).is_absolute() or os.path.isabs(name) or ".." in parts:
        raise UsageError(f"refusing to write '{name}': the name leads outside the output folder '{root}'")
    return root.joinpath(*(fit_file_name(part) for part in parts))


class Staging:
    """A multi-file result built step by step (the maps of every material of a bake): `add` writes
    one file to a temp beside its destination through `write(temp)`, after the checks of
    `destination`; `commit` renames them all at once (the ones already renamed are put back on a
    failure). Leaving the `with` block without a commit removes every temp and every folder made.

    Each folder a file is staged in is locked until the commit or the clean-up (`claim` locks one
    up front); with `root`, a path outside it is refused; `own(folder, names)` declares the folder
    the result owns (its manifest is written and its stale files removed at the commit). Inside the
    `with` block, SIGTERM/SIGHUP/SIGINT discard the staging and exit 128 + the signal's number."""

    def __init__(self, protect: Iterable[str | Path] = (), root: str | Path | None = None) -> None:
        self.protect = list(protect)
        self.root = None if root is None else Path(root)
        self.staged: list[tuple[Path, Path, Path]] = []
        self.made: list[Path] = []
        self.locks: dict[Path, FolderLock] = {}
        self.owned: list[tuple[Path, set[str], set[str]]] = []
        self.guard = SignalGuard()
        self.committed = False

    def claim(self, folder: Path) -> None:
        """Create `folder` (when missing) and lock it now, before anything is staged there."""
        try:
            _make_parents(Path(folder), self.made)
            self._lock(Path(os.path.realpath(folder)))
        except OSError as exc:
            raise os_error(folder, exc) from None

    def _lock(self, folder: Path) -> None:
        if folder not in self.locks:
            lock = FolderLock(folder)
            lock.acquire()
            self.locks[folder] = lock

    def add(self, path: Path, write: Callable[[Path], None]) -> None:
        if self.root is not None and not inside(self.root, Path(path)):
            raise UsageError(f"refusing to write '{path}': it is outside the output folder '{self.root}'")
        real = destination(path, self.protect)
        if any(real == other for _, other, _ in self.staged):
            raise UsageError(f"cannot write '{path}': two files of this result have that name")
        try:
            _make_parents(real.parent, self.made)
            self._lock(real.parent)
            temp = self._new_temp(real, Path(path))
        except OSError as exc:
            raise os_error(path, exc) from None
        try:
            write(temp)
            os.chmod(temp, usual_mode())  # mkstemp makes 0600
        except OSError as exc:
            raise os_error(path, exc) from None

    def _new_temp(self, real: Path, shown: Path) -> Path:
        """An empty temp beside `real`, staged BEFORE it exists: a signal at any moment leaves no
        temp the clean-up does not know (with mkstemp, one between the file's creation and its
        recording was left behind). The name carries this process's id and 64 random bits, so a
        name staged but not yet created is no other file's."""
        suffix = real.suffix if 0 < len(real.suffix) <= MAX_TEMP_SUFFIX else ".tmp"
        while True:
            temp = real.parent / f"{temp_prefix(real.name)}{os.urandom(8).hex()}{suffix}"
            self.staged.append((temp, real, shown))  # before the write: a failed one is removed too
            try:
                os.close(os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
                return temp
            except FileExistsError:
                self.staged.pop()  # not ours: another name

    def own(self, folder: Path, names: Iterable[str]) -> None:
        """The result owns `folder`: `names` are its files there now (already added). The commit
        writes the manifest and removes the files the old manifest lists and `names` lacks."""
        new = set(names)
        if not new and not os.path.isdir(folder):
            return
        if os.path.isdir(folder):
            try:
                self._lock(Path(os.path.realpath(folder)))
            except OSError as exc:
                raise os_error(folder, exc) from None
        old = read_manifest(Path(folder))
        if new:
            self.add(Path(folder) / MANIFEST_NAME, _writer(manifest_text(new).encode("utf-8")))
        if old or new:
            self.owned.append((Path(folder), old, new))

    def commit(self) -> list[Path]:
        """Rename every staged file over its destination; returns the paths as given to `add`
        (the manifests `own` added left out)."""
        _commit(self.staged)
        self.committed = True
        for folder, old, new in self.owned:
            remove_stale(folder, old, new)
        self._release()
        for folder, _, new in self.owned:
            if not new:
                prune(folder)
        for made in reversed(self.made):  # a folder claimed for a result that put nothing in it
            with contextlib.suppress(OSError):
                made.rmdir()
        return [shown for _, _, shown in self.staged if shown.name != MANIFEST_NAME]

    def _release(self) -> None:
        for lock in self.locks.values():
            lock.release()
        self.locks = {}

    def discard(self) -> None:
        for temp, _, _ in self.staged:
            with contextlib.suppress(OSError):
                temp.unlink(missing_ok=True)
        self._release()
        for folder in reversed(self.made):
            with contextlib.suppress(OSError):
                folder.rmdir()
        self.staged, self.made = [], []

    def __enter__(self) -> Staging:
        self.guard.__enter__()
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: object) -> None:
        try:
            if not self.committed:
                self.discard()
            self._release()
        finally:
            self.guard.__exit__(kind, exc, None)


def _writer(data: bytes) -> Callable[[Path], None]:
    def write(temp: Path) -> None:
        temp.write_bytes(data)

    return write


def write_files(
    files: Sequence[tuple[Path, str | bytes]],
    protect: Iterable[str | Path] = (),
    owned: Path | None = None,
    root: Path | None = None,
) -> list[Path]:
    """Write every (path, content) all-or-nothing (see the module docstring); returns the paths.
    Every destination is checked before anything is written. Raises UsageError naming the path
    and the reason; then nothing is changed. `owned`: the folder the result owns (its files there
    get a manifest, and the ones an earlier write left there and this one lacks are removed);
    `root`: no file may go outside it."""
    protect = list(protect)
    reals: list[Path] = []
    for path, _ in files:
        real = destination(path, protect)
        if real in reals:
            raise UsageError(f"cannot write '{path}': two files of this result have that name")
        reals.append(real)
    with Staging(protect, root) as staging:
        for path, content in files:
            staging.add(path, _writer(content.encode("utf-8") if isinstance(content, str) else content))
        if owned is not None:
            staging.own(owned, [path.name for path, _ in files if path.parent == owned])
        staging.commit()
    return [path for path, _ in files]


def write_atomic(path: Path, content: str | bytes, protect: Iterable[str | Path] = ()) -> None:
    """One file, atomically, through the checks of `destination` (UsageError on a refusal or an OS error)."""
    write_files([(Path(path), content)], protect)


def looks_like_file(out: str) -> bool:
    target = Path(out)
    return not out.endswith(("/", os.sep)) and not os.path.isdir(target) and bool(target.suffix)


def main_file_name(out: str | None, default: str) -> str:
    """The name the main file of a multi-file result gets for `-o out` (the target's `default`
    when `out` is a folder or not given): what a target names its own folder after (owned_folder)."""
    return Path(out).name if out and looks_like_file(out) else default


def texture_folder(out: str | None, default: str) -> str:
    """Where a result's textures go, relative to its main file: `textures/<main file name>`."""
    return owned_folder(main_file_name(out, default))


def write_artifacts(artifacts: Sequence[Artifact], out: str, protect: Iterable[str | Path] = ()) -> list[Path]:
    """`out` a file path: the first (main) artifact goes there, the others beside it.
    `out` a folder (existing, ending in '/', or without a suffix): every artifact goes into it.
    All-or-nothing, never over an input in `protect`, never outside the output folder; the files
    in the main file's own folder (`texture_folder`) are its, with a manifest (see the module
    docstring). No artifact: nothing is written (e.g. the maps target on materials without maps)."""
    if not artifacts:
        return []
    root, first = _placed(out, len(artifacts) == 1)
    paths = [first or safe_name(artifacts[0].name, root)] + [safe_name(a.name, root) for a in artifacts[1:]]
    owned = paths[0].parent / owned_folder(paths[0].name)
    files = [(path, a.content) for path, a in zip(paths, artifacts)]
    return write_files(files, protect, owned=owned, root=root)


def _placed(out: str, single: bool) -> tuple[Path, Path | None]:
    """(the output folder, the main file's path when `out` names it) for `-o out`."""
    target = Path(out)
    if looks_like_file(out) or (single and not os.path.isdir(target) and not out.endswith(("/", os.sep))):
        return target.parent, target
    return target, None


def write_streamed(name: str, out: str, write: Callable[[BinaryIO], None], protect: Iterable[str | Path] = ()) -> Path:
    """One file (named `name` in the folder when `out` is one) whose content `write(file)` writes
    piece by piece to its staged temp, e.g. a large IR one material at a time: the guarantees of
    write_artifacts for a one-file result (checked before `write` runs; atomic; a signal or any
    exception from `write` discards the temp and changes nothing). Returns the path written."""
    root, first = _placed(out, True)
    path = first or safe_name(name, root)
    with Staging(protect, root) as staging:
        staging.add(path, _streaming_writer(write))
        staging.own(path.parent / owned_folder(path.name), [])
        staging.commit()
    return path


def _streaming_writer(write: Callable[[BinaryIO], None]) -> Callable[[Path], None]:
    def to_temp(temp: Path) -> None:
        with temp.open("wb", buffering=STREAM_BUFFER) as file:
            write(file)

    return to_temp
