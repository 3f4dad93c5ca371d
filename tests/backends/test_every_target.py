"""Every registered target × every IR model kind: it emits, and it says what it approximated.

The one path for what a target cannot express (backends/capabilities.py) is checked end to
end: every feature of every material either is exact for the target or comes back as a note.
"""

import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.capabilities import ALL_FEATURES, POLICIES, material_features
from cnlmc.backends.registry import BUILTIN_BACKENDS, TargetUnavailable, get_target
from cnlmc.lexicon import load_lexicon
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


def stdlib_pairs(every: bool) -> list[str]:
    """Stdlib adjective + noun phrases ('matte denim', 'brushed walnut', ...): with `every`, each
    adjective before every noun that can read differently — the first noun of each noun class
    and of each model, and every noun an adjective names in its `on` table (per-class and
    per-noun formulas are what differ; 30,000 pairs of the same class repeat one another) —;
    else each adjective and each noun at least once (round robin)."""
    lexicon = load_lexicon()
    adjectives, nouns = sorted(lexicon.all_of("adjectives")), sorted(lexicon.all_of("nouns"))
    if every:
        return [f"{adjective} {noun}" for adjective in adjectives for noun in _distinct_nouns(lexicon, nouns)]
    count = max(len(adjectives), len(nouns))
    return [f"{adjectives[i % len(adjectives)]} {nouns[i % len(nouns)]}" for i in range(count)]


def _distinct_nouns(lexicon, nouns: list[str]) -> list[str]:
    firsts: dict[tuple[str, str], str] = {}
    for key in nouns:
        entry = lexicon.entry("nouns", key)
        firsts.setdefault(("class", str(entry.get("class"))), key)
        firsts.setdefault(("model", str(entry.get("model"))), key)
    named = {name for a in lexicon.all_of("adjectives").values() for name in (a.get("on") or {})}
    return sorted(set(firsts.values()) | (named & set(nouns)))


def pairs_document(every: bool):
    """One document of the pairs, one material per line; it compiles cleanly."""
    source = "".join(f"m{i}: {phrase}\n" for i, phrase in enumerate(stdlib_pairs(every)))
    result = compile_source(source)
    assert result.ok, [d.message for d in result.diagnostics if d.is_error][:5]
    return result


def test_matte_denim_through_mitsuba_from_the_command_line():
    """#13: `echo "matte denim" | cnlmc compile - --target mitsuba` was `internal error: KeyError: 'ior'`."""
    r = run_cnlmc("compile", "-", "--target", "mitsuba", "--option", "maps=none", stdin="matte denim\n")
    assert r.returncode == 0, r.stderr
    assert 'id="matte_denim"' in r.stdout and "internal error" not in r.stderr


def emits_every_material(result, bsdf: str) -> None:
    [scene] = emit(result.ir, "mitsuba", {"maps": "none", "bsdf": bsdf}).artifacts
    missing = [m["name"] for m in result.ir["materials"] if f'id="{m["name"]}"' not in scene.content]
    assert not missing, missing[:5]


@pytest.mark.parametrize("bsdf", ["native", "cnlm"])
def test_every_adjective_and_every_noun_through_mitsuba(bsdf):
    """#13: 41 stdlib adjective x noun pairs crashed the Mitsuba target (KeyError: 'ior')."""
    backend("mitsuba")
    emits_every_material(pairs_document(every=False), bsdf)


@pytest.fixture(scope="module")
def every_pair():
    return pairs_document(every=True)


@pytest.mark.slow
@pytest.mark.parametrize("bsdf", ["native", "cnlm"])
def test_every_adjective_noun_pair_through_mitsuba(every_pair, bsdf):
    backend("mitsuba")
    emits_every_material(every_pair, bsdf)


@pytest.mark.slow
@pytest.mark.parametrize(
    ("target", "options"),
    [("ir", {}), ("glsl", {}), ("materialx", {"maps": "none"}), ("usd", {"maps": "none"})],
)
def test_every_adjective_noun_pair_through_every_target(every_pair, target, options):
    backend(target)
    result = emit(every_pair.ir, target, options)
    assert result.artifacts
