"""The on-disk cache (#13): plain verified data, never code. A flipped byte is ignored and rebuilt,
a crafted pickle never runs, a FIFO in its place never blocks, and the folder stays under its size."""

from __future__ import annotations

import os
import pickle
from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.cache import SUFFIX, DiskCache, cached, decode, dump_json, encode, load_json, source_key
from cnlmc.lexicon import from_data, lexicon_sources, load_lexicon, to_data
from tests.helpers import run_cnlmc


def lexicon_cache_file(cache_home: Path) -> Path:
    """Where the CLI keeps the stdlib lexicon with XDG_CACHE_HOME=cache_home (the same key it computes)."""
    key = source_key("lexicon", lexicon_sources((), ()))
    assert key is not None
    return cache_home / "cnlmc" / f"lexicon-{key}{SUFFIX}"


def cli(cache_home: Path, phrase: str = "brushed steel\n"):
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    env.pop("CNLMC_NO_CACHE", None)
    return run_cnlmc("compile", "-", stdin=phrase, env=env, timeout=60)


class Marker:
    """Unpickling this creates a file: the proof that a cache was executed."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def __reduce__(self):
        return (open, (str(self.path), "w"))


def test_the_lexicon_round_trips_through_plain_data(stdlib):
    again = from_data(load_json(dump_json(to_data(stdlib))))
    assert again.entries == stdlib.entries
    assert (again.settings, again.inflections, again.keywords) == (stdlib.settings, stdlib.inflections, stdlib.keywords)
    assert again.forms == stdlib.forms


def test_the_cli_writes_then_reads_a_verified_cache(tmp_path):
    first = cli(tmp_path)
    path = lexicon_cache_file(tmp_path)
    assert first.returncode == 0 and path.is_file(), first.stderr
    assert path.read_bytes().startswith(b"cnlmc-cache 2 sha256=")
    written = path.stat().st_mtime_ns
    second = cli(tmp_path)
    assert second.returncode == 0 and second.stdout == first.stdout
    assert path.read_bytes().startswith(b"cnlmc-cache 2 sha256=")
    assert oct(path.stat().st_mode & 0o777) == oct(0o600) and written  # private to the user


def test_a_cache_file_with_flipped_bytes_is_ignored_and_rebuilt(tmp_path):
    reference = cli(tmp_path)
    [path] = (tmp_path / "cnlmc").glob("lexicon-*")  # (a key computed here could differ if a source was just edited)
    data = bytearray(path.read_bytes())
    for offset in (100, 2000, 5000, 20000, len(data) - 3):  # five flipped bytes, as in the issue
        data[offset] ^= 0x5A
    path.write_bytes(bytes(data))
    again = cli(tmp_path)
    assert again.returncode == 0, again.stderr
    assert again.stdout == reference.stdout
    decode(path.name[: -len(SUFFIX)], path.read_bytes())  # rebuilt: verifies again
    assert cli(tmp_path).stdout == reference.stdout


@pytest.mark.parametrize("where", ["current", "legacy"])
def test_a_crafted_pickle_at_the_cache_path_never_runs(tmp_path, where):
    marker = tmp_path / "EXECUTED"
    path = lexicon_cache_file(tmp_path)
    if where == "legacy":  # what the pickle cache used to be called
        path = path.with_name(path.name.replace(SUFFIX, ".pickle"))
    path.parent.mkdir(parents=True)
    path.write_bytes(pickle.dumps(Marker(marker)))
    assert pickle.loads(path.read_bytes()) and marker.exists()  # the payload works when unpickled
    marker.unlink()
    result = cli(tmp_path)
    assert result.returncode == 0, result.stderr
    assert not marker.exists()
    assert not path.with_name(path.name.replace(SUFFIX, ".pickle")).exists()  # old pickles are deleted


def test_a_crafted_json_cache_with_a_good_checksum_cannot_smuggle_a_map_role(tmp_path, stdlib):
    data = load_json(dump_json(to_data(stdlib)))  # a copy: the shared lexicon stays as it is
    data["entries"]["nouns"]["oak"][0]["maps"] = {"a/../../../ESCAPED": {"graph": "wood"}}
    path = lexicon_cache_file(tmp_path)
    path.parent.mkdir(parents=True)
    path.write_bytes(encode(path.name[: -len(SUFFIX)], dump_json(data)))
    result = cli(tmp_path, "oak\n")
    assert result.returncode == 0, result.stderr
    assert "ESCAPED" not in result.stdout


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_at_the_cache_path_is_ignored(tmp_path):
    path = lexicon_cache_file(tmp_path)
    path.parent.mkdir(parents=True)
    os.mkfifo(path)
    result = cli(tmp_path)
    assert result.returncode == 0, result.stderr


def test_a_truncated_or_foreign_file_is_corrupt():
    blob = encode("x", b'{"a": 1}')
    assert load_json(decode("x", blob)) == {"a": 1}
    for bad in (blob[:-1], b"", b"garbage", blob.replace(b"cnlmc-cache 2", b"cnlmc-cache 3"), encode("y", b"{}")):
        with pytest.raises(Exception) as info:
            decode("x", bad)
        assert type(info.value).__name__ == "Corrupt"
    with pytest.raises(ValueError):
        load_json(b'{"a": NaN}')


def test_eviction_keeps_the_folder_under_its_limit_oldest_first(tmp_path):
    cache = DiskCache(tmp_path, max_bytes=10_000)
    for i in range(12):
        cache.store(f"entry-{i}", b"x" * 2_000)
        os.utime(cache.path(f"entry-{i}"), (1_000_000 + i, 1_000_000 + i))  # a clear age order
    cache.evict()
    kept = sorted(p.name for p in tmp_path.iterdir())
    assert sum(p.stat().st_size for p in tmp_path.iterdir()) <= 10_000
    assert kept and f"entry-11{SUFFIX}" in kept and f"entry-0{SUFFIX}" not in kept


def test_stale_temporaries_are_cleaned_and_fresh_ones_kept(tmp_path):
    cache = DiskCache(tmp_path, max_bytes=1_000_000)
    old, new = tmp_path / ".tmp-old.cache.json", tmp_path / ".tmp-new.cache.json"
    old.write_bytes(b"x")
    new.write_bytes(b"x")
    os.utime(old, (1_000_000, 1_000_000))
    cache.store("entry", b"{}")
    assert not old.exists() and new.exists()


def test_a_value_the_loader_refuses_is_rebuilt(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    source = tmp_path / "source.txt"
    source.write_text("v1")
    builds = []

    def build() -> dict[str, int]:
        builds.append(1)
        return {"n": len(builds)}

    def load(payload: bytes) -> dict[str, int]:
        value = load_json(payload)
        if not isinstance(value.get("n"), int):
            raise TypeError("n must be a number")
        return dict(value)

    assert cached("test", [source], build, dump_json, load) == {"n": 1}
    assert cached("test", [source], build, dump_json, load) == {"n": 1}  # read back, not rebuilt
    name = f"test-{source_key('test', [source])}"
    DiskCache().store(name, dump_json({"n": "not a number"}))
    assert cached("test", [source], build, dump_json, load) == {"n": 2}


def test_an_unreadable_source_builds_without_the_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    loop = tmp_path / "loop.toml"
    loop.symlink_to(loop)
    assert source_key("test", [loop]) is None
    assert cached("test", [loop], lambda: 7, dump_json, load_json) == 7


def test_a_user_lexicon_is_cached_and_a_changed_file_is_reread(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    from cnlmc.lexicon import cached_lexicon

    folder = tmp_path / "lex"
    folder.mkdir()
    (folder / "nouns_x.toml").write_text("[steel]\nroughness = 0.5\n")
    assert load_lexicon([folder]).entry("nouns", "steel").get("roughness") == 0.5
    first = cached_lexicon.__wrapped__((str(folder),), ())
    (folder / "nouns_x.toml").write_text("[steel]\nroughness = 0.25\n")
    os.utime(folder / "nouns_x.toml", (2_000_000_000, 2_000_000_000))
    second = cached_lexicon.__wrapped__((str(folder),), ())
    assert (first.entry("nouns", "steel").get("roughness"), second.entry("nouns", "steel").get("roughness")) == (
        0.5,
        0.25,
    )


def test_the_parser_tables_come_back_from_plain_data_and_parse_alike(tmp_path, monkeypatch, stdlib):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    from importlib import resources

    from cnlmc import parser
    from cnlmc.grammar_cache import cached_lark

    grammar = resources.files("cnlmc.grammar").joinpath("cnl.lark").read_text("utf-8")
    options = {"parser": "lalr", "propagate_positions": False, "maybe_placeholders": False}
    built = cached_lark(grammar, parser._Lexer, **options)
    files = list((tmp_path / "cnlmc").glob("grammar-*"))
    assert [p.name.endswith(SUFFIX) for p in files] == [True]
    assert b"pickle" not in files[0].read_bytes()[:64]
    loaded = cached_lark(grammar, parser._Lexer, **options)
    assert loaded is not built
    phrases = "lightly brushed, blue anodized aluminum\noak with a glossy white varnish\nred or blue plastic\ndarker\n"
    results = []
    monkeypatch.setattr(stdlib.caches.shapes, "persistent", False)  # parsed, not recalled from stored shapes
    for lark in (built, loaded):
        monkeypatch.setattr(parser, "lark_parser", lambda lark=lark: lark)
        stdlib.caches.shapes.clear()  # parse every line again, with this parser
        results.append(compile_source(phrases, "x.cnl", stdlib).ir)
    stdlib.caches.shapes.clear()
    assert results[0] == results[1] and results[0]["materials"]


def test_a_crafted_lark_pickle_in_the_cache_never_runs(tmp_path):
    marker = tmp_path / "EXECUTED"
    folder = tmp_path / "cnlmc"
    folder.mkdir()
    for name in ("grammar-a03d5813137f7dc8.lark-cache", "grammar-0000000000000000.lark-cache"):
        (folder / name).write_bytes(pickle.dumps(Marker(marker)))
    result = cli(tmp_path)
    assert result.returncode == 0, result.stderr
    assert not marker.exists()
    assert not list(folder.glob("*.lark-cache"))  # removed with the other old pickles


def test_a_cache_folder_others_may_write_is_not_used(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    folder = tmp_path / "cnlmc"
    folder.mkdir()
    folder.chmod(0o777)
    source = tmp_path / "source.txt"
    source.write_text("v1")
    name = f"test-{source_key('test', [source])}"
    (folder / f"{name}{SUFFIX}").write_bytes(encode(name, dump_json({"planted": True})))
    assert cached("test", [source], lambda: {"built": True}, dump_json, load_json) == {"built": True}
    assert [p.name for p in folder.iterdir()] == [f"{name}{SUFFIX}"]  # nothing written there either
    folder.chmod(0o700)
    assert cached("test", [source], lambda: {"built": True}, dump_json, load_json) == {"planted": True}
