"""The paper's worked examples (§3.3, §4.2), number for number, under --lexicon paper."""

import pytest

from cnlmc.api import Session, compile_source

from .conftest import first


def params(text, lexicon):
    return first(compile_source(text, "paper.cnl", lexicon))["params"]


def test_aluminium_base_values(paper):
    p = params("Aluminium", paper)
    assert p["base_color"] == [0.75, 0.75, 0.75]
    assert p["roughness"] == 0.1
    assert p["eta"] == [1.097] * 3 and p["k"] == [6.794] * 3
    assert p["alpha_convention"] == "linear" and p["alpha"] == [0.1, 0.1]


def test_aluminium_is_isotropic_microfacet(paper):
    m = first(compile_source("aluminium", "paper.cnl", paper))
    assert m["model"] == {
        "base": "conductor",
        "distribution": "ggx",
        "anisotropic": False,
        "coat": False,
        "diffuse": None,
    }


def test_anodized_sets_m_to_0_3(paper):
    assert params("anodized aluminum", paper)["roughness"] == 0.3


def test_blue_is_rgb_0_0_1(paper):
    assert params("blue anodized aluminum", paper)["base_color"] == [0.0, 0.0, 1.0]


def test_darker_blue_halves_blue(paper):
    assert params("blue anodized aluminum\ndarker blue", paper)["base_color"] == [0.0, 0.0, 0.5]


def test_less_then_more_diffuse_bisects(paper):
    assert params("blue anodized aluminum\nless diffuse", paper)["roughness"] == 0.2
    assert params("blue anodized aluminum\nless diffuse\nmore diffuse", paper)["roughness"] == 0.25


def test_brushed_multiplies_m_by_1_2_but_wood_by_1_25(paper):
    assert params("brushed aluminum", paper)["roughness"] == pytest.approx(0.1 * 1.2)
    wood = params("wood", paper)["roughness"]
    assert params("brushed wood", paper)["roughness"] == pytest.approx(wood * 1.25)


def test_lightly_brushed_is_1_1(paper):
    assert params("lightly brushed aluminum", paper)["roughness"] == pytest.approx(0.11)


def test_brushed_selects_the_anisotropic_ward_model(paper):
    m = first(compile_source("brushed aluminum", "paper.cnl", paper))
    assert m["model"]["anisotropic"] is True
    assert m["model"]["distribution"] == "ward"
    assert "normal" in m["maps"] and m["maps"]["normal"]["graph"] == "brushed"


def test_lightly_weakens_the_brush_strokes(paper):
    strong = first(compile_source("brushed aluminum", "p.cnl", paper))["maps"]["normal"]["params"]["strength"]
    light = first(compile_source("lightly brushed aluminum", "p.cnl", paper))["maps"]["normal"]["params"]["strength"]
    assert light == pytest.approx(strong / 2)


def test_the_full_phrase(paper):
    m = first(compile_source("lightly brushed, blue anodized aluminum", "p.cnl", paper))
    assert m["params"]["roughness"] == 0.3  # brushed first (0.11), then anodized sets 0.3
    assert m["params"]["base_color"] == [0.0, 0.0, 1.0]
    assert m["model"]["anisotropic"]


def test_session_refines_like_the_paper(paper):
    s = Session("blue anodized aluminum", lexicon=paper)
    assert s.refine("darker blue")["params"]["base_color"] == [0.0, 0.0, 0.5]
    assert s.refine("less diffuse")["params"]["roughness"] == 0.2
    assert s.refine("more diffuse")["params"]["roughness"] == 0.25


def test_session_rejects_a_bad_refinement_and_keeps_the_material(paper):
    s = Session("blue anodized aluminum", lexicon=paper)
    with pytest.raises(ValueError, match="unknown word 'drkr'"):
        s.refine("drkr")
    assert s.material["params"]["base_color"] == [0.0, 0.0, 1.0]


def test_paper_f0_follows_from_its_eta_and_k(paper):
    import numpy as np

    from cnlmc.bsdf import fresnel_conductor

    p = params("aluminium", paper)
    exact = fresnel_conductor(np.array([1.0, 1 / 7]), np.array(1.097), np.array(6.794))
    assert p["f0"] == pytest.approx([exact[0]] * 3, abs=1e-4)
    assert p["f82"] == pytest.approx([exact[1]] * 3, abs=1e-4)
