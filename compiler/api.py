"""The facade: parse, analyze, emit, compile. What the CLI, the LSP and pipelines call."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .analyze import analyze, to_ir
from .diagnostics import has_errors
from .document import parse_document
from .lexicon import cached_lexicon
from .state import Context


def lexicon_for(specs=()) -> Lexicon:  # noqa: F821
    """`specs` are overlay names ('paper') or lexicon folders; folders are searched first."""
    paths = tuple(str(s) for s in specs if Path(s).is_dir())
    overlays = tuple(str(s) for s in specs if not Path(s).is_dir())
    return cached_lexicon(paths, overlays)


@dataclass
class Result:
    """What compiling one source gives: the IR document, diagnostics, and the stages on the way."""

    ir: dict
    diagnostics: list
    document: object = None
    states: list = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not has_errors(self.diagnostics)

    @property
    def materials(self) -> list[dict]:
        return self.ir["materials"]


def compile_source(source: str, filename: str = "<input>", lexicon=None, seed: int = 0) -> Result:
    lexicon = lexicon or lexicon_for()
    doc = parse_document(source, lexicon, filename)
    ctx = Context(lexicon, seed=seed, filename=filename)
    states, diags = analyze(doc, ctx)
    return Result(to_ir(states, diags, ctx), diags, doc, states)


def compile_phrase(phrase: str, lexicon=None, seed: int = 0) -> dict:
    """One phrase -> its first material's IR (raises ValueError with the rendered errors)."""
    result = compile_source(phrase, "<phrase>", lexicon, seed)
    if not result.ok or not result.materials:
        from .diagnostics import render

        raise ValueError(
            "\n".join(render(d, phrase, "<phrase>") for d in result.diagnostics if d.is_error)
            or "the phrase names no material"
        )
    return result.materials[0]


def emit(ir: dict, target: str, options: dict | None = None):
    """Run a backend on an IR document; returns its artifacts."""
    from cnlmc.backends.registry import get_backend

    return get_backend(target).emit(ir, options or {})


class Session:
    """Interactive refinement: session.refine("darker") changes the material, as in the paper."""

    def __init__(self, phrase: str, lexicon=None, seed: int = 0):
        self.lines = [phrase]
        self.lexicon = lexicon or lexicon_for()
        self.seed = seed
        self.result = self._compile()

    def _compile(self) -> Result:
        return compile_source("\n".join(self.lines), "<session>", self.lexicon, self.seed)

    def refine(self, words: str) -> dict:
        """Apply a refinement line; a line that fails leaves the material as it was."""
        self.lines.append(words)
        result = self._compile()
        if not result.ok:
            self.lines.pop()
            raise ValueError("; ".join(d.message for d in result.diagnostics if d.is_error))
        self.result = result
        return self.material

    @property
    def material(self) -> dict:
        return self.result.materials[0]

    @property
    def warnings(self) -> list:
        return [d for d in self.result.diagnostics if not d.is_error]
