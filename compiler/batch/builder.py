"""A build: the catalogue compiled, its tasks keyed, the up-to-date ones skipped, the others run
(serially, on a pool, or on Dask), their files written, and the manifest written last."""

from __future__ import annotations

import json
import time
from collections import Counter
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from cnlmc import __version__

from ..errors import UsageError
from ..inputs import DEFAULT_MAX_BYTES
from ..lexicon import Lexicon, cached_lexicon
from ..lexicon_schema import LexiconError
from ..output import write_atomic
from .catalog import Catalog, Entry, read_catalog
from .keys import BUILD_FORMAT, task_key
from .modes import RESULT_MODES
from .runners import available_cpus, run_dask, run_pool, run_serial
from .tasks import Outcome, Task, up_to_date, write_task
from .work import target_options

MANIFEST_NAME = "cnlmc-build.json"
BUILT, UP_TO_DATE, FAILED = "built", "up to date", "failed"
STATUSES = (BUILT, UP_TO_DATE, FAILED)


class Done(NamedTuple):
    """How far a build is, as its progress callback hears it after each task that ran."""

    materials_done: int  # materials whose every target is built, up to date or failed
    materials: int
    tasks_done: int
    tasks: int
    seconds: float  # since the first task was handed out
    ran: int  # tasks that ran (were not up to date) so far, of `to_run`
    to_run: int


Progress = Callable[[Done], None]


@dataclass
class BuildReport:
    """What a build did: the manifest (also written to OUT/cnlmc-build.json), each task's status,
    the failures (where, target, what went wrong) and the catalogue's warnings."""

    manifest: dict[str, Any]
    statuses: dict[tuple[str, str], str] = field(default_factory=dict)  # (material folder, target) -> status
    failures: list[tuple[str, str, str]] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    cpu_seconds: float = 0.0  # the workers' CPU time for the tasks that ran (not the catalogue's compile)

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
    ledger = Ledger(root, compiled, list(_tasks(compiled.entries, per_target)))
    ledger.run(_run(ledger.to_run, root, jobs, scheduler, results, pool), progress)
    report = BuildReport(manifest(compiled, per_target, ledger.hashes, ledger.errors), ledger.statuses)
    report.failures = _failures(compiled, ledger.errors)
    report.warnings = compiled.warnings
    report.cpu_seconds = ledger.cpu_seconds
    write_atomic(root / MANIFEST_NAME, _manifest_bytes(report.manifest))
    return report


class Ledger:
    """What each task of a build came to: up to date (found on disk), built or failed, with its
    files' hashes or its error; and how far the build is."""

    def __init__(self, root: Path, compiled: Catalog, tasks: list[Task]) -> None:
        self.root = root
        self.tasks = tasks
        self.materials = len(compiled.entries)
        self.hashes: dict[tuple[str, str], dict[str, str]] = {}
        self.errors: dict[tuple[str, str], str] = {}
        self.statuses: dict[tuple[str, str], str] = {}
        self.to_run: list[Task] = []
        self.cpu_seconds = 0.0
        for task in tasks:
            current = up_to_date(root, task)
            if current is None:
                self.to_run.append(task)
            else:
                self.hashes[_place(task)] = current
                self.statuses[_place(task)] = UP_TO_DATE

    def run(self, outcomes: Iterator[Outcome], progress: Progress | None) -> None:
        started = time.monotonic()
        left = Counter(_place(task)[0] for task in self.to_run)  # tasks still to finish, per material
        finished = self.materials - len(left)
        by_folder = {task.folder: task for task in self.to_run}
        for ran, outcome in enumerate(outcomes, start=1):
            task = by_folder[outcome.folder]
            self.record(task, _deliver(outcome, self.root, task))
            left[_place(task)[0]] -= 1
            finished += left[_place(task)[0]] == 0
            if progress is not None:
                done = len(self.tasks) - len(self.to_run) + ran
                seconds = time.monotonic() - started
                progress(Done(finished, self.materials, done, len(self.tasks), seconds, ran, len(self.to_run)))
        for task in self.to_run:  # a runner that lost a task (it never should) fails it rather than hide it
            if _place(task) not in self.statuses:
                self.record(task, Outcome(task.key, task.folder, task.target, error="error: the task did not finish"))

    def record(self, task: Task, outcome: Outcome) -> None:
        place = _place(task)
        self.cpu_seconds += outcome.cpu_seconds
        if outcome.ok:
            self.hashes[place] = outcome.hashes
            self.statuses[place] = BUILT
        else:
            self.errors[place] = outcome.error or ""
            self.statuses[place] = FAILED


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
        fresh = getattr(cached_lexicon, "__wrapped__", cached_lexicon)  # past its in-memory lru_cache
        lexicon: Lexicon = fresh(folders, overlays)
        return lexicon
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
