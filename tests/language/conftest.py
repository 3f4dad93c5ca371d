import pytest

from cnlmc.api import compile_source, lexicon_for


@pytest.fixture(scope="session")
def stdlib():
    return lexicon_for()


@pytest.fixture(scope="session")
def paper():
    return lexicon_for(("paper",))


@pytest.fixture
def compile_text(stdlib):
    def run(text, lexicon=None):
        return compile_source(text, "test.cnl", lexicon or stdlib)

    return run


def first(result):
    assert result.ok, [d.message for d in result.diagnostics]
    return result.materials[0]


def look(lexicon, text):
    """Compile one phrase that must compile without a warning (notes are fine): the result and
    the meaning of its one material (model, params, maps), to compare with another phrase's."""
    result = compile_source(text, "look.cnl", lexicon)
    assert result.ok, (text, [d.message for d in result.diagnostics])
    assert not [d for d in result.diagnostics if d.severity.name == "WARNING"], text
    (material,) = result.ir["materials"]
    return result, {k: material[k] for k in ("model", "params", "maps")}
