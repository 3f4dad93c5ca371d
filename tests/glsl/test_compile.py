"""Every stdlib noun and the adjective combinations compile with glslangValidator for both
profiles (library, standalone fragment and vertex shaders) and link in moderngl on EGL."""

from __future__ import annotations

import re

import pytest

from cnlmc.api import lexicon_for
from tests.helpers import PHRASE_BY_MODEL

from .conftest import emit_phrase, run_glslang

PROFILES = ("330", "es300")
PROFILE_VERSION = {"330": "#version 330 core\n", "es300": "#version 300 es\n"}
LIBRARY_PROBE = """
out vec4 cnlm_probe_out;
void main() { cnlm_probe_out = vec4(cnlm_bsdf(vec3(0, 0, 1), vec3(0.3, 0.4, 0.866), vec3(-0.3, 0, 0.954), vec2(0)), 1); }
"""


def all_phrases() -> list[str]:
    return sorted(lexicon_for().all_of("nouns")) + sorted(PHRASE_BY_MODEL.values())


def sources_for(phrase: str, profile: str, **options) -> list[tuple[str, str]]:
    files = emit_phrase(phrase, profile=profile, **options)
    stem = re.sub(r"\W", "_", f"{phrase}_{profile}_{'_'.join(options.values())}")
    return [
        (f"{stem}.frag", files["frag"]),
        (f"{stem}.vert", files["vert"]),
        (f"{stem}_library.frag", PROFILE_VERSION[profile] + files["glsl"] + LIBRARY_PROBE),
    ]


@pytest.mark.slow  # 20-40 s per profile: every noun and combination through glslangValidator
@pytest.mark.parametrize("profile", PROFILES)
def test_glslang_accepts_every_noun_and_combination(glslang, profile):
    sources = [s for phrase in all_phrases() for s in sources_for(phrase, profile)]
    sources += [
        s
        for phrase in PHRASE_BY_MODEL.values()
        for fresnel in ("f82", "schlick")
        for s in sources_for(phrase, profile, fresnel=fresnel, multiscatter="on")
    ]
    failures = [f"{name}:\n{out}" for name, code, out in run_glslang(sources) if code != 0]
    assert not failures, "\n".join(failures[:5])


def _structure_key(text: str) -> str:
    """The source without comments and uniform initialisers: materials that differ only in
    values share one program, so the link test compiles each structure once."""
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r"(uniform \w+ \w+) = [^;]*;", r"\1;", text)


@pytest.mark.parametrize("profile", PROFILES)
def test_standalone_links_in_moderngl(gl, profile):
    linked = {}
    for phrase in all_phrases():
        files = emit_phrase(phrase, profile=profile)
        key = _structure_key(files["frag"]) + _structure_key(files["vert"])
        if key not in linked:
            program = gl.program(vertex_shader=files["vert"], fragment_shader=files["frag"])
            linked[key] = program
            assert "cnlm_view_projection" in program
    assert len(linked) >= 8  # the stdlib spans many model structures
    for program in linked.values():
        program.release()
