"""Every backend has a policy for every feature and a reason for every non-exact one, and every
non-exact feature a material uses reaches the notes (IR model kinds x backends)."""

from __future__ import annotations

import pytest

from tests.helpers import PHRASE_BY_MODEL, require

require("MaterialX", "materialx")
require("pxr", "usd")
pytestmark = [pytest.mark.materialx, pytest.mark.usd]

from cnlmc.api import emit  # noqa: E402
from cnlmc.backends.capabilities import ALL_FEATURES, POLICIES, material_features  # noqa: E402
from cnlmc.backends.exchange import materialx, mitsuba, usd  # noqa: E402

from .conftest import ir_of, synthetic_ir  # noqa: E402

TABLES = {
    "materialx": materialx.CAPABILITIES,
    "usd": usd.CAPABILITIES,
    "mitsuba": mitsuba.CAPABILITIES,
    **{f"materialx/{s}": t for s, t in materialx.CAPABILITIES_BY_SURFACE.items()},
}
MODEL_KINDS = list(PHRASE_BY_MODEL.values())


@pytest.mark.parametrize("table", TABLES)
def test_every_feature_has_a_policy_and_reason(table):
    capabilities = TABLES[table]
    assert set(capabilities) == set(ALL_FEATURES)
    for feature, (policy, reason) in capabilities.items():
        assert policy in POLICIES and policy != "error", feature
        if policy != "exact":
            assert len(reason) > 15, f"{table}: {feature} needs a reason"


@pytest.mark.parametrize("target", ["materialx", "usd", "mitsuba"])
@pytest.mark.parametrize("source", MODEL_KINDS + ["<synthetic>"])
def test_notes_cover_every_non_exact_feature(target, source):
    ir = synthetic_ir() if source == "<synthetic>" else ir_of(source)
    notes = emit(ir, target, {"maps": "none"}).notes
    capabilities = TABLES[target]
    for material in ir["materials"]:
        expected = {f for f in material_features(material) if capabilities[f][0] != "exact" or f.startswith("maps.")}
        got = {n.feature for n in notes if n.material == material["name"]}
        assert got == expected, material["name"]


def test_named_approximations():
    """The ones the brief names: Ward -> anisotropic GGX everywhere; USD drops coat colour and
    anisotropy, bakes maps and makes Oren-Nayar Lambert."""
    for table in (materialx.CAPABILITIES, usd.CAPABILITIES, mitsuba.CAPABILITIES):
        assert table["distribution.ward"][0] == "approximate" and "GGX" in table["distribution.ward"][1]
    assert usd.CAPABILITIES["coat.color"][0] == "drop" and usd.CAPABILITIES["anisotropic"][0] == "drop"
    assert "Lambert" in usd.CAPABILITIES["diffuse.oren_nayar"][1]
    assert all(materialx.CAPABILITIES[f][0] == "bake" for f in ("maps.base_color", "maps.normal", "maps.roughness"))
