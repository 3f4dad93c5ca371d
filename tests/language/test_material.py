"""The typed IR (cnlmc.material): from_ir validates once, to_ir gives back exactly the JSON it came from."""

import copy
import dataclasses
import json
from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.material import Coat, Document, Material, Params

ROOT = Path(__file__).resolve().parents[2]
GOLDEN_IR = sorted((Path(__file__).parent / "golden").glob("*.ir.json")) + [
    ROOT / "tests/exchange/golden/input.ir.json"
]
EXAMPLES = sorted((ROOT / "examples").glob("*.cnl"))


@pytest.mark.parametrize("path", GOLDEN_IR, ids=lambda p: p.name)
def test_golden_ir_round_trips(path):
    ir = json.loads(path.read_text())
    assert Document.from_ir(ir).to_ir() == ir


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_ir_round_trips_in_order(path):
    ir = compile_source(path.read_text(), path.name, lexicon_for()).ir
    back = Document.from_ir(ir).to_ir()
    assert back == ir
    assert json.dumps(back) == json.dumps(ir)  # key order too


def test_absent_params_hold_the_table_default():
    m = Material.from_ir(compile_source("weathered concrete", "x.cnl").ir["materials"][0])
    assert m.model.base == "diffuse" and "ior" not in m.params.present
    assert m.params.ior == Params.ior == 1.5 and m.params.alpha_convention == "squared"


def test_hand_written_material_gets_derived_alpha():
    m = Material.from_ir(
        {
            "model": {"base": "conductor", "distribution": "ggx", "anisotropic": False, "coat": True, "diffuse": None},
            "params": {"roughness": 0.4, "coat": {"roughness": 0.1}},
        }
    )
    assert m.params.alpha == pytest.approx((0.16, 0.16))
    assert isinstance(m.params.coat, Coat) and m.params.coat.alpha == pytest.approx((0.01, 0.01))


def test_records_are_frozen_and_replace_changes_the_key():
    m = Document.from_ir(compile_source("steel\noak", "x.cnl").ir).materials[0]
    with pytest.raises(dataclasses.FrozenInstanceError):
        m.params.ior = 2.0  # type: ignore[misc]
    with pytest.raises(TypeError):
        m.maps["x"] = None  # type: ignore[index]
    changed = dataclasses.replace(m, params=dataclasses.replace(m.params, roughness=0.9))
    assert changed.key != m.key
    assert dataclasses.replace(m, name="other").key == m.key


def test_to_ir_gives_fresh_containers():
    doc = Document.from_ir(compile_source("oak with a glossy white varnish", "x.cnl").ir)
    ir = doc.to_ir()
    ir["materials"][0]["provenance"]["base_color"][0]["words"].append("x")
    assert doc.to_ir() != ir


def _broken(path_fn):
    ir = copy.deepcopy(json.loads(GOLDEN_IR[0].read_text()))
    path_fn(ir)
    return ir


@pytest.mark.parametrize(
    "break_it, message",
    [
        (
            lambda ir: ir["materials"][0]["params"].__setitem__("ior", "x"),
            "materials[0].params.ior: expected a number in [1, 5], got 'x'",
        ),
        (
            lambda ir: ir["materials"][0]["params"].__setitem__("roughness", 2.0),
            "materials[0].params.roughness: expected a number in [0, 1], got 2.0",
        ),
        (
            lambda ir: ir["materials"][0]["params"].__setitem__("base_color", [1, 2]),
            "materials[0].params.base_color: expected a list of 3 numbers",
        ),
        (
            lambda ir: ir["materials"][0]["model"].__setitem__("base", "metal"),
            "materials[0].model.base: expected one of",
        ),
        (
            lambda ir: ir["materials"][0]["params"].__setitem__("alpha_convention", "cubed"),
            "materials[0].params.alpha_convention",
        ),
        (lambda ir: ir["materials"][0].__setitem__("maps", {"bump": {}}), "materials[0].maps role: expected one of"),
        (lambda ir: ir.__setitem__("ir_version", 2), "ir_version: expected 1, got 2"),
        (
            lambda ir: ir["materials"][0]["params"].__setitem__("sheen", 0.5),
            "materials[0].params.sheen: not a parameter of the table",
        ),
        (lambda ir: ir.pop("materials"), "materials: missing"),
    ],
)
def test_malformed_ir_is_rejected_naming_the_path(break_it, message):
    ir = _broken(break_it)
    with pytest.raises(ValueError) as err:
        Document.from_ir(ir)
    assert str(err.value).startswith(message)


def test_result_types_its_ir_once():
    result = compile_source("brushed steel", "x.cnl")
    assert result.document is result.document  # built on first use, kept
    assert result.document.to_ir() == result.ir
    assert result.source_document is not None and result.source_document.items
