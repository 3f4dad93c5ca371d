"""Exports carry a fibre noun's sheen where the target has a slot (issue #15 item 5, docs/bsdf.md
"Sheen"): OpenPBR fuzz_*, Standard Surface sheen*, each MaterialX document valid against the
standard library; a material without a sheen writes none. (glTF's KHR_materials_sheen is checked
with every stdlib noun in test_gltf.py.)"""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.exchange.surface_inputs import zeltner_albedo
from cnlmc.bsdf.sheen import sheen_albedo_direct

MaterialX = pytest.importorskip("MaterialX")

SLOTS = {
    "open_pbr_surface": ("fuzz_weight", "fuzz_color", "fuzz_roughness"),
    "standard_surface": ("sheen", "sheen_color", "sheen_roughness"),
}


def document(phrase: str, surface: str):
    ir = compile_source(phrase + "\n").ir
    result = emit(ir, "materialx", {"surface": surface})
    text = result.artifacts[0].content
    doc = MaterialX.createDocument()
    MaterialX.readFromXmlString(doc, text if isinstance(text, str) else text.decode())
    return ir["materials"][0]["params"], doc


def inputs(doc) -> dict[str, object]:
    (shader,) = [n for n in doc.getNodes() if n.getType() == "surfaceshader"]
    return {i.getName(): i.getValue() for i in shader.getInputs()}


def validated(doc):
    library = MaterialX.createDocument()
    MaterialX.loadLibraries(MaterialX.getDefaultDataLibraryFolders(), MaterialX.getDefaultDataSearchPath(), library)
    doc.importLibrary(library)
    ok, message = doc.validate()
    assert ok, message


@pytest.mark.parametrize("surface", SLOTS)
def test_velvet_writes_its_sheen(surface):
    params, doc = document("navy blue velvet", surface)
    weight, colour, roughness = (inputs(doc)[k] for k in SLOTS[surface])
    sheen = params["sheen_color"]
    assert weight == pytest.approx(max(sheen), abs=1e-6)
    assert [weight * c for c in colour] == pytest.approx(sheen, abs=1e-5)
    alpha = params["sheen_roughness"] ** 2
    if surface == "standard_surface":
        assert roughness == pytest.approx(alpha, abs=1e-6)  # the Charlie lobe's alpha
    else:  # Zeltner's LTC sheen: the roughness with the Charlie lobe's energy (2 int E mu dmu)
        x, w = np.polynomial.legendre.leggauss(16)
        mu, weight = 0.5 * (x + 1.0), w * 0.5 * (x + 1.0)
        charlie = weight @ sheen_albedo_direct(mu, alpha, n=8192)
        assert weight @ zeltner_albedo(mu, roughness) == pytest.approx(charlie, rel=0.03)
        assert weight @ zeltner_albedo(mu, alpha) < 0.5 * charlie  # alpha itself returns far less
    validated(doc)


@pytest.mark.parametrize("surface", SLOTS)
def test_no_sheen_no_slot(surface):
    params, doc = document("blue plastic", surface)
    assert "sheen_color" not in params
    assert not set(SLOTS[surface]) & set(inputs(doc))
