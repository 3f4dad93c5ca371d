"""Package C of #14: the syntax of inline comparatives, adverbs on refinement words, clauses.

Phrases here are deliberately not the ones of tests/language/everyday.toml.
"""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc import ast
from cnlmc.document import parse_document
from cnlmc.passes.feature_colour import lch


def parse(text, lexicon):
    doc = parse_document(text, lexicon, "test.cnl")
    assert not [d for d in doc.diagnostics if d.is_error], [d.message for d in doc.diagnostics]
    (item,) = doc.items
    return item


def target_text(item):
    target = item.target
    if target is None:
        return None
    return " ".join(w.text for w in target.words) if isinstance(target, ast.Colour) else target.text


@pytest.mark.parametrize(
    "text,adverbs,word",
    [
        ("slightly duller", ["slightly"], "duller"),
        ("a little glossier", ["a little"], "glossier"),
        ("very slightly rougher", ["very", "slightly"], "rougher"),
    ],
)
def test_adverbs_before_a_refinement_word(stdlib, text, adverbs, word):
    item = parse(text, stdlib)
    assert isinstance(item, ast.Refinement)
    (refine,) = item.items
    assert refine.word.text == word
    assert [a.text for a in refine.adverbs] == adverbs


def test_adverbs_on_each_item_of_a_refinement_list(stdlib):
    item = parse("slightly darker, heavily rougher", stdlib)
    assert isinstance(item, ast.Refinement)
    assert [(r.word.text, [a.text for a in r.adverbs]) for r in item.items] == [
        ("darker", ["slightly"]),
        ("rougher", ["heavily"]),
    ]


@pytest.mark.parametrize(
    "text,word,target,adverbs,nouns,group_words",
    [
        ("smoother granite", "smoother", None, [], ["granite"], []),
        ("slightly duller copper", "duller", None, ["slightly"], ["copper"], []),
        ("less rough concrete", "less", "rough", [], ["concrete"], []),
        ("more polished brass", "more", "polished", [], ["brass"], []),
        ("darker green velvet", "darker", "green", [], ["velvet"], []),
        ("less shiny lightly brushed steel", "less", "shiny", [], ["steel"], ["lightly", "brushed"]),
        ("more grain oak", "more", "grain", [], ["oak"], []),
    ],
)
def test_inline_comparative_before_a_material(stdlib, text, word, target, adverbs, nouns, group_words):
    item = parse(text, stdlib)
    assert isinstance(item, ast.Material)
    (refine,) = item.refinements
    assert refine.word.text == word
    assert target_text(refine) == target
    assert [a.text for a in refine.adverbs] == adverbs
    assert [n.text for n in item.nouns] == nouns
    words = [
        w.text for g in item.groups for w in g.adverbs + tuple(x for c in g.colours for x in c.words) + g.adjectives
    ]
    assert words == group_words


def test_a_material_without_comparative_has_no_refinements(stdlib):
    item = parse("lightly brushed, blue anodized aluminum with a clear coat", stdlib)
    assert isinstance(item, ast.Material)
    assert item.refinements == ()


def test_inline_comparative_keeps_the_coat(stdlib):
    item = parse("darker oak with a glossy varnish", stdlib)
    assert [r.word.text for r in item.refinements] == ["darker"]
    assert item.coat is not None and item.coat.coat.text == "varnish"


def test_inline_comparative_compiles(compile_text):
    result = compile_text("smoother granite\nrougher\n")
    assert result.ok, [d.message for d in result.diagnostics]


@pytest.mark.parametrize(
    "listed", ["lighter, smoother granite", "a lighter and smoother granite", "lighter smoother granite"]
)
def test_a_list_of_comparatives_before_a_material_applies_each_in_order(compile_text, listed):
    """'a warmer, lighter oak': each comparative moves the material in turn, as the same
    comparatives on lines of their own below it do."""
    said = compile_text(listed)
    assert not said.diagnostics
    below = compile_text("granite\nlighter\nsmoother").ir["materials"][0]
    inline = said.ir["materials"][0]
    assert inline["params"] == below["params"]
    assert inline["params"] != compile_text("granite").ir["materials"][0]["params"]


def test_refinement_after_the_noun_still_says_where_it_goes(compile_text):
    """'polished granite darker' reads as 'polished granite, darker' (cnlmc.noun_first); a line that
    cannot be read so keeps the taught error."""
    (d,) = compile_text("polished granite darker and").diagnostics
    assert d.message == "a refinement changes the material above it and stands on its own line"


def test_shape_cache_keeps_adverbs_apart(stdlib):
    """Two lines with the same tags share a parse shape; each builds from its own words."""
    first = parse("slightly darker", stdlib)
    second = parse("heavily rougher", stdlib)
    assert [a.text for a in first.items[0].adverbs] == ["slightly"]
    assert [a.text for a in second.items[0].adverbs] == ["heavily"]
    assert second.items[0].word.text == "rougher"


def test_a_line_that_ends_in_a_noun_reads_as_a_material(stdlib):
    """'copper' is a colour and a noun: before a noun reading, the refinement reading loses."""
    item = parse("a bit duller silver", stdlib)
    assert isinstance(item, ast.Material)
    assert [n.key for n in item.nouns] == ["silver"]
    assert [r.word.text for r in item.refinements] == ["duller"]


def test_a_refinement_of_a_colour_stays_a_refinement(stdlib):
    item = parse("darker navy", stdlib)
    assert isinstance(item, ast.Refinement)


def test_the_coat_clause_span_starts_at_with(stdlib):
    item = parse("walnut with a satin lacquer", stdlib)
    assert item.coat is not None
    assert item.text[item.coat.span.start : item.coat.span.end] == "with a satin lacquer"


# ---------------------------------------------------------------- feature clauses (compiled)


def compiled(compile_text, text):
    result = compile_text(text)
    assert result.ok, [d.message for d in result.diagnostics]
    (material,) = result.materials
    return material, result.diagnostics


def graphs(material):
    return {ref["graph"] for ref in (material.get("maps") or {}).values()}


def map_params(material, graph):
    """The params of the material's first map of `graph` (base colour first)."""
    refs = sorted(material["maps"].items(), key=lambda item: item[0] != "base_color")
    return next(ref["params"] for _role, ref in refs if ref["graph"] == graph)


def test_veins_on_a_stone_without_them_draw_the_marble_graph_in_the_named_colour(compile_text):
    material, _ = compiled(compile_text, "limestone with dark green veins")
    assert "marble" in graphs(material)
    params = map_params(material, "marble")
    assert params["color_amount"] == 1.0
    assert params["color_g"] > params["color_r"] and params["color_g"] > params["color_b"]


def test_a_material_keeps_its_own_map_and_a_degree_scales_it(compile_text):
    plain, _ = compiled(compile_text, "oak")
    strong, _ = compiled(compile_text, "oak with a pronounced grain")
    subtle, _ = compiled(compile_text, "oak with a faint grain")
    assert graphs(plain) == graphs(strong) == graphs(subtle)
    contrast = [map_params(m, "wood").get("contrast", 1.0) for m in (subtle, plain, strong)]
    assert contrast[0] < contrast[1] < contrast[2]


def test_degree_words_multiply(compile_text):
    few, _ = compiled(compile_text, "cast iron with a few rust spots")
    many, _ = compiled(compile_text, "cast iron with many rust spots")
    assert map_params(few, "rust")["coverage"] < map_params(many, "rust")["coverage"]


def test_scratches_and_cracks_draw_what_their_adjectives_draw(compile_text):
    material, _ = compiled(compile_text, "chrome with thin scratches")
    assert "scratched" in graphs(material)
    material, _ = compiled(compile_text, "plaster with hairline cracks")
    assert "cracked" in graphs(material)


def test_a_patina_in_a_named_colour(compile_text):
    verdigris, _ = compiled(compile_text, "bronze with a patina")
    brown, _ = compiled(compile_text, "bronze with a brown patina")
    assert "patina" in graphs(verdigris) and "patina" in graphs(brown)
    assert map_params(verdigris, "patina").get("color_amount", 0.0) == 0.0
    assert map_params(brown, "patina")["color_r"] > map_params(brown, "patina")["color_b"]


def test_a_finish_is_the_surface(compile_text):
    finish, _ = compiled(compile_text, "brass with a polished finish")
    polished, _ = compiled(compile_text, "polished brass")
    assert finish["params"]["roughness"] == polished["params"]["roughness"]
    assert not finish["model"]["coat"]


def test_a_tint_colours_the_glass(compile_text):
    material, _ = compiled(compile_text, "glass with a yellow tint")
    r, g, b = material["params"]["base_color"]
    assert r > b


def test_speckles_on_a_plain_material(compile_text):
    material, _ = compiled(compile_text, "grey rubber with white flecks")
    assert "granite" in graphs(material)
    assert map_params(material, "granite")["color_r"] == 1.0


def test_a_coat_and_a_feature_together(compile_text):
    material, diags = compiled(compile_text, "steel with a satin lacquer and some fine scratches")
    assert material["model"]["coat"]
    assert "scratched" in graphs(material)
    assert not [d for d in diags if d.severity.value == "warning"]


def test_a_feature_nothing_draws_says_what_is_missing(compile_text):
    material, diags = compiled(compile_text, "oak with knots")  # flakes, the earlier example, are drawn (#15)
    (w,) = [d for d in diags if d.code == "W120"]
    assert "knots" in w.message and "drawn as wood grain" in w.message
    assert "features drawn today" in w.hints[0]


def test_a_second_coat_is_reported(compile_text):
    _material, diags = compiled(compile_text, "oak with a varnish and a wax")
    (w,) = [d for d in diags if d.code == "W121"]
    assert "'wax'" in w.message and "'varnish' is kept" in w.message


def test_a_word_the_feature_cannot_use_is_a_note_not_a_warning(compile_text):
    _material, diags = compiled(compile_text, "nickel with glossy scratches")
    assert [d.code for d in diags] == ["N121"]
    assert diags[0].severity.value == "note"


def test_a_clause_without_its_feature_word_still_says_so(compile_text):
    (d,) = compile_text("slate with a subtle").diagnostics
    assert d.code == "E002"


def test_a_clause_on_a_refinement_line_parses(stdlib):
    item = parse("with fine scratches", stdlib)
    assert isinstance(item, ast.Refinement)
    assert item.items == () and [f.word.key for f in item.features] == ["scratches"]


# ---------------------------------------------------------------- German: 'mit' clauses


@pytest.fixture(scope="module")
def german():
    from cnlmc.api import lexicon_for

    return lexicon_for(("de",))


@pytest.mark.parametrize(
    "text,graph",
    [
        ("Granit mit weißen Sprenkeln", "granite"),
        ("Bronze mit einer Patina", "patina"),
        ("Eiche mit einer deutlichen Maserung", "wood"),
        ("Chrom mit zahlreichen Kratzern", "scratched"),
        ("Putz mit vereinzelten Haarrissen", "cracked"),
    ],
)
def test_german_feature_clauses(compile_text, german, text, graph):
    result = compile_text(text, german)
    assert result.ok, [d.message for d in result.diagnostics]
    assert graph in graphs(result.materials[0])


def test_german_degree_words_weigh_like_the_english_ones(compile_text, german):
    few = compile_text("Stahl mit wenigen Rostflecken", german).materials[0]
    english = compile_text("steel with a few rust spots").materials[0]
    assert map_params(few, "rust") == map_params(english, "rust")


# ---------------------------------------------------------------- nouns as describing words


def notes(diags, code):
    return [d.message for d in diags if d.code == code]


def test_a_metal_noun_before_plated_is_the_plating(compile_text):
    plated, diags = compiled(compile_text, "silver plated copper")
    silver, _ = compiled(compile_text, "silver")
    assert plated["params"]["f0"] == silver["params"]["f0"]
    plated, diags = compiled(compile_text, "titanium plated steel")
    titanium, _ = compiled(compile_text, "titanium")
    assert plated["params"]["f0"] == titanium["params"]["f0"]
    assert notes(diags, "N122") == ["read 'titanium plated' as plated with titanium"]


def test_a_colour_named_after_a_noun_is_the_colour_as_seen_on_it_with_a_note(compile_text):
    """'oak green': green leaning half way (OKLab) toward oak's own colour (colour_compounds.toml
    [named_after]), as 'plaster pink' is a paler pink."""
    from cnlmc.colour import mix_oklab

    named, diags = compiled(compile_text, "oak green velvet")
    green, _ = compiled(compile_text, "green velvet")
    oak, _ = compiled(compile_text, "oak")
    expected = mix_oklab(green["params"]["base_color"], oak["params"]["base_color"], 0.5)
    assert named["params"]["base_color"] == pytest.approx(expected, abs=1e-6)
    assert notes(diags, "N122") == [
        "read 'oak green' as the colour 'green' as seen on oak: 0.5 of the way toward its colour"
    ]


def test_a_noun_alone_tints_with_its_own_colour(compile_text):
    """'a walnut tint': walnut's colour (read as the noun's colour, or as the colour named after it)."""
    tinted, _ = compiled(compile_text, "glass with a walnut tint")
    walnut, _ = compiled(compile_text, "walnut")
    assert tinted["params"]["base_color"] == pytest.approx(walnut["params"]["base_color"], abs=0.01)


def test_a_noun_after_a_comma_is_still_the_material(compile_text):
    (d,) = compile_text("polished, steel aluminum").diagnostics
    assert d.code == "E002"


def test_a_noun_then_an_adjective_alone_still_says_the_order(compile_text):
    (d,) = compile_text("chrome lightly").diagnostics
    assert d.message == "'lightly' comes after the noun: describing words come before it"
    (d,) = compile_text("heavily hammered").diagnostics
    assert d.message == "no material named: read 'heavily hammered' as 'heavily hammered copper'"


# ---------------------------------------------------------------- describing words after the noun


@pytest.mark.parametrize(
    "postfix,prefix",
    [
        ("Walnut, waxed.", "waxed walnut"),
        ("brass (brushed)", "brushed brass"),
        ("granite, honed, dark", "honed dark granite"),
        ("aluminium (lightly sandblasted)", "lightly sandblasted aluminium"),
    ],
)
def test_describing_words_after_a_comma_or_in_brackets(compile_text, postfix, prefix):
    after, _ = compiled(compile_text, postfix)
    before, _ = compiled(compile_text, prefix)
    assert after["params"] == before["params"] and after["model"] == before["model"]


def test_german_describing_words_after_a_comma(compile_text, german):
    after = compile_text("Stahl, gebürstet.", german).materials[0]
    before = compile_text("gebürsteter Stahl", german).materials[0]
    assert after["params"] == before["params"]


def test_a_postfix_before_a_clause(compile_text):
    material, _ = compiled(compile_text, "maple, stained, with a satin lacquer")
    assert material["model"]["coat"]


def test_a_finish_said_of_a_coat_is_the_coat(compile_text):
    material, diags = compiled(compile_text, "maple with a transparent finish")
    assert material["model"]["coat"]
    assert [d.code for d in diags] == ["N123"]


def test_a_glaze_in_a_colour(compile_text):
    material, _ = compiled(compile_text, "stoneware with a green glaze")
    r, g, b = material["params"]["base_color"]
    assert g > r and g > b


def test_knots_say_what_is_missing_and_draw_the_grain(compile_text):
    material, diags = compiled(compile_text, "cedar with knots")
    assert "wood" in graphs(material)
    assert [d.code for d in diags] == ["W120"]


def test_a_comma_before_with(compile_text):
    material, _ = compiled(compile_text, "satin nickel, with light scuffs")
    assert "scratched" in graphs(material)
    material, _ = compiled(compile_text, "pine (waxed), with a clear lacquer")
    assert material["model"]["coat"]


@pytest.mark.parametrize(
    "text,graph_or_param",
    [
        ("sterling silver with a little tarnish", "tarnished"),
        ("zinc with some oxidation", "oxidized"),
        ("cast iron with light pitting", "sandblasted"),
        ("suede with signs of wear", "scratched"),
        ("brass with a few dents", "hammered"),
        ("titanium with fine brush marks", "brushed"),
        ("canvas with a coarse weave", "fabric"),
    ],
)
def test_more_features_draw_what_their_words_say(compile_text, text, graph_or_param):
    result = compile_text(text)
    assert result.ok, [d.message for d in result.diagnostics]
    material = result.materials[0]
    rules = {step["rule"] for steps in result.ir["materials"][0].get("provenance", {}).values() for step in steps}
    assert graph_or_param in graphs(material) or any(graph_or_param in r for r in rules)


def test_a_stain_named_after_a_wood_with_a_shade(compile_text):
    dark, _ = compiled(compile_text, "maple with a dark walnut stain")
    plain, _ = compiled(compile_text, "maple with a walnut stain")
    assert sum(dark["params"]["base_color"]) < sum(plain["params"]["base_color"])


def test_an_unknown_word_in_a_clause_is_an_error_not_a_crash(compile_text, german):
    result = compile_text("Leinen mit xqzartiger Webstruktur", german)
    assert [d.code for d in result.diagnostics if d.is_error] == ["E001"]


CLAUSE_WORDS = [
    "oak",
    "walnut",
    "chrome",
    "steel",
    "gold",
    "with",
    "a",
    "and",
    "or",
    ",",
    "(",
    ")",
    "dark",
    "brown",
    "plated",
    "brushed",
    "slightly",
    "darker",
    "less",
    "glossy",
    "veins",
    "patina",
    "finish",
    "tint",
    "scratches",
    "a few",
    "fine",
    "varnish",
    "xyzzy",
    "stain",
    "amber",
    "mirror finish",
    "rust spots",
]


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.lists(st.sampled_from(CLAUSE_WORDS), min_size=1, max_size=8))
def test_any_sequence_of_clause_words_compiles_or_says_why(stdlib, words):
    from cnlmc.api import compile_source

    result = compile_source(" ".join(words), "fuzz.cnl", stdlib)
    assert result.ok or any(d.is_error and d.span is not None for d in result.diagnostics)


@pytest.mark.parametrize("text", ["zinc [brushed]", "zinc - brushed", "zinc – brushed"])
def test_square_brackets_and_dashes_set_words_off_too(compile_text, text):
    after, _ = compiled(compile_text, text)
    before, _ = compiled(compile_text, "brushed zinc")
    assert after["params"] == before["params"]


def test_a_noun_that_is_no_colour_tints_with_its_own_colour(compile_text, stdlib):
    """A dielectric noun that is not also a colour name: the N122 reading gives its base colour."""
    noun = next(
        key
        for key, entry in sorted(stdlib.all_of("nouns").items())
        if " " not in key
        and entry.get("model") == "dielectric"
        and [e.category for e in stdlib.lookup((key,))] == ["nouns"]
    )
    tinted, diags = compiled(compile_text, f"glass with a {noun} tint")
    assert tinted["params"]["base_color"] == stdlib.require("nouns", noun).get("base_color")
    assert notes(diags, "N122") == [f"read '{noun}' as the colour of {noun}"]


def test_a_clause_in_brackets(compile_text):
    material, _ = compiled(compile_text, "pewter (with light scuffs)")
    assert "scratched" in graphs(material)


def test_a_feature_that_is_an_adjective_too_ends_its_clause_at_and(compile_text):
    """'glaze' is an adjective (glazed) and a feature: in a clause the feature, so 'and' starts a second clause."""
    material, diags = compiled(compile_text, "stoneware with a white glaze and hairline cracks")
    assert "cracked" in graphs(material)
    assert not [d for d in diags if d.code == "N121"]


def test_a_shade_before_a_feature_without_a_colour_is_a_degree(compile_text):
    light, diags = compiled(compile_text, "pewter with light scratches")
    deep, _ = compiled(compile_text, "pewter with deep scratches")
    plain, _ = compiled(compile_text, "pewter with scratches")
    strength = [map_params(m, "scratched")["strength"] for m in (light, plain, deep)]
    assert strength[0] < strength[1] < strength[2]
    assert [d.code for d in diags] == ["N124"]


def test_alternatives_in_a_clause_are_variants(compile_text):
    result = compile_text("travertine with beige or brown veins")
    assert result.ok and len(result.materials) == 2
    reds = sorted(map_params(m, "marble")["color_r"] for m in result.materials)
    assert reds[0] < reds[1]


# ---------------------------------------------------------------- a colour word meets a feature's own colour


def named_rgb(material, graph):
    params = map_params(material, graph)
    return [params["color_r"], params["color_g"], params["color_b"]]


@pytest.mark.parametrize("colour", ["teal", "jade", "sea green", "greenish"])
def test_a_colour_of_the_patinas_own_hue_keeps_the_verdigris(compile_text, colour):
    plain, _ = compiled(compile_text, "brass with a patina")
    named, diags = compiled(compile_text, f"brass with a {colour} patina")
    assert map_params(named, "patina") == map_params(plain, "patina")  # the texture untouched
    (note,) = notes(diags, "N125")
    assert "own colour of the patina" in note and "hue family" in note


def test_a_shade_on_the_own_hue_shades_the_verdigris(compile_text):
    dark, diags = compiled(compile_text, "brass with a dark teal patina")
    shade_only, _ = compiled(compile_text, "brass with a dark patina")
    assert named_rgb(dark, "patina") == pytest.approx(named_rgb(shade_only, "patina"))
    assert "made dark" in notes(diags, "N125")[0]


def test_a_colour_of_another_hue_keeps_the_patinas_lightness_character(compile_text, stdlib):
    material, diags = compiled(compile_text, "brass with a red patina")
    L, C, h = lch(named_rgb(material, "patina"))
    red_L, red_C, red_h = lch(stdlib.require("colours", "red").get("rgb"))
    own_L, own_C, _ = lch([0.16, 0.42, 0.33])  # stdlib/graphs/patina.toml
    assert abs(h - red_h) < 3  # the named hue
    assert min(own_L, red_L) < L < max(own_L, red_L) and own_C < C < red_C  # between the two
    assert "keeping 0.4" in notes(diags, "N125")[0]


def test_a_survey_name_with_a_shade_is_the_shade_on_the_met_colour(compile_text):
    dark, _ = compiled(compile_text, "pewter with a dark blue patina")
    plain, _ = compiled(compile_text, "pewter with a blue patina")
    dark_L, _, dark_h = lch(named_rgb(dark, "patina"))
    plain_L, _, plain_h = lch(named_rgb(plain, "patina"))
    assert dark_L < plain_L and abs(dark_h - plain_h) < 10


@pytest.mark.parametrize("colour", ["black", "white", "charcoal grey"])
def test_a_colourless_word_is_used_as_it_is(compile_text, stdlib, colour):
    material, diags = compiled(compile_text, f"slate with {colour} veins")
    L, C, _ = lch(named_rgb(material, "marble"))
    assert C < 0.04
    assert not notes(diags, "N125")


def test_gold_veins_are_a_muted_gold(compile_text, stdlib):
    material, _ = compiled(compile_text, "travertine with gold veins")
    _, C, h = lch(named_rgb(material, "marble"))
    _, gold_C, gold_h = lch(stdlib.require("colours", "gold").get("rgb"))
    assert abs(h - gold_h) < 3 and 0.3 * gold_C < C < 0.7 * gold_C


def test_german_patina_in_its_own_colour_is_the_verdigris(compile_text, german):
    result = compile_text("Messing mit grüner Patina", german)
    assert result.ok, [d.message for d in result.diagnostics]
    plain, _ = compiled(compile_text, "brass with a patina")
    assert map_params(result.materials[0], "patina") == map_params(plain, "patina")


# ---------------------------------------------------------------- a head word inside a clause


@pytest.mark.parametrize(
    "text,same",
    [
        ("walnut with a matte finish and a few cracks", "matte walnut with a few cracks"),
        ("pewter with a satin texture and light scuffs", "satin pewter with light scuffs"),
        ("zinc with a hammered effect and a patina", "hammered zinc with a patina"),
    ],
)
def test_a_finish_before_and_keeps_its_describing_word(compile_text, text, same):
    """'finish', 'texture', 'effect' are head words ('satin finish steel'); after a 'with' the
    clause's feature reads them, also when another clause follows."""
    material, diags = compiled(compile_text, text)
    expected, _ = compiled(compile_text, same)
    assert material["params"] == expected["params"] and material.get("maps") == expected.get("maps")
    assert not notes(diags, "N121") and not notes(diags, "N101")


# ---------------------------------------------------------------- 'of' and the feature's colour


@pytest.mark.parametrize(
    "text,same",
    [
        ("travertine with veins of ochre", "travertine with ochre veins"),
        ("white tile with flecks of black", "white tile with black flecks"),
        ("onyx with streaks of dark red", "onyx with dark red streaks"),
        ("acrylic with a tinge of amber", "acrylic with an amber tinge"),
    ],
)
def test_the_colour_after_of_is_the_features_colour(compile_text, text, same):
    material, _ = compiled(compile_text, text)
    expected, _ = compiled(compile_text, same)
    assert material["params"] == expected["params"] and material.get("maps") == expected.get("maps")


def test_a_hint_of_a_colour_is_half_a_tint(compile_text):
    plain, _ = compiled(compile_text, "frosted glass")
    hint, _ = compiled(compile_text, "frosted glass with a hint of violet")
    tint, _ = compiled(compile_text, "frosted glass with a violet tint")
    (L0, C0, _), (L1, C1, h1), (L2, C2, h2) = (lch(m["params"]["base_color"]) for m in (plain, hint, tint))
    assert C0 < C1 < C2 and L2 < L1 < L0  # a violet, less of it than a tint
    assert abs(h1 - h2) < 20


def test_a_touch_of_a_colour_is_a_hint_and_a_touch_before_a_word_still_an_adverb(compile_text):
    touch, _ = compiled(compile_text, "frosted glass with a touch of teal")
    hint, _ = compiled(compile_text, "frosted glass with a hint of teal")
    assert touch["params"] == hint["params"]
    adverb, _ = compiled(compile_text, "a touch glossier grey plastic")
    slightly, _ = compiled(compile_text, "slightly glossier grey plastic")
    assert adverb["params"] == slightly["params"]


@pytest.mark.parametrize("text", ["limestone with veins of", "bronze with dents of", "glass with a trace of"])
def test_of_without_a_colour_says_what_it_needs(compile_text, text):
    result = compile_text(text)
    assert not result.ok
    (error,) = [d for d in result.diagnostics if d.is_error]
    assert error.message == "'of' after a feature needs the feature's colour"


# ---------------------------------------------------------------- a colour alone after 'in'


@pytest.mark.parametrize(
    "text,same",
    [
        ("aluminium in gunmetal grey", "gunmetal grey aluminium"),
        ("velvet in a deep burgundy", "deep burgundy velvet"),
        ("brushed brass in pale gold", "pale gold brushed brass"),
    ],
)
def test_a_colour_alone_after_in_is_the_materials_colour(compile_text, text, same):
    material, _ = compiled(compile_text, text)
    expected, _ = compiled(compile_text, same)
    assert material["params"] == expected["params"]


def test_german_colour_after_in(compile_text, german):
    result = compile_text("Keramik in Dunkelblau", german)
    assert result.ok, [d.message for d in result.diagnostics]
    english, _ = compiled(compile_text, "dark blue ceramic")
    assert result.materials[0]["params"] == english["params"]


def test_a_colour_after_in_then_clauses(compile_text):
    material, _ = compiled(compile_text, "pewter in slate grey with a satin lacquer and a few scratches")
    expected, _ = compiled(compile_text, "slate grey pewter with a satin lacquer and a few scratches")
    assert material["params"] == expected["params"] and material.get("maps") == expected.get("maps")


@pytest.mark.parametrize(
    "text,same",
    [
        ("brass with a high polish", "polished brass"),
        ("steel with a polish", "polished steel"),
        ("plastic with a high gloss", "glossy plastic"),
        ("oak with a satin polish", "satin oak"),
        ("steel, with a mirror polish", "mirror steel"),
    ],
)
def test_a_finish_noun_is_its_adjective_unless_the_clause_describes_it(compile_text, text, same):
    """'polish' and 'gloss' name a finish as 'finish' does: alone (with degree words) they are their
    own adjective; with describing words of the clause, those are the surface ('a satin polish')."""
    material, diags = compiled(compile_text, text)
    expected, _ = compiled(compile_text, same)
    assert material["params"] == expected["params"] and material.get("maps") == expected.get("maps")
    assert not [d for d in diags if d["severity"] in ("error", "warning")]
