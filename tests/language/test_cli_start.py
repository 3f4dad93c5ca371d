"""A cold `cnlmc compile` (#14 speed): what it loads, the lexicon's stored form, and `-o -`.

Speed itself is measured by bench/cold_start.py (numbers against a peer process, never timed
assertions); these tests check the behaviour the fast start rests on: the same bytes out, only
the modules a compile needs, a stored lexicon equal to the loaded one and checked when read.
"""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from cnlmc.backends.registry import TargetUnavailable, get_target, load_command
from cnlmc.cache import SUFFIX, encode
from cnlmc.cli import FRONT_END_COMMANDS, build_parser
from cnlmc.lexicon import from_stored, load_lexicon, stored_form
from tests.helpers import run_cnlmc

#: What a compile to standard output never needs: the other commands' front ends, the output
#: writer (only -o), TOML (the lexicon, keywords and graph tables come from the disk cache),
#: lark (stored parse shapes). (tempfile still comes with importlib.resources.)
NOT_ON_A_COLD_COMPILE = (
    "cnlmc.studio.command",
    "cnlmc.batch.command",
    "cnlmc.speech.command",
    "cnlmc.explain",
    "cnlmc.output",
    "cnlmc.lexicon_load",
    "cnlmc.lexicon_schema",
    "socket",
    "numpy",  # the IR needs no array maths (a metal mix imports it only for its own phrase)
    "tomllib",
    "lark",
)


def cli_env(cache_home: Path) -> dict[str, str]:
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    env.pop("CNLMC_NO_CACHE", None)
    return env


def test_a_cold_compile_with_a_warm_cache_loads_only_what_it_needs(tmp_path):
    code = (
        "import sys, io; from cnlmc.cli import main; sys.stdin = io.TextIOWrapper(io.BytesIO(b'white varnished oak\\n'));"
        "code = main(['compile', '-']); "
        "print(code, sorted(m for m in sys.modules if m in set(sys.argv[1:])), file=sys.stderr)"
    )
    command = [sys.executable, "-c", code, *NOT_ON_A_COLD_COMPILE]
    env = cli_env(tmp_path)
    first = subprocess.run(command, capture_output=True, text=True, env=env, timeout=120)  # fills the cache
    assert first.stderr.splitlines()[-1].startswith("0 "), first.stderr
    again = subprocess.run(command, capture_output=True, text=True, env=env, timeout=120)
    assert again.stdout == first.stdout and json.loads(again.stdout)["materials"][0]["name"] == "white_varnished_oak"
    assert again.stderr.splitlines()[-1] == "0 []", again.stderr


def test_each_front_end_command_is_listed_as_it_names_itself():
    for name, entry in FRONT_END_COMMANDS.items():
        command = load_command(name, entry)
        assert (command.name, command.help) == (name, entry.help) and not command.help.startswith(" ")
    assert [load_command(n, e).writes_stdout for n, e in FRONT_END_COMMANDS.items()] == [False, False, True]
    argv = ["build", "catalogue.cnl", "-o", "out", "--target", "ir"]
    assert build_parser(argv).parse_args(argv).command == "build"  # its own arguments, once chosen


def test_the_stored_lexicon_is_the_loaded_one(stdlib):
    fresh = load_lexicon()
    stored = from_stored(stored_form(fresh))
    assert stored.entries == fresh.entries  # (every stored entry decodes its fields here)
    assert stored.forms == fresh.forms
    assert (stored.followers, stored.lengths_from, stored.max_form_words) == (
        fresh.followers,
        fresh.lengths_from,
        fresh.max_form_words,
    )
    assert (stored.keywords, stored.settings, stored.inflections) == (fresh.keywords, fresh.settings, fresh.inflections)
    assert stored.word_formation == json.loads(json.dumps(fresh.word_formation))  # as plain data (tuples: lists)


def test_a_stored_lexicon_looks_words_up_as_the_loaded_one():
    fresh = load_lexicon()
    stored = from_stored(stored_form(fresh))
    for words in [("stainless", "steel"), ("oak",), ("blue-grey",), ("nothing",), ("stainless steel",), ()]:
        assert stored.lookup(words) == fresh.lookup(words), words
    assert stored._forms is None  # looked up without building every form


def test_a_stored_entry_that_fails_its_check_stops_the_run_naming_the_cache(tmp_path):
    from cnlmc.cache import source_key
    from cnlmc.lexicon import lexicon_sources

    payload = stored_form(load_lexicon())
    head, _, body = payload.partition(b"\n")
    table = json.loads(head)["entries"]
    ends = [end for category in table.values() for end in category["ends"]]  # the fields lie one after another
    before = list(table)[: list(table).index("nouns")]
    at = sum(len(table[category]["keys"]) for category in before) + table["nouns"]["keys"].index("oak")
    start, end = (ends[at - 1] if at else 0), ends[at]
    oak = body[start:end]
    assert b'"graph":"wood"' in oak
    forged_oak = oak.replace(b'"graph":"wood"', b'"graph":"w/.."')  # the same length: offsets stay
    forged = head + b"\n" + body[:start] + forged_oak + body[end:]
    key = source_key("lexicon", lexicon_sources((), ()))
    path = tmp_path / "cnlmc" / f"lexicon-{key}{SUFFIX}"
    path.parent.mkdir(mode=0o700)
    path.write_bytes(encode(path.name[: -len(SUFFIX)], forged))
    result = run_cnlmc("compile", "-", stdin="oak\n", env=cli_env(tmp_path), timeout=120)
    assert result.returncode == 2 and result.stdout == ""
    assert "fails its check" in result.stderr and "Traceback" not in result.stderr
    assert "delete the cache folder" in result.stderr


def test_a_malformed_stored_lexicon_is_refused_so_the_cache_rebuilds_it():
    payload = stored_form(load_lexicon())
    head, _, body = payload.partition(b"\n")
    for bad in (b"{}", head, payload.replace(b'"max_form_words":', b'"max_form_words":-', 1), b"[]\n" + body):
        with pytest.raises((ValueError, TypeError, KeyError, IndexError)):
            from_stored(bad)
    table = json.loads(head)
    for part, forged in (("lengths", ["x"]), ("followers", [1])):  # ill-typed derived data: refused at load
        first = next(iter(table[part]))
        wrong = json.dumps({**table, part: {**table[part], first: forged}}, separators=(",", ":")).encode()
        with pytest.raises((ValueError, TypeError)):
            from_stored(wrong + b"\n" + body)


@pytest.mark.parametrize("target", ["ir", "glsl"])
def test_dash_o_dash_is_standard_output_for_a_text_target(tmp_path, target):
    plain = run_cnlmc("compile", "-", "--target", target, stdin="glossy red plastic\n", cwd=tmp_path)
    dashed = run_cnlmc("compile", "-", "--target", target, "-o", "-", stdin="glossy red plastic\n", cwd=tmp_path)
    assert plain.returncode == dashed.returncode == 0, dashed.stderr
    assert dashed.stdout == plain.stdout and dashed.stdout.strip()
    assert list(tmp_path.iterdir()) == []  # no file named '-'


def test_dash_o_dash_for_a_target_that_writes_binary_files_says_what_to_do(tmp_path):
    try:
        get_target("gltf")
    except TargetUnavailable as exc:
        pytest.skip(f"the gltf target is not here: {exc}")
    result = run_cnlmc("compile", "-", "--target", "gltf", "-o", "-", stdin="red plastic\n", cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert "cnlmc: error: -o - writes to standard output, which takes text" in result.stderr
    assert "give -o FOLDER or -o FILE" in result.stderr and "Traceback" not in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_result_with_a_binary_file_prints_nothing_of_it_on_stdout(tmp_path):
    try:
        get_target("materialx")
    except TargetUnavailable as exc:
        pytest.skip(f"the materialx target is not here: {exc}")
    result = run_cnlmc("compile", "-", "--target", "materialx", stdin="white varnished oak\n", cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""  # the .mtlx is not printed half-way
    assert "is binary: give -o PATH" in result.stderr


def test_the_stdout_spool_moves_to_a_file_past_its_limit():
    from cnlmc.commands import Spool

    out = io.BytesIO()
    with Spool(limit=10) as spool:
        spool.write(b"0123456789")
        assert spool.file is None  # in memory up to the limit
        spool.write(b"abc")
        assert spool.file is not None and spool.memory is None
        spool.flush()
        spool.copy_to(out)
    assert out.getvalue() == b"0123456789abc"


def test_a_stored_form_that_names_no_entry_is_refused_when_looked_up():
    from cnlmc.cache import CacheDamaged, dump_json

    head, _, body = stored_form(load_lexicon()).partition(b"\n")
    data = json.loads(head)
    data["forms"]["oak"] = 10**6
    stored = from_stored(dump_json(data) + b"\n" + body)
    assert stored.lookup(("steel",))
    with pytest.raises(CacheDamaged, match="names no entry"):
        stored.lookup(("oak",))


def test_entries_and_results_copy_and_pickle_as_plain_data():
    """An entry read from the stored form pickles and copies as a plain entry (its fields decoded),
    so a compile result can be deep-copied or sent to another process."""
    import copy
    import pickle

    from cnlmc.api import compile_source, lexicon_for

    entry = lexicon_for().require("nouns", "oak")
    for twin in (copy.copy(entry), copy.deepcopy(entry), pickle.loads(pickle.dumps(entry))):
        assert twin == entry and twin.data == entry.data and twin.origin == entry.origin
    result = compile_source("white varnished oak\n")
    assert copy.deepcopy(result).ir == result.ir


@pytest.mark.parametrize("command", ["preview", "bake"])
def test_o_dash_on_a_command_that_writes_files_is_a_usage_error(tmp_path, command):
    """`-o -` is standard output only for compile (and listen); elsewhere it never makes a file named '-'."""
    (tmp_path / "a.cnl").write_text("white varnished oak\n", encoding="utf-8")
    result = run_cnlmc(command, "a.cnl", "-o", "-", cwd=tmp_path)
    assert result.returncode == 2, result.stderr
    assert f"`cnlmc {command}` writes files" in result.stderr and "Traceback" not in result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.cnl"]
