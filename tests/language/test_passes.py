"""Each pass against its fixture file (fixtures/passes.toml): input -> expected pairs."""

import tomllib
from pathlib import Path

import pytest

from cnlmc.analyze import BUILD_PASSES, FINAL_PASSES, attach_refinements
from cnlmc.api import lexicon_for
from cnlmc.document import parse_document
from cnlmc.passes.refine import apply_refinement
from cnlmc.passes.variants import expand
from cnlmc.state import Context, MaterialState

FIXTURES = tomllib.loads((Path(__file__).parent / "fixtures" / "passes.toml").read_text())
ORDER = [
    "base",
    "words",
    "subsurface",
    "coats",
    "refine",
    "metal_tone",
    "films",
    "model",
    "subsurface_model",
    "ranges",
]  # metal_tone: passes/metal_tone.py; films: conformal_coat


def run_until(pass_name: str, phrase: str, lexicon) -> MaterialState:
    doc = parse_document(phrase, lexicon, "fixture.cnl")
    assert not doc.diagnostics, [d.message for d in doc.diagnostics]
    ctx = Context(lexicon)
    material, refinements = attach_refinements(doc, lexicon)[0]
    selection, variant = expand(material, "m", [])[0]
    state = MaterialState("m", phrase, selection, variant)
    stop = ORDER.index(pass_name)
    for step in BUILD_PASSES[: stop + 1]:
        state = step(state, ctx)
    if stop >= ORDER.index("refine"):
        for refinement in refinements:
            for item in refinement.items:
                apply_refinement(state, ctx, item)
    for step in FINAL_PASSES[: max(0, stop - ORDER.index("refine"))]:
        state = step(state, ctx)
    return state


def lookup(state: MaterialState, path: str):
    head, *rest = path.split(".")
    if head == "codes":
        return sorted(d.code for d in state.diagnostics)
    if head == "kind":
        return state.kind
    value = {"params": state.params, "model": state.model, "coat": state.coat, "maps": state.maps}[head]
    for part in rest:
        value = value[part]
    return "" if value is None else value


CASES = [(name, case) for name in ORDER for case in FIXTURES.get(name, [])]


@pytest.mark.parametrize("pass_name,case", CASES, ids=[f"{n}:{c['phrase'].splitlines()[-1]}" for n, c in CASES])
def test_pass_fixture(pass_name, case):
    lexicon = lexicon_for((case["lexicon"],) if "lexicon" in case else ())
    state = run_until(pass_name, case["phrase"], lexicon)
    for path, expected in case["expect"].items():
        got = lookup(state, path)
        if isinstance(expected, float) or (isinstance(expected, list) and expected and isinstance(expected[0], float)):
            assert got == pytest.approx(expected, abs=1e-9), path
        else:
            assert got == expected, path
