"""Completion, hover, quick fixes, semantic tokens, colours and inlay hints over stdio."""

from __future__ import annotations

import pytest
from lsprotocol import types

from cnlmc.api import compile_source
from cnlmc.lsp.tokens import TOKEN_TYPES

from .conftest import fresh_uri, open_document, open_fixture, position_of, wait_diagnostics

pytestmark = [pytest.mark.lsp, pytest.mark.asyncio(loop_scope="module")]


def doc_id(uri):
    return types.TextDocumentIdentifier(uri=uri)


async def complete_at(client, text: str, uri=None):
    """Open a one-line document and complete at its end."""
    uri = uri or fresh_uri("complete")
    open_document(client, uri, text)
    await wait_diagnostics(client, uri, 1)
    result = await client.text_document_completion_async(
        types.CompletionParams(text_document=doc_id(uri), position=types.Position(0, len(text)))
    )
    return sorted(result.items, key=lambda item: item.sort_text)


async def test_completion_after_adverb_lists_adjectives_first(client):
    items = await complete_at(client, "lightly ")
    labels = [i.label for i in items]
    assert items[0].kind == types.CompletionItemKind.Function  # an adjective comes first
    assert "brushed" in labels and "anodized" in labels
    assert "aluminum" not in labels  # a noun right after an adverb only warns (W103)
    brushed = next(i for i in items if i.label == "brushed")
    assert "roughness *= 1.2" in brushed.detail
    assert "Abraded in one direction" in brushed.documentation.value


async def test_completion_after_with_a_lists_coats(client):
    items = await complete_at(client, "white oak with a ")
    first = {i.label for i in items[:5]}
    assert {"varnish", "lacquer", "clear coat"} <= first


async def test_completion_at_the_end_offers_nouns_that_fit(client):
    labels = [i.label for i in await complete_at(client, "blue anodized ")]
    assert "aluminum" in labels and "titanium" in labels or "aluminum" in labels
    assert "oak" not in labels  # anodizing is for metals


async def test_completion_knows_the_noun_after_the_cursor(client):
    uri = fresh_uri("noun")
    text = "lightly  oak"
    open_document(client, uri, text)
    await wait_diagnostics(client, uri, 1)
    result = await client.text_document_completion_async(
        types.CompletionParams(text_document=doc_id(uri), position=types.Position(0, 8))
    )
    labels = {i.label for i in result.items}
    assert "brushed" in labels and "anodized" not in labels


async def test_completion_of_a_partial_word_replaces_it(client):
    items = await complete_at(client, "lightly brushed, blue anod")
    assert [i.label for i in items] == ["anodized"]
    assert items[0].text_edit.range == types.Range(types.Position(0, 22), types.Position(0, 26))


async def test_completion_in_a_comment_is_empty(client):
    assert await complete_at(client, "steel # bru") == []


async def test_hover_on_a_word_shows_doc_and_effect(client):
    uri, text, _ = await open_fixture(client, "materials.cnl")
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=doc_id(uri), position=position_of(text, "anodized aluminum", offset=2))
    )
    value = hover.contents.value
    assert "**anodized** — adjective" in value
    assert "roughness = 0.3" in value
    assert hover.range.start == position_of(text, "anodized aluminum")


async def test_hover_on_a_coat_named_alone_shows_the_coat_not_its_implied_substrate(client):
    """'satin varnish' is wood with a satin varnish: 'wood' has the span of 'varnish', and hover
    over 'varnish' still shows the coat the user typed."""
    uri, text = fresh_uri("implied"), "satin varnish"
    open_document(client, uri, text)
    await wait_diagnostics(client, uri, 1)
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=doc_id(uri), position=position_of(text, "varnish", offset=3))
    )
    assert "**varnish**" in hover.contents.value and "**wood**" not in hover.contents.value
    assert hover.range.start == position_of(text, "varnish")


async def test_hover_on_a_material_line_shows_the_explain_table(client):
    uri, text, _ = await open_fixture(client, "materials.cnl")
    hover = await client.text_document_hover_async(
        types.HoverParams(text_document=doc_id(uri), position=position_of(text, "aluminum", offset=1))
    )
    value = hover.contents.value
    material = compile_source(text, "x").materials[0]
    assert "model: conductor + anisotropic" in value
    assert "adjectives.anodized: roughness = 0.3" in value
    assert "colour `#022fa4`" in value  # the survey's blue, made darker by the refinement below
    assert material["name"] == "hull"


async def test_quick_fixes(client):
    uri, text, diags = await open_fixture(client, "materials.cnl")
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=doc_id(uri),
            range=types.Range(types.Position(0, 0), types.Position(20, 0)),
            context=types.CodeActionContext(diagnostics=list(diags)),
        )
    )
    titles = [a.title for a in actions]
    assert "Replace 'blu' with 'blue'" in titles
    assert "Remove 'polished'" in titles and "Remove 'anodized'" in titles and "Remove 'lightly'" in titles
    fixed = apply_all(text, [a for a in actions if a.title.startswith(("Replace 'blu' with 'blue'", "Remove"))], uri)
    assert compile_source(fixed, "x").diagnostics == []


async def test_quick_fix_nearest_named_colour(client):
    uri = fresh_uri("colour")
    open_document(client, uri, "bluuish plastic")  # bluish is a survey colour now
    diags = await wait_diagnostics(client, uri, 1)
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(
            text_document=doc_id(uri), range=diags[0].range, context=types.CodeActionContext(diagnostics=list(diags))
        )
    )
    colour = next(a for a in actions if a.title.startswith("Use the nearest named colour"))
    assert colour.edit.changes[uri][0].new_text == "blue"


def apply_all(text: str, actions, uri) -> str:
    """Apply single-line edits, rightmost first."""
    lines = text.split("\n")
    edits = sorted(
        (e for a in actions for e in a.edit.changes[uri]),
        key=lambda e: (e.range.start.line, e.range.start.character),
        reverse=True,
    )
    for edit in edits:
        line = lines[edit.range.start.line]
        lines[edit.range.start.line] = (
            line[: edit.range.start.character] + edit.new_text + line[edit.range.end.character :]
        )
    return "\n".join(lines)


def decode_tokens(data, text):
    lines = text.split("\n")
    line = col = 0
    out = []
    for i in range(0, len(data), 5):
        delta_line, delta_col, length, kind, _mods = data[i : i + 5]
        line += delta_line
        col = col + delta_col if delta_line == 0 else delta_col
        out.append((lines[line][col : col + length], TOKEN_TYPES[kind]))
    return out


async def test_semantic_tokens(client):
    uri = fresh_uri("tokens")
    text = "# every kind\nhull: lightly brushed, pale orange plastic with a clear coat\nless diffuse\ndark slate blue steel"
    open_document(client, uri, text)
    await wait_diagnostics(client, uri, 1)
    result = await client.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(text_document=doc_id(uri))
    )
    tokens = decode_tokens(result.data, text)
    assert tokens == [
        ("# every kind", "comment"),
        ("hull", "name"),
        ("lightly", "adverb"),
        ("brushed", "adjective"),
        (",", "keyword"),
        ("pale orange", "colour"),  # the survey's name
        ("plastic", "noun"),
        ("with", "keyword"),
        ("a", "keyword"),
        ("clear coat", "coat"),
        ("less", "refinement"),
        ("diffuse", "property"),
        ("dark slate blue", "colour"),
        ("steel", "noun"),
    ]


async def test_semantic_tokens_count_utf16(client):
    uri, text, _ = await open_fixture(client, "unicode.cnl")
    result = await client.text_document_semantic_tokens_full_async(
        types.SemanticTokensParams(text_document=doc_id(uri))
    )
    # decode in UTF-16 code units
    lines = [line.encode("utf-16-le") for line in text.split("\n")]
    line = col = 0
    found = []
    for i in range(0, len(result.data), 5):
        delta_line, delta_col, length, kind, _ = result.data[i : i + 5]
        line += delta_line
        col = col + delta_col if delta_line == 0 else delta_col
        found.append((lines[line][2 * col : 2 * (col + length)].decode("utf-16-le"), TOKEN_TYPES[kind]))
    assert ("plastic", "noun") in found and ("aluminum", "noun") in found and ("木材", "name") in found


async def test_document_colours_and_presentation(client):
    uri, text, _ = await open_fixture(client, "materials.cnl")
    infos = await client.text_document_document_color_async(types.DocumentColorParams(text_document=doc_id(uri)))
    slate = position_of(text, "dark slate blue")
    swatch = next(i for i in infos if i.range.start == slate)
    assert abs(swatch.color.red - 0x21 / 255) < 0.01 and abs(swatch.color.blue - 0x61 / 255) < 0.01  # the survey's
    noun = next(i for i in infos if i.range.start == position_of(text, "aluminum"))
    assert noun.color.blue > 0.5 and noun.color.red < 0.01  # the resolved base colour (darker blue)
    answers = await client.text_document_color_presentation_async(
        types.ColorPresentationParams(text_document=doc_id(uri), color=swatch.color, range=swatch.range)
    )
    assert answers[0].label == "dark slate blue"
    assert answers[0].text_edit.range == swatch.range
    answers = await client.text_document_color_presentation_async(
        types.ColorPresentationParams(
            text_document=doc_id(uri), color=types.Color(0.0, 0.0, 0.5, 1.0), range=swatch.range
        )
    )
    assert {a.label for a in answers} & {
        "dark pure blue",
        "dark ultramarine blue",
        "deep indigo blue",
        "navy",
        "dark blue",
    }  # the survey's names


async def test_inlay_hints(client):
    uri, text, _ = await open_fixture(client, "materials.cnl")
    hints = await client.text_document_inlay_hint_async(
        types.InlayHintParams(text_document=doc_id(uri), range=types.Range(types.Position(0, 0), types.Position(20, 0)))
    )
    by_line = {h.position.line: h.label for h in hints}
    assert by_line[1] == "→ roughness 0.3 · #022fa4"
    assert hints[0].position == types.Position(1, len(text.split("\n")[1]))
    assert 2 not in by_line  # refinement lines carry no hint
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"cnlmc": {"inlayHints": False}})
    )
    hints = await client.text_document_inlay_hint_async(
        types.InlayHintParams(text_document=doc_id(uri), range=types.Range(types.Position(0, 0), types.Position(20, 0)))
    )
    assert list(hints) == []
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"cnlmc": {"inlayHints": True}})
    )
