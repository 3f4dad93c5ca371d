"""One roughness -> alpha function and one mirror threshold (cnlmc.conventions) for the IR, the reference and GLSL."""

import re
from pathlib import Path

import numpy as np
import pytest

from cnlmc import conventions
from cnlmc.bsdf import ALPHA_MIRROR, alpha_from_roughness
from cnlmc.conventions import alpha_of

ROOT = Path(__file__).resolve().parents[2]


def test_one_mirror_threshold():
    assert ALPHA_MIRROR is conventions.ALPHA_MIRROR
    glsl = (ROOT / "backends/glsl/snippets/common.glsl").read_text()
    (literal,) = re.findall(r"const float CNLM_ALPHA_MIRROR = ([0-9.e+-]+);", glsl)
    assert float(literal) == conventions.ALPHA_MIRROR


@pytest.mark.parametrize("convention", ["squared", "linear"])
@pytest.mark.parametrize("aniso", [0.0, 0.5, 1.0])
def test_the_reference_clamps_the_ir_alpha(convention, aniso):
    for r in [0.0, 0.01, 0.2, 0.7, 1.0]:
        ir = alpha_of(r, aniso, convention)
        ref = alpha_from_roughness(r, aniso, convention)
        assert [float(a) for a in ref] == [min(max(a, ALPHA_MIRROR), 1.0) for a in ir]


def test_lanes_match_scalars():
    r = np.linspace(0.0, 1.0, 11)
    ax, ay = alpha_from_roughness(r, 0.8)
    for i, ri in enumerate(r):
        sx, sy = alpha_from_roughness(float(ri), 0.8)
        assert ax[i] == sx and ay[i] == sy


def test_ir_alpha_is_not_clamped_below():
    assert alpha_of(0.0) == [0.0, 0.0]
    with pytest.raises(ValueError, match="unknown alpha convention"):
        alpha_of(0.5, 0.0, "cubed")
