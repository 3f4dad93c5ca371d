"""Finite numbers at the IR boundary (issue 13): no NaN or infinity reaches the IR, and the IR
is always strict JSON; a value that would not be finite is replaced with a W109 naming the words."""

from __future__ import annotations

import json
import math
import sys
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source
from cnlmc.cache import dump_json, load_json
from cnlmc.lexicon import Lexicon, from_data, load_lexicon, to_data
from cnlmc.lexicon_schema import LexiconError
from cnlmc.material import Document

REFINEMENTS = [
    "more grain",
    "less grain",
    "darker",
    "lighter",
    "rougher",
    "smoother",
    "glossier",
    "more diffuse",
    "less diffuse",
]
MATERIALS = ["white varnished oak", "polished white marble", "lightly brushed, blue anodized aluminum", "red glass"]


def strict(ir: dict[str, Any]) -> str:
    return json.dumps(ir, allow_nan=False)  # raises ValueError on NaN or infinity


def nonfinite_paths(value: Any, path: str = "") -> list[str]:
    if isinstance(value, float):
        return [] if math.isfinite(value) else [path]
    if isinstance(value, list):
        return [p for i, v in enumerate(value) for p in nonfinite_paths(v, f"{path}[{i}]")]
    if isinstance(value, dict):
        return [p for k, v in value.items() for p in nonfinite_paths(v, f"{path}.{k}")]
    return []


def test_a_map_refinement_repeated_stays_in_its_range_and_says_so() -> None:
    """'more grain' 1751 times: each step stops halfway to the graph's range end (as surface
    parameters do), so the value never leaves the range nor overflows; once there, a note says the
    refinement leaves it at the end of its range. Strict JSON, no warning."""
    source = "white varnished oak\n" + "more grain\n" * 1751
    result = compile_source(source, "oak.cnl")
    strict(result.ir)
    assert nonfinite_paths(result.ir) == []
    (material,) = result.materials
    assert material["maps"]["base_color"]["params"]["grain"] == pytest.approx(2.0)  # the range's top
    assert not [d for d in result.diagnostics if d.code in ("W107", "W109")]
    n106 = [d for d in result.diagnostics if d.code == "N106" and "maps.base_color.grain" in d.message]
    assert n106 and n106[-1].span is not None and n106[-1].span.line == 1752


def unchecked_lexicon(folder: Path) -> Lexicon:
    """The stdlib plus a folder's entries, put together without the loader's checks (as a program
    building a Lexicon could): the IR boundary must still hold against such data."""
    data = load_json(dump_json(to_data(load_lexicon())))
    for path in folder.glob("*.toml"):
        category = path.name.split("_")[0]
        for key, fields in tomllib.loads(path.read_text("utf-8")).items():
            data["entries"][category][key] = [fields, str(path)]
    return from_data(data)


def test_nan_and_infinity_from_lexicon_formulas_are_replaced(tmp_path: Path) -> None:
    (tmp_path / "nouns_studio.toml").write_text(
        '[unobtainium]\nclass = "metal"\nmodel = "conductor"\n'
        "roughness = 0.2\nbase_color = [1.0, 0.5, 0.2]\neta = [1e308, 1.0, 1.0]\nk = [3.0, -1e308, 3.0]\n"
        'source = "studio"\ndoc = "A studio metal."\nexample = "cursed unobtainium"\n',
        "utf-8",
    )
    (tmp_path / "adjectives_studio.toml").write_text(
        '[cursed]\naliases = []\ndoc = "Overflows."\nexample = "cursed unobtainium"\n'
        'effects = [{ param = "roughness", op = "mul", value = nan }, { param = "eta", op = "mul", value = 10.0 },'
        ' { param = "k", op = "add", value = [0.0, -1e308, inf] }]\n',
        "utf-8",
    )
    with pytest.raises(
        LexiconError, match=r"adjectives_studio.toml:5:47: key 'cursed.effects\[0\].value': expected a finite"
    ):
        load_lexicon([tmp_path])  # the loader refuses such a folder, naming the key
    result = compile_source("cursed unobtainium", "x.cnl", unchecked_lexicon(tmp_path))
    strict(result.ir)
    assert nonfinite_paths(result.ir) == []
    params = result.materials[0]["params"]
    biggest = sys.float_info.max
    assert params["eta"] == [biggest, 10.0, 10.0]  # +inf without a range -> the largest finite float
    assert params["k"] == [3.0, -biggest, biggest]
    assert params["roughness"] == 0.0  # NaN with a range -> its low end (W107)
    found = {d.message.split(" ")[0]: d.hints for d in result.diagnostics if d.code == "W109"}
    assert found["eta"] == ("set by: cursed",) and found["k"] == ("set by: cursed",)
    assert any(d.code == "W107" and d.message.startswith("roughness nan") for d in result.diagnostics)


@settings(max_examples=50, deadline=None)
@given(
    material=st.sampled_from(MATERIALS),
    lines=st.lists(
        st.tuples(st.sampled_from(REFINEMENTS), st.integers(min_value=1, max_value=1200)), min_size=1, max_size=4
    ),
)
def test_any_refinement_sequence_gives_strict_json(material: str, lines: list[tuple[str, int]]) -> None:
    source = material + "\n" + "".join(f"{word}\n" * count for word, count in lines)
    result = compile_source(source, "x.cnl")
    strict(result.ir)
    assert nonfinite_paths(result.ir) == []


def test_an_ir_with_nan_or_infinity_is_refused_where_backends_read_it() -> None:
    ir = compile_source("polished gold", "x.cnl").ir
    for path, bad in ((("eta", 0), math.nan), (("roughness",), math.inf), (("f0", 2), -math.inf)):
        broken = json.loads(json.dumps(ir))
        holder = broken["materials"][0]["params"]
        if len(path) == 2:
            holder[path[0]][path[1]] = bad
        else:
            holder[path[0]] = bad
        with pytest.raises(ValueError, match=f"materials\\[0\\].params.{path[0]}: expected"):
            Document.from_ir(broken)
    Document.from_ir(ir)  # the compiler's own IR passes
