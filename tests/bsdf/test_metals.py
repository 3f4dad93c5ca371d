"""Conductor Fresnel per metal against the spectral reference curves (metals_rgb.json)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from cnlmc.bsdf.fresnel import fresnel_conductor, fresnel_f82, fresnel_schlick

BENCH = Path(__file__).parents[2] / "bench" / "fresnel_table.py"
# JSON errors were evaluated on a 0.5° grid, the CSV curves are tabulated every 5° and
# rounded to 5 decimals, F0/F82/η/k in the JSON to 4 decimals: our max over the 5°
# grid must not exceed the listed max by more than that rounding (2e-4), and where the
# listed maximum lies on the 5° grid it must be reproduced to the same 2e-4.
ROUNDING = 2e-4
METHODS = {"schlick_with_true_F0": "schlick", "f82_tint_model": "f82", "exact_fresnel_with_fitted_nk": "exact_fit"}


def _approx(primary, mu):
    m = mu[:, None]
    f0, f82 = np.array(primary["F0_srgb_linear"]), np.array(primary["F82_srgb_linear"])
    return {
        "schlick": fresnel_schlick(m, f0),
        "f82": fresnel_f82(m, f0, f82),
        "exact_fit": fresnel_conductor(m, np.array(primary["eta_rgb_fit"]), np.array(primary["k_rgb_fit"])),
    }


def test_every_metal_has_a_reference_curve(metals, angular_reference):
    assert len(metals) == 17
    assert {m["key"] for m in metals} <= set(angular_reference)


def test_fresnel_errors_reproduce_metals_json(metals, angular_reference):
    for metal in metals:
        theta, ref = angular_reference[metal["key"]]
        approx = _approx(metal["primary"], np.cos(np.radians(theta)))
        listed = metal["primary"]["fresnel_errors_vs_spectral_reference"]
        for data_key, name in METHODS.items():
            err = np.abs(approx[name] - ref)
            expect = listed[data_key]
            assert err.max() <= expect["max_abs"] + ROUNDING, (metal["key"], name)
            on_grid = np.isclose(theta, expect["at_theta_deg"])
            if on_grid.any():
                ch = "rgb".index(expect["channel"])
                assert err[on_grid, ch][0] == pytest.approx(expect["max_abs"], abs=ROUNDING), (metal["key"], name)


def test_exact_fit_within_3e3_where_f0_is_inside_srgb(metals, angular_reference):
    """data/README: exact Fresnel with the fitted η/k is within ≤ 0.003 — except where
    the reference leaves [0, 1] (Au) or the fit is poor near grazing (Cu, brasses,
    whose listed errors exceed 0.003; those are checked against their listed value)."""
    checked = 0
    for metal in metals:
        listed = metal["primary"]["fresnel_errors_vs_spectral_reference"]
        if listed["exact_fresnel_with_fitted_nk"]["max_abs"] > 0.003:
            continue
        theta, ref = angular_reference[metal["key"]]
        approx = _approx(metal["primary"], np.cos(np.radians(theta)))["exact_fit"]
        assert np.abs(approx - ref).max() <= 0.003, metal["key"]
        checked += 1
    assert checked >= 12


def _load_bench():
    spec = importlib.util.spec_from_file_location("fresnel_table", BENCH)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_fresnel_table_ordering(data_dir):
    """exact ≤ F82 ≤ Schlick (max error) for every metal where the data says so."""
    bench = _load_bench()
    rows = bench.table_rows(data_dir)
    ordered = 0
    for row in rows:
        d = row["data"]
        if not d["exact_fit"] <= d["f82"] <= d["schlick"]:
            continue
        ours = {m: row["ours"][m][0] for m in bench.METHODS}
        assert ours["exact_fit"] <= ours["f82"] <= ours["schlick"], row["key"]
        ordered += 1
    assert ordered >= 15  # all but Au (F0 > 1 in red) in the current data
    md = bench.markdown(rows)
    assert md.count("\n") == len(rows) + 2 and "| Ag |" in md
