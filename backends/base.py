"""The backend contract: what a target provides, and the one path every target's options,
materials and files take.

A target is a subclass of `Target` (its declarations are class attributes; an instance may own
what it loads once, such as templates, for its lifetime):

    class GlslTarget(Target):
        name = "glsl"
        description = "GLSL 330 / ES 300 BRDF library + standalone preview shaders"
        capabilities = {"model.diffuse": ("exact", "Lambert"), ...}   # every ALL_FEATURES key
        options = (
            Option("fresnel", str, "exact", choices=("exact", "f82", "schlick"), doc="conductor Fresnel"),
            Option("size", int, 512, doc="image size in pixels"),
        )

        def emit(self, document: Document, options: Options) -> EmitResult:
            return emit_each(self, document, lambda material: [...Artifacts of one material...])

    TARGET = GlslTarget()                               # what the registry imports

- `Option(name, type, default, choices=None, doc="", range=None)`: type is str, int, float or
  bool (bool reads on/off, true/false, yes/no, 1/0). A default of None means "not set". A float
  is always finite (nan and inf are refused); `range=(low, high)` bounds a number, inclusive.
- `parse_options(declared, pairs, target) -> Options`: the raw `--option KEY=VALUE` pairs (strings,
  or values of the option's type already) parsed once into typed values; every declared
  option is present, with its default when not given. The compiler's own options (`seed`
  int, `output` str, see COMPILER_OPTIONS) are accepted by every target. Unknown keys and
  values outside `choices` raise `OptionError` (a ValueError) whose text names the target
  and says "did you mean 'x'?" for a close match. `Options` is a read-only mapping with
  attribute access: `options["size"]` or `options.size`.
- `Target.emit(document, options) -> EmitResult`: typed materials in (`cnlmc.material.Document`),
  files out (`Artifact`s, written by the caller through `cnlmc.output.write_artifacts`),
  capability notes beside them. `Target.emit_ir(ir, pairs)` is what callers use: it parses
  the options once and hands a typed Document to `emit`.
- `emit_each(target, document, emit_material, capabilities_of=None) -> EmitResult`: the one
  per-material loop: each material goes through the target's capability table
  (`capabilities.check_material`: notes for approximations, `BackendRefused` for a refusal;
  `capabilities_of(material)` where options or the material choose the table), then
  `emit_material(material)`; two artifacts with one name raise a ValueError naming both materials.
- `as_document(ir)`: the typed Document of an IR in either form.
- `Command`: a CLI subcommand a target brings (name, help, add_arguments(parser),
  run(args) -> exit code), e.g. `cnlmc bake` of the maps target (backends/maps/commands.py).
  The registry lists each by name, class and help (`registry.BUILTIN_COMMANDS`, one line per
  command) so the CLI builds its parser without importing any target; the command's module
  is imported only when that command runs.
- Maps that have to become images go through the one baking service,
  `cnlmc.backends.maps.service` (`bake_arrays`, `bake_files`, `bake_artifacts`; errors are
  `MapBakeError`, naming the material).
- Module-form targets (NAME, DESCRIPTION, CAPABILITIES, emit(ir_dict, options_dict)), as older
  plugins are written, still load: the registry wraps them (`registry.ModuleTarget`).
"""

from __future__ import annotations

import argparse
import difflib
import math
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

from cnlmc.material import COLOUR_SPACE, Document, Material

from .capabilities import EmitResult, Note, check_material

__all__ = [
    "Artifact",
    "Command",
    "COMPILER_OPTIONS",
    "EmitResult",
    "Option",
    "OptionError",
    "Options",
    "Target",
    "did_you_mean",
    "emit_each",
    "parse_options",
]

DOCUMENT_FIELDS = ("ir_version", "source", "lexicon", "colour_space", "materials", "diagnostics")
TRUE_WORDS, FALSE_WORDS = ("on", "true", "yes", "1"), ("off", "false", "no", "0")


@dataclass(frozen=True)
class Artifact:
    """One output file: a name relative to the output folder, and its content."""

    name: str
    content: str | bytes
    kind: str = "text"


class OptionError(ValueError):
    """An option name or value a target does not know; the text is meant for users."""


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """'; did you mean 'x'?' for the closest choice, or ''."""
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""


@dataclass(frozen=True)
class Option:
    """One declared `--option`: its name, value type, default, allowed values and meaning."""

    name: str
    type: type
    default: Any
    choices: tuple[Any, ...] | None = None
    doc: str = ""
    range: tuple[float, float] | None = None  # inclusive bounds of a number

    def parse(self, raw: object, target: str) -> Any:
        """A raw value (text, or already of the option's type) -> the typed value."""
        if raw is None or (isinstance(raw, str) and not raw.strip() and self.default is None):
            return self.default
        value = self._typed(raw, target)
        if self.choices is not None and value not in self.choices:
            shown = ", ".join(str(c) for c in self.choices)
            hint = did_you_mean(str(value), [str(c) for c in self.choices])
            raise OptionError(f"{target}: option {self.name}={value!r} is not one of {shown}{hint}")
        if self.range is not None and not self.range[0] <= value <= self.range[1]:
            low, high = (_shown(bound) for bound in self.range)
            raise OptionError(f"{target}: option {self.name}={value!r} is outside [{low}, {high}]")
        return value

    def _typed(self, raw: object, target: str) -> Any:
        if self.type is str:
            text = str(raw).strip()
            return self._choice_spelling(text)
        if isinstance(raw, self.type) and not (self.type is int and isinstance(raw, bool)):
            return raw
        text = str(raw).strip().lower()
        if self.type is bool:
            if text in TRUE_WORDS or text in FALSE_WORDS:
                return text in TRUE_WORDS
            raise OptionError(f"{target}: option {self.name}={raw!r} must be on or off")
        try:
            value = self.type(text)
        except ValueError:
            what = "a whole number" if self.type is int else "a number"
            raise OptionError(f"{target}: option {self.name}={raw!r} must be {what}") from None
        if self.type is float and not math.isfinite(value):
            raise OptionError(f"{target}: option {self.name}={raw!r} must be a finite number")
        return value

    def _choice_spelling(self, text: str) -> str:
        """A choice matches whatever its case: FRESNEL=Schlick is 'schlick'."""
        if self.choices is None or text in self.choices:
            return text
        folded = {str(c).lower(): c for c in self.choices}
        return str(folded.get(text.lower(), text))


def _shown(number: float) -> str:
    """A bound as a person writes it: 1048576, 0.5, 1e+06 only past whole numbers' reach."""
    return str(int(number)) if float(number).is_integer() and abs(number) < 1e15 else f"{number:g}"


#: Options the compiler passes to every target, beside the user's --option KEY=VALUE pairs.
COMPILER_OPTIONS = (
    Option("seed", int, 0, doc="seed for procedural maps (the --seed flag)"),
    Option("output", str, None, doc="where the files go (the -o flag), when the target needs to know"),
)


class Options(Mapping[str, Any]):
    """Parsed options: every declared name -> its typed value. Read-only."""

    def __init__(self, target: str, values: Mapping[str, Any]):
        self._target = target
        self._values = dict(values)

    def __getitem__(self, key: str) -> Any:
        return self._values[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __getattr__(self, key: str) -> Any:
        try:
            values: dict[str, Any] = self.__dict__["_values"]
            return values[key]
        except KeyError:
            raise AttributeError(f"{self.__dict__.get('_target', '?')}: no option {key!r}") from None

    def __repr__(self) -> str:
        return f"Options({self._target!r}, {self._values!r})"


def parse_options(declared: Iterable[Option], pairs: Mapping[str, object] | None, target: str) -> Options:
    """Parse raw option pairs once against the declared options (see the module docstring)."""
    own = {option.name: option for option in declared}
    table = {**{o.name: o for o in COMPILER_OPTIONS}, **own}
    raw = dict(pairs or {})
    unknown = sorted(set(raw) - set(table))
    if unknown:
        hint = did_you_mean(unknown[0], own)
        raise OptionError(f"{target}: unknown option(s) {', '.join(unknown)}; known: {', '.join(own)}{hint}")
    return Options(target, {name: option.parse(raw.get(name), target) for name, option in table.items()})


class Command:
    """A CLI subcommand a target brings: `cnlmc NAME ...`."""

    name: ClassVar[str]
    help: ClassVar[str]
    #: whether `-o -` is standard output (the CLI refuses `-o -` for a command that writes files)
    writes_stdout: ClassVar[bool] = False

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        """Declare the subcommand's arguments on its own subparser."""

    def run(self, args: argparse.Namespace) -> int:
        """Do the work; return the exit code (0 ok, 1 errors in the input, 2 usage)."""
        raise NotImplementedError


class Target:
    """A backend: see the module docstring. Subclasses set the class attributes and `emit`."""

    name: str
    description: str
    capabilities: Mapping[str, tuple[str, str]]
    options: tuple[Option, ...] = ()

    def emit(self, document: Document, options: Options) -> EmitResult:
        raise NotImplementedError

    def parse_options(self, pairs: Mapping[str, object] | None) -> Options:
        return parse_options(self.options, pairs, self.name)

    def emit_ir(self, ir: Document | Mapping[str, Any], pairs: Mapping[str, object] | None = None) -> EmitResult:
        """Parse the options once, type the IR once, emit."""
        options = self.parse_options(pairs)
        return self.emit(as_document(ir), options)


def as_document(ir: Document | Mapping[str, Any]) -> Document:
    """The typed document of an IR in either form. A dict with `materials` but not every
    document field (tools and tests build such) gets the others empty."""
    if isinstance(ir, Document):
        return ir
    if set(DOCUMENT_FIELDS) <= set(ir):
        return Document.from_ir(dict(ir))
    materials = tuple(Material.from_ir(m, f"materials[{i}]") for i, m in enumerate(ir["materials"]))
    return Document(1, "", (), COLOUR_SPACE, materials, ())


def emit_each(
    target: Target,
    document: Document,
    emit_material: Callable[[Material], Iterable[Artifact]],
    capabilities_of: Callable[[Material], Mapping[str, tuple[str, str]]] | None = None,
) -> EmitResult:
    """The per-material loop every target shares: capability notes, then the material's files.
    `capabilities_of(material)`: the table for one material where options or the material
    choose it (e.g. maps=none, a per-material plugin); default `target.capabilities`."""
    notes: list[Note] = []
    artifacts: list[Artifact] = []
    seen: dict[str, str] = {}
    for material in document.materials:
        table = target.capabilities if capabilities_of is None else capabilities_of(material)
        check_material(notes, target.name, table, material)
        for artifact in emit_material(material):
            if artifact.name in seen:
                raise ValueError(
                    f"{target.name}: materials '{seen[artifact.name]}' and '{material.name}' "
                    f"both write '{artifact.name}'"
                )
            seen[artifact.name] = material.name
            artifacts.append(artifact)
    return EmitResult(artifacts, notes)
