"""A bounded fuzz suite over random lexicon folders (#13).

Each example is a folder of lexicon files: real stdlib entries (the words the phrases below use)
with one part of them replaced by a random or wrong value (a string for a number, NaN, a huge
number, a table for a list, a mistyped name, a map role with '/' or '..'), removed, or joined by
an unknown field; whole new entries copied from a real one under a new name; settings and
inflection files; and files of garbage bytes. `cnlmc compile --lexicon FOLDER` then compiles a
few phrases (cnlmc.cli.main in process, in tests/fuzz/cli_fuzz.py's sandbox). Every run must exit
0, 1 or 2, print no traceback or "internal error", write no file outside its output folder, and
any IR it prints is strict JSON (no NaN, no Infinity). Derandomized, with a fixed budget.
"""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from cnlmc.lexicon import load_lexicon
from cnlmc.lexicon_load import schema
from tests.fuzz.cli_fuzz import Sandbox, check_run, run_cli, strict_json

STDLIB = load_lexicon()
SCHEMA = schema()
#: the entries the phrases use: mutating these reaches the compiler's passes, not only the loader
FOCUS = {
    "nouns": ("steel", "oak", "copper", "glass", "aluminum", "iron"),
    "adjectives": ("brushed", "varnished", "rusty", "glossy", "anodized", "lacquered"),
    "adverbs": ("very", "lightly"),
    "colours": ("red", "blue"),
    "shades": ("pale", "dark"),
    "coats": ("varnish", "clear coat"),
    "refinements": ("darker", "more", "less", "rougher"),
    "properties": ("grain", "diffuse", "gloss", "colour"),
}
NEW_KEYS = ("zork", "blip")
#: phrases of stdlib words only (they compile when the lexicon loads), then phrases of the new words
PHRASES = (
    "lightly brushed steel\nvery pale red varnished oak\ndarker\nmore grain\nless diffuse\nrougher\n"
    "glossy blue anodized aluminum\ncopper with a clear coat\nrusty iron\nlacquered glass\n"
)
NEW_PHRASES = "zork\nblip zork\nvery blip steel\ndark zork oak\nsteel with a zork\nwith zork\n"
#: names the loader and the passes look for, and names that attack paths
WORDS = (
    *("set", "mul", "add", "blend", "saturate", "pow", "#fff", "#ggg", "#ffaa00", "", " ", "wood", "brushed"),
    *("normal", "color", "base_color", "roughness", "mask", "conductor", "dielectric", "model", "ior", "eta"),
    *("a/../../../ESCAPED", "..", "/tmp/x", "varnish", "steel", "metal", "colour", "any", "grain", "strength"),
    *NEW_KEYS,
    *("with", "or", "a"),
)
#: every name of the stdlib (nouns, classes, coats, graphs' words): what a mistyped or swapped name becomes
NAMES = tuple(sorted({key for category in STDLIB.entries.values() for key in category} | {"metal", "wood"})[:400])
FIELDS = sorted({f for c in SCHEMA.values() for f in c["fields"]} | {"op", "param", "value", "amount", "graph"})

scalars = st.one_of(
    st.booleans(),
    st.integers(-3, 3),
    st.integers(-(10**30), 10**30),
    st.floats(0, 1),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(WORDS),
    st.text(max_size=8),
)
values = st.recursive(
    scalars,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(st.one_of(st.sampled_from(FIELDS), st.sampled_from(WORDS)), inner, max_size=3),
    ),
    max_leaves=10,
)


# ---------------------------------------------------------------- TOML text


def toml_key(key: str) -> str:
    return json.dumps(key)


def toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf") if math.isinf(value) else repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    return "{ " + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + " }"


def toml_table(fields: dict[str, Any]) -> str:
    return "".join(f"{toml_key(k)} = {toml_value(v)}\n" for k, v in fields.items())


def toml_entries(entries: dict[str, Any]) -> str:
    return "".join(
        f"[{toml_key(key)}]\n{toml_table(fields)}"
        if isinstance(fields, dict)
        else f"{toml_key(key)} = {toml_value(fields)}\n"
        for key, fields in entries.items()
    )


# ---------------------------------------------------------------- mutations of real entries


def paths_in(value: Any, path: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every place inside a nested value: table keys and list indices."""
    found = [path] if path else []
    if isinstance(value, dict):
        for k, v in value.items():
            found += paths_in(v, (*path, k))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            found += paths_in(v, (*path, i))
    return found


def mutate(data: dict[str, Any], path: tuple[Any, ...], how: str, new: Any) -> dict[str, Any]:
    data = copy.deepcopy(data)
    holder: Any = data
    for part in path[:-1]:
        holder = holder[part]
    last = path[-1]
    if how == "replace":
        holder[last] = new
    elif how == "delete":
        del holder[last]
    elif isinstance(holder, dict):  # add a field beside it
        holder[f"{last}x" if isinstance(last, str) else "extra"] = new
    return data


def real_entry(category: str, key: str) -> dict[str, Any]:
    data = dict(STDLIB.require(category, key).data)
    data.pop("rgb", None)  # computed from hex
    return data


def strings_by_key(value: Any, key: Any = None, found: dict[str, set[str]] | None = None) -> dict[str, set[str]]:
    """Every string the stdlib holds under each key ('op' -> set, mul, ...; 'graph' -> wood, ...)."""
    found = {} if found is None else found
    if isinstance(value, str) and isinstance(key, str):
        found.setdefault(key, set()).add(value)
    elif isinstance(value, dict):
        for k, v in value.items():
            strings_by_key(v, k, found)
    elif isinstance(value, list):
        for v in value:
            strings_by_key(v, key, found)
    return found


#: what a string field holds in the stdlib: a swapped but valid name reaches the compiler
VALID_STRINGS = {
    k: tuple(sorted(v))
    for k, v in strings_by_key({c: {k: e.data for k, e in by.items()} for c, by in STDLIB.entries.items()}).items()
}


def similar(original: Any, key: Any = None) -> st.SearchStrategy[Any]:
    """A value of the same shape as `original`: what gets past the type checks to the compiler."""
    if isinstance(original, str) and key in VALID_STRINGS:
        return st.one_of(
            st.sampled_from(VALID_STRINGS[key]), st.sampled_from(VALID_STRINGS[key]), st.sampled_from(WORDS)
        )
    if isinstance(original, bool):
        return st.booleans()
    if isinstance(original, (int, float)):
        edges = st.sampled_from((0, 0.0, 1, 1.0, -1, 1e-300, 5e-324, 0.999999, 1e6, -1e6, 10.0, 3))
        return st.one_of(edges, st.floats(-2, 2), st.floats(0, 1), st.integers(-2, 2))
    if isinstance(original, str):
        return st.one_of(st.sampled_from(WORDS), st.sampled_from(NAMES))
    if isinstance(original, list):
        item = similar(original[0]) if original else scalars
        return st.lists(item, min_size=max(0, len(original) - 1), max_size=len(original) + 1)
    return values


@st.composite
def entries_file(draw: st.DrawFn) -> tuple[str, str]:
    category = draw(st.sampled_from(sorted(FOCUS)))
    entries = {}
    for _ in range(draw(st.sampled_from((1, 1, 1, 2, 3)))):
        source = draw(st.sampled_from(FOCUS[category]))
        key = draw(st.one_of(st.just(source), st.sampled_from(NEW_KEYS), st.sampled_from(WORDS)))
        data = real_entry(category, source)
        for _ in range(draw(st.sampled_from((0, 1, 1, 1, 2)))):
            places = paths_in(data)
            if places:
                place = draw(st.sampled_from(places))
                how = draw(st.sampled_from(("replace", "replace", "replace", "delete", "add")))
                at = data
                for part in place:
                    at = at[part]
                named = next((p for p in reversed(place) if isinstance(p, str)), None)
                data = mutate(data, place, how, draw(st.one_of(similar(at, named), similar(at, named), values)))
        if draw(st.booleans()) and key == source:  # an override sets only some fields
            data = {k: v for k, v in data.items() if draw(st.booleans())}
        entries[key] = data if draw(st.sampled_from((True,) * 9 + (False,))) else draw(values)
    return f"{category}_fuzz.toml", toml_entries(entries)


settings_file = st.dictionaries(
    st.sampled_from(sorted(SCHEMA["settings"]["fields"])),
    st.one_of(values, similar(0.5), similar("", "alpha_convention")),
    max_size=3,
).map(lambda table: ("settings.toml", toml_table(table)))
inflections_file = st.lists(
    st.one_of(st.lists(st.sampled_from(("s", "es", "", "y", "ies", "ed")), min_size=2, max_size=2), values), max_size=4
).map(lambda rules: ("inflections.toml", toml_table({"rules": rules})))
garbage_file = st.tuples(
    st.sampled_from(("nouns_g.toml", "colours_g.toml", "settings.toml", "keywords.toml", "junk.toml", "shades.toml")),
    st.one_of(st.binary(max_size=64), st.text(max_size=64)),
).map(lambda pair: (pair[0], pair[1] if isinstance(pair[1], str) else pair[1].decode("latin-1")))
truncated_file = entries_file().flatmap(
    lambda file: st.integers(0, len(file[1])).map(lambda cut: (file[0], file[1][:cut]))
)
lexicon_files = st.lists(
    st.one_of(
        entries_file(), entries_file(), entries_file(), settings_file, inflections_file, garbage_file, truncated_file
    ),
    min_size=1,
    max_size=4,
)


def write_folder(folder: Path, files: list[tuple[str, str]]) -> None:
    """The files, each under its own name (a second 'nouns_fuzz.toml' becomes 'nouns_fuzz_1.toml')."""
    folder.mkdir()
    for i, (name, text) in enumerate(files):
        path = folder / name
        if path.exists():
            path = folder / f"{name[:-5]}_{i}.toml"
        path.write_text(text, encoding="utf-8", errors="surrogateescape")


@settings(
    max_examples=100,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.function_scoped_fixture],
)
@given(files=lexicon_files)
@example(files=[("nouns_x.toml", '[steel]\nmaps = { "a/../../../ESCAPED" = { graph = "wood", output = "color" } }\n')])
@example(
    files=[("properties_x.toml", '[diffuse]\nstep = { op = "blend", value = 0.1 }\n')]
)  # a colour step on a number
@example(files=[("colours_x.toml", '[zork]\nhex = "#fff"\ndoc = "d"\nexample = "zork steel"\n')])
@example(files=[("adjectives_x.toml", '[brushed]\neffects = [{ param = "roughness", op = "mul", value = 1e300 }]\n')])
def test_random_lexicon_folders_never_crash_the_compiler(tmp_path_factory, files):
    with Sandbox.made(tmp_path_factory.getbasetemp()) as sandbox:
        folder = sandbox.root / "lexicon"
        write_folder(folder, files)
        for name, phrases in (("stdlib_words", PHRASES), ("new_words", NEW_PHRASES)):
            source = sandbox.cwd / f"{name}.cnl"
            source.write_text(phrases, encoding="utf-8")
            before = sandbox.snapshot()
            output = sandbox.out / f"{name}.json"
            run = run_cli(["compile", str(source), "--lexicon", str(folder), "-o", str(output)], b"", sandbox)
            check_run(run, sandbox, before)
            if output.exists():
                strict_json(output.read_text(encoding="utf-8"))
            assert not list(sandbox.root.rglob("*ESCAPED*")), run
            if run.code == 2:  # the lexicon did not load: the second document would say the same
                break
