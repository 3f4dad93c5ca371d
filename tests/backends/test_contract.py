"""The backend contract (backends/base.py): declared options parsed once, the shared emit loop,
the registry's targets and commands, the map-baking service's one error type."""

import subprocess
import sys

import pytest

from cnlmc.api import compile_source
from cnlmc.backends.base import Artifact, Command, Option, OptionError, Target, as_document, emit_each, parse_options
from cnlmc.backends.capabilities import ALL_FEATURES
from cnlmc.backends.registry import (
    BUILTIN_BACKENDS,
    BUILTIN_COMMANDS,
    TargetUnavailable,
    UnknownTarget,
    get_command,
    get_target,
)
from tests.helpers import run_cnlmc

DECLARED = (
    Option("fresnel", str, "exact", choices=("exact", "f82", "schlick")),
    Option("size", int, 512),
    Option("exposure", float, 1.0),
    Option("flip", bool, False),
    Option("budget_ms", float, None),
)


def test_options_are_typed_with_defaults_and_the_compiler_options():
    options = parse_options(DECLARED, {"size": "64", "flip": "on", "fresnel": "Schlick", "seed": 3}, "toy")
    assert dict(options) == {
        "seed": 3,
        "output": None,
        "fresnel": "schlick",
        "size": 64,
        "exposure": 1.0,
        "flip": True,
        "budget_ms": None,
    }
    assert options.size == options["size"] == 64
    with pytest.raises(AttributeError):
        options.colour  # noqa: B018


def test_unknown_keys_and_values_say_did_you_mean():
    with pytest.raises(OptionError, match=r"toy: unknown option\(s\) fresnl; known: .*did you mean 'fresnel'\?"):
        parse_options(DECLARED, {"fresnl": "exact"}, "toy")
    with pytest.raises(OptionError, match=r"is not one of exact, f82, schlick; did you mean 'schlick'\?"):
        parse_options(DECLARED, {"fresnel": "shlick"}, "toy")
    with pytest.raises(OptionError, match="must be a whole number"):
        parse_options(DECLARED, {"size": "big"}, "toy")
    with pytest.raises(OptionError, match="must be on or off"):
        parse_options(DECLARED, {"flip": "maybe"}, "toy")


@pytest.mark.parametrize("raw", ["nan", "inf", "-inf", "1e400"])
def test_a_float_option_is_finite(raw):
    declared = (Option("exposure", float, 1.0, range=(0.0, 1e4)),)
    with pytest.raises(OptionError, match=f"toy: option exposure='{raw}' must be a finite number"):
        parse_options(declared, {"exposure": raw}, "toy")


def test_a_declared_range_bounds_the_value():
    declared = (Option("exposure", float, 1.0, range=(0.0, 1e4)), Option("spp", int, 64, range=(1, 1 << 20)))
    assert parse_options(declared, {"exposure": "1e4", "spp": "1"}, "toy").spp == 1  # bounds are inclusive
    with pytest.raises(OptionError, match=r"toy: option exposure=1e\+308 is outside \[0, 10000\]"):
        parse_options(declared, {"exposure": "1e308"}, "toy")
    with pytest.raises(OptionError, match=r"toy: option spp=100000000000000000000000 is outside \[1, 1048576\]"):
        parse_options(declared, {"spp": str(10**23)}, "toy")


@pytest.mark.parametrize(
    ("target", "option", "value", "message"),
    [
        ("preview", "exposure", "nan", "must be a finite number"),
        ("preview", "exposure", "1e308", "is outside [0, 10000]"),
        ("preview", "msaa", "3", "is not one of 0, 1, 2, 4, 8"),
        ("mitsuba", "spp", "100000000000000000000000", "is outside [1, 1048576]"),
    ],
)
def test_the_issue_s_bad_options_are_usage_errors(tmp_path, target, option, value, message):
    """#13: exposure=nan wrote a black image, msaa=3 was an internal error, spp=1e23 a scene Mitsuba cannot load."""
    r = run_cnlmc(
        "compile", "-", "--target", target, "--option", f"{option}={value}", "-o", str(tmp_path / "out"), stdin="gold\n"
    )
    assert r.returncode == 2 and message in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()


class EchoTarget(Target):
    name = "echo"
    description = "one file per material, always called out.txt"
    capabilities = dict.fromkeys(ALL_FEATURES, ("approximate", "echoed"))

    def emit(self, document, options):
        return emit_each(self, document, lambda m: [Artifact("out.txt", m.name)])


def test_the_emit_loop_notes_every_feature_and_refuses_two_files_with_one_name():
    document = as_document(compile_source("gold\n").ir)
    result = EchoTarget().emit(document, EchoTarget().parse_options({}))
    assert {n.feature for n in result.notes} >= {"model.conductor"}
    twice = as_document(compile_source("a: gold\nb: steel\n").ir)
    with pytest.raises(ValueError, match="materials 'a' and 'b' both write 'out.txt'"):
        EchoTarget().emit(twice, EchoTarget().parse_options({}))


def test_every_builtin_target_is_a_target_object():
    for name in BUILTIN_BACKENDS:
        try:
            target = get_target(name)
        except TargetUnavailable:
            continue
        assert isinstance(target, Target) and target.name == name and target.description
    with pytest.raises(UnknownTarget, match="did you mean 'glsl'"):
        get_target("glls")


def test_every_listed_command_is_what_its_module_provides():
    for name, entry in BUILTIN_COMMANDS.items():
        try:
            command = get_command(name)
        except TargetUnavailable:
            continue
        assert isinstance(command, Command) and command.name == name and command.help == entry.help


def test_the_parser_imports_no_backend_until_a_backend_command_runs():
    code = (
        "import sys; from cnlmc.cli import build_parser; build_parser(['compile']); "
        "print(sorted(m for m in sys.modules if m.startswith('cnlmc.backends.')))"
    )
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert loaded.returncode == 0, loaded.stderr
    assert eval(loaded.stdout) == ["cnlmc.backends.base", "cnlmc.backends.capabilities", "cnlmc.backends.registry"]


def test_the_baking_service_names_the_material_it_cannot_bake():
    pytest.importorskip("OpenImageIO")
    from cnlmc.backends.maps import MapBakeError, bake_artifacts

    [material] = as_document(compile_source("oak\n").ir).materials
    with pytest.raises(MapBakeError, match="^oak: map size 100 is not a power of two") as caught:
        bake_artifacts(material, 100, "png8", 0)
    assert caught.value.material == "oak"
    files = bake_artifacts(material, 16, "png8", 0, folder="textures")
    assert sorted(a.name for a in files) == ["textures/oak_base_color.png", "textures/oak_roughness.png"]
