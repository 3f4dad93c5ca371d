"""Treatment and coating words by what they do to each class (issue #14, docs/language.md "Finishes"):
glass processes, coats that are real layers, diffuse surfaces that get their Oren-Nayar sigma from
the words. Phrases here are deliberately not those of everyday.toml."""

import pytest

from cnlmc.api import compile_source, lexicon_for

from .conftest import first

LEXICON = lexicon_for()


def material(text):
    return first(compile_source(text, "finishes.cnl", LEXICON))


def params(text):
    return material(text)["params"]


def luminance(rgb):
    r, g, b = rgb
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def warnings(text):
    return [d.code for d in compile_source(text, "finishes.cnl", LEXICON).diagnostics if d.severity == "warning"]


# ---- glass: what each process does to a pane


def test_smoked_glass_is_a_neutral_darker_absorber_than_tinted_glass():
    clear, tinted, smoked = (luminance(params(t)["base_color"]) for t in ("quartz", "tinted quartz", "smoked quartz"))
    assert clear > tinted > smoked > 0.1
    r, g, b = params("smoked quartz")["base_color"]
    assert max(r, g, b) - min(r, g, b) < 0.02


def test_heavier_smoke_is_darker_and_stays_grey():
    shades = [params(f"{a}smoked glass")["base_color"] for a in ("lightly ", "", "heavily ", "extremely ")]
    lum = [luminance(c) for c in shades]
    assert lum == sorted(lum, reverse=True) and lum[-1] > 0.0
    # the smoke adds no hue: the glass's own faint cyan (soda-lime, seen through 5 cm) and no more
    glass = [c**5 for c in params("glass")["base_color"]]  # its 1 cm colour through 5 cm
    own = (max(glass) - min(glass)) / max(glass)
    for r, g, b in shades:
        assert max(r, g, b) - min(r, g, b) < (own + 0.02) * max(r, g, b) + 1e-6


def test_a_tint_colour_is_the_glass_colour_and_it_stays_glass():
    m = material("amber tinted glass")
    r, g, b = m["params"]["base_color"]
    assert m["model"]["base"] == "glass" and r > g > b


@pytest.mark.parametrize("word", ["frosted", "acid-etched", "sandblasted", "brushed"])
def test_abraded_or_etched_glass_scatters_what_it_transmits(word):
    m = material(f"{word} borosilicate glass")
    assert m["model"]["base"] == "glass" and m["params"]["roughness"] >= 0.25
    assert warnings(f"{word} borosilicate glass") == []


def test_brushed_glass_is_a_lighter_frosting_than_etching():
    assert params("brushed glass")["roughness"] < params("etched glass")["roughness"]


def test_etched_metal_is_matted_not_refused():
    assert warnings("etched pewter") == []
    assert params("etched pewter")["roughness"] > params("pewter")["roughness"]


def test_polished_cloth_has_a_sheen_not_a_gloss():
    rough = params("polished linen")["roughness"]
    assert 0.4 <= rough <= 0.7


# ---- coats: each finish lays the layer it really has


@pytest.mark.parametrize("word,coat", [("powder-coated", "powder coat"), ("enamelled", "enamel coat")])
def test_an_opaque_finish_hides_the_metal_under_a_clear_layer(word, coat):
    m = material(f"green {word} copper")
    assert m["model"]["base"] == "dielectric" and m["model"]["coat"] is True
    assert m["params"]["coat"]["name"] == coat and "eta" not in m["params"]
    r, g, b = m["params"]["base_color"]
    assert g > r and g > b  # the pigment is the base


def test_powder_coat_is_satin_and_enamel_glossy():
    powder = params("powder-coated zinc")["coat"]["roughness"]
    enamel = params("enamelled zinc")["coat"]["roughness"]
    assert 0.25 <= powder < 0.5 and enamel < 0.25


@pytest.mark.parametrize("gloss,direction", [("glossy", -1), ("matte", 1)])
def test_a_gloss_word_describes_the_powder_coat(gloss, direction):
    plain = params("powder-coated iron")
    said = params(f"{gloss} powder-coated iron")
    assert direction * (said["coat"]["roughness"] - plain["coat"]["roughness"]) > 0
    assert said["roughness"] == plain["roughness"]  # the pigment under it is unchanged


def test_opaque_layers_cover_the_substrates_colour_pattern():
    assert "base_color" in material("walnut")["maps"]
    for text in ("yellow painted walnut", "enamelled walnut"):
        assert "base_color" not in material(text)["maps"], text
    assert "base_color" in material("varnished walnut")["maps"]  # a clear coat shows the grain


def test_a_layer_follows_the_shape_under_it():
    assert "normal" in material("hammered powder-coated iron")["maps"]


@pytest.mark.parametrize("text", ["galvanized iron", "gold plated pewter", "anodized titanium"])
def test_metal_finishes_stay_metal(text):
    assert material(text)["model"]["base"] == "conductor"


def test_plated_takes_the_plating_metals_optics():
    assert params("copper plated zinc")["f0"] == params("copper")["f0"]


# ---- a surface the words make diffuse gets its Oren-Nayar sigma from them


def sigma(text):
    m = material(text)
    return m["model"]["diffuse"], m["params"].get("diffuse_roughness", 0.0)


def test_words_that_make_a_plastic_diffuse_give_it_a_sigma():
    lobe, value = sigma("extremely matte polypropylene")
    assert lobe == "oren_nayar" and 0.5 < value < 0.8


def test_a_stronger_matte_word_means_a_larger_sigma():
    values = [sigma(f"{a}matte linen")[1] for a in ("", "very ", "extremely ")]
    assert values == sorted(values) and len(set(values)) == 3


def test_matte_raises_a_smoother_cloth_to_matte_and_keeps_a_rougher_one():
    assert sigma("matte silk")[1] >= sigma("silk")[1]
    assert sigma("matte velvet") == sigma("velvet")  # velvet is already beyond 'matte'
    assert sigma("very matte velvet")[1] > sigma("velvet")[1]


def test_a_matte_plastic_that_stays_specular_keeps_its_lambert_lobe():
    assert sigma("matte nylon")[0] == "lambert"


# ---- treatment words by class: the same word, the physics of each class


@pytest.mark.parametrize("noun", ["borosilicate glass", "titanium", "polycarbonate"])
def test_water_on_a_sealed_surface_glosses_it_without_darkening(noun):
    dry, wet = params(noun), params(f"wet {noun}")
    assert luminance(wet["base_color"]) == pytest.approx(luminance(dry["base_color"]))
    assert wet["roughness"] <= dry["roughness"]


@pytest.mark.parametrize("noun", ["sandstone", "pine", "terracotta"])
def test_water_in_a_porous_surface_darkens_it(noun):
    assert luminance(params(f"wet {noun}")["base_color"]) < luminance(params(noun)["base_color"])


@pytest.mark.parametrize("noun", ["cedar", "acrylic", "porcelain"])
def test_blasting_roughens_wood_plastic_and_ceramic_too(noun):
    assert warnings(f"bead-blasted {noun}") == []
    assert params(f"bead-blasted {noun}")["roughness"] > params(noun)["roughness"]


def test_reclaimed_ages_brick_and_stone_and_is_rough_sawn_on_wood():
    assert warnings("reclaimed limestone") == []
    assert params("reclaimed limestone").get("roughness", 1.0) > params("limestone")["roughness"]  # 1.0: diffuse
    assert luminance(params("reclaimed ash")["base_color"]) != luminance(params("ash")["base_color"])


# ---- a word of how a thing is made that changes nothing on its surface says so (a note)


def notes(text):
    return [d.code for d in compile_source(text, "finishes.cnl", LEXICON).diagnostics if d.severity == "note"]


@pytest.mark.parametrize("text,plain", [("toughened glass", "glass"), ("laminated quartz", "quartz")])
def test_a_process_that_leaves_the_look_says_so_in_a_note(text, plain):
    assert material(text)["params"] == material(plain)["params"]
    assert "N141" in notes(text) and warnings(text) == []


def test_a_word_that_changes_the_look_has_no_such_note():
    assert "N141" not in notes("frosted glass")


def test_a_wet_cloth_darkens_and_stays_diffuse():
    m = material("wet flannel")
    assert m["model"]["base"] == "diffuse"
    assert luminance(m["params"]["base_color"]) < luminance(params("flannel")["base_color"])


def test_dull_glass_is_hazed():
    assert params("dull quartz")["roughness"] > params("quartz")["roughness"]


@pytest.mark.parametrize("metal", ["brass", "gold", "silver", "chrome", "copper"])
def test_a_dull_metal_has_lost_its_gloss(metal):
    """'dull brass' / 'brass that isn't shiny': past the glossy band (everyday.toml's 0.25), whatever
    the metal's own roughness (a multiple of brass's 0.12 left it glossy)."""
    dull = params(f"dull {metal}")["roughness"]
    assert dull >= 0.25 and dull > params(metal)["roughness"]
    assert params(f"{metal} that isn't shiny")["roughness"] == pytest.approx(dull)


def test_the_metal_between_rust_patches_is_dark_and_rough():
    """Rusting steel carries a dark oxide film and pits between the patches: the clean metal the rust
    map shows between them is darker and rougher than the clean iron (the preview showed chrome)."""
    clean, rusty = params("iron"), params("rusty iron")
    assert max(rusty["base_color"]) < 0.5 * min(clean["base_color"])
    assert rusty["roughness"] >= 0.55
    slightly = params("slightly rusty iron")
    assert max(rusty["base_color"]) < max(slightly["base_color"]) < max(clean["base_color"])


def test_a_clear_plastic_takes_what_a_process_does_to_glass():
    """Plexiglass is a plastic whose model is glass: smoke and tint absorb in it as in glass."""
    assert params("smoked plexiglass")["base_color"] == pytest.approx(
        [c * 0.35 for c in params("plexiglass")["base_color"]]
    )
    assert params("brushed plexiglass")["roughness"] > 0.0


def test_painted_glass_is_opaque_colour_behind_the_glass_face():
    m = material("green painted borosilicate glass")
    assert m["model"]["base"] == "dielectric"  # no longer transmissive
    assert m["params"]["roughness"] == params("borosilicate glass")["roughness"]  # the pane's face


def test_tinted_concrete_takes_its_pigment():
    assert warnings("ochre tinted stucco") == []
    r, g, b = params("ochre tinted stucco")["base_color"]
    assert r > b


# ---- '<material> coated': the coating material is the surface


def test_a_metal_coating_lends_its_optics():
    m = material("zinc coated iron")
    assert m["model"]["base"] == "conductor" and m["params"]["f0"] == params("zinc")["f0"]


@pytest.mark.parametrize("coating", ["rubber", "vinyl", "epoxy"])
def test_a_non_metal_coating_is_the_surface_and_hides_the_metal(coating):
    m = material(f"{coating} coated aluminum")
    assert m["model"]["base"] != "conductor" and "eta" not in m["params"]
    assert m["params"]["base_color"] == params(coating)["base_color"]


def test_a_finish_word_describes_the_coating():
    assert params("rubber coated glossy iron")["roughness"] < params("rubber coated iron")["roughness"]


def test_hard_anodizing_is_darker_and_matter_than_anodizing():
    hard, plain = params("hard anodized titanium"), params("anodized titanium")
    assert luminance(hard["base_color"]) < 0.5 * luminance(plain["base_color"])
    assert hard["roughness"] > plain["roughness"]


@pytest.mark.parametrize(
    "text,same", [("clear anodized aluminium", "anodized aluminium"), ("hot-dip galvanized iron", "galvanized iron")]
)
def test_trade_names_of_finishes(text, same):
    assert params(text) == params(same) and warnings(text) == []


def test_oil_on_metal_is_a_film_not_a_stain():
    assert warnings("oiled iron") == []
    oiled, plain = params("oiled iron"), params("iron")
    assert oiled["roughness"] < plain["roughness"]
    r, g, b = oiled["base_color"]
    assert r == g == b  # no warm stain, as oil gives wood


def test_wax_and_oil_dress_cloth():
    assert warnings("waxed twill") == [] and material("waxed twill")["model"]["coat"] is True
    assert warnings("oiled denim") == []
    assert luminance(params("oiled denim")["base_color"]) < luminance(params("denim")["base_color"])


@pytest.mark.parametrize("metal", ["gold", "aluminium", "copper"])
def test_a_metal_that_does_not_rust_keeps_its_colour_under_rusty(metal):
    """The oxide film between the rust patches is iron's: on other metals 'rusty' only roughens."""
    assert params(f"rusty {metal}")["base_color"] == pytest.approx(params(metal)["base_color"])
