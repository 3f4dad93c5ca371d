"""The parameter table (cnlmc.params) is the one place a parameter is declared; the rest is derived."""

from pathlib import Path

import pytest

from cnlmc import params_doc
from cnlmc.ir import PARAMS_BY_MODEL
from cnlmc.lexicon import load_lexicon
from cnlmc.lexicon_schema import TABLE_FIELDS, Checker, LexiconError, check_entry
from cnlmc.lexicon_source import SourceText
from cnlmc.params import PARAMS, Params
from cnlmc.passes.ranges import COAT_RANGES, RANGES
from cnlmc.state import NOUN_PARAMS

ROOT = Path(__file__).resolve().parents[2]


def test_committed_schema_is_the_generated_one():
    assert (ROOT / "compiler" / "ir_schema.json").read_text() == params_doc.schema_text(), (
        "run: python -m cnlmc.params_doc"
    )


def test_docs_table_is_current():
    text = (ROOT / "docs" / "ir.md").read_text()
    assert params_doc.with_params_table(text) == text, "run: python -m cnlmc.params_doc"


def test_derived_maps_keep_their_v1_values_and_order():
    assert RANGES == {
        "roughness": (0.0, 1.0),
        "anisotropy": (0.0, 1.0),
        "diffuse_roughness": (0.0, 1.6),
        "ior": (1.0, 5.0),
        "base_color": (0.0, 1.0),
        "transmission_depth": (1e-5, 100.0),
        "sheen_color": (0.0, 1.0),
        "sheen_roughness": (0.0, 1.0),
        "flake_color": (0.0, 1.0),
        "flake_density": (0.0, 1.0),
        "flake_roughness": (0.0, 1.0),
        "flake_size": (0.00001, 0.001),
    }
    assert list(RANGES) == [
        *("roughness", "anisotropy", "diffuse_roughness", "ior", "base_color"),
        "transmission_depth",  # issue #15 item 1: a glass's colour is Beer-Lambert absorption
        *("sheen_color", "sheen_roughness"),  # issue #15 item 5: velvet's and cloth's sheen
        *("flake_color", "flake_density", "flake_roughness", "flake_size"),  # #15 item 5: paints' flakes
    ]
    assert list(COAT_RANGES.items()) == [
        ("roughness", (0.0, 1.0)),
        ("ior", (1.0, 3.0)),
        ("color", (0.0, 1.0)),
        ("thickness", (0.0, 10.0)),
    ]
    assert PARAMS_BY_MODEL == {
        "diffuse": ("base_color",),
        "dielectric": ("base_color", "roughness", "ior"),
        "conductor": ("base_color", "roughness", "eta", "k", "f0", "f82"),
        "glass": ("base_color", "roughness", "ior", "transmission_depth"),
    }
    assert NOUN_PARAMS == (
        *("base_color", "roughness", "eta", "k", "f0", "f82", "ior", "transmission_depth", "diffuse_roughness"),
        *("sheen_color", "sheen_roughness"),
    )


def test_every_row_is_documented_and_has_a_default():
    for spec in PARAMS:
        assert spec.doc and spec.kind
        assert getattr(Params(), spec.name) == spec.default


def test_the_lexicon_schema_takes_noun_ranges_from_the_table():
    assert load_lexicon().entries["nouns"]  # loads and checks the stdlib against the schema
    assert TABLE_FIELDS["params.roughness"] == {"type": "float", "range": [0.0, 1.0]}
    assert TABLE_FIELDS["params.diffuse_roughness"] == {"type": "float", "range": [0.0, 1.6]}
    assert TABLE_FIELDS["params.eta"] == {"type": "rgb"}
    assert TABLE_FIELDS["coat.thickness"] == {"type": "float", "range": [0.0, 10.0]}


def test_a_noun_out_of_the_tables_range_is_rejected_naming_the_key():
    fields = {"roughness": {"from": "params.roughness", "required": True}}
    checker = Checker(SourceText("nouns.toml", "[steel]\nroughness = 1.5\n"))
    with pytest.raises(LexiconError, match=r"nouns.toml:2:1: key 'steel.roughness': 1.5 is outside \[0, 1\]"):
        check_entry(checker, {"roughness": 1.5, "doc": "d", "example": "e"}, fields, ("steel",))
