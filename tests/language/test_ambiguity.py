"""Words with several parts of speech: the parser picks the reading the grammar accepts."""

import pytest

from .conftest import first


@pytest.mark.parametrize(
    "text,noun,colour_words",
    [
        ("gold plated steel", "steel", None),
        ("polished gold", "gold", None),
        ("gold or silver", "gold", None),
        ("bright alice blue silk", "silk", ["bright", "alice blue"]),  # silk: a noun, and 'satin' adjective
        ("white wax", "wax", ["white"]),
        ("pine with a wax", "pine", None),
        ("more gloss", None, None),
    ],
)
def test_reading_is_the_one_that_parses(compile_text, text, noun, colour_words):
    if noun is None:
        r = compile_text("steel\n" + text)
        assert r.ok
        return
    m = first(compile_text(text))
    assert m["provenance"]["base_color"][0]["words"][-1].lower() == noun or m["phrase"].endswith(noun)
    if colour_words:
        steps = [s for s in m["provenance"]["base_color"] if s["rule"].startswith("colours: ")]
        assert steps[-1]["words"] == colour_words
