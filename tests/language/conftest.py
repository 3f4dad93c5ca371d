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
