"""A build: the catalogue compiled, its tasks keyed, the up-to-date ones skipped, the others run
(serially, on a pool, or on Dask), their files written, and the manifest written last."""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from cnlmc import __version__

from ..errors import UsageError
from ..inputs import DEFAULT_MAX_BYTES
from ..lexicon import Lexicon, cached_lexicon
from ..lexicon_schema import LexiconError
from ..output import write_atomic
from .catalog import Catalog, Entry, read_catalog
from .keys import BUILD_FORMAT, task_key
from .runners import RESULT_MODES, available_cpus, run_dask, run_pool, run_serial
from .tasks import Outcome, Task, up_to_date, write_task
from .work import target_options

MANIFEST_NAME = "cnlmc-build.json"
BUILT, UP_TO_DATE, FAILED = "built", "up to date", "failed"
STATUSES = (BUILT, UP_TO_DATE, FAILED)
Progress = Callable[[int, int, float], None]  # (tasks done, tasks in all, seconds since the start)


@dataclass
class BuildReport:
    """What a build did: the manifest (also written to OUT/cnlmc-build.json), each task's status,
    the failures (where, target, what went wrong) and the catalogue's warnings."""

    manifest: dict[str, Any]
    statuses: dict[tuple[str, str], str] = field(default_factory=dict)  # (material folder, target) -> status
    failures: list[tuple[str, str, str]] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    def count(self, status: str, target: str | None = None) -> int:
        return sum(1 for (_, t), s in self.statuses.items() if s == status and target in (None, t))

    @property
    def ok(self) -> bool:
        return not self.failures


def build(catalog: str | Path, out: str | Path, targets: Sequence[str], **settings: Any) -> dict[str, Any]:
    """Build every material of `catalog` (a .cnl file or a folder of them) to every target into
    `out`; returns the manifest. Settings: size, jobs, scheduler, results, options, lexicon,
    seed, max_bytes, progress (see build_report)."""
    return build_report(catalog, out, targets, **settings).manifest


def build_report(
    catalog: str | Path,
    out: str | Path,
    targets: Sequence[str],
    *,
    size: int | None = None,
    jobs: int | None = None,
    scheduler: str | None = None,
    results: str = "return",
    options: Iterable[str] | Mapping[str, object] = (),
    lexicon: Iterable[str | Path] = (),
    seed: int = 0,
    max_bytes: int = DEFAULT_MAX_BYTES,
    progress: Progress | None = None,
    pool: bool | None = None,
) -> BuildReport:
    """The build, with what happened to each task. `jobs`: worker processes (None: every CPU;
    1: this process); `scheduler`: a Dask scheduler's address (then `results` is 'return' or
    'shared', docs/build.md); `pool`: True runs even one worker in a pool process, False runs
    every task in this process (None: a pool when more than one worker); `options`: 'KEY=VALUE' (every target that declares KEY) or
    'TARGET.KEY=VALUE' strings, or such a mapping; `lexicon`: overlay names or folders."""
    if results not in RESULT_MODES:
        raise UsageError(f"results must be one of {', '.join(RESULT_MODES)}, got '{results}'")
    per_target = target_options(targets, options, size, seed)
    root = Path(out)
    compiled = read_catalog(Path(catalog), _lexicon(lexicon), seed, max_bytes)
    tasks = list(_tasks(compiled.entries, per_target))
    report = BuildReport({})
    report.warnings = compiled.warnings
    hashes: dict[tuple[str, str], dict[str, str]] = {}
    errors: dict[tuple[str, str], str] = {}
    to_run = []
    for task in tasks:
        done = up_to_date(root, task)
        if done is None:
            to_run.append(task)
        else:
            hashes[_place(task)] = done
            report.statuses[_place(task)] = UP_TO_DATE
    started = time.monotonic()
    total = len(tasks)
    finished = total - len(to_run)
    by_folder = {task.folder: task for task in to_run}
    for outcome in _run(to_run, root, jobs, scheduler, results, pool):
        place = _place(by_folder[outcome.folder])
        outcome = _deliver(outcome, root, by_folder[outcome.folder])
        if outcome.ok:
            hashes[place] = outcome.hashes
            report.statuses[place] = BUILT
        else:
            errors[place] = outcome.error or ""
            report.statuses[place] = FAILED
        finished += 1
        if progress is not None:
            progress(finished, total, time.monotonic() - started)
    for task in to_run:  # a runner that lost a task (it never should) fails it rather than hide it
        if _place(task) not in report.statuses:
            errors[_place(task)] = "error: the task did not finish; run the build again"
            report.statuses[_place(task)] = FAILED
    report.failures = _failures(compiled, errors)
    report.manifest = manifest(compiled, per_target, hashes, errors)
    write_atomic(root / MANIFEST_NAME, _manifest_bytes(report.manifest))
    return report


def _place(task: Task) -> tuple[str, str]:
    return task.folder.rpartition("/")[0], task.target


def _lexicon(specs: Iterable[str | Path]) -> Lexicon:
    """The lexicon as its files are now. cnlmc.api.lexicon_for keeps the lexicons it made in memory
    by folder name, so a pipeline that edits an overlay and builds again in the same process would
    get the old one; this goes to the disk cache, keyed by the files' names, sizes and times."""
    names = tuple(str(spec) for spec in specs)
    folders = tuple(name for name in names if Path(name).is_dir())
    overlays = tuple(name for name in names if not Path(name).is_dir())
    try:
        return cached_lexicon.__wrapped__(folders, overlays)
    except LexiconError as exc:
        raise UsageError(f"lexicon: {exc}") from None


def _tasks(entries: list[Entry], per_target: dict[str, dict[str, Any]]) -> Iterator[Task]:
    for entry in entries:
        for target, options in per_target.items():
            key = task_key(entry.document, target, options)
            yield Task(key, f"{entry.folder}/{target}", target, options, entry.document)


def _run(
    tasks: list[Task], root: Path, jobs: int | None, scheduler: str | None, results: str, pool: bool | None
) -> Iterator[Outcome]:
    if not tasks:
        return iter(())
    if scheduler is not None:
        return run_dask(tasks, root, scheduler, results)
    workers = min(jobs or available_cpus(), len(tasks))
    if pool is False or (workers <= 1 and not pool):
        return run_serial(tasks, root)
    return run_pool(tasks, root, workers)


def _deliver(outcome: Outcome, root: Path, task: Task) -> Outcome:
    """Write the files that came back as bytes (a Dask run with results='return'), here."""
    if outcome.ok and outcome.version != __version__:
        outcome.error = f"error: the worker runs cnlmc {outcome.version}, this build {__version__}: install the same version on every worker"
    if outcome.ok and outcome.files is not None:
        try:
            write_task(root, task, outcome.files)
        except UsageError as exc:
            outcome.error = f"error: {exc}"
        outcome.files = None
    return outcome


def _failures(compiled: Catalog, errors: dict[tuple[str, str], str]) -> list[tuple[str, str, str]]:
    failures = [(f"{p.file}:{p.line}", "", p.text) for p in compiled.problems]
    where = {e.folder: f"{e.file}:{e.line}: {e.name}" for e in compiled.entries}
    failures += [(where.get(folder, folder), target, text) for (folder, target), text in errors.items()]
    return failures


def manifest(
    compiled: Catalog,
    per_target: dict[str, dict[str, Any]],
    hashes: dict[tuple[str, str], dict[str, str]],
    errors: dict[tuple[str, str], str],
) -> dict[str, Any]:
    """The build's manifest: each material in catalogue order with each target's files and their
    content hashes (or its error), and what the build was made with. Nothing in it depends on
    how or where the tasks ran, or on what was up to date."""
    materials = []
    for entry in compiled.entries:
        outputs: dict[str, Any] = {}
        for target in per_target:
            folder = f"{entry.folder}/{target}"
            files = hashes.get((entry.folder, target))
            if files is not None:
                outputs[target] = {"folder": folder, "files": dict(sorted(files.items()))}
            else:
                outputs[target] = {"folder": folder, "error": errors.get((entry.folder, target), "not built")}
        materials.append(
            {"name": entry.name, "source": entry.file, "line": entry.line, "phrase": entry.phrase, "outputs": outputs}
        )
    return {
        "cnlmc": __version__,
        "format": BUILD_FORMAT,
        "catalog": compiled.files,
        "targets": dict(per_target),
        "materials": materials,
        "failed": [{"where": f"{p.file}:{p.line}", "error": p.text} for p in compiled.problems],
    }


def _manifest_bytes(value: dict[str, Any]) -> bytes:
    return (json.dumps(value, indent=1, ensure_ascii=False) + "\n").encode("utf-8")
