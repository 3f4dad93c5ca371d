"""The key light's pre-integrated diffusion table (backends/preview/subsurface_profile.py): the
Christensen-Burley profile spread over a ring of the surface's curvature radius (Penner 2011)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from cnlmc.backends.preview.subsurface import preintegrated_table, settings
from cnlmc.backends.preview.subsurface_profile import preintegrated

SHADER = Path(__file__).resolve().parents[2] / "backends" / "glsl" / "snippets" / "subsurface.glsl"


def test_k0_matches_tabulated_values():
    # Abramowitz & Stegun Table 9.8 (K0 at 0.1, 1, 2, 5)
    k0 = preintegrated_table().k0
    assert np.allclose(k0(np.array([0.1, 1.0, 2.0, 5.0])), [2.4270690, 0.4210244, 0.1138939, 0.0036911], rtol=1e-6)


def test_a_flat_surface_keeps_the_cosine_and_a_tight_curve_spreads_it():
    k0, cos = preintegrated_table().k0, np.linspace(-1.0, 1.0, 9)
    assert np.allclose(preintegrated(cos, 0.0, k0), np.maximum(cos, 0.0))
    soft = preintegrated(cos, 1.0, k0)
    assert (soft[1:4] > 0.0).all()  # light wraps past the terminator
    assert soft[0] == 0.0  # but not round to the far pole: that light crossed the body (T_l's)
    assert soft[-1] < 0.9  # and the lit pole loses what it gives away (0.78 at rho 1)
    # light is moved around the ring, not made: the mean over the ring is the plain cosine's (1/pi)
    thetas = np.linspace(0.0, np.pi, 2001)
    spread = np.trapezoid(preintegrated(np.cos(thetas), 1.0, k0), thetas) / np.pi
    assert spread == pytest.approx(1.0 / np.pi, rel=0.01)


def test_the_table_is_read_only_and_its_lookup_is_near_the_integral():
    table = preintegrated_table()
    with pytest.raises(ValueError):
        table.values[0, 0] = 1.0
    for cos, rho in [(0.3, 0.05), (-0.2, 0.4), (0.9, 3.0), (0.0, 12.0)]:
        exact = float(preintegrated(np.array([cos]), rho, table.k0, 8192)[0])
        assert table.lookup(cos, rho) == pytest.approx(exact, abs=0.008)


def test_the_shader_reads_the_tables_size_from_its_texture():
    """The table is a texture (cnlm_sss_lut): the shader takes its size from it, no copy of the
    data's steps to keep in step."""
    text = SHADER.read_text()
    assert "textureSize(cnlm_sss_lut, 0)" in text and "#define" not in text
    constants = settings()
    assert preintegrated_table().values.shape == (constants.profile_cos_steps, constants.profile_rho_steps)
