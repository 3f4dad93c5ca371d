"""The material being compiled: parameters, provenance and diagnostics, shared by the passes."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from . import ast
from .diagnostics import Diagnostic
from .formulas import round6, rounded
from .lexicon import Entry, Lexicon
from .params import noun_params

NOUN_PARAMS = noun_params()  # what a lexicon noun may set, from the parameter table

Words = tuple[ast.Word, ...]
WordLists = tuple[list[str], list[list[int]]]  # a step's words as JSON: their texts and spans
JSONDict = dict[str, Any]


class Step:
    """One provenance step: the rule, the words (AST Words) and the value it produced."""

    __slots__ = ("rule", "words", "value", "source")

    def __init__(self, rule: str, words: Words, value: Any, source: str | None = None) -> None:
        self.rule, self.words, self.value, self.source = rule, words, value, source

    @property
    def texts(self) -> list[str]:
        return [w.text for w in self.words]

    def to_json(self, memo: dict[int | tuple[int, ...], WordLists] | None = None) -> JSONDict:
        """The JSON form; `memo` shares the word lists of steps that name the same words."""
        return step_json(self, {} if memo is None else memo)


def words_key(words: Words) -> int | tuple[int, ...]:
    """The words by where they start in the source: one word, one token (cheaper than hashing the words)."""
    return words[0].span.start if len(words) == 1 else tuple([w.span.start for w in words])


def same_texts(texts: list[str], words: Words) -> bool:
    """Whether remembered word texts are those of `words` ('wood' implied by 'varnish' starts where it does)."""
    if len(words) == 1:
        return texts[0] == words[0].text
    return texts == [w.text for w in words]


def step_json(step: Step, shared: dict[int | tuple[int, ...], WordLists]) -> JSONDict:
    """A step's JSON form; `shared` (words_key -> their texts and spans) is filled as it goes."""
    words = step.words
    key = words[0].span.start if len(words) == 1 else words_key(words)  # words_key, its common case inline
    lists = shared.get(key)
    if lists is None or not same_texts(lists[0], words):  # an implied word shares its implier's start
        lists = shared[key] = ([w.text for w in words], [w.span.as_list() for w in words])
    if step.source:  # lexicon values are exact
        return {"rule": step.rule, "words": lists[0], "spans": lists[1], "value": step.value, "source": step.source}
    value = step.value
    return {
        "rule": step.rule,
        "words": lists[0],
        "spans": lists[1],
        "value": round6(value) if type(value) is float else rounded(value),
    }


@dataclass
class Context:
    lexicon: Lexicon
    seed: int = 0
    filename: str = "<input>"

    @property
    def settings(self) -> dict[str, Any]:
        return self.lexicon.settings


@dataclass
class MaterialState:
    """Everything one material (one variant) accumulates on its way to the IR."""

    name: str
    phrase: str
    selection: ast.Material
    variant: dict[str, Any] | None = None
    noun: Entry | None = None
    kind: str = "dielectric"
    params: dict[str, Any] = field(default_factory=dict)
    coat: dict[str, Any] | None = None
    maps: dict[str, JSONDict] = field(default_factory=dict)
    provenance: dict[str, list[Step]] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    applied: list[tuple[str, ast.Word]] = field(default_factory=list)  # (adjective key, Word) in order
    brackets: dict[str, Any] = field(default_factory=dict)  # refinement search state per target
    model: dict[str, Any] | None = None
    label: str = ""  # the name as written, when `name` (an identifier) could not keep it

    def record(
        self,
        param: str,
        value: Any,
        rule: str,
        words: tuple[ast.Word, ...] | list[ast.Word] = (),
        source: str | None = None,
    ) -> None:
        """Set a parameter and remember which words and rule set it."""
        self.params[param] = value
        self.note(param, value, rule, words, source)

    def note(
        self,
        param: str,
        value: Any,
        rule: str,
        words: tuple[ast.Word, ...] | list[ast.Word] = (),
        source: str | None = None,
    ) -> None:
        self.provenance.setdefault(param, []).append(Step(rule, tuple(words), value, source))

    def words_of(self, param: str) -> set[str]:
        """Lexicon keys of the words that set `param` (for 'darker blue')."""
        return {w.key for step in self.provenance.get(param, []) for w in step.words}
