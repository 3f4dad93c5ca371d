"""Hostile and broken lexicon folders (#13): every malformed file is a clear error naming
FILE:LINE:COL and the key, with a did-you-mean for a mistyped name; never a traceback or an
internal error. The issue's reproductions run through the real CLI; the schema's corners
through the loader (each error message checked)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.colour import hex_to_linear
from cnlmc.lexicon import load_lexicon
from cnlmc.lexicon_schema import LexiconError
from tests.helpers import run_cnlmc

PHRASES = "brushed steel\nsteel\n"


@pytest.fixture(scope="module")
def cache_home(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("cache")


def compile_with(folder: Path, cache_home: Path, phrases: str = PHRASES):
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    return run_cnlmc("compile", "-", "--lexicon", str(folder), stdin=phrases, env=env, timeout=60)


def lexicon_folder(tmp_path: Path, name: str, data: bytes | str) -> Path:
    folder = tmp_path / "lexicon"
    folder.mkdir(exist_ok=True)
    path = folder / name
    path.write_bytes(data.encode() if isinstance(data, str) else data)
    return folder


def assert_usage_error(result, *texts: str) -> None:
    assert result.returncode == 2, result.stderr
    assert "internal error" not in result.stderr and "Traceback" not in result.stderr, result.stderr
    for text in texts:
        assert text in result.stderr, result.stderr


# ---------------------------------------------------------------- the reproductions, through the CLI


@pytest.mark.parametrize(
    "name,data,expected",
    [
        pytest.param(
            "nouns_x.toml",
            b'[steel]\ndoc = "caf\xff"\n',
            ("nouns_x.toml:2:11: not UTF-8 text", "save the file as UTF-8"),
            id="invalid-utf8",
        ),
        pytest.param(
            "nouns_x.toml",
            '[steel]\ncoat = "lacqer"\n',
            ("nouns_x.toml:2:1: key 'steel.coat': no coat named 'lacqer' (did you mean 'lacquer'?)",),
            id="unknown-coat",
        ),
        pytest.param(
            "adjectives_x.toml",
            '[brushed]\neffects = [{ param = "roughness", op = "mul", value = "high" }]\n',
            ("adjectives_x.toml:2:47: key 'brushed.effects[0].value': expected a number, got a string 'high'",),
            id="string-formula-value",
        ),
        pytest.param(
            "adjectives_x.toml",
            '[brushed]\neffects = [{ param = "roughness", op = "mull", value = 1.2 }]\n',
            (
                "adjectives_x.toml:2:35: key 'brushed.effects[0].op': 'mull' is not a known formula op (did you mean 'mul'?)",
            ),
            id="bad-op",
        ),
        pytest.param(
            "inflections.toml",
            'rules = [["ies", "y"], ["es"]]\n',
            ("inflections.toml:1:24: key 'rules[1]': expected a pair [suffix, replacement]",),
            id="bad-inflection-rule",
        ),
        pytest.param(
            "nouns_x.toml",
            '[steel]\nmaps = { "a/../../../ESCAPED" = { graph = "wood" } }\n',
            ("key 'steel.maps.\"a/../../../ESCAPED\"': 'a/../../../ESCAPED' is not a known map role",),
            id="map-role-escapes",
        ),
        pytest.param(
            "nouns_x.toml",
            "[steel]\nroughness = 0.1\nroughness = 0.2\n",
            ("nouns_x.toml:3:1: not valid TOML: key 'steel.roughness' is defined twice (first on line 2)",),
            id="duplicate-key",
        ),
        pytest.param(
            "settings.toml",
            "weight_stepp = 0.3\n",
            ("settings.toml:1:1: key 'weight_stepp': unknown field 'weight_stepp' (did you mean 'weight_step'?)",),
            id="unknown-top-level-key",
        ),
        pytest.param(
            "colours_x.toml",
            '[mud]\nhex = "#ggg"\ndoc = "d"\nexample = "mud plastic"\n',
            ("colours_x.toml:2:1: key 'mud.hex': a string '#ggg' is not a hex colour; write '#rrggbb'",),
            id="bad-hex",
        ),
        pytest.param(
            "nouns_x.toml",
            "[steel]\nroughness = nan\n",
            ("nouns_x.toml:2:1: key 'steel.roughness': expected a finite number, got nan",),
            id="nan",
        ),
    ],
)
def test_malformed_lexicon_is_a_usage_error_naming_file_line_and_key(tmp_path, cache_home, name, data, expected):
    result = compile_with(lexicon_folder(tmp_path, name, data), cache_home)
    assert_usage_error(result, *expected)


def test_short_hex_colour_is_accepted(tmp_path, cache_home):
    folder = lexicon_folder(tmp_path, "colours_x.toml", '[mud]\nhex = "#fa0"\ndoc = "d"\nexample = "mud plastic"\n')
    result = compile_with(folder, cache_home, "mud plastic\n")
    assert result.returncode == 0, result.stderr
    assert load_lexicon([folder]).entry("colours", "mud").get("rgb") == hex_to_linear("#ffaa00")


def test_map_role_escape_writes_nothing_outside(tmp_path, cache_home):
    folder = lexicon_folder(tmp_path, "nouns_x.toml", '[steel]\nmaps = { "a/../../../ESCAPED" = { graph = "wood" } }\n')
    out = tmp_path / "deep" / "er" / "out"
    out.mkdir(parents=True)
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    source = tmp_path / "m.cnl"
    source.write_text("steel\n")
    result = run_cnlmc("bake", str(source), "--lexicon", str(folder), "-o", str(out), env=env, timeout=120)
    assert result.returncode == 2 and "internal error" not in result.stderr, result.stderr
    assert not list(tmp_path.rglob("ESCAPED*"))


def _fifo(folder: Path) -> None:
    os.mkfifo(folder / "nouns_x.toml")


def _dev_zero(folder: Path) -> None:
    (folder / "nouns_x.toml").symlink_to("/dev/zero")


def _loop(folder: Path) -> None:
    (folder / "nouns_x.toml").symlink_to("nouns_x.toml")


def _sub_folder(folder: Path) -> None:
    (folder / "nouns_x.toml").mkdir()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
@pytest.mark.parametrize(
    "make,expected",
    [
        (_fifo, "it is a FIFO (named pipe)"),
        (_dev_zero, "it is a device"),
        (_loop, "Too many levels of symbolic links"),
        (_sub_folder, "it is a folder"),
    ],
    ids=["fifo", "dev-zero", "symlink-loop", "folder"],
)
def test_a_lexicon_file_that_is_not_a_regular_file_is_refused(tmp_path, cache_home, make, expected):
    folder = tmp_path / "lexicon"
    folder.mkdir()
    make(folder)
    result = compile_with(folder, cache_home)
    assert_usage_error(result, "nouns_x.toml", expected)


def test_a_lexicon_path_that_is_a_file_says_so(tmp_path, cache_home):
    path = tmp_path / "nouns.toml"
    path.write_text("[steel]\nroughness = 0.2\n")
    assert_usage_error(compile_with(path, cache_home), f"{path}: not a lexicon folder (it is a file)")


def test_a_lexicon_folder_that_is_a_symlink_loop_says_so(tmp_path, cache_home):
    loop = tmp_path / "loop"
    loop.symlink_to(loop)
    assert_usage_error(compile_with(loop, cache_home), "not a lexicon folder (cannot be followed")


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files whatever their mode")
def test_an_unreadable_lexicon_file_names_it(tmp_path, cache_home):
    folder = lexicon_folder(tmp_path, "nouns_x.toml", "[steel]\nroughness = 0.2\n")
    (folder / "nouns_x.toml").chmod(0)
    assert_usage_error(compile_with(folder, cache_home), "nouns_x.toml", "Permission denied")


def test_an_overlay_typo_suggests_the_name(cache_home, tmp_path):
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    result = run_cnlmc("compile", "-", "--lexicon", "papr", stdin="steel\n", env=env, cwd=tmp_path, timeout=60)
    assert_usage_error(result, "no lexicon overlay named 'papr'", "did you mean 'paper'?")


def test_a_folder_over_the_byte_limit_is_refused(tmp_path, cache_home):
    folder = lexicon_folder(tmp_path, "nouns_x.toml", "[steel]\nroughness = 0.2\n" + "# padding\n" * 200)
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home), "CNLMC_LEXICON_MAX_BYTES": "1000"}
    result = run_cnlmc("compile", "-", "--lexicon", str(folder), stdin="steel\n", env=env, timeout=60)
    assert_usage_error(result, "nouns_x.toml", "holds more than 1000 bytes", "CNLMC_LEXICON_MAX_BYTES")


# ---------------------------------------------------------------- the schema, field by field, through the loader

NEW_NOUN = (
    'class = "metal"\nmodel = "conductor"\nroughness = 0.2\nbase_color = [1.0, 0.5, 0.2]\n'
    "eta = [1.0, 1.0, 1.0]\nk = [3.0, 3.0, 3.0]\nf0 = [0.69, 0.69, 0.69]\nf82 = [0.75, 0.75, 0.75]\n"
    'source = "studio"\ndoc = "A metal."\nexample = "unobtainium"\n'
)

SCHEMA_CASES = [
    # plain fields: type, range, choice, unknown, missing
    ("nouns_x.toml", "[steel]\nclass = { a = 1 }\n", "2:1: key 'steel.class': expected a string, got a table"),
    ("nouns_x.toml", "[steel]\nbase_color = [1, 2]\n", "2:1: key 'steel.base_color': expected an RGB triple"),
    ("nouns_x.toml", "[steel]\nbase_color = [1, 0.5, 7]\n", "key 'steel.base_color[2]': 7 is outside [0, 1]"),
    ("nouns_x.toml", "[steel]\nroughness = -0.5\n", "key 'steel.roughness': -0.5 is outside [0, 1]"),
    ("nouns_x.toml", '[steel]\nmodel = "metal"\n', "'metal' is not a known value"),
    ("nouns_x.toml", "[steel]\nrougness = 0.2\n", "unknown field 'rougness' (did you mean 'roughness'?)"),
    (
        "nouns_x.toml",
        '[steel]\naliases = ["  "]\n',
        "2:12: key 'steel.aliases[0]': expected a word, got an empty string",
    ),
    ("nouns_x.toml", "[steel]\naliases = [1]\n", "key 'steel.aliases[0]': expected a string, got a number 1"),
    ("nouns_x.toml", "[unobtainium]\nroughness = 0.1\n", "1:1: key 'unobtainium': missing required field 'doc'"),
    (
        "nouns_x.toml",
        "[stel]\nroughness = 0.1\n",
        "missing required field 'doc' (a new entry needs: doc, example, class",
    ),
    ("nouns_x.toml", "[stel]\nroughness = 0.1\n", "); did you mean to change 'steel'?"),
    ("nouns_x.toml", "steel = 3\n", "1:1: key 'steel': expected a table of fields, got a number 3"),
    ("nouns_x.toml", '[""]\nroughness = 0.1\n', "an entry needs a name"),
    ("nouns_x.toml", "[" + "a" * 5000 + "]\nroughness = 0.1\n", "a name of 5000 characters; at most 4096"),
    ("adverbs_x.toml", "[very]\nweight = inf\n", "key 'very.weight': expected a finite number, got inf"),
    ("adverbs_x.toml", "[very]\nweight = 1" + "0" * 400 + "\n", "key 'very.weight': 1000000000"),
    ("adverbs_x.toml", '[very]\nweight = "2"\n', "expected a number, got a string '2'"),
    ("adverbs_x.toml", "[very]\nweight = true\n", "expected a number, got a boolean True"),
    ("refinements_x.toml", "[darker]\ndirection = 2\n", "key 'darker.direction': a number 2 is not a known value"),
    ("properties_x.toml", '[gloss]\ninvert = "yes"\n', "key 'gloss.invert': expected true or false"),
    ("coats_x.toml", "[varnish]\nior = 0.5\n", "key 'varnish.ior': 0.5 is outside [1, 3]"),
    ("settings.toml", "[alpha_convention]\nx = 1\n", "key 'alpha_convention': expected a string, got a table"),
    # formulas
    ("adjectives_x.toml", '[brushed]\neffects = { param = "roughness" }\n', "key 'brushed.effects': expected a list"),
    ("adjectives_x.toml", "[brushed]\neffects = [1]\n", "key 'brushed.effects[0]': expected a formula table"),
    ("adjectives_x.toml", '[brushed]\neffects = [{ op = "mul", value = 1 }]\n', "missing required field 'param'"),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughnes", op = "mul", value = 1 }]\n',
        "did you mean 'roughness'?",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "eta", op = "set", value = 1 }]\n',
        "'eta' is not a known parameter",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "mul", value = 1e300 }]\n',
        "1e+300 is outside [-1000, 1000]",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "set", value = 3 }]\n',
        "3 is outside [0, 1]",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "mul" }]\n',
        "missing required field 'value'",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "mul", value = 1, amount = 1 }]\n',
        "'amount' belongs to op = 'blend' or 'mix' only",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "mul", value = 1, how = 1 }]\n',
        "unknown field 'how'",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "model", op = "mul", value = 2 }]\n',
        "the model can only be set",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "model", op = "set", value = "metal" }]\n',
        "'metal' is not a known model",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "base_color", op = "set", value = [1, 1] }]\n',
        "expected an RGB triple",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\non.wood = [{ param = "roughness", op = "pow", value = 1 }]\n',
        "key 'brushed.on.wood[0].op'",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\non.wod = [{ param = "roughness", op = "mul", value = 1 }]\n',
        "no noun or noun class named 'wod' (did you mean 'wood'?)",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\napplies_to = ["metl"]\n',
        "key 'brushed.applies_to[0]': no noun or noun class named 'metl' (did you mean 'metal'?)",
    ),
    (
        "adjectives_x.toml",
        '[brushed]\nopposes = ["polishd"]\n',
        "no adjective named 'polishd' (did you mean 'polished'?)",
    ),
    ("adjectives_x.toml", '[brushed]\ncoat = "varnsh"\n', "no coat named 'varnsh' (did you mean 'varnish'?)"),
    (
        "adjectives_x.toml",
        '[brushed]\nfeatures_on = { copper = "patna" }\n',
        "no feature named 'patna' (did you mean 'patina'?)",
    ),
    ("adjectives_x.toml", '[brushed]\nfeatures_on = { copr = "patina" }\n', "no noun or noun class named 'copr'"),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "roughness", op = "mix", value = 0.5 }]\n',
        "op = 'mix' blends colours in OKLab: 'roughness' is not a colour",
    ),
    ("adjectives_x.toml", '[brushed]\nmaterial = "oak"\n', "'oak' is not a metal"),
    (
        "adjectives_x.toml",
        '[brushed]\neffects = [{ param = "model", op = "set", value = "conductor" }]\n',
        "a formula cannot make a metal: its optics come from a noun (material = 'copper')",
    ),
    ("nouns_x.toml", "[unobtainium]\n" + NEW_NOUN.replace("f0 = [0.69, 0.69, 0.69]\n", ""), "missing: f0"),
    ("adjectives_x.toml", '[brushed]\ncolour_target = "bass"\n', "did you mean 'base'?"),
    # shades
    ("shades_x.toml", '[pale]\nops = [{ op = "lighten", amount = 1 }]\n', "'lighten' is not a known colour operation"),
    (
        "shades_x.toml",
        '[pale]\nops = [{ op = "saturate" }]\n',
        "missing required field 'amount' (op = 'saturate' takes amount)",
    ),
    (
        "shades_x.toml",
        '[pale]\nops = [{ op = "mul", value = 0.5, amount = 1 }]\n',
        "unknown field for op = 'mul' 'amount'",
    ),
    (
        "shades_x.toml",
        '[pale]\nops = [{ op = "blend", value = 1, amount = 1 }]\n',
        "key 'pale.ops[0].value': expected an RGB triple",
    ),
    ("shades_x.toml", "[pale]\nops = []\n", "expected at least one colour operation"),
    # steps, refinements and properties
    (
        "properties_x.toml",
        '[diffuse]\nstep = { op = "add", value = "x" }\n',
        "2:22: key 'diffuse.step.value': expected a number",
    ),
    ("properties_x.toml", '[diffuse]\nstep = { op = "mul", value = 0 }\n', "key 'diffuse.step.value': 0 is outside"),
    (
        "properties_x.toml",
        '[diffuse]\nstep = { op = "add", value = 0.1, to = [1, 1, 1] }\n',
        "'to' belongs to op = 'blend' only",
    ),
    ("properties_x.toml", '[grain]\nparam = "roughness"\n', "key 'grain.param': a property names exactly one of param"),
    (
        "properties_x.toml",
        '[diffuse]\nstep = { op = "blend", value = 0.1 }\n',
        "2:10: key 'diffuse.step.op': a blend step moves towards a colour: it is for param = 'base_color' only",
    ),
    (
        "properties_x.toml",
        '[shine]\nparam = "roughnes"\nstep = { op = "add", value = 0.1 }\ndoc = "d"\nexample = "more shine"\n',
        "did you mean 'roughness'?",
    ),
    (
        "properties_x.toml",
        '[fibre]\nmap_param = "grian"\nstep = { op = "add", value = 0.1 }\ndoc = "d"\nexample = "more fibre"\n',
        "no graph parameter named 'grian' (did you mean 'grain'?)",
    ),
    ("refinements_x.toml", '[darker]\ntarget = "colur"\n', "did you mean 'colour'?"),
    (
        "refinements_x.toml",
        '[rougher]\nstep = { op = "add", value = 0.3 }\n',
        "2:1: key 'rougher.step': a step is used only with target = 'colour' (here properties.roughness.step applies)",
    ),
    (
        "refinements_x.toml",
        '[dimmer2]\ndirection = -1\ntarget = "colour"\ndoc = "d"\nexample = "dimmer2"\n',
        "a refinement of the colour needs a step",
    ),
    # maps
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_colour = { graph = "wood" } }\n',
        "'base_colour' is not a known map role (did you mean 'base_color'?)",
    ),
    ("nouns_x.toml", '[steel]\nmaps = { ".." = { graph = "wood" } }\n', "'..' is not a known map role"),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_color = { graph = "woood" } }\n',
        "2:25: key 'steel.maps.base_color.graph': 'woood' is not a known graph (did you mean 'wood'?)",
    ),
    ("nouns_x.toml", '[steel]\nmaps = { base_color = { graph = "../../x" } }\n', "'../../x' is not a known graph"),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_color = { graph = "wood", output = "colour" } }\n',
        "'colour' is not a known output of graph 'wood' (did you mean 'color'?)",
    ),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_color = { graph = "wood", params = { grian = 1 } } }\n',
        "'grian' is not a known parameter of graph 'wood' (did you mean 'grain'?)",
    ),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_color = { graph = "wood", params = { grain = 9 } } }\n',
        "key 'steel.maps.base_color.params.grain': 9 is outside [0, 2]",
    ),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { base_color = { graph = "wood", weighted = ["x"] } }\n',
        "key 'steel.maps.base_color.weighted[0]'",
    ),
    (
        "nouns_x.toml",
        '[steel]\nmaps = { normal = { graph = "brushed" } }\n',
        "graph 'brushed' has no 'color' output; name one",
    ),
    ("nouns_x.toml", '[steel]\nmaps = { base_color = "wood" }\n', "expected a graph reference"),
    # special files
    ("inflections.toml", 'rules = "ies"\n', "key 'rules': expected a list of [suffix, replacement] pairs"),
    ("inflections.toml", 'rules = [["", "y"]]\n', "key 'rules[0][0]': expected a word"),
    ("inflections.toml", "rule = []\n", "unknown field 'rule' (did you mean 'rules'?)"),
    ("keywords.toml", '[terminals]\nANDD = ["und"]\n', "unknown grammar terminal 'ANDD' (did you mean 'AND'?)"),
    ("keywords.toml", "x = 1\n", "unknown field 'x'"),
    ("noun_x.toml", "", "noun_x.toml:1:1: unknown lexicon file (did you mean 'nouns'?)"),
    # TOML itself
    (
        "nouns_x.toml",
        "[steel]\nroughness = 0.1\n[steel]\n",
        "3:1: not valid TOML: key 'steel' is defined twice (first on line 1)",
    ),
    ("nouns_x.toml", "[steel\n", "1:7: not valid TOML"),
    (
        "nouns_x.toml",
        "a = " + "[" * 3000 + "]" * 3000 + "\n",
        "1:1: not valid TOML: arrays or tables nested too deeply",
    ),
]


@pytest.mark.parametrize("name,text,expected", SCHEMA_CASES, ids=[f"{i}-{c[0]}" for i, c in enumerate(SCHEMA_CASES)])
def test_every_field_is_checked_with_file_line_and_key(tmp_path, name, text, expected):
    folder = lexicon_folder(tmp_path, name, text)
    with pytest.raises(LexiconError) as info:
        load_lexicon([folder])
    message = str(info.value)
    assert message.startswith(str(folder / name)), message
    assert expected in message, message


def test_an_empty_file_adds_nothing(tmp_path, stdlib):
    folder = lexicon_folder(tmp_path, "nouns_x.toml", "")
    assert load_lexicon([folder]).entries == stdlib.entries


def test_hidden_files_are_skipped(tmp_path, stdlib):
    folder = lexicon_folder(tmp_path, ".#nouns_x.toml", "garbage [")
    assert load_lexicon([folder]).entries == stdlib.entries


def test_a_complete_new_entry_still_loads_and_compiles(tmp_path):
    folder = lexicon_folder(tmp_path, "nouns_studio.toml", "[unobtainium]\n" + NEW_NOUN)
    result = compile_source("brushed unobtainium", "x.cnl", load_lexicon([folder]))
    assert result.ok, [d.message for d in result.diagnostics]


# ---------------------------------------------------------------- graph files: names are plain identifiers

GRAPH = """
doc = "test"
[params.scale]
default = 1.0
range = [0.5, 2.0]
doc = "density"
[nodes.noise]
type = "perlin"
scale = { param = "scale", mul = 4 }
[outputs]
mask = "noise"
"""


@pytest.mark.parametrize(
    "old,new,expected",
    [
        ("[nodes.noise]", '[nodes."../x"]', "nodes.../x: '../x' is not a plain name"),
        ("[params.scale]", '[params."a b"]', "params.a b: 'a b' is not a plain name"),
        ('doc = "test"', 'doc = "test"\nname = "a/b"', "name: 'a/b' is not a plain name"),
    ],
)
def test_graph_names_are_plain_identifiers(tmp_path, old, new, expected):
    from cnlmc.backends.maps import GraphSchemaError, load_graph_file

    path = tmp_path / "g.toml"
    path.write_text(GRAPH.replace(old, new))
    with pytest.raises(GraphSchemaError) as info:
        load_graph_file(path)
    assert expected in str(info.value)
