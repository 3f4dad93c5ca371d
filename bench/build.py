"""Batch-build benchmark (#20): prints numbers, asserts nothing.

.venv/bin/python bench/build.py [--materials 200] [--size 512] [--target maps]

Materials per second for 1 and 2 workers on a local process pool and on a Dask LocalCluster (2
worker processes, one thread each) over a catalogue of `--materials` materials with procedural
maps, every task built from scratch; the scaling efficiency (rate with 2 / (2 x rate with 1));
Dask's own cost per task (empty tasks through the same cluster, and the Dask run against the pool
with the same number of workers); and, from these, the catalogue size at which a cluster of
machines pays off (printed; docs/build.md explains the formula).
"""

from __future__ import annotations

import argparse
import os
import shutil
import tempfile
import time
from pathlib import Path

from cnlmc.batch import build_report

#: phrases whose materials bake maps (wood, rust, brushing, hammering, concrete, stone grain):
#: the catalogue cycles through them with a distinct name per line
PHRASES = (
    "polished oak",
    "heavily rusted iron",
    "brushed steel",
    "hammered copper",
    "weathered concrete",
    "lightly brushed, blue anodized aluminum",
    "dark walnut",
    "rusted steel",
    "brushed gold",
    "oak with a glossy white varnish",
)


def catalogue(folder: Path, count: int) -> Path:
    path = folder / "catalogue.cnl"
    path.write_text("".join(f"m{i:05d}: {PHRASES[i % len(PHRASES)]}\n" for i in range(count)), encoding="utf-8")
    return path


def timed_build(catalog: Path, out: Path, targets: list[str], size: int, **how: object) -> tuple[float, int, float]:
    """(wall seconds, materials, the workers' CPU seconds for the tasks) of a build from scratch."""
    shutil.rmtree(out, ignore_errors=True)
    start = time.perf_counter()
    report = build_report(catalog, out, targets, size=size, **how)  # type: ignore[arg-type]
    seconds = time.perf_counter() - start
    assert report.ok, report.failures[:3]
    return seconds, len(report.manifest["materials"]), report.cpu_seconds


def say(label: str, seconds: float, count: int, cpu: float) -> None:
    print(
        f"{label:<22} {count} materials in {seconds:6.2f} s: {count / seconds:6.2f} materials/s "
        f"(CPU {1000 * cpu / count:.0f} ms a material)"
    )


def empty_task(number: int) -> int:
    return number


def dask_overhead_per_task(client: object, tasks: int) -> float:
    """Seconds per task of submitting and gathering tasks that do nothing."""
    start = time.perf_counter()
    futures = client.map(empty_task, range(tasks), pure=False)  # type: ignore[attr-defined]
    client.gather(futures)  # type: ignore[attr-defined]
    return (time.perf_counter() - start) / tasks


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--materials", type=int, default=200)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--target", default="maps")
    args = parser.parse_args()
    targets = args.target.split(",")
    from distributed import Client, LocalCluster

    print(f"load average before: {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        catalog = catalogue(folder, args.materials)
        rates: dict[str, float] = {}
        cpu_costs: dict[str, float] = {}
        for label, how in (
            ("in this process (1)", {"jobs": 1}),
            ("pool of 1", {"jobs": 1, "pool": True}),
            ("pool of 2", {"jobs": 2}),
        ):
            seconds, count, cpu = timed_build(catalog, folder / "out", targets, args.size, **how)
            rates[label] = count / seconds
            cpu_costs[label] = cpu / count
            say(label, seconds, count, cpu)
        written = sum(p.stat().st_size for p in (folder / "out").rglob("*") if p.is_file()) / args.materials
        print(f"written: {written / 1000:.0f} kB a material")
        for workers in (1, 2):  # a cluster of each size, started afresh
            start = time.perf_counter()
            with LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
            ) as cluster:
                started = time.perf_counter() - start
                print(f"LocalCluster ({workers} processes) started in {started:.1f} s")
                with Client(cluster.scheduler_address) as client:
                    overhead = dask_overhead_per_task(client, 1000)
                print(f"Dask overhead per empty task ({workers} workers): {overhead * 1000:.2f} ms")
                seconds, count, cpu = timed_build(
                    catalog, folder / "out", targets, args.size, scheduler=cluster.scheduler_address
                )
                rates[f"dask {workers}"] = count / seconds
                say(f"dask, {workers} worker(s)", seconds, count, cpu)
        print_summary(rates, cpu_costs["in this process (1)"], overhead, started, written)
    print(f"load average after: {os.getloadavg()[0]:.1f}")


def print_summary(rates: dict[str, float], cpu_cost: float, overhead: float, started: float, written: float) -> None:
    print(f"scaling efficiency, pool: {rates['pool of 2'] / (2 * rates['pool of 1']):.0%} (2 workers against 1)")
    print(f"scaling efficiency, dask: {rates['dask 2'] / (2 * rates['dask 1']):.0%} (2 workers against 1)")
    print(f"dask against the pool, 2 workers: {rates['dask 2'] / rates['pool of 2']:.2f}x the rate")
    per_material = cpu_cost  # CPU seconds: what a material costs on a core of its own
    per_task_cost = max(0.0, 1 / rates["dask 1"] - 1 / rates["pool of 1"])
    print(f"per-material CPU cost, one process: {per_material * 1000:.0f} ms")
    print(f"Dask cost per task over the pool (1 worker): {per_task_cost * 1000:.1f} ms")
    print_payoff(per_material, overhead, started, written)


#: what carries the files back to the client with results='return' (our choice: 1 Gbit/s Ethernet, about 110 MB/s)
BANDWIDTH = 110e6


def print_payoff(
    per_material: float, per_task: float, startup: float, written: float, cores: int = 16, machines: int = 8
) -> None:
    """When `machines` machines of `cores` cores beat one such machine (docs/build.md):
    n c / P > S + n (c + o) / (k P) + n B / W  <=>  n > S / (c / P - (c + o) / (k P) - B / W)."""
    for scale, label in ((1, "the bench's size"), (16, "4x the side (16x the pixels)")):
        c, b = per_material * scale, written * scale
        for mode, bandwidth in (("shared", float("inf")), ("return", BANDWIDTH)):
            gain = c / cores - (c + per_task) / (machines * cores) - b / bandwidth
            n = startup / gain if gain > 0 else float("inf")
            print(
                f"{machines} x {cores} cores beat one {cores}-core machine at {label}, results={mode}: "
                f"from about {n:,.0f} materials ({n * c / cores:,.0f} s on one machine)"
            )


if __name__ == "__main__":
    main()
