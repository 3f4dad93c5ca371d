"""Options, markers and fixtures shared by every test folder.

- ``--update-goldens``: golden tests rewrite the golden files whose content changed instead of
  failing on them (write-if-different); the run ends with the list of rewritten files.
  ``--refreeze`` also recompiles the frozen IR inputs (tests/exchange/golden/input.ir.json).
- ``goldens``: the fixture golden tests compare (or update) through.
- ``gl``: a standalone OpenGL context on EGL for tests that draw with it themselves.
- ``gl_available``: skips unless the preview can open its own OpenGL context here.
Tests that use either GL fixture carry the ``gl`` marker (``-m "not gl"`` leaves them out).
Plain helpers (the CLI runner, the phrase-per-model table) are in tests/helpers.py.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest

from tests.helpers import Goldens

GOLDENS = pytest.StashKey[Goldens]()
GL_FIXTURES = ("gl", "gl_available")


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("goldens")
    group.addoption(
        "--update-goldens",
        action="store_true",
        help="rewrite the golden files whose content changed instead of comparing; review git diff afterwards",
    )
    group.addoption(
        "--refreeze",
        action="store_true",
        help="also recompile frozen IR inputs from their phrases (tests/exchange); implies --update-goldens",
    )


def pytest_configure(config: pytest.Config) -> None:
    config.stash[GOLDENS] = Goldens(config.getoption("update_goldens"), config.getoption("refreeze"))


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if any(name in getattr(item, "fixturenames", ()) for name in GL_FIXTURES):
            item.add_marker(pytest.mark.gl)


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter, config: pytest.Config) -> None:
    goldens = config.stash.get(GOLDENS, None)
    if goldens is None or not goldens.updating:
        return
    if not goldens.rewritten:
        terminalreporter.write_line("update-goldens: every golden file checked was up to date")
        return
    terminalreporter.write_line(f"update-goldens: rewrote {len(goldens.rewritten)} file(s); review git diff:")
    for path in goldens.rewritten:
        terminalreporter.write_line(
            f"  {path.relative_to(config.rootpath) if path.is_relative_to(config.rootpath) else path}"
        )


@pytest.fixture(scope="session")
def goldens(pytestconfig: pytest.Config) -> Goldens:
    return pytestconfig.stash[GOLDENS]


@pytest.fixture(scope="session")
def gl() -> Iterator[Any]:
    """A standalone OpenGL context on EGL (moderngl), released at the end of the session."""
    moderngl = pytest.importorskip("moderngl", reason="moderngl is not installed (pip install -e '.[glsl]')")
    try:
        ctx = moderngl.create_context(standalone=True, backend="egl")
    except Exception as exc:
        pytest.skip(f"no OpenGL context on EGL ({exc}); install libegl1 libgl1 libegl-mesa0")
    yield ctx
    ctx.release()


@pytest.fixture(autouse=True)
def _gl_is_current(request: pytest.FixtureRequest) -> None:
    """The preview makes its own context current: a test that draws with ``gl`` gets it back first."""
    if "gl" in request.fixturenames:
        request.getfixturevalue("gl").__enter__()


@pytest.fixture(scope="session")
def gl_available() -> None:
    """Skips unless an OpenGL 3.3 context on EGL opens here, as the preview needs (preview, AR)."""
    moderngl = pytest.importorskip("moderngl", reason="moderngl is not installed (pip install -e '.[preview]')")
    try:
        probe = moderngl.create_context(standalone=True, backend="egl", require=330)
    except Exception as exc:  # pragma: no cover - machine without EGL
        pytest.skip(f"no OpenGL 3.3 on EGL here ({exc}); install libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri")
    probe.release()
