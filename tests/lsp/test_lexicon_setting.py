"""The `lexicon` setting: the server speaks German (or the paper's table) when asked."""

from __future__ import annotations

import pytest
import pytest_lsp
from lsprotocol import types
from pytest_lsp import LanguageClient

from .conftest import CONFIG, fresh_uri, initialize_params, open_document, replace_all, wait_diagnostics

pytestmark = [pytest.mark.lsp, pytest.mark.asyncio(loop_scope="module")]


@pytest_lsp.fixture(config=CONFIG, scope="module")
async def german(lsp_client: LanguageClient):
    await lsp_client.initialize_session(initialize_params(lexicon=["de"]))
    yield
    await lsp_client.shutdown_session()


async def test_german_phrase_is_clean_with_the_de_lexicon(german):
    uri = fresh_uri("de")
    open_document(german, uri, "leicht gebürstetes, blau eloxiertes Aluminium\n")
    assert not await wait_diagnostics(german, uri, 1)


async def test_changing_the_setting_rechecks_open_documents(german):
    uri = fresh_uri("de_switch")
    open_document(german, uri, "poliertes Messing\n")
    assert not await wait_diagnostics(german, uri, 1)
    german.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"lexicon": []}))
    replace_all(german, uri, "poliertes Messing\n", 2)
    diags = await wait_diagnostics(german, uri, 2)
    assert [d.message for d in diags][:1] == ["unknown word 'poliertes'"]
    german.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"lexicon": ["de"]}))
    replace_all(german, uri, "poliertes Messing\n", 3)
    assert not await wait_diagnostics(german, uri, 3)


async def test_a_bad_lexicon_setting_keeps_the_old_words(german):
    german.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"lexicon": ["klingon"]}))
    uri = fresh_uri("de_bad")
    open_document(german, uri, "poliertes Messing\n")
    assert not await wait_diagnostics(german, uri, 1)
