"""Every IR the compiler writes validates against the schema in the repo (compiler/ir_schema.json)."""

import json
from importlib import resources

import jsonschema
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for

from .golden_cases import CASES

SCHEMA = json.loads(resources.files("cnlmc").joinpath("ir_schema.json").read_text())
VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)


@pytest.mark.parametrize("name", sorted(CASES))
def test_golden_phrases_validate(name):
    VALIDATOR.validate(compile_source(CASES[name], "x.cnl").ir)


def test_every_lexicon_example_validates():
    lexicon = lexicon_for()
    for category in ("nouns", "adjectives", "colours", "coats"):
        for entry in lexicon.all_of(category).values():
            VALIDATOR.validate(compile_source(entry.get("example"), "x.cnl", lexicon).ir)


def test_schema_rejects_a_broken_ir():
    ir = compile_source("steel", "x.cnl").ir
    ir["materials"][0]["params"]["roughness"] = 2.0
    with pytest.raises(jsonschema.ValidationError):
        VALIDATOR.validate(ir)


@settings(max_examples=60, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("abcdefghilmnoprstuvwy ,\n")), max_size=80))
def test_ir_of_any_text_validates(text):
    VALIDATOR.validate(compile_source(text, "x.cnl").ir)
