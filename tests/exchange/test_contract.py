"""The exchange targets on the backend contract: options declared and parsed once, typed
materials in, each material's identifier unique even when two materials are equal."""

from __future__ import annotations

import copy
import re

import pytest

from cnlmc.api import emit
from cnlmc.backends.base import OptionError
from cnlmc.backends.registry import TargetUnavailable, get_target

from .conftest import ir_of

TARGETS = ("materialx", "usd", "mitsuba")
MAP_OPTIONS = ("maps", "map_size", "map_format")


@pytest.mark.parametrize("name", TARGETS)
def test_every_exchange_target_declares_the_map_options(name):
    try:
        target = get_target(name)
    except TargetUnavailable as exc:  # a partial install: MaterialX or pxr missing
        pytest.skip(str(exc))
    declared = {option.name: option for option in target.options}
    assert set(MAP_OPTIONS) <= set(declared)
    assert declared["map_size"].type is int and declared["map_size"].default == 256
    assert all(option.doc for option in declared.values())


def test_a_misspelt_value_gets_a_suggestion():
    with pytest.raises(OptionError, match="did you mean 'fragment'"):
        emit(ir_of("polished gold"), "mitsuba", {"form": "fragmnt"})


def test_a_misspelt_option_gets_a_suggestion():
    with pytest.raises(OptionError, match="did you mean 'map_size'"):
        emit(ir_of("polished gold"), "mitsuba", {"map_sise": "16"})


def test_counts_must_be_positive():
    with pytest.raises(OptionError, match=r"spp=0 is outside \[1, 1048576\]"):
        emit(ir_of("polished gold"), "mitsuba", {"spp": "0"})


def test_equal_materials_get_distinct_identifiers():
    ir = copy.deepcopy(ir_of("polished gold"))
    ir["materials"].append(copy.deepcopy(ir["materials"][0]))
    xml = emit(ir, "mitsuba", {"form": "fragment", "maps": "none"}).artifacts[0].content
    ids = re.findall(r'<bsdf type="[a-z]+" id="([^"]+)"', xml)
    assert ids == ["polished_gold", "polished_gold_2"]
