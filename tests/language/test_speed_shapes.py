"""Parse shapes kept in the disk cache (cnlmc.shape_store): a warm start never loads lark, and what
a stored shape builds is exactly what a fresh parse builds; a damaged entry is parsed again."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from cnlmc.api import lexicon_for
from cnlmc.cache import SUFFIX, DiskCache
from cnlmc.parser import parse_line_shape
from cnlmc.shape_store import StoredShapes, decode_entry, encode_entry, save_shapes
from cnlmc.syntax import ShapeCache
from cnlmc.tagger import Tagger

PHRASES = [
    "hull: lightly brushed, blue anodized aluminum",
    "oak with a glossy white varnish",
    "red or blue anodized aluminum",
    "darker blue, less diffuse",
    "pale dark slate gray plastic",
    "gold plated steel",
    "polished gold",
    "shinier aluminum",
    "marble with grey veins",
    "steel in charcoal",
    "Oak, oiled",
    "walnut brown leather",
]
ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def lexicon():
    return lexicon_for()


def _words(lexicon, line):
    tagged, _ = Tagger(lexicon).tag_line(line, 1, 0)
    return [t for t in tagged if t.candidates]


@pytest.mark.parametrize("line", PHRASES)
def test_a_stored_shape_builds_what_a_fresh_parse_builds(lexicon, line):
    words = _words(lexicon, line)
    shapes = ShapeCache(persistent=False)
    shape, picks = parse_line_shape(words, shapes)
    ((key, (_, choice)),) = shapes.items()
    again, again_choice = decode_entry(key, json.loads(json.dumps(encode_entry(shape, choice))))
    assert again == shape and again_choice == choice
    assert again.build(words, picks, line) == shape.build(words, picks, line)


@pytest.mark.parametrize(
    "damage",
    [
        lambda e: [[99], e[1], e[2]],  # a word position outside the line
        lambda e: [e[0], ["M", *e[1][1:]] if e[1][0] == "R" else ["R", *e[1][1:]], e[2]],  # the other kind of line
        lambda e: [e[0], [e[1][0], *e[1][1:-1]], e[2]],  # a field missing
        lambda e: [e[0], e[1], [7] * 40],  # a reading the words do not have
        lambda e: [e[0], json.loads(json.dumps(e[1]).replace("0", "50")), e[2]],  # indices past the words
        lambda e: "not an entry",
    ],
)
def test_a_damaged_entry_is_dropped_and_the_line_parsed(lexicon, damage):
    line = "hull: lightly brushed, blue anodized aluminum"
    words = _words(lexicon, line)
    fresh = ShapeCache(persistent=False)
    shape, picks = parse_line_shape(words, fresh)
    ((key, (_, choice)),) = fresh.items()
    store = StoredShapes(None, "", {key: damage(encode_entry(shape, choice))})
    assert store.recall(key) is None and key not in store.entries
    shapes = ShapeCache()
    shapes.stored = store  # this store, not the disk's
    again, again_picks = parse_line_shape(words, shapes)
    assert again.build(words, again_picks, line) == shape.build(words, picks, line)
    assert shapes.fresh == 1, "parsed, not recalled"


def _run(args, cache_home, no_cache=False):
    env = {k: v for k, v in os.environ.items() if k != "CNLMC_NO_CACHE"}
    env["XDG_CACHE_HOME"] = str(cache_home)
    if no_cache:
        env["CNLMC_NO_CACHE"] = "1"
    code = (
        "import runpy, sys; sys.argv = ['cnlmc', *sys.argv[1:]]\n"
        "try:\n    runpy.run_module('cnlmc', run_name='__main__')\n"
        "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
        "sys.stderr.write('LARK LOADED' if 'lark' in sys.modules else 'NO LARK')\n"
    )
    done = subprocess.run([sys.executable, "-c", code, *args], env=env, capture_output=True, timeout=120, cwd=ROOT)
    assert done.returncode == 0, done.stderr.decode()
    return done.stdout, done.stderr.decode()


def test_a_warm_start_never_loads_lark_and_writes_the_same_bytes(tmp_path):
    source = tmp_path / "a.cnl"
    source.write_text("\n".join(PHRASES[:8]) + "\nmore grain\n", encoding="utf-8")
    args = ["compile", str(source), "--target", "ir"]
    first, first_log = _run(args, tmp_path / "cache")
    assert first_log.endswith("LARK LOADED")
    stored = list((tmp_path / "cache" / "cnlmc").glob(f"shapes-*{SUFFIX}"))
    assert len(stored) == 1
    warm, warm_log = _run(args, tmp_path / "cache")
    assert warm_log.endswith("NO LARK"), warm_log
    plain, _ = _run(args, tmp_path / "other", no_cache=True)
    assert warm == first == plain and b'"materials"' in warm
    assert not (tmp_path / "other").exists(), "CNLMC_NO_CACHE writes nothing"


def test_a_new_line_shape_is_parsed_and_added(tmp_path):
    source = tmp_path / "a.cnl"
    source.write_text("blue anodized aluminum\n", encoding="utf-8")
    _run(["compile", str(source), "--target", "ir"], tmp_path / "cache")
    source.write_text("blue anodized aluminum\noak with a glossy white varnish\n", encoding="utf-8")
    _, log = _run(["compile", str(source), "--target", "ir"], tmp_path / "cache")
    assert log.endswith("LARK LOADED")
    (stored,) = (tmp_path / "cache" / "cnlmc").glob(f"shapes-*{SUFFIX}")
    cache = DiskCache(stored.parent)
    rows = json.loads(cache.load(stored.name[: -len(SUFFIX)]))["shapes"]
    assert len(rows) == 2
    _, log = _run(["compile", str(source), "--target", "ir"], tmp_path / "cache")
    assert log.endswith("NO LARK")


def test_a_stored_entry_with_a_wrong_digest_is_not_used(tmp_path, monkeypatch, lexicon):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CNLMC_NO_CACHE", raising=False)
    store = StoredShapes.load()
    assert store.cache is not None and store.entries == {}
    line = "blue anodized aluminum"
    words = _words(lexicon, line)
    shapes = ShapeCache()
    parse_line_shape(words, shapes)
    save_shapes(shapes)
    path = store.cache.path(StoredShapes.load().name)
    assert StoredShapes.load().entries
    blob = path.read_bytes()
    path.write_bytes(blob[:-3] + b"[]}")  # the payload changed, its digest not
    assert StoredShapes.load().entries == {}
