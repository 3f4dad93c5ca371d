"""Refinement that never traps (issue #14, docs/refinement.md): sequences a person types after a
material, none of them from tests/language/everyday.toml, through cnlmc.api.Session, the
compiler and the command line."""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import Session, compile_source, lexicon_for
from cnlmc.changes import material_changes
from cnlmc.colour import linear_to_oklab
from tests.helpers import run_cnlmc

LEX = lexicon_for()


def visible_roughness(material: dict) -> float:
    """The roughness one sees: the coat's when there is one, 1.0 for a model without a highlight."""
    params = material["params"]
    if params.get("coat"):
        return float(params["coat"]["roughness"])
    if material["model"]["base"] == "diffuse":
        return 1.0
    return float(params["roughness"])


def lightness(material: dict) -> float:
    return linear_to_oklab(material["params"]["base_color"])[0]


def chroma(material: dict) -> float:
    _l, a, b = linear_to_oklab(material["params"]["base_color"])
    return math.hypot(a, b)


def lab(material: dict) -> list[float]:
    return linear_to_oklab(material["params"]["base_color"])


def warnings_of(session: Session) -> list[str]:
    return [d.code for d in session.result.diagnostics if d.severity.value == "warning"]


def notes_of(session: Session) -> list[str]:
    return [d.code for d in session.result.diagnostics if d.severity.value == "note"]


def roughness_step() -> float:
    """One step of roughness, as the lexicon declares it (properties.toml)."""
    return float(LEX.require("properties", "roughness").get("step")["value"])


# ---------------------------------------------------------------- gloss and roughness, relative to now


@pytest.mark.parametrize("phrase", ["glossy blue ceramic", "high-gloss white paint", "glossy black plastic"])
def test_less_glossy_on_a_glossy_material_is_rougher_and_never_freezes(phrase: str) -> None:
    s = Session(phrase, LEX)
    start = visible_roughness(s.material)
    after_less = visible_roughness(s.refine("less glossy"))
    assert after_less > start
    after_rougher = visible_roughness(s.refine("rougher"))
    assert after_rougher > after_less  # before #14 the bracket had collapsed: nothing moved again
    after_smoother = visible_roughness(s.refine("smoother"))
    assert after_less < after_smoother < after_rougher  # bracketed: between the last two


@pytest.mark.parametrize(
    ("phrase", "line", "way"),
    [
        ("blue ceramic", "more matte", 1),
        ("brass", "more matte", 1),
        ("white ceramic", "less glossy", 1),
        ("pine", "more glossy", -1),
        ("matte grey paint", "less matte", -1),
        ("gold", "less shiny", 1),
        ("steel", "more polished", -1),
    ],
)
def test_a_gloss_word_the_phrase_does_not_have_moves_the_current_value(phrase: str, line: str, way: int) -> None:
    try:
        s = Session(phrase, LEX)
    except ValueError:
        pytest.skip(f"{phrase!r} is not a material of this lexicon")
    before = s.material["params"].get("roughness", 1.0)
    after = s.refine(line)["params"].get("roughness", 1.0)
    assert (after - before) * way > 0, (before, after)
    assert "W104" not in warnings_of(s)


def test_a_refinement_read_relative_to_the_material_says_so_in_a_note() -> None:
    s = Session("green plastic", LEX)
    s.refine("more matte")
    (note,) = [d for d in s.result.diagnostics if d.code == "N104"]
    assert note.severity.value == "note" and "'matte' is not among its describing words" in note.message
    assert warnings_of(s) == []


def test_a_treatment_the_material_lacks_still_says_so() -> None:
    s = Session("copper", LEX)
    s.refine("more brushed")
    assert "W104" in warnings_of(s)


def test_gloss_refines_the_coat_one_sees() -> None:
    s = Session("cherry with a satin lacquer", LEX)
    base = s.material["params"]["roughness"]
    coat = s.material["params"]["coat"]["roughness"]
    after = s.refine("glossier")
    assert after["params"]["coat"]["roughness"] < coat
    assert after["params"]["roughness"] == base


def test_rougher_reaches_the_oren_nayar_sigma_of_a_diffuse_material() -> None:
    s = Session("sandstone", LEX)
    sigma = s.material["params"].get("diffuse_roughness", 0.0)
    if s.material["model"]["diffuse"] != "oren_nayar":
        pytest.skip("sandstone is not an Oren-Nayar surface in this lexicon")
    rougher = s.refine("rougher")["params"]["diffuse_roughness"]
    smoother = s.refine("smoother")["params"]["diffuse_roughness"]
    assert sigma < smoother < rougher


def test_a_with_line_adds_a_coat_that_later_lines_refine() -> None:
    s = Session("ash", LEX)
    assert not s.material["params"].get("coat")
    coated = s.refine("with a satin lacquer")
    assert coated["params"]["coat"]["name"] == "lacquer" and coated["model"]["coat"]
    before = coated["params"]["coat"]["roughness"]
    assert s.refine("glossier")["params"]["coat"]["roughness"] < before


def test_a_with_line_adds_a_feature() -> None:
    s = Session("stainless steel", LEX)
    before = s.material
    rows = material_changes(before, s.refine("with fine scratches"))
    assert any(row.strip().startswith("maps.") for row in rows), rows


def test_the_range_end_is_a_bound_so_nothing_is_clamped_and_it_comes_back() -> None:
    s = Session("polished chrome", LEX)
    values = [visible_roughness(s.material)]
    for _ in range(6):
        values.append(visible_roughness(s.refine("glossier")))
    assert all(0.0 <= v for v in values) and values == sorted(values, reverse=True)
    assert "W107" not in warnings_of(s)
    assert visible_roughness(s.refine("rougher")) > values[-1]


def test_a_value_at_its_range_end_says_so_instead_of_warning() -> None:
    s = Session("aluminum", lexicon_for(["paper"]))  # the paper's aluminum: m 0.1, one step to 0
    s.refine("more gloss")
    assert s.refine("more gloss")["params"]["roughness"] == 0.0
    assert "N106" in notes_of(s) and warnings_of(s) == []
    assert s.refine("less gloss")["params"]["roughness"] > 0.0


def test_a_user_who_keeps_asking_gets_past_the_old_bound() -> None:
    """'less', 'more', then 'more' again and again: the bracket reopens instead of freezing."""
    s = Session("satin nickel", LEX)
    start = visible_roughness(s.material)
    s.refine("less diffuse")
    values = [visible_roughness(s.refine("more diffuse")) for _ in range(8)]
    assert values == sorted(values) and len(set(values)) == len(values)  # every line moved it
    assert values[-1] > start  # past the bound the first 'less' set


def test_the_paper_bisection_is_kept_on_a_new_material() -> None:
    s = Session("satin brass", LEX)
    m0 = visible_roughness(s.material)
    m1 = visible_roughness(s.refine("smoother"))
    m2 = visible_roughness(s.refine("rougher"))
    m3 = visible_roughness(s.refine("smoother"))
    assert m1 == pytest.approx(m0 - roughness_step())
    assert m2 == pytest.approx((m0 + m1) / 2) and m3 == pytest.approx((m1 + m2) / 2)


# ---------------------------------------------------------------- adverbs on refinements


def test_adverbs_scale_a_refinement_step() -> None:
    def moved(line: str) -> float:
        s = Session("satin plastic", LEX)
        start = visible_roughness(s.material)
        return visible_roughness(s.refine(line)) - start

    assert 0 < moved("very slightly rougher") < moved("slightly rougher") < moved("rougher")
    assert moved("rougher") < moved("much rougher") < moved("very much rougher")
    assert 0 > moved("a little glossier") > moved("glossier")


def test_an_adverb_on_a_colour_step() -> None:
    plain, slight = Session("sage ceramic", LEX), Session("sage ceramic", LEX)
    start = lightness(plain.material)
    full = lightness(plain.refine("darker"))
    half = lightness(slight.refine("slightly darker"))
    assert full < half < start


# ---------------------------------------------------------------- colour refinements


def test_hue_refinements_move_the_colour_in_oklab_and_keep_its_lightness() -> None:
    s = Session("beige linen", LEX)
    start = lab(s.material)
    bluer = lab(s.refine("bluer"))
    assert bluer[2] < start[2]  # OKLab b: towards blue
    assert bluer[0] == pytest.approx(start[0], abs=0.02)
    back = lab(s.refine("yellower"))
    assert bluer[2] < back[2] < start[2] + 1e-9  # the same axis: bisected, not pushed past the start
    redder = lab(s.refine("redder"))
    assert redder[1] > back[1]  # OKLab a: towards red
    assert lab(s.refine("greener"))[1] < redder[1]


def test_warmer_and_cooler() -> None:
    s = Session("grey felt", LEX)
    start = lab(s.material)
    warm = lab(s.refine("warmer"))
    assert warm[1] > start[1] and warm[2] > start[2]  # towards orange: a and b up
    cool = lab(s.refine("cooler"))
    assert cool[2] < warm[2]


def test_a_hue_step_on_white_gives_up_a_little_lightness_for_its_hue() -> None:
    s = Session("white linoleum", LEX)
    warm = lab(s.refine("warmer"))
    assert warm[2] > 0.01 and warm[0] > 0.85  # a warm white: some yellow-orange, still light


@pytest.mark.parametrize(
    ("comparative", "plain"),
    [("more brushed steel", "brushed steel"), ("deeper green velvet", "velvet"), ("cooler white paint", "paint")],
)
def test_an_inline_comparative_keeps_the_words_the_material_needs(comparative: str, plain: str) -> None:
    """'more brushed steel' is brushed steel, more brushed (no W104); 'deeper green velvet' is green."""
    a = compile_source(comparative, "c.cnl", LEX)
    assert a.ok and not [d for d in a.diagnostics if d.severity.value == "warning"], a.diagnostics
    b = compile_source(plain, "p.cnl", LEX).materials[0]
    assert a.materials[0]["params"] != b["params"]
    assert bool(a.materials[0]["maps"]) == bool(b["maps"]) or "brushed" in comparative


def test_saturation_up_and_down_keeps_the_hue() -> None:
    s = Session("teal velvet", LEX)
    c0, h0 = chroma(s.material), math.atan2(lab(s.material)[2], lab(s.material)[1])
    c1 = chroma(s.refine("more saturated"))
    c2 = chroma(s.refine("less saturated"))
    assert c2 < c1 and c1 >= c0 - 1e-9
    assert math.atan2(lab(s.material)[2], lab(s.material)[1]) == pytest.approx(h0, abs=0.05)
    c3 = chroma(s.refine("less colour"))
    assert c3 < c2


@pytest.mark.parametrize(
    ("phrase", "line", "what"),
    [
        ("sage plastic", "richer", lambda before, after: chroma(after) > chroma(before)),
        ("sage plastic", "greyer", lambda before, after: chroma(after) < chroma(before)),
        ("grey rubber", "browner", lambda before, after: lab(after)[2] > lab(before)[2]),
        ("grey rubber", "whiter", lambda before, after: lightness(after) > lightness(before)),
    ],
)
def test_one_word_colour_refinements(phrase: str, line: str, what) -> None:
    s = Session(phrase, LEX)
    before = s.material
    assert what(before, s.refine(line))


@pytest.mark.parametrize(
    ("phrase", "line", "what"),
    [("teak", "grainier", "grain"), ("hammered brass", "bumpier", "strength"), ("rusty iron", "rustier", "coverage")],
)
def test_one_word_map_refinements(phrase: str, line: str, what: str) -> None:
    s = Session(phrase, LEX)
    before = s.material
    rows = material_changes(before, s.refine(line))
    assert any(what in row for row in rows), rows


def test_a_saturated_colour_gives_up_a_little_lightness_to_be_more_saturated() -> None:
    s = Session("scarlet velvet", LEX)
    before = s.material
    after = s.refine("more saturated")
    assert chroma(after) > chroma(before) and abs(lightness(after) - lightness(before)) <= 0.1 + 1e-9


def test_a_grey_has_no_hue_to_saturate_and_says_so() -> None:
    s = Session("white ceramic", LEX)
    before = s.material["params"]["base_color"]
    assert s.refine("more saturated")["params"]["base_color"] == before
    assert "N105" in notes_of(s) and warnings_of(s) == []


def test_more_and_less_of_a_named_colour() -> None:
    s = Session("grey concrete", LEX)
    start = lab(s.material)
    greener = lab(s.refine("more green"))
    assert greener[1] < start[1] - 0.01  # OKLab a: towards green
    less = lab(s.refine("less green"))
    assert greener[1] < less[1]
    orange = Session("orange plastic", LEX)
    before = chroma(orange.material)
    assert chroma(orange.refine("less orange")) < before


def test_less_of_a_colour_the_material_lacks_says_so() -> None:
    s = Session("white porcelain", LEX)
    before = s.material["params"]["base_color"]
    assert s.refine("less purple")["params"]["base_color"] == before
    assert "N105" in notes_of(s)


def test_a_shade_as_a_refinement_target() -> None:
    s = Session("green velvet", LEX)
    c0 = chroma(s.material)
    c1 = chroma(s.refine("more muted"))
    c2 = chroma(s.refine("less muted"))
    assert c1 < c2 and c1 < c0


def test_a_metal_is_tinted_through_its_measured_colour() -> None:
    """A metal shows base colour x f0: 'redder' gold is a rose gold; 'lighter' cannot pass f0 and says so."""
    s = Session("gold", LEX)
    seen = lambda m: [b * f for b, f in zip(m["params"]["base_color"], m["params"]["f0"])]
    before = linear_to_oklab(seen(s.material))
    after = linear_to_oklab(seen(s.refine("redder")))
    assert after[1] > before[1] + 0.01  # OKLab a of what one sees: towards red
    plain = Session("silver", LEX)
    plain.refine("lighter")
    assert "N106" in notes_of(plain) and warnings_of(plain) == []


def test_axes_do_not_pull_each_other_back() -> None:
    """'darker', then 'bluer', then 'lighter': the lightness bracket is forgotten once the colour
    moved on another axis, so 'lighter' is a step up, not back to the old bound's midpoint."""
    s = Session("tan leather", LEX)
    dark = lightness(s.refine("darker"))
    s.refine("bluer")
    assert lightness(s.refine("lighter")) > dark


# ---------------------------------------------------------------- inline comparatives


@pytest.mark.parametrize(
    ("comparative", "plain", "measure", "way"),
    [
        ("glossier black plastic", "black plastic", visible_roughness, -1),
        ("less shiny chrome", "chrome", visible_roughness, 1),
        ("rougher slate", "slate", visible_roughness, 1),
        ("darker maple", "maple", lightness, -1),
        ("slightly lighter walnut", "walnut", lightness, 1),
        ("more saturated sage velvet", "sage velvet", chroma, 1),
    ],
)
def test_an_inline_comparative_is_the_material_then_one_step(comparative, plain, measure, way) -> None:
    a = compile_source(comparative, "c.cnl", LEX)
    b = compile_source(plain, "p.cnl", LEX)
    assert a.ok and b.ok, [d.message for d in a.diagnostics]
    assert (measure(a.materials[0]) - measure(b.materials[0])) * way > 0


@pytest.mark.parametrize("phrase", ["lighter grain oak", "darker colour walnut", "matter black plastic"])
def test_a_comparative_before_a_property_word_compiles(phrase: str) -> None:
    result = compile_source(phrase, "x", LEX)
    assert result.ok and not [d for d in result.diagnostics if d.severity.value == "warning"], result.diagnostics


def test_less_of_a_colour_before_a_material_takes_it_from_the_material() -> None:
    """'less red brick' is brick with less red, not red brick; 'deeper blue velvet' is blue velvet."""
    brick = compile_source("brick", "x", LEX).materials[0]
    less_red = compile_source("less red brick", "x", LEX).materials[0]
    assert lab(less_red)[1] < lab(brick)[1]
    velvet = compile_source("velvet", "x", LEX).materials[0]
    deeper_blue = compile_source("deeper blue velvet", "x", LEX).materials[0]
    assert lab(deeper_blue)[2] < lab(velvet)[2] - 0.05


def test_slightly_is_between_the_material_and_its_comparative() -> None:
    base, slight, full = (
        lightness(compile_source(p, "x", LEX).materials[0]) for p in ("cedar", "slightly darker cedar", "darker cedar")
    )
    assert full < slight < base


def test_a_comparative_first_line_then_the_opposite_bisects() -> None:
    s = Session("darker maple", LEX)
    plain = lightness(compile_source("maple", "x", LEX).materials[0])
    dark = lightness(s.material)
    back = lightness(s.refine("lighter"))
    assert dark < back < plain  # the first line's step is on the same bracket


def test_brighter_keeps_the_hue() -> None:
    s = compile_source("brighter green plastic", "x", LEX).materials[0]
    g = compile_source("green plastic", "x", LEX).materials[0]
    h = lambda m: math.degrees(math.atan2(lab(m)[2], lab(m)[1]))
    assert lightness(s) > lightness(g) and h(s) == pytest.approx(h(g), abs=3)


# ---------------------------------------------------------------- map refinements are changes


@pytest.mark.parametrize(
    ("phrase", "line", "what"),
    [
        ("maple", "finer", "maps.base_color.scale"),
        ("cherry", "lower contrast", "maps.base_color.contrast"),
        ("rusty steel", "less rust", "coverage"),
        ("green marble", "more veins", "maps.base_color.scale"),
        ("grey granite", "fewer speckles", "maps.base_color.contrast"),
        ("steel with fine scratches", "more scratches", "coverage"),
        ("walnut", "bolder grain", "grain"),
    ],
)
def test_a_map_refinement_is_reported_as_a_change(phrase: str, line: str, what: str) -> None:
    s = Session(phrase, LEX)
    before = s.material
    rows = material_changes(before, s.refine(line))
    assert any(what in row for row in rows), rows


def test_veins_are_the_marbles_not_the_woods() -> None:
    s = Session("ash", LEX)
    s.refine("fewer veins")
    (w106,) = [d for d in s.result.diagnostics if d.code == "W106"]
    assert "marble" in w106.message


def test_changes_name_the_coat() -> None:
    s = Session("oak with a gloss varnish", LEX)
    before = s.material
    rows = material_changes(before, s.refine("duller"))
    assert any("coat.roughness" in row for row in rows), rows


# ---------------------------------------------------------------- property: never trapped

ROUGHER = ["rougher", "duller", "less glossy", "more matte", "less shiny", "less polished"]
SMOOTHER = ["smoother", "glossier", "shinier", "more glossy", "less matte", "more polished"]
MATERIALS = [
    "satin plastic",
    "blue ceramic",
    "brass",
    "glossy red paint",
    "matte black rubber",
    "maple with a clear coat",
]


@settings(max_examples=25, deadline=None, derandomize=True)
@given(st.sampled_from(MATERIALS), st.lists(st.tuples(st.booleans(), st.integers(0, 5)), min_size=1, max_size=7))
def test_every_gloss_line_moves_the_visible_roughness_its_way(material: str, lines: list[tuple[bool, int]]) -> None:
    s = Session(material, LEX)
    for up, index in lines:
        line = (ROUGHER if up else SMOOTHER)[index]
        before = visible_roughness(s.material)
        after = visible_roughness(s.refine(line))
        at_end = (up and before >= 1.0) or (not up and before <= 0.0)
        assert at_end or (after - before) * (1 if up else -1) > 0, (material, line, before, after)
    assert "W107" not in warnings_of(s)


# ---------------------------------------------------------------- the command line


def test_the_cli_compiles_a_refinement_file_with_a_note_and_no_warning(tmp_path) -> None:
    source = tmp_path / "plastic.cnl"
    source.write_text("lighter sage plastic\nless glossy\nslightly rougher\nbluer\n")
    proc = run_cnlmc("compile", str(source))
    assert proc.returncode == 0, proc.stderr
    assert "note[N104]" in proc.stderr and "warning" not in proc.stderr and "Traceback" not in proc.stderr
    (material,) = json.loads(proc.stdout)["materials"]
    plain = compile_source("sage plastic", "x", LEX).materials[0]
    assert material["params"]["roughness"] > plain["params"]["roughness"]
    assert lightness(material) > lightness(plain)


COLOUR_LINES = {
    "darker": (lightness, -1),
    "lighter": (lightness, 1),
    "brighter": (lightness, 1),
    "slightly darker": (lightness, -1),
    "more saturated": (chroma, 1),
    "less saturated": (chroma, -1),
    "richer": (chroma, 1),
    "greyer": (chroma, -1),
}
COLOURED = ["sage ceramic", "tan leather", "teal velvet", "brick red paint", "navy wool", "mustard plastic"]


@settings(max_examples=25, deadline=None, derandomize=True)
@given(st.sampled_from(COLOURED), st.lists(st.sampled_from(sorted(COLOUR_LINES)), min_size=1, max_size=6))
def test_every_colour_line_moves_its_quantity_its_way_or_says_why(material: str, lines: list[str]) -> None:
    s = Session(material, LEX)
    for line in lines:
        measure, way = COLOUR_LINES[line]
        before = measure(s.material)
        after = measure(s.refine(line))
        said = [d.code for d in s.result.diagnostics if d.span and d.span.line == len(s.lines)]
        assert (after - before) * way > 1e-6 or "N106" in said or "N105" in said, (material, lines, line)
    assert "W107" not in warnings_of(s)


def test_the_live_session_reports_map_changes_and_its_notes(gl_available, tmp_path) -> None:
    """`cnlmc preview FILE --interactive`: a map refinement prints the map's change; a reading
    relative to the material prints its note; nothing says 'no parameter changed'."""
    material = tmp_path / "oak.cnl"
    material.write_text("oak\n")
    out = tmp_path / "oak.png"
    proc = run_cnlmc(
        "preview", str(material), "-o", str(out), "--size", "32", "--interactive", stdin="more grain\nmore matte\n"
    )
    assert proc.returncode == 0, proc.stderr
    assert "maps.base_color.grain" in proc.stdout and "note[N104]" in proc.stdout
    assert "no parameter changed" not in proc.stdout and "Traceback" not in proc.stderr


HUE_LINES = {"bluer": "blue", "yellower": "yellow", "redder": "red", "greener": "green", "pinker": "pink"}


@pytest.mark.parametrize("colour", ["bright green", "red", "sky blue", "mustard", "grey", "lavender"])
@pytest.mark.parametrize("line", sorted(HUE_LINES))
def test_a_hue_step_moves_towards_its_hue_from_any_colour(colour: str, line: str) -> None:
    """The colour's OKLab a, b along the named hue grows, even past that colour's own chroma."""
    s = Session(f"{colour} plastic", LEX)
    target = linear_to_oklab(LEX.require("colours", HUE_LINES[line]).get("rgb"))
    norm = math.hypot(target[1], target[2])

    def along() -> float:
        _l, a, b = lab(s.material)
        return (a * target[1] + b * target[2]) / norm

    before = along()
    s.refine(line)
    said = [d.code for d in s.result.diagnostics if d.span and d.span.line == 2]
    assert along() > before + 1e-4 or "N106" in said
