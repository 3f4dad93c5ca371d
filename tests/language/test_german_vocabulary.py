"""German keeps pace (issue #14): the everyday vocabulary, declension and degrees with `--lexicon de`.

The German overlay (stdlib/overlays/de) only names what the stdlib defines, so a German phrase
must compile to exactly what its English translation compiles to: these tests compare the two
through the real compiler. None of the phrases here is in tests/language/everyday.toml.
"""

import tomllib
from importlib import resources
from pathlib import Path

import pytest

from cnlmc.api import Session, compile_source, lexicon_for
from tests.helpers import load_module

from .conftest import first

ADJECTIVE_ENDINGS = ("e", "en", "er", "es", "em")  # strong, weak and mixed declension
ROOT = Path(__file__).resolve().parents[2]
COMPARATIVES = ROOT / "stdlib" / "overlays" / "de" / "refinements_declined_de.toml"


gen_comparatives = load_module("gen_de_comparatives", ROOT / "scripts" / "gen_de_comparatives.py")


@pytest.fixture(scope="module")
def de():
    return lexicon_for(("de",))


def overlay_file(name):
    """One file of the German overlay as data (which words the overlay itself adds)."""
    return tomllib.loads(resources.files("cnlmc.stdlib").joinpath("overlays", "de", name).read_text("utf-8"))


def material(text, lexicon):
    return first(compile_source(text, "de.cnl", lexicon))


def same_look(a, b):
    return a["model"] == b["model"] and a["params"] == b["params"] and a["maps"] == b["maps"]


# ---------------------------------------------------------------- nouns of the new vocabulary


@pytest.mark.parametrize(
    "german,english",
    [
        ("Travertin", "travertine"),
        ("Kalkstein", "limestone"),
        ("Speckstein", "soapstone"),
        ("Quarzit", "quartzite"),
        ("Lärche", "larch"),
        ("Fichtenholz", "spruce"),
        ("Kiefer", "pine"),
        ("Esche", "ash"),
        ("Zeder", "cedar"),
        ("Palisander", "rosewood"),
        ("Sperrholz", "plywood"),
        ("Spanplatte", "chipboard"),
        ("Wildleder", "suede"),
        ("Jute", "burlap"),
        ("Kunstleder", "faux leather"),
        ("Kaschmir", "cashmere"),
        ("Gipskarton", "drywall"),
        ("Faserzement", "fiber cement"),
        ("Steinzeug", "stoneware"),
        ("Polycarbonat", "polycarbonate"),
        ("Epoxidharz", "epoxy resin"),
        ("Kohlefaser", "carbon fibre"),
        ("Gusseisen", "cast iron"),
        ("Schmiedeeisen", "wrought iron"),
        ("Blattgold", "gold leaf"),
        ("Neusilber", "nickel silver"),
        ("Bernstein", "amber"),
        ("Bleikristall", "crystal"),
    ],
)
def test_german_noun_is_the_english_noun(de, german, english):
    assert same_look(material(german, de), material(english, de))


def test_fichte_is_spruce_not_pine(de):
    """Fichte (Picea) and Kiefer (Pinus) are different trees with different numbers in the stdlib."""
    fichte, kiefer = material("Fichte", de), material("Kiefer", de)
    assert same_look(fichte, material("spruce", de)) and same_look(kiefer, material("pine", de))
    assert fichte["params"] != kiefer["params"]


def test_every_german_noun_names_one_stdlib_noun(de):
    """An alias of the overlay never shadows another entry's word (no new ambiguity in German)."""
    english = lexicon_for()
    overlay = overlay_file("nouns_de.toml")
    assert len(overlay) >= 150  # the stdlib's nouns, most of them named in German
    for key, entry in overlay.items():
        assert de.entry("nouns", key) is not None, key
        for alias in entry["aliases"]:
            hits = {(e.category, e.key) for e in english.lookup(tuple(alias.split()))}
            assert hits <= {("nouns", key), ("colours", alias)}, (alias, key, hits)


# ---------------------------------------------------------------- declension


@pytest.mark.parametrize(
    "stem,english",
    [("matt", "matte"), ("glänzend", "glossy"), ("rau", "rough"), ("glatt", "smooth"), ("stumpf", "dull")],
)
@pytest.mark.parametrize("noun,english_noun", [("Kunststoff", "plastic"), ("Keramik", "ceramic"), ("Stahl", "steel")])
def test_every_declined_form_means_the_adjective(de, stem, english, noun, english_noun):
    """German grammatical gender must not change the numbers: matter/mattes/matte/matten Kunststoff."""
    want = material(f"{english} {english_noun}", de)
    for ending in ADJECTIVE_ENDINGS:
        assert same_look(material(f"{stem}{ending} {noun}", de), want), f"{stem}{ending} {noun}"


@pytest.mark.parametrize("stem,shade", [("dunkl", "dark"), ("hell", "light")])
def test_declined_shades_including_the_dropped_e(de, stem, shade):
    """dunkel loses its e before an ending (dunkles, dunkler); hell keeps its stem."""
    want = material(f"{shade} oak", de)
    for ending in ADJECTIVE_ENDINGS:
        assert same_look(material(f"{stem}{ending} Eiche", de), want), f"{stem}{ending} Eiche"


@pytest.mark.parametrize("stem,english", [("beige", "beige"), ("orange", "orange"), ("rosa", "pink")])
def test_colours_ending_in_a_vowel_decline_too(de, stem, english):
    """beiger, beigem (the ending's consonant only), orangene, rosaner (an -n- before the ending)."""
    want = material(f"{english} velvet", de)
    forms = [stem + e for e in ("r", "s", "n", "m")] if stem.endswith("e") else []
    forms += [stem + "n" + e for e in ADJECTIVE_ENDINGS]
    for form in forms:
        assert same_look(material(f"{form} Samt", de), want), form


def test_the_er_form_alone_on_a_line_is_still_the_comparative(de):
    s = Session("roter Kunststoff", lexicon=de)
    before = s.material["params"]
    assert s.refine("matter")["params"]["roughness"] > before["roughness"]
    assert sum(s.refine("dunkler")["params"]["base_color"]) < sum(before["base_color"])
    assert s.refine("glänzender")["params"]["roughness"] < s.refine("rauer")["params"]["roughness"]


def test_every_comparative_that_is_also_a_declined_positive_reads_both_ways(de):
    """The rule behind the -er aliases: a German refinement 'Xer' whose 'X' is an adjective, a shade,
    a colour or a degree word must also read as that word, else 'Xer Stahl' becomes a refinement."""
    for key, refinement in overlay_file("refinements_de.toml").items():
        for form in refinement["aliases"]:
            if not form.endswith("er") or key in ("more", "less"):  # mehr, weniger: quantities, not qualities
                continue
            kinds = ("adjectives", "shades", "colours", "adverbs")
            positives = [e for e in de.lookup((form[:-2],)) if e.category in kinds]
            readings = {(e.category, e.key) for e in de.lookup((form,))}
            if positives:  # at least one positive reading, so the form before a noun is not a refinement
                assert readings & {(e.category, e.key) for e in positives}, (form, positives)


@pytest.mark.parametrize(
    "german,english",
    [
        ("dunkleres Holz", "darker wood"),
        ("etwas helleres Holz", "slightly lighter wood"),
        ("glänzenderes Aluminium", "shinier aluminum"),
        ("rauere Keramik", "rougher ceramic"),
    ],
)
def test_a_comparative_with_an_ending_is_the_comparative(de, german, english):
    """dunkleres Holz = darker wood (not 'dark wood', which 'dunkles Holz' is)."""
    assert same_look(material(german, de), material(english, de))
    assert not same_look(material(german, de), material(german.replace("eres ", "es ").replace("ere ", "e "), de))


def test_the_generated_comparatives_are_up_to_date():
    assert COMPARATIVES.read_text("utf-8") == gen_comparatives.generate(), "rerun scripts/gen_de_comparatives.py"


# ---------------------------------------------------------------- degrees and colours


@pytest.mark.parametrize(
    "german,english",
    [
        ("sehr leicht gebürsteter Stahl", "very lightly brushed steel"),
        ("kaum zerkratztes Chrom", "barely scratched chrome"),
        ("ziemlich verwittertes Holz", "fairly weathered wood"),
        ("ein wenig angelaufenes Silber", "a bit tarnished silver"),
        ("äußerst glänzendes Glas", "extremely glossy glass"),
        ("stark verrostetes Gusseisen", "heavily rusty cast iron"),
        ("vollständig gewachste Buche", "fully waxed beech"),
    ],
)
def test_degrees_mean_what_the_english_ones_mean(de, german, english):
    assert same_look(material(german, de), material(english, de))


@pytest.mark.parametrize(
    "german,english",
    [
        ("weinroter Samt", "wine red velvet"),
        ("himmelblaue Keramik", "sky blue ceramic"),
        ("olivgrünes Leinen", "olive green linen"),
        ("bläuliches Glas", "bluish glass"),
        ("rötliches Leder", "reddish leather"),
        ("gräulicher Filz", "greyish felt"),
        ("cremeweißes Leder", "cream leather"),
        ("anthrazit lackiertes Metall", "charcoal lacquered metal"),
        ("silbernes Glas", "silver glass"),
    ],
)
def test_german_colour_names_are_the_survey_colours(de, german, english):
    assert same_look(material(german, de), material(english, de))


def test_german_colours_do_not_replace_the_surveys_own_words(de):
    """'marine' and 'creme' are survey names of their own: the overlay must not re-point them."""
    english = lexicon_for()
    for word in ("marine", "creme"):
        want = {e.key for e in english.lookup((word,)) if e.category == "colours"}
        got = {e.key for e in de.lookup((word,)) if e.category == "colours"}
        assert want and want == got, (word, want, got)


# ---------------------------------------------------------------- refinement lines


def german_and_english_sessions(de, german_first, english_first):
    return Session(german_first, lexicon=de), Session(english_first, lexicon=de)


@pytest.mark.parametrize(
    "german,english",
    [("weniger gesättigt", "less saturated"), ("etwas heller", "slightly lighter"), ("wärmer", "warmer")],
)
def test_a_german_refinement_line_is_the_english_one(de, german, english):
    ours, theirs = german_and_english_sessions(de, "blauer Samt", "blue velvet")
    assert ours.refine(german)["params"] == theirs.refine(english)["params"]


def test_viel_is_a_bigger_step_than_etwas(de):
    start = Session("roter Kunststoff", lexicon=de).material["params"]["base_color"]
    much = Session("roter Kunststoff", lexicon=de).refine("viel dunkler")["params"]["base_color"]
    little = Session("roter Kunststoff", lexicon=de).refine("etwas dunkler")["params"]["base_color"]
    assert sum(much) < sum(little) < sum(start)


def test_the_er_form_of_a_degree_word_in_a_clause(de):
    """'mit feiner Maserung' (strong dative): fine grain, not the comparative 'finer'."""
    assert same_look(material("Eiche mit feiner Maserung", de), material("oak with fine grain", de))
    assert same_look(material("Eiche mit feiner Maserung", de), material("Eiche mit einer feinen Maserung", de))


@pytest.mark.parametrize(
    "german,english",
    [
        ("besonders glänzendes Kupfer", "especially glossy copper"),
        ("recht rauer Sandstein", "reasonably rough sandstone"),
        ("eher matte Keramik", "rather matte ceramic"),
        ("total glatter Schiefer", "totally smooth slate"),
        ("handgehämmertes Kupfer", "hand-hammered copper"),
    ],
)
def test_intensifiers_mean_what_the_english_ones_mean(de, german, english):
    assert same_look(material(german, de), material(english, de))


@pytest.mark.parametrize(
    "german,english",
    [("weniger Adern", "fewer veins"), ("mehr Glanz", "more gloss"), ("höherer Kontrast", "higher contrast")],
)
def test_german_map_refinements_are_the_english_ones(de, german, english):
    ours, theirs = german_and_english_sessions(de, "weißer Marmor", "white marble")
    a, b = ours.refine(german), theirs.refine(english)
    assert a["params"] == b["params"] and a["maps"] == b["maps"]


@pytest.mark.parametrize(
    "german,english",
    [
        ("verchromter Stahl", "chromed steel"),
        ("vergoldetes Silber", "gilded silver"),
        ("geräucherte Eiche", "smoked oak"),
        ("geprägtes Leder", "embossed leather"),
        ("gelochtes Aluminium", "perforated aluminum"),
        ("spaltrauer Schiefer", "riven slate"),
        ("versiegelter Beton", "sealed concrete"),
        ("gewellter Stahl", "corrugated steel"),
    ],
)
def test_german_participles_are_the_english_adjectives(de, german, english):
    assert same_look(material(german, de), material(english, de))
