"""The lexicons a program keeps (cnlmc.lexicon.LexiconStore): state with an owner, bounded, fresh (#13).

It replaced a module-level `lru_cache` that kept every lexicon it made by folder name for the
life of the process: a user lexicon edited while the language server or a build pipeline ran
was never read again, and nothing could let the lexicons (and their memos) go.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.lexicon import STORE, LexiconStore, cached_lexicon


@pytest.fixture
def user_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    folder = tmp_path / "lex"
    folder.mkdir()
    (folder / "nouns_x.toml").write_text("[steel]\nroughness = 0.5\n")
    return folder


def roughness(lexicon: object) -> float:
    return compile_source("steel", "<store>", lexicon).materials[0]["params"]["roughness"]  # type: ignore[arg-type]


def test_an_unchanged_lexicon_is_the_same_object(user_folder: Path) -> None:
    store = LexiconStore()
    assert store.get((str(user_folder),)) is store.get((str(user_folder),))
    assert lexicon_for() is lexicon_for() is cached_lexicon((), ()) and cached_lexicon is STORE


def test_an_edited_user_lexicon_is_read_again_and_the_old_one_let_go(user_folder: Path) -> None:
    store = LexiconStore()
    first = store.get((str(user_folder),))
    assert roughness(first) == 0.5
    (user_folder / "nouns_x.toml").write_text("[steel]\nroughness = 0.25\n")
    os.utime(user_folder / "nouns_x.toml", (2_000_000_000, 2_000_000_000))
    second = store.get((str(user_folder),))
    assert second is not first and roughness(second) == 0.25
    assert len(store) == 1  # the edited folder's old lexicon is not kept beside the new one
    (user_folder / "nouns_more.toml").write_text("[copper]\nroughness = 0.125\n")  # a file added
    assert store.get((str(user_folder),)) is not second


def test_the_store_is_bounded_and_can_let_everything_go(tmp_path: Path, user_folder: Path) -> None:
    store = LexiconStore(limit=1)
    other = tmp_path / "other"
    other.mkdir()
    (other / "nouns_x.toml").write_text("[steel]\nroughness = 0.125\n")
    first = store.get((str(user_folder),))
    assert roughness(store.get((str(other),))) == 0.125
    assert len(store) == 1 and store.get((str(user_folder),)) is not first  # the least recently used went
    store.clear()
    assert len(store) == 0
