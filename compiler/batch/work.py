"""The targets of a build (the only module of cnlmc.batch that reaches the backends, through the
registry): each target's options parsed, and what a worker runs, one task's target on its material. The same function runs in this process, in a pool
worker and on a Dask worker; each process imports a target once and keeps it for its lifetime.
"""

from __future__ import annotations

import time
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from cnlmc.backends.registry import BackendRefused, Target, TargetUnavailable, UnknownTarget, get_target

from ..errors import UsageError
from .keys import content_hash
from .tasks import Outcome, Task, write_task


def run_task(task: Task, root: str | None) -> Outcome:
    """Emit the task's files. With `root` (the output folder, seen from this process) they are
    written there and only their hashes come back; without, their bytes come back too."""
    outcome = Outcome(task.key, task.folder, task.target)
    start = time.process_time()
    try:
        emitted = get_target(task.target).emit_ir(task.document, task.options)
        files = [
            (a.name, a.content.encode("utf-8") if isinstance(a.content, str) else a.content) for a in emitted.artifacts
        ]
        outcome.notes = [f"warning[{note.code}]: {note.text()}" for note in emitted.notes]
        outcome.hashes = {name: content_hash(data) for name, data in files}
        if root is None:
            outcome.files = files
        else:
            write_task(Path(root), task, files)
    except BackendRefused as exc:
        outcome.error = f"error[E201]: {exc}"
    except (UsageError, ValueError) as exc:
        outcome.error = f"error: {exc}"
    except Exception as exc:  # a target's failure on one material fails that task, not the build
        outcome.error = f"error: the {task.target} target failed: {type(exc).__name__}: {exc}"
    outcome.cpu_seconds = time.process_time() - start
    return outcome


#: the option that sets a target's image size in pixels, by preference: what `--size N` sets (a
#: target declaring neither as an integer writes no image: GLSL, IR). `map_size` comes first: the
#: exchange targets that bake maps also declare `size`, and there it is the object's size in metres.
SIZE_OPTIONS = ("map_size", "size")
#: the compiler's own options: the build sets seed itself and places the files itself
SET_BY_THE_BUILD = ("output",)


def target_options(
    targets: Sequence[str], pairs: Iterable[str] | Mapping[str, object], size: int | None, seed: int
) -> dict[str, dict[str, Any]]:
    """Each target's options, parsed and typed by the target (every declared option, defaults
    included: the task key holds them all). A 'KEY=VALUE' pair goes to every target that declares
    KEY, 'TARGET.KEY=VALUE' to that target; a key no target declares is a usage error."""
    loaded = {name: _target(name) for name in dict.fromkeys(targets)}
    if not loaded:
        raise UsageError("give at least one target: --target maps,preview (see `cnlmc targets`)")
    raw = _option_items(pairs)
    chosen: dict[str, dict[str, object]] = {name: {"seed": seed} for name in loaded}
    for key, value in raw:
        scope, _, name = key.rpartition(".")
        receivers = [t for t in loaded if (scope in ("", t)) and _declares(loaded[t], name)]
        if not receivers:
            raise UsageError(f"no target of this build ({', '.join(loaded)}) has the option '{key}'")
        for target in receivers:
            chosen[target][name] = value
    if size is not None:
        for target, instance in loaded.items():
            declared = [o for o in SIZE_OPTIONS if _declares_pixels(instance, o)]
            if declared:
                chosen[target].setdefault(declared[0], size)
    return {name: _parsed(loaded[name], chosen[name]) for name in loaded}


def _target(name: str) -> Target:
    try:
        return get_target(name)
    except (UnknownTarget, TargetUnavailable) as exc:
        raise UsageError(str(exc)) from None


def _declares(target: Target, name: str) -> bool:
    return any(option.name == name for option in target.options)


def _declares_pixels(target: Target, name: str) -> bool:
    return any(option.name == name and option.type is int for option in target.options)


def _option_items(pairs: Iterable[str] | Mapping[str, object]) -> list[tuple[str, object]]:
    if isinstance(pairs, Mapping):
        return [(str(k), v) for k, v in pairs.items()]
    items: list[tuple[str, object]] = []
    for pair in pairs:
        key, equals, value = pair.partition("=")
        if not equals or not key.strip():
            raise UsageError(f"--option expects KEY=VALUE or TARGET.KEY=VALUE, got '{pair}'")
        items.append((key.strip(), value.strip()))
    return items


def _parsed(target: Target, pairs: dict[str, object]) -> dict[str, Any]:
    try:
        options = target.parse_options(pairs)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return {key: options[key] for key in sorted(options) if key not in SET_BY_THE_BUILD}
