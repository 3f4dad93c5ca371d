"""More languages (the paper's future work, and its own language): the German overlay `de`.

Vocabulary, closed-class words and inflection rules are data in stdlib/overlays/de; the
grammar is the same file. The paper's worked examples hold number for number in German.
"""

import pytest

from cnlmc.api import Session, compile_source, lexicon_for

from .conftest import first


@pytest.fixture(scope="module")
def de():
    return lexicon_for(("de",))


@pytest.fixture(scope="module")
def paper_de():
    return lexicon_for(("paper", "de"))


def material(text, lexicon):
    return first(compile_source(text, "de.cnl", lexicon))


def test_the_papers_phrase_in_german_matches_the_english(de):
    german = material("leicht gebürstetes, blau eloxiertes Aluminium", de)
    english = material("lightly brushed, blue anodized aluminum", de)
    assert german["params"] == english["params"] and german["model"] == english["model"]
    assert german["name"] == "leicht_geburstetes_blau_eloxiertes_aluminium"  # the default name keeps every word (#14)


def test_paper_numbers_in_german(paper_de):
    s = Session("blau eloxiertes Aluminium", lexicon=paper_de)
    assert s.material["params"]["roughness"] == 0.3
    assert s.refine("dunkleres Blau")["params"]["base_color"] == [0.0, 0.0, 0.5]
    assert s.refine("weniger diffus")["params"]["roughness"] == 0.2
    assert s.refine("mehr diffus")["params"]["roughness"] == 0.25


@pytest.mark.parametrize(
    "german,english",
    [
        ("weiß lackierte Eiche", "white lacquered oak"),
        ("Eiche mit einer glänzenden weißen Lasur", "oak with a glossy white varnish"),
        ("stark verrostetes Eisen", "heavily rusty iron"),
        ("poliertes Messing", "polished brass"),
        ("mattes schwarzes Gummi", "matte black rubber"),
        ("sandgestrahltes Edelstahl", "sandblasted stainless steel"),
    ],
)
def test_everyday_german_phrases(de, german, english):
    a, b = material(german, de), material(english, de)
    assert a["params"] == b["params"] and a["maps"] == b["maps"]


def test_german_alternatives_and_keywords(de):
    r = compile_source("rot oder blau eloxiertes Aluminium und poliertes Messing", "de.cnl", de)
    assert not r.ok  # 'und' joins describing groups, not two materials
    r = compile_source("Rumpf: rot oder blau eloxiertes Aluminium", "de.cnl", de)
    assert [m["variant"]["name"] for m in r.materials] == ["rot", "blau"]


def test_german_misspelling_gets_a_suggestion(de):
    d = compile_source("gebürstetes Aluminum", "de.cnl", de).ok, compile_source("gebürstetes Aluminim", "de.cnl", de)
    assert d[0]
    diag = d[1].diagnostics[0]
    assert diag.code == "E001" and "aluminium" in diag.suggestions


def test_the_english_stdlib_does_not_know_german():
    r = compile_source("poliertes Messing", "x.cnl", lexicon_for())
    assert not r.ok and r.diagnostics[0].message == "unknown word 'poliertes'"
