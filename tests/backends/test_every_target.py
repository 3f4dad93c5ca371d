"""Every registered target × every IR model kind: it emits, and it says what it approximated.

The one path for what a target cannot express (backends/capabilities.py) is checked end to
end: every feature of every material either is exact for the target or comes back as a note.
"""

import importlib

import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.capabilities import ALL_FEATURES, POLICIES, material_features
from cnlmc.backends.registry import BUILTIN_BACKENDS

# One phrase per model kind and feature, so every row of the capability tables is exercised.
KINDS = {
    "diffuse": "weathered concrete",
    "diffuse_oren_nayar": "navy blue velvet",
    "dielectric": "glossy red plastic",
    "conductor": "polished gold",
    "glass": "frosted glass",
    "anisotropic_ward": "lightly brushed, blue anodized aluminum",
    "coat": "oak with a glossy white varnish",
    "tinted_coat": "steel with a red lacquer",
    "maps": "heavily rusted iron",
    "variants": "red or blue plastic",
}
FAST_OPTIONS = {"preview": {"size": "32", "msaa": "0"}, "maps": {"size": "16"}}


def backend(name):
    try:
        return importlib.import_module(BUILTIN_BACKENDS[name])
    except ImportError as exc:  # an optional dependency is missing on this machine
        pytest.skip(f"target {name} cannot load here: {exc}")


@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_capability_table_is_complete(target):
    table = backend(target).CAPABILITIES
    assert set(ALL_FEATURES) <= set(table), set(ALL_FEATURES) - set(table)
    for feature, (policy, reason) in table.items():
        assert policy in POLICIES, (feature, policy)
        if policy != "exact":
            assert reason.strip(), f"{target}: {feature} is {policy} without a reason"


@pytest.mark.parametrize("kind", sorted(KINDS))
@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_every_kind_emits_and_reports_its_approximations(target, kind):
    module = backend(target)
    ir = compile_source(KINDS[kind] + "\n").ir
    result = emit(ir, target, {**FAST_OPTIONS.get(target, {}), "seed": 0})
    if target != "maps" or any(m["maps"] for m in ir["materials"]):
        assert result.artifacts, f"{target} wrote nothing for {kind}"
    noted = {(n.material, n.feature) for n in result.notes}
    for material in ir["materials"]:
        for feature in material_features(material):
            policy = module.CAPABILITIES[feature][0]
            if policy != "exact":
                assert (material["name"], feature) in noted, f"{target}: {feature} of {kind} not reported"


@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_every_target_from_the_command_line(tmp_path, target):
    import subprocess
    import sys

    backend(target)
    extra = {"preview": ["--option", "size=32"], "maps": ["--option", "size=16"]}.get(target, [])
    r = subprocess.run(
        [sys.executable, "-m", "cnlmc", "compile", "-", "-t", target, "-o", str(tmp_path) + "/", *extra],
        input="hull: lightly brushed, blue anodized aluminum\ndeck: red or blue plastic\n",
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr
    assert any(tmp_path.iterdir()), f"{target} wrote nothing"
