"""Modifier semantics (issue #14, docs/language.md "Degrees and order"): adverb weights compose,
formulas saturate inside each parameter's range, adjectives apply in a canonical order, roughness
words reach the Oren-Nayar sigma. Phrases here are deliberately not those of everyday.toml."""

import itertools

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for

from .conftest import first

LEXICON = lexicon_for()
PROPERTY = settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])


def compiled(text, lexicon=LEXICON):
    return compile_source(text, "modifiers.cnl", lexicon)


def params(text, lexicon=LEXICON):
    return first(compiled(text, lexicon))["params"]


def codes(text):
    return [d.code for d in compiled(text).diagnostics]


# ---- adverb weights compose in the direction of the inner adverb


def test_very_lightly_is_lighter_than_lightly_and_extremely_lightly_lighter_still():
    aniso = [
        params(f"{a}brushed copper")["anisotropy"] for a in ("extremely lightly ", "very lightly ", "lightly ", "")
    ]
    assert aniso == sorted(aniso) and len(set(aniso)) == 4
    rough = [params(f"{a}brushed copper")["roughness"] for a in ("very lightly ", "lightly ", "")]
    assert rough == sorted(rough) and len(set(rough)) == 3


def test_very_heavily_is_heavier_than_heavily_and_very_very_than_very():
    heavy = [params(f"{a}hammered bronze")["roughness"] for a in ("", "heavily ", "very heavily ")]
    assert heavy == sorted(heavy) and len(set(heavy)) == 3
    glossy = [params(f"{a}glossy ceramic")["roughness"] for a in ("", "very ", "very very ")]
    assert glossy == sorted(glossy, reverse=True) and len(set(glossy)) == 3


def test_the_degree_words_form_one_ordered_scale():
    scale = ["barely", "slightly", "somewhat", "almost", "", "quite", "very", "extra", "extremely"]
    rough = [params(f"{a} shiny titanium".strip())["roughness"] for a in scale]
    assert rough == sorted(rough, reverse=True) and len(set(rough)) == len(scale)
    assert rough[-1] > 0.0  # never a perfect mirror


@pytest.mark.parametrize("word", ["super", "ultra", "incredibly", "extra", "pretty", "really", "quite", "a bit"])
def test_intensifiers_are_adverbs_of_the_lexicon(word):
    assert [e.category for e in LEXICON.lookup(tuple(word.split()))] == ["adverbs"]
    assert codes(f"{word} matte ceramic") == []


def test_paper_numbers_stay_for_weights_up_to_one(paper):
    assert params("lightly brushed aluminium", paper)["roughness"] == pytest.approx(0.11)
    assert params("brushed aluminium", paper)["roughness"] == pytest.approx(0.12)
    assert params("very lightly brushed aluminium", paper)["roughness"] == pytest.approx(0.1 * (1 + 0.2 * 0.5**1.5))


# ---- saturation: intensified words stay inside the range, without a clamp warning


@pytest.mark.parametrize(
    "text",
    [
        "extremely extremely rough asphalt",
        "very very matte plaster",
        "incredibly shiny silver",
        "super polished nickel",
        "ultra glossy porcelain",
        "very heavily hammered copper",
        "extremely dark navy blue felt",
        "extremely heavily oiled teak",
        "really really rusty cast iron",
    ],
)
def test_intensified_phrases_do_not_clamp(text):
    result = compiled(text)
    assert result.ok and "W107" not in [d.code for d in result.diagnostics]
    p = result.materials[0]["params"]
    for name in ("roughness", "anisotropy"):
        if name in p:
            assert 0.0 < p[name] < 1.0 or p[name] == 0.0 and name == "anisotropy"


def test_intensifying_a_level_goes_beyond_it_on_every_material():
    # chrome (r 0.03) is already glossier than 'glossy' (0.08): 'extremely glossy' still makes it glossier
    assert params("extremely glossy chrome")["roughness"] < params("chrome")["roughness"]
    assert params("very matte glass")["roughness"] > params("matte glass")["roughness"]


def test_a_colour_stays_when_its_adjective_does_not_apply():
    result = compiled("pale honed cherry")  # honing is for stone: W102, but the wood is still pale
    assert [d.code for d in result.diagnostics] == ["W102"]
    assert sum(result.materials[0]["params"]["base_color"]) > sum(params("cherry")["base_color"])


def test_a_process_level_is_not_a_degree():
    # anodizing and galvanizing leave a surface (r 0.3, 0.35): "heavily" does not make it glossier
    assert params("heavily anodized titanium")["roughness"] == params("anodized titanium")["roughness"]
    assert params("very galvanized iron")["roughness"] == params("galvanized iron")["roughness"]


def test_a_shade_word_alone_that_is_an_adjective_is_the_adjective():
    dusty = first(compiled("dusty mirror"))
    assert dusty["params"]["roughness"] > params("mirror")["roughness"]
    assert dusty["provenance"]["roughness"][-1]["words"] == ["dusty"]
    assert params("dusty pink mirror")["roughness"] == params("mirror")["roughness"]  # a colour, no dust


def test_very_dark_is_darker_than_dark_and_never_black():
    def luminance(text):
        r, g, b = params(text)["base_color"]
        return 0.2126 * r + 0.7152 * g + 0.0722 * b

    steps = [luminance(f"{a}teal plastic") for a in ("extremely dark ", "very dark ", "dark ", "")]
    assert steps == sorted(steps) and len(set(steps)) == 4 and steps[0] > 0.0


def test_an_adverb_before_a_colour_modifies_the_colour_not_the_adjective():
    very, plain = params("very dark brushed zinc"), params("dark brushed zinc")
    assert very["anisotropy"] == plain["anisotropy"] and very["roughness"] == plain["roughness"]
    assert sum(very["base_color"]) < sum(plain["base_color"])
    assert sum(params("very dark green anodized titanium")["base_color"]) < sum(
        params("dark green anodized titanium")["base_color"]
    )


# ---- roughness words reach the Oren-Nayar sigma of a diffuse surface


def test_rough_and_smooth_change_a_diffuse_surface():
    sigma = {t: params(f"{t}stucco")["diffuse_roughness"] for t in ("", "rough ", "very rough ", "smooth ")}
    assert sigma["smooth "] < sigma[""] < sigma["rough "] < sigma["very rough "] < 1.6
    assert first(compiled("rough stucco"))["model"]["diffuse"] == "oren_nayar"


def test_sigma_provenance_names_the_word():
    steps = first(compiled("rough mortar"))["provenance"]["diffuse_roughness"]
    assert steps[-1]["words"] == ["rough"] and "Oren-Nayar" in steps[-1]["rule"]


def test_a_level_word_on_a_diffuse_surface_moves_sigma_by_the_roughness_ratio():
    assert params("glossy mortar")["diffuse_roughness"] < params("mortar")["diffuse_roughness"]


# ---- a gloss word is at least that gloss, and describes the coat one sees


def test_a_degree_level_never_goes_the_wrong_way():
    assert params("glossy rhodium")["roughness"] <= params("rhodium")["roughness"]  # already glossier
    assert params("matte felt")["diffuse_roughness"] == params("felt")["diffuse_roughness"]  # already matte
    assert first(compiled("matte felt"))["model"]["base"] == "diffuse"


@pytest.mark.parametrize("gloss,coat", [("matte", "varnished"), ("satin", "lacquered"), ("dull", "waxed")])
def test_a_gloss_word_with_a_coat_describes_the_coat(gloss, coat):
    for text in (f"{gloss} {coat} ash", f"{coat} {gloss} ash"):
        m = first(compiled(text))
        assert m["params"]["coat"]["roughness"] > params(f"{coat} ash")["coat"]["roughness"], text


def test_a_gloss_word_on_a_noun_with_its_own_coat():
    assert params("matte car paint")["coat"]["roughness"] > params("car paint")["coat"]["roughness"]


# ---- dark finishes


@pytest.mark.parametrize("text", ["fumed oak", "gun-blued iron", "oil rubbed brass", "blackened iron"])
def test_dark_finishes_are_dark(text):
    m = first(compiled(text))
    p = m["params"]
    colour = [c * f for c, f in zip(p["base_color"], p.get("f0") or [1.0, 1.0, 1.0])]
    luminance = 0.2126 * colour[0] + 0.7152 * colour[1] + 0.0722 * colour[2]
    assert luminance < 0.09, (text, colour)  # OKLab L below 0.45


def test_smoked_glass_is_grey_not_brown():
    r, g, b = params("smoked glass")["base_color"]
    assert abs(r - b) < 0.02


# ---- canonical order


@pytest.mark.parametrize(
    "words,noun",
    [
        (("sandblasted", "anodized", "scratched"), "titanium"),
        (("honed", "wet", "dark"), "slate"),
        (("sanded", "stained", "worn"), "maple"),
        (("hammered", "satin", "tarnished"), "pewter"),
        (("orange", "worn", "textured"), "leather"),
    ],
)
def test_word_order_does_not_change_the_numbers(words, noun):
    results = [first(compiled(" ".join((*order, noun)))) for order in itertools.permutations(words)]
    for m in results[1:]:
        assert (m["model"], m["params"], m["maps"]) == (results[0]["model"], results[0]["params"], results[0]["maps"])


def test_shaping_before_treatment_is_the_papers_order(paper):
    for text in ("lightly brushed, blue anodized aluminum", "blue anodized, lightly brushed aluminum"):
        assert params(text, paper)["roughness"] == 0.3


def test_a_contradiction_says_which_word_won_whatever_the_order():
    for text in ("polished sandblasted zinc", "sandblasted polished zinc"):
        result = compiled(text)
        (w101,) = [d for d in result.diagnostics if d.code == "W101"]
        assert w101.message == "'polished' contradicts 'sandblasted': 'polished' wins"
        assert "shaping" in w101.hints[0] and "finish" in w101.hints[0]
    same_stage = compiled("dull shiny pewter").diagnostics
    assert [d.message for d in same_stage if d.code == "W101"] == ["'shiny' contradicts 'dull': 'shiny' wins"]


@pytest.mark.parametrize("first_word,last_word", [("matte", "shiny"), ("shiny", "matte"), ("dull", "glossy")])
def test_within_a_stage_the_later_of_two_contradicting_words_wins(first_word, last_word):
    result = compiled(f"{first_word} {last_word} vinyl")
    (w101,) = [d for d in result.diagnostics if d.code == "W101"]
    assert w101.message == f"'{last_word}' contradicts '{first_word}': '{last_word}' wins"
    assert result.materials[0]["provenance"]["roughness"][-1]["words"] == [last_word]  # applied last


@pytest.mark.parametrize(
    "pair", [("rough", "shiny"), ("sandblasted", "glossy"), ("mirror", "dull"), ("matte", "polished")]
)
def test_finish_words_that_contradict_warn_in_either_order(pair):
    for words in (pair, pair[::-1]):
        assert codes(f"{words[0]} {words[1]} titanium") == ["W101"], words


@pytest.mark.parametrize(
    "text,outer,inner", [("light dark beech", "light", "dark"), ("pale deep cherry", "pale", "deep")]
)
def test_shades_that_pull_opposite_ways_warn_and_the_outer_one_wins(text, outer, inner):
    (w101,) = [d for d in compiled(text).diagnostics if d.code == "W101"]
    assert w101.message == f"'{outer}' contradicts '{inner}': '{outer}' wins"
    assert codes("light pale beech") == []  # both lighter: no contradiction


@pytest.mark.parametrize(
    "text,outer,inner",
    [
        ("pale dark grey paint", "pale", "dark"),
        ("dark pale green wool", "dark", "pale"),
        ("light deep red silk", "light", "deep"),
    ],
)
def test_a_shade_against_the_shade_that_opens_a_colour_name_warns(text, outer, inner):
    """'dark grey' is one of the survey's names, and 'pale' before it still contradicts its 'dark'."""
    (w101,) = [d for d in compiled(text).diagnostics if d.code == "W101"]
    assert w101.message == f"'{outer}' contradicts '{inner}': '{outer}' wins"


@pytest.mark.parametrize("text", ["pale dark slate grey paint", "light light grey paint", "pale light blue paint"])
def test_a_longer_name_or_shades_that_agree_do_not_warn(text):
    assert codes(text) == []  # 'dark slate grey' is a name; 'light' on 'light grey' agrees


@pytest.mark.parametrize("word,like", [("finely", "lightly"), ("coarsely", "heavily"), ("freshly", "fully")])
def test_manner_adverbs_read_as_degrees(word, like):
    assert params(f"{word} brushed nickel") == params(f"{like} brushed nickel")


@pytest.mark.parametrize("word", ["kinda", "sorta", "so", "dead", "well"])
def test_colloquial_degree_words(word):
    assert [e.category for e in LEXICON.lookup((word,))] == ["adverbs"]
    assert compiled(f"{word} matte ceramic").ok


# the everyday register sits on the same scale: each word as strong as its class's anchor
REGISTER = {
    "barely": ["marginally", "fractionally", "a hair", "vaguely"],
    "slightly": ["a tad", "a touch", "a smidge", "a wee bit", "mildly", "faintly"],
    "somewhat": ["fairly", "rather", "moderately", "pretty"],
    "quite": ["notably", "distinctly", "unusually"],
    "very": ["awfully", "terribly", "hella", "mighty"],
    "extra": ["exceedingly", "hugely", "tremendously", "seriously"],
    "extremely": ["mega", "crazy", "ridiculously", "insanely", "hyper", "uber", "super duper"],
}


@pytest.mark.parametrize("anchor,word", [(a, w) for a, words in REGISTER.items() for w in words])
def test_everyday_degree_words_sit_with_their_class(anchor, word):
    assert params(f"{word} rough sandstone") == params(f"{anchor} rough sandstone")
    assert codes(f"{word} glossy enamel paint") == []


def test_the_everyday_register_keeps_the_scale_order():
    rough = [params(f"{words[0]} shiny pewter")["roughness"] for words in REGISTER.values()]
    assert rough == sorted(rough, reverse=True) and len(set(rough)) == len(rough)


def test_every_stdlib_adjective_declares_its_stage():
    from cnlmc.passes.order import STAGES

    stages = {key: entry.get("stage") for key, entry in LEXICON.all_of("adjectives").items()}
    assert [key for key, stage in stages.items() if stage not in STAGES] == []


# ---- properties over random adjective and adverb sets

NOUNS = sorted(k for k in LEXICON.all_of("nouns") if " " not in k)
ADJECTIVES = sorted(
    k for k, e in LEXICON.all_of("adjectives").items() if " " not in k and not e.get("colour_target") == "material"
)
ADVERBS = [
    "barely",
    "slightly",
    "lightly",
    "somewhat",
    "quite",
    "very",
    "really",
    "extra",
    "heavily",
    "extremely",
    "super",
]


def _opposed(adjectives):
    entries = [LEXICON.entry("adjectives", a) for a in adjectives]
    keys = {e.key for e in entries}
    return len(keys) < len(entries) or any(keys & set(e.get("opposes", [])) for e in entries)


COLOURS = ["", "red", "dark", "pale blue", "very dark grey", "extremely light", "deep green", "slightly reddish"]


@PROPERTY
@given(
    noun=st.sampled_from(NOUNS),
    groups=st.lists(
        st.tuples(st.lists(st.sampled_from(ADVERBS), max_size=2), st.sampled_from(ADJECTIVES)), min_size=1, max_size=3
    ),
    colour=st.sampled_from(COLOURS),
)
def test_no_clamp_warning_for_any_adverbs_and_adjectives(noun, groups, colour):
    text = " ".join(" ".join((*adverbs, adjective)) for adverbs, adjective in groups) + f" {colour} {noun}"
    result = compiled(text)
    assume(result.ok)
    assert "W107" not in [d.code for d in result.diagnostics], text


@PROPERTY
@given(
    noun=st.sampled_from(NOUNS),
    adjectives=st.lists(st.sampled_from(ADJECTIVES), min_size=2, max_size=3, unique=True),
    data=st.data(),
)
def test_word_order_independence(noun, adjectives, data):
    assume(not _opposed(adjectives))
    shuffled = data.draw(st.permutations(adjectives))
    one, other = compiled(" ".join((*adjectives, noun))), compiled(" ".join((*shuffled, noun)))
    assume(one.ok and other.ok)
    a, b = one.materials[0], other.materials[0]
    assert (a["model"], a["params"], a["maps"]) == (b["model"], b["params"], b["maps"]), (adjectives, shuffled, noun)
