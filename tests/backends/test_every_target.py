"""Every registered target × every IR model kind: it emits, and it says what it approximated.

The one path for what a target cannot express (backends/capabilities.py) is checked end to
end: every feature of every material either is exact for the target or comes back as a note.
"""

import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.capabilities import ALL_FEATURES, POLICIES, material_features
from cnlmc.backends.registry import BUILTIN_BACKENDS, TargetUnavailable, get_target
from tests.helpers import PHRASE_BY_MODEL, require, run_cnlmc

# One phrase per model kind and feature, so every row of the capability tables is exercised.
KINDS = PHRASE_BY_MODEL
FAST_OPTIONS = {"preview": {"size": "32", "msaa": "0"}, "maps": {"size": "16"}}


#: What a target needs when it emits (baking maps, rendering), beyond what loading it needs.
EMIT_NEEDS = {
    "maps": (("OpenImageIO", "maps"),),
    "mitsuba": (("OpenImageIO", "maps"),),
    "preview": (("moderngl", "preview"), ("OpenImageIO", "preview")),
}


def backend(name):
    try:
        target = get_target(name)
    except TargetUnavailable as exc:  # an optional dependency is missing on this machine
        pytest.skip(f"target {name} cannot load here: {exc}")
    for module, extra in EMIT_NEEDS.get(name, ()):
        require(module, extra)
    return target


@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_capability_table_is_complete(target):
    table = backend(target).capabilities
    assert set(ALL_FEATURES) <= set(table), set(ALL_FEATURES) - set(table)
    for feature, (policy, reason) in table.items():
        assert policy in POLICIES, (feature, policy)
        if policy != "exact":
            assert reason.strip(), f"{target}: {feature} is {policy} without a reason"


@pytest.mark.parametrize("kind", sorted(KINDS))
@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_every_kind_emits_and_reports_its_approximations(target, kind):
    target_object = backend(target)
    ir = compile_source(KINDS[kind] + "\n").ir
    result = emit(ir, target, {**FAST_OPTIONS.get(target, {}), "seed": 0})
    if target != "maps" or any(m["maps"] for m in ir["materials"]):
        assert result.artifacts, f"{target} wrote nothing for {kind}"
    noted = {(n.material, n.feature) for n in result.notes}
    for material in ir["materials"]:
        for feature in material_features(material):
            policy = target_object.capabilities[feature][0]
            if policy != "exact":
                assert (material["name"], feature) in noted, f"{target}: {feature} of {kind} not reported"


@pytest.mark.parametrize("target", sorted(BUILTIN_BACKENDS))
def test_every_target_from_the_command_line(tmp_path, target):
    backend(target)
    extra = {"preview": ["--option", "size=32"], "maps": ["--option", "size=16"]}.get(target, [])
    source = "hull: lightly brushed, blue anodized aluminum\ndeck: red or blue plastic\n"
    r = run_cnlmc("compile", "-", "-t", target, "-o", str(tmp_path) + "/", *extra, stdin=source)
    assert r.returncode == 0, r.stderr
    assert any(tmp_path.iterdir()), f"{target} wrote nothing"
