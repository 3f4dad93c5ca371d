"""`cnlmc build` and cnlmc.api.build: the same manifest and bytes however the tasks run (in this
process, on a pool, on a Dask cluster), incremental rebuilds, and interrupted builds resumed."""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import signal
import subprocess
import sys
import threading
import time
import zipfile
from pathlib import Path

import pytest
from PIL import Image

from cnlmc.api import build
from cnlmc.batch import build_report
from cnlmc.batch.work import target_options
from cnlmc.errors import UsageError
from tests.build.conftest import USES_STEEL
from tests.helpers import run_cnlmc

TARGETS = ["maps", "glsl", "ir"]
SIZE = 32


def tree(root: Path) -> dict[str, bytes]:
    """Every file under `root` (relative path -> bytes)."""
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def leftovers(root: Path) -> list[str]:
    """Temps and lock files cnlmc.output leaves only when a writer is killed."""
    return [p.name for p in root.rglob("*") if ".~cnlmc." in p.name or p.name == ".cnlmc.lock"]


def assert_manifest_matches_files(manifest: dict, root: Path) -> None:
    for material in manifest["materials"]:
        for output in material["outputs"].values():
            assert "files" in output, output
            for name, digest in output["files"].items():
                data = (root / output["folder"] / name).read_bytes()
                assert digest == "sha256:" + hashlib.sha256(data).hexdigest()


@pytest.mark.dask
def test_serial_pool_and_dask_give_the_same_manifest_and_bytes(catalog, tmp_path, cluster):
    serial = build(catalog, tmp_path / "serial", TARGETS, size=SIZE, jobs=1)
    pool = build(catalog, tmp_path / "pool", TARGETS, size=SIZE, jobs=2)
    returned = build(catalog, tmp_path / "dask", TARGETS, size=SIZE, scheduler=cluster.scheduler_address)
    shared = build(
        catalog, tmp_path / "shared", TARGETS, size=SIZE, scheduler=cluster.scheduler_address, results="shared"
    )
    assert serial == pool == returned == shared
    names = [m["name"] for m in serial["materials"]]
    assert names == ["hull", "floor", "rail", "trim", "tile__red", "tile__blue"]
    assert serial["cnlmc"] and serial["targets"]["maps"]["size"] == SIZE
    assert_manifest_matches_files(serial, tmp_path / "serial")
    reference = tree(tmp_path / "serial")
    assert {"floor/maps/floor_base_color.png", "hull/glsl/hull.frag", "trim/ir/materials.ir.json"} <= set(reference)
    for other in ("pool", "dask", "shared"):
        assert tree(tmp_path / other) == reference, other
    assert not leftovers(tmp_path)


@pytest.mark.dask
def test_a_killed_dask_worker_loses_nothing(catalog, tmp_path, cluster):
    """A worker killed mid-build: Dask runs its tasks again (or fails them after its retries);
    either way a rerun finishes the build, with the manifest and files of a serial run."""
    distributed = pytest.importorskip("distributed")
    out = tmp_path / "out"
    with distributed.Client(cluster.scheduler_address, set_as_default=False) as client:
        victim = sorted(client.run(os.getpid).values())[0]
    killer = threading.Thread(target=_kill_when_first_task_lands, args=(out, victim), daemon=True)
    killer.start()
    build(catalog, out, ["maps"], size=64, scheduler=cluster.scheduler_address, results="shared")
    killer.join()
    again = build_report(catalog, out, ["maps"], size=64, scheduler=cluster.scheduler_address, results="shared")
    assert again.ok and again.count("failed") == 0
    assert again.manifest == build(catalog, tmp_path / "reference", ["maps"], size=64, jobs=1)
    assert_manifest_matches_files(again.manifest, out)
    assert not leftovers(out)


def _kill_when_first_task_lands(out: Path, pid: int) -> None:
    deadline = time.monotonic() + 60
    while not any(out.rglob(".cnlmc-build.json")) and time.monotonic() < deadline:
        time.sleep(0.02)
    os.kill(pid, signal.SIGKILL)


def test_a_material_moved_down_the_catalogue_keeps_its_key(catalog, tmp_path):
    first = build(catalog, tmp_path / "out", ["ir"], jobs=1)
    catalog.write_text("\n\nextra: matte black paint\n" + catalog.read_text("utf-8"), encoding="utf-8")
    report = build_report(catalog, tmp_path / "out", ["ir"], jobs=1)
    assert report.statuses[("extra", "ir")] == "built"
    assert report.count("built") == 1 and report.count("up to date") == len(first["materials"])


def test_a_second_build_does_nothing(catalog, tmp_path):
    out = tmp_path / "out"
    arguments = ("build", str(catalog), "-o", str(out), "--target", ",".join(TARGETS), "--size", str(SIZE), "-j", "1")
    first = build_report(catalog, out, TARGETS, size=SIZE, jobs=1)
    assert first.count("built") == 18
    stamps = {p: (p.stat().st_ino, p.stat().st_mtime_ns) for p in out.rglob("*") if p.is_file()}
    second = run_cnlmc(*arguments)
    assert second.returncode == 0, second.stderr
    assert second.stdout.splitlines()[-1].split() == ["all", "0", "18", "0"]
    manifest = out / "cnlmc-build.json"
    assert {p: (p.stat().st_ino, p.stat().st_mtime_ns) for p in out.rglob("*") if p.is_file() and p != manifest} == {
        p: s for p, s in stamps.items() if p != manifest
    }


def test_a_changed_or_damaged_output_is_rebuilt(catalog, tmp_path):
    out = tmp_path / "out"
    build(catalog, out, ["maps"], size=SIZE, jobs=1)
    (out / "floor" / "maps" / "floor_base_color.png").write_bytes(b"not a png")
    report = build_report(catalog, out, ["maps"], size=SIZE, jobs=1)
    assert [place for place, status in report.statuses.items() if status == "built"] == [("floor", "maps")]
    report = build_report(catalog, out, ["maps"], size=SIZE * 2, jobs=1)  # an option changed: every task
    assert report.count("built") == len(report.statuses)


def test_changing_one_lexicon_entry_rebuilds_exactly_the_materials_that_use_it(catalog, tmp_path):
    overlay = tmp_path / "studio"
    overlay.mkdir()
    entry = overlay / "nouns_studio.toml"
    entry.write_text("[steel]\nroughness = 0.5\n", encoding="utf-8")
    out = tmp_path / "out"
    targets = ["glsl", "ir"]
    first = build_report(catalog, out, targets, jobs=1, lexicon=[overlay])
    assert first.count("built") == len(first.statuses) == 12
    entry.write_text("[steel]\nroughness = 0.45\n", encoding="utf-8")
    second = build_report(catalog, out, targets, jobs=1, lexicon=[overlay])
    rebuilt = {folder for (folder, _), status in second.statuses.items() if status == "built"}
    assert rebuilt == USES_STEEL
    assert second.count("built") == len(USES_STEEL) * len(targets)
    assert second.count("up to date") == 12 - second.count("built")
    assert json.loads((out / "hull" / "ir" / "materials.ir.json").read_text())["materials"][0]["provenance"]
    other = tmp_path / "unrelated"  # a folder whose entries no material uses: nothing to rebuild
    other.mkdir()
    (other / "nouns_more.toml").write_text("[copper]\nroughness = 0.3\n", encoding="utf-8")
    third = build_report(catalog, out, targets, jobs=1, lexicon=[overlay, other])
    assert third.count("built") == 0


def test_a_killed_build_completes_on_rerun_with_nothing_half_written(tmp_path):
    catalog = tmp_path / "big.cnl"
    phrases = ["polished oak", "heavily rusted iron", "brushed steel", "hammered copper", "weathered concrete"]
    catalog.write_text("".join(f"m{i}: {phrases[i % len(phrases)]}\n" for i in range(12)), encoding="utf-8")
    out = tmp_path / "out"
    command = [sys.executable, "-m", "cnlmc", "build", str(catalog), "-o", str(out), "-t", "maps,materialx"]
    process = subprocess.Popen([*command, "--size", "64", "-j", "2"], start_new_session=True, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    while not any(out.rglob(".cnlmc-build.json")) and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)  # the build and its workers, as a power cut would
    process.wait()
    assert not (out / "cnlmc-build.json").exists()
    rerun = subprocess.run([*command, "--size", "64", "-j", "2"], capture_output=True, text=True, timeout=120)
    assert rerun.returncode == 0, rerun.stderr
    built, up_to_date, failed = map(int, rerun.stdout.splitlines()[-1].split()[1:])
    assert up_to_date >= 1 and failed == 0 and built + up_to_date == 24  # resumed, not started again
    assert not leftovers(out)
    manifest = json.loads((out / "cnlmc-build.json").read_text())
    assert_manifest_matches_files(manifest, out)
    assert manifest == build(catalog, tmp_path / "reference", ["maps", "materialx"], size=64, jobs=1)


def test_failures_are_reported_and_the_rest_is_built(tmp_path):
    catalog = tmp_path / "c.cnl"
    catalog.write_text("good: polished gold\nbad: blorfy steel\n", encoding="utf-8")
    out = tmp_path / "out"
    result = run_cnlmc("build", str(catalog), "-o", str(out), "-t", "glsl")
    assert result.returncode == 1
    assert "c.cnl:2:6: error[E001]: unknown word 'blorfy'" in result.stderr
    assert result.stdout.splitlines()[-1].split() == ["all", "1", "0", "1"]
    manifest = json.loads((out / "cnlmc-build.json").read_text())
    assert [m["name"] for m in manifest["materials"]] == ["good"]
    assert manifest["failed"][0]["where"] == "c.cnl:2"
    assert (out / "good" / "glsl" / "good.frag").is_file()


def test_a_usage_error_says_what_to_do_and_writes_nothing(catalog, tmp_path):
    result = run_cnlmc("build", str(catalog), "-o", str(tmp_path / "out"), "-t", "glsl,mapz")
    assert result.returncode == 2
    assert "cnlmc: error: unknown target 'mapz'" in result.stderr and "did you mean 'maps'?" in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    "settings,message",
    [
        ({"options": ["glsl.colour=red"]}, "no target of this build (glsl) has the option 'glsl.colour'"),
        ({"options": ["fresnel=wrong"]}, "fresnel"),
        ({"results": "mail"}, "results must be one of return, shared"),
        ({"scheduler": "tcp://127.0.0.1:9"}, "cannot reach the Dask scheduler at 'tcp://127.0.0.1:9'"),
    ],
)
def test_bad_settings_are_usage_errors(catalog, tmp_path, settings, message):
    with contextlib.ExitStack() as stack:
        if "scheduler" in settings:  # Dask's own connect timeout (30 s by default), shortened
            dask = pytest.importorskip("dask", reason="Dask is not installed (pip install -e '.[build]')")
            stack.enter_context(dask.config.set({"distributed.comm.timeouts.connect": "1s"}))
        with pytest.raises(UsageError) as info:
            build(catalog, tmp_path / "out", ["glsl"], jobs=1, **settings)
    assert message in str(info.value)
    assert not (tmp_path / "out" / "cnlmc-build.json").exists()


def test_a_folder_catalogue_keeps_each_file_apart(tmp_path):
    folder = tmp_path / "library"
    (folder / "metals").mkdir(parents=True)
    (folder / "metals" / "a.cnl").write_text("plate: brushed steel\n", encoding="utf-8")
    (folder / "b.cnl").write_text("plate: polished oak\n", encoding="utf-8")
    manifest = build(folder, tmp_path / "out", ["glsl"], jobs=1)
    assert manifest["catalog"] == ["b.cnl", "metals/a.cnl"]
    assert [m["outputs"]["glsl"]["folder"] for m in manifest["materials"]] == ["b/plate/glsl", "metals/a/plate/glsl"]


def test_size_sets_pixels_never_an_objects_metres(tmp_path):
    """`--size N` is an image size: for the exchange targets that also declare `size` (the preview
    object's size in metres) it sets their `map_size`; a build to gltf and usdz with it succeeds."""
    options = target_options(["maps", "gltf", "usdz"], [], 16, 0)
    assert options["maps"]["size"] == 16
    assert options["gltf"]["map_size"] == 16 and options["gltf"]["size"] is None
    assert options["usdz"]["map_size"] == 16 and options["usdz"]["size"] is None
    catalog = tmp_path / "hull.cnl"
    catalog.write_text("rusty iron\n", encoding="utf-8")
    result = run_cnlmc("build", str(catalog), "-o", str(tmp_path / "out"), "-t", "gltf,usdz", "--size", "16", "-j", "1")
    assert result.returncode == 0, result.stderr
    packages = list((tmp_path / "out").rglob("*.usdz"))
    assert packages, "no usdz written"
    with zipfile.ZipFile(packages[0]) as package:
        images = [n for n in package.namelist() if n.endswith(".png")]
        assert images and all(Image.open(package.open(n)).size == (16, 16) for n in images)
