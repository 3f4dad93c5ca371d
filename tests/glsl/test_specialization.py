"""Specialization (only the code a model needs), maps -> samplers, hostile phrase text,
options and the sidecar."""

from __future__ import annotations

import copy
import json

import pytest

from cnlmc.backends import glsl
from cnlmc.backends.glsl.options import OptionError
from cnlmc.backends.glsl.render import comment_text

from .conftest import emit_material, emit_phrase, material_of, run_glslang

ANISOTROPY_MARKERS = ("anisotrop", "cnlm_rotate_tangent", "vec2 alpha", "cnlm_ward_dv")
CONDUCTOR_MARKERS = ("cnlm_fresnel_conductor", "cnlm_eta", "cnlm_k", "cnlm_fresnel_f82")
TEXTURE_MARKERS = ("sampler", "texture(")


def code_only(text: str) -> str:
    """The text without // comments (the header lists the model in words)."""
    return "\n".join(line.split("//", 1)[0] for line in text.splitlines())


def test_isotropic_plastic_has_no_anisotropy_conductor_fresnel_or_textures():
    for fresnel in ("exact", "f82", "schlick"):
        code = code_only(emit_phrase("glossy red plastic", fresnel=fresnel)["frag"])
        for marker in ANISOTROPY_MARKERS + CONDUCTOR_MARKERS + TEXTURE_MARKERS + ("cnlm_multiscatter",):
            assert marker not in code, f"{marker!r} in the specialized plastic ({fresnel})"


def test_specialized_code_follows_the_model():
    brushed = code_only(emit_phrase("lightly brushed, blue anodized aluminum")["glsl"])
    assert "cnlm_ward_dv" in brushed and "cnlm_fresnel_conductor" in brushed
    assert "cnlm_rotate_tangent" in brushed and "cnlm_lambert" not in brushed
    gold = code_only(emit_phrase("gold", fresnel="schlick")["glsl"])
    assert "cnlm_fresnel_schlick" in gold and "cnlm_fresnel_conductor" not in gold
    paper = code_only(emit_phrase("velvet")["glsl"])
    assert "cnlm_oren_nayar" in paper and "cnlm_ggx_dv" not in paper and "fresnel" not in paper
    coated = code_only(emit_phrase("clear-coated red car paint")["glsl"])
    assert "cnlm_refract_into_coat" in coated and "cnlm_coat_absorption" not in coated
    assert "cnlm_coat_absorption" in code_only(emit_phrase("red varnished oak")["glsl"])


def test_multiscatter_only_for_conductors():
    assert "cnlm_multiscatter" in emit_phrase("gold", multiscatter="on")["glsl"]
    assert "cnlm_multiscatter" not in code_only(emit_phrase("glossy red plastic", multiscatter="on")["glsl"])


@pytest.mark.parametrize(
    "phrase, roles",
    [
        ("rusty iron", ["base_color", "roughness", "mask"]),
        ("hammered copper", ["normal"]),
        ("oak", ["base_color", "roughness"]),
    ],
)
def test_maps_become_samplers_by_role(phrase, roles):
    files = emit_phrase(phrase)
    meta = json.loads(files["glsl.json"])
    assert [s["role"] for s in meta["samplers"]] == roles
    spaces = {s["role"]: s["colour_space"] for s in meta["samplers"]}
    assert spaces.get("base_color", "srgb") == "srgb" and all(
        v == "linear" for k, v in spaces.items() if k != "base_color"
    )
    code = code_only(files["glsl"])
    for sampler in meta["samplers"]:
        assert f"uniform sampler2D {sampler['name']};" in code
        assert f"texture({sampler['name']}" in code
    uniform_names = {u["name"] for u in meta["uniforms"]}
    assert ("cnlm_base_color" in uniform_names) == ("base_color" not in roles)
    assert ("cnlm_alpha" in uniform_names) == ("roughness" not in roles)


def test_no_samplers_without_maps():
    files = emit_phrase("polished gold")
    assert json.loads(files["glsl.json"])["samplers"] == []
    assert "sampler" not in code_only(files["frag"])


HOSTILE = [
    "red plastic */ void main() { discard; } /*",
    "gold\n#version 450\nvoid main(){}",
    "steel \\\nuniform float pwned;",
    "caf\u00e9 \u2028 plastic\r\x00\x1b[31m",
    "/* open",
    "*/",
]


@pytest.mark.parametrize("phrase", HOSTILE)
def test_phrase_cannot_break_out_of_comments(glslang, phrase):
    material = copy.deepcopy(material_of("glossy red plastic"))
    material["phrase"] = phrase
    files = emit_material(material)
    clean = emit_material(material_of("glossy red plastic"))
    assert code_only(files["frag"]) == code_only(clean["frag"])  # only comments differ
    phrase_lines = [line for line in files["frag"].splitlines() if line.startswith("// phrase:")]
    assert len(phrase_lines) == 1
    assert "*/" not in phrase_lines[0] and "/*" not in phrase_lines[0] and "\\" not in phrase_lines[0]
    assert json.loads(files["glsl.json"])["phrase"] == phrase  # the sidecar keeps it verbatim
    [(_, code, out)] = run_glslang([("hostile.frag", files["frag"])])
    assert code == 0, out


def test_comment_text_is_one_printable_line():
    text = comment_text("a\nb\r\nc\t*/d/*e\\f\u00e9\x00")
    assert text == "a b c * /d/ *e<backslash>f<U+00E9><U+0000>"


def test_options_are_validated_and_recorded():
    with pytest.raises(OptionError, match="fresnel"):
        emit_phrase("gold", fresnel="fast")
    with pytest.raises(OptionError, match="unknown option"):
        emit_phrase("gold", colour="blue")
    meta = json.loads(emit_phrase("gold", fresnel="f82", profile="es300")["glsl.json"])
    assert meta["options"] == {
        "fresnel": "f82",
        "multiscatter": "off",
        "profile": "es300",
        "form": "both",
        "specialize": "on",
    }


def test_forms_select_files():
    assert sorted(emit_phrase("gold", form="library")) == ["glsl", "glsl.json"]
    assert sorted(emit_phrase("gold", form="standalone")) == ["frag", "glsl.json", "vert"]
    assert sorted(emit_phrase("gold")) == ["frag", "glsl", "glsl.json", "vert"]


def test_es_profile_has_precision_and_no_initialisers():
    files = emit_phrase("gold", profile="es300")
    assert files["frag"].startswith("#version 300 es\n")
    assert "precision highp float;" in files["frag"] and "precision highp float;" in files["vert"]
    assert " = vec3(" not in "".join(l for l in code_only(files["frag"]).splitlines() if "uniform" in l)


def test_sidecar_lists_uniform_values():
    meta = json.loads(emit_phrase("lightly brushed, blue anodized aluminum")["glsl.json"])
    values = {u["name"]: (u["type"], u["value"]) for u in meta["uniforms"]}
    assert values["cnlm_alpha"] == ("vec2", [0.1125, 0.072])
    assert values["cnlm_base_color"] == ("vec3", [0.000911, 0.056128, 0.73791])  # the survey's blue
    assert values["cnlm_eta"][0] == "vec3"
    assert meta["model"]["distribution"] == "ward"


def test_capability_notes_for_non_exact_features():
    result = glsl.emit({"materials": [material_of("rusty iron"), material_of("frosted glass")]}, {})
    features = {(n.material, n.feature, n.policy) for n in result.notes}
    assert ("rusty_iron", "maps.mask", "approximate") in features
    assert ("rusty_iron", "maps.base_color", "bake") in features
    assert not any(f == "model.glass" for _, f, p in features)  # glass is exact (cnlm_btdf)
    assert set(glsl.CAPABILITIES) >= set(
        __import__("cnlmc.backends.capabilities", fromlist=["ALL_FEATURES"]).ALL_FEATURES
    )
