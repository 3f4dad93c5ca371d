"""Word formation (issue #14): unknown words read by the lexicon's rules, with a note each.

Every phrase here is one that tests/language/everyday.toml does NOT hold: the rules must be
general. Each reading is compared with the phrase it should mean, through the real compiler
(model, parameters and maps of the IR; names and provenance may differ).
"""

from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.diagnostics import Severity
from cnlmc.lexicon import load_lexicon
from cnlmc.lexicon_schema import LexiconError
from cnlmc.tagger import Tagger
from cnlmc.word_formation import NOTE_CODE


@pytest.fixture(scope="module")
def lexicon():
    return load_lexicon()


def compiled(lexicon, text):
    result = compile_source(text, "wf.cnl", lexicon)
    assert result.ok, (text, [d.message for d in result.diagnostics])
    assert not [d for d in result.diagnostics if d.severity is Severity.WARNING], text
    (material,) = result.ir["materials"]
    return result, {k: material[k] for k in ("model", "params", "maps")}


def notes(result):
    return [d.message for d in result.diagnostics if d.severity is Severity.NOTE and d.code == NOTE_CODE]


def assert_reads_as(lexicon, text, meaning, note_has=""):
    result, look = compiled(lexicon, text)
    _plain, expected = compiled(lexicon, meaning)
    assert look == expected, (text, meaning)
    said = notes(result)
    assert said, f"{text!r} was read by a rule without a note"
    assert any(note_has in n for n in said), said


# ---------------------------------------------------------------- negation


@pytest.mark.parametrize(
    ("text", "meaning", "note_has"),
    [
        ("not matte ceramic", "glossy ceramic", "opposite of 'matte'"),
        ("non-matte paint", "glossy paint", "opposite of 'matte'"),
        ("nonmatte plastic", "glossy plastic", "'glossy'"),
        ("unglossy rubber", "matte rubber", "opposite of 'glossy'"),
        ("not smooth slate", "rough slate", "opposite of 'smooth'"),
        ("not dull chrome", "shiny chrome", "opposite of 'dull'"),
        ("unwaxed pine", "raw pine", "'raw'"),
        ("unoiled teak", "raw teak", "'raw'"),
        ("unstained maple", "raw maple", "'raw'"),
        ("unanodized aluminum", "aluminum", "'raw'"),
        ("not weathered copper", "copper", "without 'weathered'"),
        ("unscratched chrome", "chrome", "without 'scratched'"),
        ("not too glossy paint", "satin paint", "'satin' (the finish between)"),
        ("not overly rough stone", "slightly rough stone", "'slightly rough'"),
        ("non-toxic paint", "paint", "no effect"),
        ("anti-fog glass", "glass", "no effect"),
        ("no-gloss ceramic", "matte ceramic", "opposite of 'glossy'"),
        ("untinted glass", "clear glass", "opposite of 'tinted'"),
        ("not clear acrylic", "frosted acrylic", "opposite of 'clear'"),
        ("un-lacquered copper", "raw copper", "'raw'"),
    ],
)
def test_negation_reads_the_declared_opposite_or_without(lexicon, text, meaning, note_has):
    assert_reads_as(lexicon, text, meaning, note_has)


def test_negation_of_a_reflective_word_is_rougher_than_the_word(lexicon):
    _r, shiny = compiled(lexicon, "shiny plastic")
    _r, not_shiny = compiled(lexicon, "not lustrous plastic")
    assert not_shiny["params"]["roughness"] > shiny["params"]["roughness"]


def test_un_before_an_unknown_word_stays_unknown(lexicon):
    result = compile_source("unblorfed steel", "wf.cnl", lexicon)
    assert [d.code for d in result.diagnostics if d.is_error] == ["E001"]


# ---------------------------------------------------------------- prefixes, suffixes, compounds


@pytest.mark.parametrize(
    ("text", "meaning", "note_has"),
    [
        ("semi-glossy plastic", "slightly glossy plastic", "slightly glossy"),
        ("semiglossy plastic", "slightly glossy plastic", "slightly glossy"),
        ("half glossy ceramic", "slightly glossy ceramic", "slightly glossy"),
        ("ultra-matte rubber", "intensely matte rubber", "intensely matte"),
        ("high-shine chrome", "very shiny chrome", "'very shiny'"),
        ("low-gloss paint", "barely glossy paint", "'barely glossy'"),
        ("mid-sheen plastic", "somewhat shiny plastic", "'somewhat shiny'"),
        ("mirror-look steel", "mirror steel", "'mirror'"),
        ("matte-finished steel", "matte steel", "'matte'"),
        ("wax-finished oak", "waxed oak", "'wax'"),
        ("bronze-coloured plastic", "bronze plastic", "'bronze'"),
        ("terracotta-toned paint", "terracotta paint", "'terracotta'"),
        ("oaken", "oak", "'oak'"),
        ("coppery plastic", "copper plastic", "'copper'"),
        ("roughish slate", "slightly rough slate", "'slightly rough'"),
        ("matte-ish rubber", "slightly matte rubber", "'slightly matte'"),
        ("oily pine", "oiled pine", "'oil'"),
        ("glossy-white ceramic", "glossy white ceramic", "'glossy white'"),
        ("brushed-steel", "brushed steel", "'brushed steel'"),
        ("hand-polished brass", "polished brass", "'polished'"),
        ("wire-brushed oak", "brushed oak", "'brushed'"),
        ("bead-polished chrome", "polished chrome", "'polished'"),
        ("matte look plastic", "matte plastic", "'look'"),
        ("brushed brass look", "brushed brass", "'look'"),
        ("marble effect tiles", "ceramic tile with a marble effect", "the look of marble"),
        ("rough-hewn pine", "rough pine", "first part"),
        ("wire brushed ash", "brushed ash", "saying how"),
        ("walnut-veneer", "walnut", "material of the veneer"),
        ("rubber mat", "rubber", "material of the mat"),
        ("walnut kitchen table", "walnut", "where or what for"),
        ("exterior oak", "oak", "where or what for"),
        ("car window", "glass", "what for"),
        ("beadboard wainscot", "pine", "material of the wainscot"),  # a building product names the material
        ("a bench in teak", "teak", "material of the bench"),  # 'in' after an object: its material
        ("steel door handle", "steel", "material of the"),
        ("leather-look vinyl", "vinyl with a leather effect", "the look of leather: its colour"),
        ("marble-effect porcelain", "porcelain with a marble effect", "the look of marble"),
        ("mirror-like chrome", "mirror chrome", "'mirror'"),
        ("gloss finish white paint", "glossy white paint", "'finish'"),
    ],
)
def test_derived_and_compound_words(lexicon, text, meaning, note_has):
    assert_reads_as(lexicon, text, meaning, note_has)


def test_a_head_word_at_the_end_is_left_to_the_clause(lexicon):
    for text in ("copper with a matte finish", "steel with a walnut finish"):
        result, _look = compiled(lexicon, text)
        assert not notes(result), text


def test_an_unknown_word_is_never_joined_to_an_object(lexicon):
    result = compile_source("blorf tiles", "wf.cnl", lexicon)
    assert [d.code for d in result.diagnostics] == ["E001"]


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("kitchen", "says where or what for"),
        ("not steel", "negates a finish or treatment word"),
        ("not white plastic", "negates a finish or treatment word"),
        ("semi steel", "no describing word after it"),
    ],
)
def test_a_rule_word_with_nothing_to_apply_to_says_so(lexicon, text, says):
    result = compile_source(text, "wf.cnl", lexicon)
    errors = [d for d in result.diagnostics if d.is_error]
    assert [d.code for d in errors] == ["E002"] and says in errors[0].message and errors[0].hints


# ---------------------------------------------------------------- WordNet (English only)


@pytest.mark.parametrize(
    ("text", "meaning", "note_has"),
    [
        ("burnished copper", "polished copper", "synonym in WordNet"),
        ("glistening steel", "shiny steel", "synonym in WordNet"),
        ("rugged slate", "rough slate", "synonym in WordNet"),
        ("gabbro", "stone", "a kind of rock (WordNet"),
        ("polished albite", "polished stone", "a kind of mineral (WordNet"),
        ("aertex", "fabric", "a kind of fabric (WordNet"),
    ],
)
def test_wordnet_reads_unknown_nouns_and_adjectives(lexicon, text, meaning, note_has):
    assert_reads_as(lexicon, text, meaning, note_has)


def test_wordnet_adjectives_are_only_the_visual_ones(lexicon):
    result = compile_source("boring steel", "wf.cnl", lexicon)  # 'dull' is 'boring' first in WordNet: not listed
    assert [d.code for d in result.diagnostics if d.is_error] == ["E001"]  # an adjective is never read past


# ---------------------------------------------------------------- objects and classes


@pytest.mark.parametrize(
    ("text", "meaning", "note_has"),
    [
        ("birch planks", "birch", "'birch'"),
        ("maple boards", "maple", "'maple'"),
        ("walnut veneer", "walnut", "'walnut'"),
        ("copper wire", "copper", "'copper'"),
        ("zinc sheets", "zinc", "'zinc'"),
        ("glass jar", "glass", "'glass'"),
        ("brushed steel handrail", "brushed steel", "'steel'"),
        ("oaken beams", "oak", "'oak'"),
        ("maple wood", "maple", "its class"),
        ("granite stone", "granite", "its class"),
        ("planks", "wood", "usual material"),
        ("pipes", "steel", "usual material"),
        ("floor tiles", "tiles with grout", "laid tiles"),
        ("cinder blocks", "cinder block", ""),
        ("paving stones", "paving stone", ""),
    ],
)
def test_objects_read_as_their_material(lexicon, text, meaning, note_has):
    if note_has:
        assert_reads_as(lexicon, text, meaning, note_has)
    else:
        assert compiled(lexicon, text)[1] == compiled(lexicon, meaning)[1]


# ---------------------------------------------------------------- decorative punctuation


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("Polished copper.", "polished copper"),
        ("matte black rubber!", "matte black rubber"),
        ("walnut?!", "walnut"),
        ("• satin nickel", "satin nickel"),
        ("> glossy red plastic", "glossy red plastic"),
        ("\u201cbrushed brass\u201d", "brushed brass"),
        ("'rough concrete'.", "rough concrete"),
        ("oak;", "oak"),
        ("white ceramic\u2026", "white ceramic"),
        ("1. brushed steel", "brushed steel"),
        ("12) glossy red plastic", "glossy red plastic"),
        ("(brushed steel)", "brushed steel"),
        ("walnut \u2014", "walnut"),
    ],
)
def test_decorative_punctuation_is_dropped_silently(lexicon, text, meaning):
    result, look = compiled(lexicon, text)
    assert look == compiled(lexicon, meaning)[1]
    assert not result.diagnostics


def test_punctuation_alone_is_still_an_error(lexicon):
    for text in ("?", "...", "- -", "3.5 oak", "12"):
        result = compile_source(text, "wf.cnl", lexicon)
        assert not result.ok and all(d.span is not None for d in result.diagnostics), text


# ---------------------------------------------------------------- speed: only unknown words


def test_known_words_never_reach_word_formation():
    lexicon = load_lexicon()
    tagger = Tagger(lexicon)
    for line in ("brushed aluminum", "glossy red plastic", "white varnished oak"):
        tagger.tag_line(line, 1, 0)
    assert lexicon.caches.word_formation is None
    tagger.tag_line("semi-glossy plastic", 1, 0)
    engine = lexicon.caches.word_formation
    assert engine is not None and "semi-glossy" in engine.memo


def test_a_reading_is_remembered(lexicon):
    tagger = Tagger(lexicon)
    first = tagger.tag_line("unpolished brass", 1, 0)
    engine = tagger.formation()
    remembered = engine.memo["unpolished"]
    second = tagger.tag_line("unpolished brass", 1, 0)
    assert engine.memo["unpolished"] is remembered
    assert [t.candidates for t in first[0]] == [t.candidates for t in second[0]]


# ---------------------------------------------------------------- rules as data in any lexicon


def test_a_user_lexicon_brings_its_own_rules(tmp_path: Path):
    (tmp_path / "word_formation.toml").write_text(
        '[negation]\nwords = ["nie"]\n\n[[prefix]]\nforms = ["mezzo"]\nadverb = "somewhat"\ndoc = "mezzo-X: X at three quarters"\n',
        encoding="utf-8",
    )
    lexicon = load_lexicon([tmp_path])
    assert_reads_as(lexicon, "nie glossy plastic", "matte plastic", "opposite of 'glossy'")
    assert_reads_as(lexicon, "mezzo-matte plastic", "somewhat matte plastic", "somewhat matte")
    assert_reads_as(lexicon, "unpolished brass", "rough brass", "opposite")  # the stdlib's rules still apply


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[negation]\nwordz = []\n", "unknown field 'wordz'"),
        ('[[prefix]]\nforms = ["x"]\nadverb = "hugely"\ndoc = "d"\n', "no adverb named 'hugely'"),
        ('[[suffix]]\nforms = ["ish"]\nreads_as = ["VERB"]\ndoc = "d"\n', "VERB"),
        ("[compounds]\nsplit = 1\n", "expected true or false"),
        ('[wordnet]\nadjectives = ["sparkly-ish"]\n', "no adjective named 'sparkly-ish'"),
        ('[wordnet]\nnoun_roots = { rock = "rocc" }\n', "no noun named 'rocc'"),
        ('[wordnet]\nfile = "nope.toml"\n', "no file 'nope.toml'"),
    ],
)
def test_bad_rules_name_file_line_and_column(tmp_path: Path, text, message):
    (tmp_path / "word_formation.toml").write_text(text, encoding="utf-8")
    with pytest.raises(LexiconError) as caught:
        load_lexicon([tmp_path])
    assert "word_formation.toml:" in str(caught.value) and message in str(caught.value)


def test_an_object_names_a_noun(tmp_path: Path):
    (tmp_path / "objects.toml").write_text(
        '[spoon]\nmaterial = "unobtainium"\ndoc = "d"\nexample = "silver spoon"\nsource = "s"\n', encoding="utf-8"
    )
    with pytest.raises(LexiconError, match="no noun named 'unobtainium'"):
        load_lexicon([tmp_path])


def test_every_object_and_rule_reading_is_a_note_never_a_warning(lexicon):
    for key, entry in lexicon.all_of("objects").items():
        result, _look = compiled(lexicon, entry.get("example"))
        assert notes(result), key


# ---------------------------------------------------------------- everyday adjectives (adjectives_everyday.toml)


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("chromed brass", "chrome"),  # plating words take the plated metal's optics
        ("gilded plaster", "gold"),
        ("tinned copper", "tin"),
    ],
)
def test_plating_words_show_the_plated_metal(lexicon, text, meaning):
    _r, look = compiled(lexicon, text)
    _r, metal = compiled(lexicon, meaning)
    assert look["model"]["base"] == "conductor"
    assert look["params"]["f0"] == metal["params"]["f0"]


def test_shape_words_are_accepted_and_change_no_value(lexicon):
    for word in ("embossed", "perforated", "quilted", "corrugated"):
        assert compiled(lexicon, f"{word} leather")[1] == compiled(lexicon, "leather")[1], word


def test_stone_finishes_are_ordered_by_roughness(lexicon):
    r = {
        w: compiled(lexicon, f"{w} granite")[1]["params"]["roughness"]
        for w in ("polished", "honed", "tumbled", "flamed")
    }
    assert r["polished"] < r["honed"] < r["tumbled"] < r["flamed"]


def test_everyday_colour_names_the_survey_lacks(lexicon):
    for text in ("cognac suede", "oxblood leather", "off-black rubber", "jet black plastic"):
        result, _look = compiled(lexicon, text)
        assert result.ok, text


# ---------------------------------------------------------------- over the data: every opposite, every object


def look_of(lexicon, text):
    result = compile_source(text, "wf.cnl", lexicon)
    assert result.ok, (text, [d.message for d in result.diagnostics])
    (material,) = result.ir["materials"]
    warnings = sorted(d.code for d in result.diagnostics if d.severity is Severity.WARNING)
    return {k: material[k] for k in ("model", "params", "maps")}, warnings


def test_every_declared_opposite_is_what_not_and_un_read(lexicon):
    for key, entry in lexicon.all_of("adjectives").items():
        opposite = entry.get("opposite")
        if opposite is None or " " in key:
            continue
        expected = look_of(lexicon, f"{opposite} plastic")
        for text in (f"not {key} plastic", f"non-{key} plastic"):
            assert look_of(lexicon, text) == expected, (text, opposite)


def test_every_object_after_a_noun_is_that_noun_and_alone_its_material(lexicon):
    for key, entry in lexicon.all_of("objects").items():
        for form in (key, *entry.get("aliases", ())):
            if " " in form or lexicon.lookup((form,)) != [entry]:
                continue  # multi-word forms and words with other readings are tested above
            drawn = f" with {entry.get('feature')}" if entry.get("feature") else ""  # 'copper tiles': laid, with grout
            sheet = "metal" in (entry.get("sheet_classes") or ())  # 'copper splashback': one sheet, no grout
            assert look_of(lexicon, f"copper {form}") == look_of(lexicon, "copper" if sheet else f"copper{drawn}"), form
            assert look_of(lexicon, form) == look_of(lexicon, f"{entry.get('material')}{drawn}"), form


# ---------------------------------------------------------------- resemblance ([resemblance], cnlmc.resemblance)


def apparent_colour(lexicon, noun):
    """A noun's apparent colour by the rule the notes state: base colour, for a metal x f0."""
    entry = lexicon.entry("nouns", noun)
    f0 = entry.get("f0") or [1.0, 1.0, 1.0]
    return [min(1.0, b * f) for b, f in zip(entry.get("base_color"), f0)]


def oklab_distance(x, y):
    from cnlmc.colour import linear_to_oklab

    return sum((p - q) ** 2 for p, q in zip(linear_to_oklab(x), linear_to_oklab(y))) ** 0.5


def ladder_word(lexicon, noun):
    """The adjective the surface ladder of the rules gives the noun's roughness."""
    ladder = next(
        layer["resemblance"]["surface"] for layer in lexicon.word_formation if layer["resemblance"]["surface"]
    )
    roughness = lexicon.entry("nouns", noun).get("roughness")
    return next(a for top, a in ladder if roughness <= top)


@pytest.mark.parametrize(
    ("text", "noun", "material"),
    [
        ("zincy rubber", "zinc", "rubber"),  # a metal lends its colour (base x f0), not its metal-ness
        ("titaniumish rubber", "titanium", "rubber"),
        ("nickel-like velvet", "nickel", "velvet"),
        ("chromish rubber", "chrome", "rubber"),
        ("titanium-colored velvet", "titanium", "velvet"),  # a colour form: the colour, whatever the class
        ("titanium colored velvet", "titanium", "velvet"),  # spaced
        ("zinc coloured rubber", "zinc", "rubber"),
        ("zinc toned rubber", "zinc", "rubber"),
        ("milk-coloured rubber", "milk", "rubber"),
        ("stainless-like rubber", "steel", "rubber"),
        ("titanium like velvet", "titanium", "velvet"),  # spaced  # a WordNet noun: stainless is a kind of steel
    ],
)
def test_a_noun_as_a_describing_word_lends_its_apparent_colour(lexicon, text, noun, material):
    result, look = compiled(lexicon, text)
    _plain, plain = compiled(lexicon, material)
    assert look["model"] == plain["model"], text  # the material stays itself: no metal paint
    assert oklab_distance(look["params"]["base_color"], apparent_colour(lexicon, noun)) < 0.06, text
    assert oklab_distance(plain["params"]["base_color"], apparent_colour(lexicon, noun)) > 0.06, text  # it changed
    assert any(noun in n for n in notes(result)), notes(result)


@pytest.mark.parametrize(
    ("word", "noun"),
    [
        ("leathery", "leather"),
        ("rubbery", "rubber"),
        ("glassy", "glass"),
        ("feltish", "felt"),
        ("suede-like", "suede"),
        ("plasticky", "plastic"),  # a doubled final consonant is undone (plastic + k + y)
        ("rubber like", "rubber"),  # spaced
    ],
)
def test_a_surface_class_noun_lends_its_surface(lexicon, word, noun):
    """A fabric, leather, glass, rubber or plastic is known by its surface: the ladder's word for its roughness."""
    assert_reads_as(lexicon, f"{word} ceramic", f"{ladder_word(lexicon, noun)} ceramic", noun)


def test_surface_resemblance_follows_roughness(lexicon):
    _r, glassy = compiled(lexicon, "glassy ceramic")
    _r, leathery = compiled(lexicon, "leathery ceramic")
    assert glassy["params"]["roughness"] < leathery["params"]["roughness"]


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("nickel finish brass", "nickel plated brass"),  # a metal finish is a plating
        ("chrome finished aluminum", "chrome plated aluminum"),
        ("gold finish plastic", "gold plated plastic"),  # a metal that names a colour too: still a plating
        ("gold finish ceramic", "gold ceramic"),  # where plating does not apply: its colour
        ("enamel coat finish copper", "copper with an enamel coat"),  # a coat named as the finish
        ("glossy red powder coat finish aluminum", "aluminum with a glossy red powder coat"),
        ("cherry finish pine", "cherry-coloured pine"),  # a noun that is a colour too: its colour
        ("cream coloured ceramic", "cream ceramic"),  # a colour word before 'coloured': the colour
    ],
)
def test_a_finish_or_colour_head_after_a_noun_is_not_a_second_material(lexicon, text, meaning):
    assert_reads_as(lexicon, text, meaning)


def test_a_non_metal_finish_is_its_colour(lexicon):
    result, look = compiled(lexicon, "limestone finish plywood")
    assert oklab_distance(look["params"]["base_color"], apparent_colour(lexicon, "limestone")) < 0.06
    assert any("limestone" in n for n in notes(result))


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('[resemblance]\nsurface = [[0.5, "shinyish"]]\n', "no adjective named 'shinyish'"),
        ('[resemblance]\nsurface = [[0.8, "matte"], [0.2, "glossy"]]\n', "rising roughness"),
        ('[resemblance]\nfinish_adjectives = { metal = "platted" }\n', "no adjective named 'platted'"),
        ("[resemblance]\nform = []\n", "unknown field 'form'"),
    ],
)
def test_bad_resemblance_rules_name_file_line_and_column(tmp_path: Path, text, message):
    (tmp_path / "word_formation.toml").write_text(text, encoding="utf-8")
    with pytest.raises(LexiconError) as caught:
        load_lexicon([tmp_path])
    assert "word_formation.toml:" in str(caught.value) and message in str(caught.value)


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("steely grey ceramic", "steel grey ceramic"),  # resembling word + colour word = a named colour
        ("steely blue plastic", "steel blue plastic"),
        ("icy blue plastic", "ice blue plastic"),  # ic + e: a two-letter stem plus its ending
        ("tan colour leather", "tan leather"),  # spaced colour heads
        ("sand tone fabric", "sand fabric"),
        ("satin chrome finish brass", "chrome plated satin brass"),  # the plating moves before the describing words
        ("lightly brushed nickel finish steel", "nickel plated lightly brushed steel"),
    ],
)
def test_resembling_words_with_colour_words_and_finishes_after_describing_words(lexicon, text, meaning):
    assert_reads_as(lexicon, text, meaning)


def test_a_metal_tone_is_its_colour_not_a_metal(lexicon):
    result, look = compiled(lexicon, "titanium tone plastic")
    _plain, plastic = compiled(lexicon, "plastic")
    assert look["model"] == plastic["model"]
    assert oklab_distance(look["params"]["base_color"], apparent_colour(lexicon, "titanium")) < 0.06


def test_tiles_are_drawn_laid_with_grout_lines(lexicon):
    """objects.toml `feature`: 'terracotta tiles' is terracotta with the tiles graph's grid, as
    'terracotta with grout'; a material with a colour pattern of its own keeps it and shows the
    joints in relief (`patterned_feature`: 'marble tiles' = marble's veins, the tiles' normal)."""
    tiles, _ = compiled(lexicon, "terracotta tiles")
    plain, _ = compiled(lexicon, "terracotta")
    graphs = {m.get("graph") for m in tiles.materials[0]["maps"].values()}
    assert "tiles" in graphs and "tiles" not in {m.get("graph") for m in plain.materials[0]["maps"].values()}
    assert "read 'tiles' as laid tiles: with grout" in notes(tiles)
    marble_tiles, _ = compiled(lexicon, "marble tiles")
    marble, _ = compiled(lexicon, "marble")
    laid = marble_tiles.materials[0]["maps"]
    assert laid["base_color"] == marble.materials[0]["maps"]["base_color"]  # the veins stay
    assert laid["normal"]["graph"] == "tiles" and "read 'tiles' as laid tiles: with joints" in notes(marble_tiles)


@pytest.mark.parametrize(
    ("said", "same_as"),
    [("sandstone pavers", "sandstone"), ("wool blend", "wool"), ("anthracite grey paint", "charcoal grey paint")],
)
def test_trade_words_read_as_the_material(lexicon, said, same_as):
    """A paver is a shape (objects_building.toml), a blend names its fibre (a head word), anthracite
    grey is the survey's charcoal grey."""
    assert look_of(lexicon, said) == look_of(lexicon, same_as)


def test_primed_is_a_flat_off_white_undercoat(lexicon):
    primed, _ = compiled(lexicon, "primed MDF")
    p = primed.materials[0]["params"]
    assert p["roughness"] >= 0.8 and min(p["base_color"]) > 0.7 and not primed.materials[0]["maps"]


def test_chalk_paint_is_paint_not_chalk_and_flatter_than_matte_paint(lexicon):
    chalky, _ = compiled(lexicon, "sage green chalk paint")
    matte, _ = compiled(lexicon, "sage green matte paint")
    c, m = chalky.materials[0], matte.materials[0]
    assert c["params"]["base_color"] == m["params"]["base_color"]
    assert c["model"]["diffuse"] == "oren_nayar" and c["model"]["base"] == "diffuse"


def test_moody_is_darker_and_greyer_and_moodier_a_step_of_it(lexicon):
    from cnlmc.colour import linear_to_oklab

    def lch(text):
        result, _ = compiled(lexicon, text)
        L, a, b = linear_to_oklab(result.materials[-1]["params"]["base_color"])
        return L, (a * a + b * b) ** 0.5

    plain, moody, moodier = lch("green paint"), lch("moody green paint"), lch("green paint\nmoodier")
    assert moody[0] < moodier[0] < plain[0] and moody[1] < moodier[1] < plain[1]


@pytest.mark.parametrize(
    ("said", "same_as"),
    [("absolute black granite", "black granite"), ("peeling paint", "distressed paint")],
)
def test_stone_and_paint_trade_words(lexicon, said, same_as):
    assert look_of(lexicon, said) == look_of(lexicon, same_as)


def test_leathered_stone_is_rougher_than_honed_and_has_a_relief(lexicon):
    leathered, _ = compiled(lexicon, "leathered granite")
    honed, _ = compiled(lexicon, "honed granite")
    lm, hm = leathered.materials[0], honed.materials[0]
    assert lm["params"]["roughness"] > hm["params"]["roughness"] and "normal" in lm["maps"]


def test_a_slash_between_materials_is_or_and_in_a_fraction_a_size(lexicon):
    slash = compile_source("copper/brass", "wf.cnl", lexicon)
    spelled = compile_source("copper or brass", "wf.cnl", lexicon)
    assert len(slash.materials) == 2
    assert [m["params"] for m in slash.materials] == [m["params"] for m in spelled.materials]
    assert look_of(lexicon, "3/4 inch oak plywood") == look_of(lexicon, "oak plywood")


def test_corten_is_steel_under_a_nearly_whole_rust(lexicon):
    corten, _ = compiled(lexicon, "corten steel")
    maps = corten.materials[0]["maps"]
    assert maps["base_color"]["graph"] == "rust" and maps["base_color"]["params"]["coverage"] > 0.9
    assert look_of(lexicon, "Weathering Steel (Corten)")[0]["maps"]["base_color"]["graph"] == "rust"


def test_smoked_plastic_is_transparent_grey_and_duck_egg_is_the_survey_colour(lexicon):
    smoked, _ = compiled(lexicon, "smoked acrylic")
    assert smoked.materials[0]["model"]["base"] == "glass"
    assert look_of(lexicon, "duck-egg paint") == look_of(lexicon, "duck egg blue paint")
    assert look_of(lexicon, "sort of a dusty blue paint") == look_of(lexicon, "somewhat dusty blue paint")
