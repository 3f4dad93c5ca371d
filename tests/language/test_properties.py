"""Property tests: random text never crashes; random lexicon phrases give finite, in-range IR."""

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for

LEX = lexicon_for()
NOUNS = sorted(LEX.all_of("nouns"))
ADJECTIVES = sorted(LEX.all_of("adjectives"))
ADVERBS = sorted(LEX.all_of("adverbs"))
COLOURS = sorted(LEX.all_of("colours"))
SHADES = sorted(LEX.all_of("shades"))
COATS = sorted(LEX.all_of("coats"))
REFINEMENTS = [
    "darker",
    "lighter",
    "rougher",
    "smoother",
    "less diffuse",
    "more diffuse",
    "more grain",
    "less grain",
    "higher contrast",
    "finer",
    "coarser",
    "glossier",
    "duller",
    "stronger brushing",
    "weaker brushing",
    "more gloss",
    "less anisotropy",
    "more rust",
    "lighter blue",
]

FAST = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@FAST
@given(st.text(max_size=200))
def test_random_text_never_crashes(text):
    result = compile_source(text, "fuzz.cnl", LEX)
    for d in result.diagnostics:
        assert d.code and d.message


words = st.sampled_from(
    NOUNS + ADJECTIVES + ADVERBS + COLOURS + SHADES + COATS + REFINEMENTS + [",", "and", "or", "with", "a", ":", "#"]
)


@FAST
@given(st.lists(words, max_size=12))
def test_random_word_salad_never_crashes(tokens):
    result = compile_source(" ".join(tokens), "salad.cnl", LEX)
    assert isinstance(result.diagnostics, list)


def _reads_as_written(g) -> bool:
    """Whether the word before a colour name stays itself: the tagger reads the longest name first,
    so 'bright' + 'red wine' is 'bright red' + 'wine' (a noun), and the adverb 'strong' + 'blue with
    a hint of purple' is the colour 'strong blue' + 'with ...': phrases no one would write."""
    adverbs, colour, _ = g
    if colour is None or " " not in colour[1]:
        return True
    before = colour[0][:1] or adverbs[-1:]
    return not before or f"{before[0]} {colour[1].split()[0]}" not in COLOURS


group = st.tuples(
    st.lists(st.sampled_from(ADVERBS), max_size=2),
    st.one_of(
        st.none(),
        st.tuples(st.lists(st.sampled_from(SHADES), max_size=1), st.sampled_from(COLOURS)),
    ),
    st.one_of(st.none(), st.sampled_from(ADJECTIVES)),
).filter(_reads_as_written)


def group_text(g):
    adverbs, colour, adjective = g
    parts = list(adverbs)
    if colour:
        parts += colour[0] + [colour[1]]
    if adjective:
        parts.append(adjective)
    return " ".join(parts)


def phrase_of(groups, noun, coat, refinements):
    text = ", ".join(t for t in map(group_text, groups) if t)
    text = f"{text} {noun}".strip()
    if coat:
        text += f" with a {coat}"
    return "\n".join([text, *refinements])


def finite_in(value, low, high):
    values = value if isinstance(value, list) else [value]
    return all(math.isfinite(v) and low <= v <= high for v in values)


@FAST
@given(
    st.lists(group, max_size=3),
    st.sampled_from(NOUNS),
    st.one_of(st.none(), st.sampled_from(COATS)),
    st.lists(st.sampled_from(REFINEMENTS), max_size=5),
)
def test_lexicon_combinations_give_finite_in_range_ir(groups, noun, coat, refinements):
    result = compile_source(phrase_of(groups, noun, coat, refinements), "combo.cnl", LEX)
    assert not [d for d in result.diagnostics if d.code in ("E001", "E002", "E003")], [
        d.message for d in result.diagnostics
    ]
    for m in result.materials:
        p = m["params"]
        assert finite_in(p["base_color"], 0.0, 1.0)
        assert finite_in(p.get("roughness", 0.5), 0.0, 1.0)
        assert finite_in(p.get("alpha", [0.5, 0.5]), 0.0, 1.0)
        assert finite_in(p.get("ior", 1.5), 1.0, 5.0)
        assert finite_in(p.get("eta", [1.0] * 3), 0.0, 50.0) and finite_in(p.get("k", [1.0] * 3), 0.0, 50.0)
        assert finite_in(p.get("anisotropy", 0.0), 0.0, 1.0)
        if p["coat"]:
            assert finite_in(p["coat"]["roughness"], 0.0, 1.0) and finite_in(p["coat"]["color"], 0.0, 1.0)
        for ref in m["maps"].values():
            assert all(math.isfinite(v) for v in ref["params"].values())
