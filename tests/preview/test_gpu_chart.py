"""The preview chart's GPU timing (bench/preview_chart_gpu.py): the speed-up at equal error from
measured times and the CPU chart's errors, folders merged, and a tier timed with its GPU side."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from tests.helpers import bench_modules

ROOT = Path(__file__).resolve().parents[2]
RUNS = [ROOT / "bench" / "data" / "gpu_chart" / "run1", ROOT / "bench" / "data" / "gpu_chart" / "run2"]


@pytest.fixture(scope="module")
def gpu_chart():
    return bench_modules("preview_chart_gpu")[0]


def curve(material: str, times_ms: list[float], flips: list[float]) -> list[dict]:
    return [
        {"material": material, "method": f"mitsuba{spp}", "ms512": t, "flip": e}
        for spp, t, e in zip((1, 4, 16, 64), times_ms, flips)
    ]


def test_speed_up_is_mitsubas_time_for_the_tiers_error_over_the_tiers_time(gpu_chart):
    # Mitsuba halves its error with each 4x the samples; the best real-time tier (splitsum,
    # FLIP 0.02 on the CPU chart) equals its 16-spp render: 40 ms against 2 ms is 20x.
    gpu = curve("m", [10, 20, 40, 80], [0.08, 0.04, 0.02, 0.01])
    gpu += [
        {"material": "m", "method": "analytic", "ms512": 1.0},
        {"material": "m", "method": "splitsum", "ms512": 2.0},
    ]
    cpu = [
        {"material": "m", "method": "analytic", "ms512": 10.0, "flip": 0.05},
        {"material": "m", "method": "splitsum", "ms512": 20.0, "flip": 0.02},
    ]
    cpu += [dict(r, ms512=r["ms512"] * 10) for r in curve("m", [10, 20, 40, 80], [0.9, 0.9, 0.9, 0.9])]
    (row,) = gpu_chart.speedups(gpu, cpu, {"m": "metal"})
    assert row["tier"] == "splitsum" and row["flip"] == 0.02
    assert row["mitsuba_ms512_gpu"] == pytest.approx(40.0)
    assert row["speedup_gpu"] == pytest.approx(20.0)
    # the CPU column: the chart's CPU times along the same (GPU-measured, 128^2) errors
    assert row["speedup_cpu"] == pytest.approx(400.0 / 20.0)


def test_between_two_spp_the_time_is_interpolated_log_log(gpu_chart):
    gpu = curve("m", [10, 20, 40, 80], [0.08, 0.04, 0.02, 0.01]) + [
        {"material": "m", "method": "splitsum", "ms512": 1.0}
    ]
    cpu = [{"material": "m", "method": "splitsum", "ms512": 1.0, "flip": math.sqrt(0.04 * 0.02)}]
    (row,) = gpu_chart.speedups(gpu, cpu, {})
    assert row["mitsuba_ms512_gpu"] == pytest.approx(math.sqrt(20 * 40))


def test_a_material_without_a_curve_or_tier_times_is_left_out(gpu_chart):
    gpu = [{"material": "m", "method": "splitsum", "ms512": 1.0}]
    cpu = [{"material": "m", "method": "splitsum", "ms512": 1.0, "flip": 0.01}]
    assert gpu_chart.speedups(gpu, cpu, {}) == []


def test_the_first_folder_wins_and_later_ones_add_what_it_lacks(gpu_chart, tmp_path):
    for name, rows in (("a", "m,splitsum,1.0,\n"), ("b", "m,splitsum,9.0,\nm,mc16,3.0,\n")):
        (tmp_path / name).mkdir()
        (tmp_path / name / "gpu_times.csv").write_text("material,method,ms512,flip\n" + rows)
    rows = gpu_chart.merged([tmp_path / "a", tmp_path / "b"])
    assert [(r["method"], r["ms512"]) for r in rows] == [("splitsum", 1.0), ("mc16", 3.0)]
    assert math.isnan(rows[0]["flip"])


def test_the_committed_runs_give_every_chart_material_a_speed_up(gpu_chart):
    """The H200 runs of session 23 (docs/preview.md): every chart row has times, a curve and a
    finite speed-up, and the GPU side of a frame is never longer than the frame."""
    gpu = gpu_chart.merged(RUNS)
    cpu = gpu_chart.read_rows(ROOT / "docs" / "preview_chart.csv")
    table = gpu_chart.speedups(gpu, cpu, {})
    assert len(table) == len({r["material"] for r in cpu}) == 66
    assert all(0 < r["speedup_gpu"] < 1000 and r["ms512_gpu"] > 0 for r in table)
    wall = {(r["material"], r["method"]): r["ms512"] for r in gpu_chart.read_gpu(RUNS[1] / "gpu_times.csv")}
    sides = [(m, t, v) for (m, t), v in wall.items() if t.endswith(gpu_chart.GPU_SIDE)]
    assert sides and all(v <= wall[(m, t.removesuffix(gpu_chart.GPU_SIDE))] for m, t, v in sides)


@pytest.mark.usefixtures("gl_available")
def test_a_tier_is_timed_by_the_wall_clock_and_by_a_timer_query(gpu_chart, tmp_path):
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer

    material = compile_source("copper\n").ir["materials"][0]
    log = gpu_chart.Log(tmp_path)
    with Renderer(64) as renderer:
        scene = gpu_chart.scenes()[gpu_chart.ERROR_SIZE]
        gpu_chart.time_tiers(log, (renderer, renderer), scene, "copper", material, ("analytic",), 2, True)
    log.file.close()
    rows = gpu_chart.read_gpu(tmp_path / "gpu_times.csv")
    assert [r["method"] for r in rows] == ["analytic", "analytic:gpu"]
    assert all(r["ms512"] > 0 and math.isfinite(r["ms512"]) for r in rows)
