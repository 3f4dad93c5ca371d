"""Hostile names and phrases cannot break or inject into MaterialX, USD or Mitsuba output."""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET

import pytest

from cnlmc.api import emit
from cnlmc.backends.exchange.naming import identifier, unique_identifiers, xml_text
from tests.helpers import require

from .conftest import ir_of, write_artifacts

HOSTILE = [
    'evil" injected="1',
    '</bsdf><bsdf type="diffuse" id="pwn"/><!--',
    "a & b < c > d",
    "]]><![CDATA[ x",
    "*/ /* -- --> <!-- ",
    "line one\nline two\r\n\tthree",
    "ünïcödé 漢字 ✨ émoji 🙂",
    "nul\x00 and escape\x1b[31m",
    '""" triple """ quotes \'\'\' @asset@ </Root> #usda 1.0',
    "9 starts with a digit",
    "",
]


def hostile_ir(phrase: str, source: str = "lightly brushed, blue anodized aluminum") -> dict:
    ir = copy.deepcopy(ir_of(source))
    for material in ir["materials"]:
        material["phrase"] = phrase
        material["name"] = phrase + material["name"][-3:]
    return ir


@pytest.mark.parametrize("text", HOSTILE)
def test_identifiers_are_valid(text):
    ident = identifier(text)
    assert ident and (ident[0].isalpha() or ident[0] == "_")
    assert all(c.isascii() and (c.isalnum() or c == "_") for c in ident)


def test_identifiers_stay_unique():
    names = unique_identifiers(["a b", "a-b", "a_b", "a b"])
    assert len(set(names)) == 4


@pytest.mark.materialx
@pytest.mark.parametrize("phrase", HOSTILE)
def test_materialx(phrase, mx_library):
    mx = require("MaterialX", "materialx")

    ir = hostile_ir(phrase)
    xml = emit(ir, "materialx", {"maps": "none"}).artifacts[0].content
    ET.fromstring(xml.encode("utf-8"))
    doc = mx.createDocument()
    mx.readFromXmlString(doc, xml)
    doc.setDataLibrary(mx_library)
    assert doc.validate()[0]
    materials = doc.getMaterialNodes()
    assert len(materials) == 1 and not doc.getChild("pwn")
    assert materials[0].getDocString().split() == xml_text(phrase).split()


@pytest.mark.usd
@pytest.mark.parametrize("phrase", HOSTILE)
def test_usd(phrase, tmp_path):
    Usd = require("pxr.Usd", "usd")

    ir = hostile_ir(phrase, "red or green glass")
    write_artifacts(emit(ir, "usd", {"maps": "none", "mesh": "sphere"}).artifacts, tmp_path)
    stage = Usd.Stage.Open(str(tmp_path / "materials.usda"))
    (prim,) = stage.GetDefaultPrim().GetChild("Looks").GetChildren()
    assert prim.GetCustomDataByKey("cnlmc:phrase") == xml_text(phrase)
    assert prim.GetMetadata("documentation") == xml_text(phrase)
    assert len(prim.GetVariantSets().GetVariantSet("material").GetVariantNames()) == 2
    assert [p.GetName() for p in stage.GetPseudoRoot().GetChildren()] == ["Root"]


@pytest.mark.mitsuba
@pytest.mark.parametrize("phrase", HOSTILE)
@pytest.mark.parametrize("form", ["scene", "fragment"])
def test_mitsuba(phrase, form, tmp_path):
    mi = require("mitsuba", "mitsuba")
    mi.set_variant("scalar_rgb")
    ir = hostile_ir(phrase, "red or green glass")
    result = emit(ir, "mitsuba", {"maps": "none", "form": form})
    xml = result.artifacts[0].content
    root = ET.fromstring(xml.encode("utf-8"))
    ids = [b.get("id") for b in root.findall("bsdf")]
    assert len(ids) == 2 and "pwn" not in ids
    assert all(identifier(i) == i for i in ids)
    write_artifacts(result.artifacts, tmp_path)
    params = {"spp": 1, "resx": 8, "resy": 8} if form == "scene" else {}
    mi.load_file(str(tmp_path / result.artifacts[0].name), **params)


def test_envmap_path_is_escaped():
    xml = emit(ir_of("glass"), "mitsuba", {"envmap": 'sky "&<>.exr'}).artifacts[0].content
    root = ET.fromstring(xml.encode("utf-8"))
    assert root.find("emitter/string").get("value") == 'sky "&<>.exr'
