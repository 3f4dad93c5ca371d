"""Target name -> Target object, and CLI command name -> Command, each imported only when used.
The front ends (the CLI, cnlmc.api) reach the backends through this module only.

A built-in target module exposes `TARGET`, an instance of `cnlmc.backends.base.Target`.
Third-party targets register through the entry point group 'cnlmc.backends' (a module with
TARGET, or the module form: NAME, DESCRIPTION, CAPABILITIES and emit(ir_dict, options_dict)).
Commands are listed here by name and help, so the CLI builds its parser without importing
any target; `get_command` imports the one that runs.
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from types import ModuleType
from typing import Any, NamedTuple

from cnlmc.material import Document

from .base import Artifact, Command, Options, Target, did_you_mean
from .capabilities import BackendRefused, EmitResult

__all__ = [
    "Artifact",
    "BackendRefused",
    "Command",
    "EmitResult",
    "Target",
    "BUILTIN_BACKENDS",
    "BUILTIN_COMMANDS",
    "CommandEntry",
    "TargetUnavailable",
    "UnknownTarget",
    "available",
    "get_command",
    "load_command",
    "get_target",
    "plugin_command",
]

BUILTIN_BACKENDS = {
    "ir": "cnlmc.backends.ir_json",
    "glsl": "cnlmc.backends.glsl",
    "materialx": "cnlmc.backends.exchange.materialx",
    "usd": "cnlmc.backends.exchange.usd",
    "mitsuba": "cnlmc.backends.exchange.mitsuba",
    "gltf": "cnlmc.backends.exchange.gltf",
    "usdz": "cnlmc.backends.exchange.usdz_arkit",
    "maps": "cnlmc.backends.maps.target",
    "preview": "cnlmc.backends.preview",
}


class CommandEntry(NamedTuple):
    """A CLI subcommand listed without importing it: the pip extra that installs what it needs
    (for a backend's command, the backend), where its Command class is, and its one-line help —
    the one place the help is written (the class reads it from here).
    (A NamedTuple, not a dataclass: the CLI imports this module on every start.)"""

    extra: str
    module: str
    cls: str
    help: str


BUILTIN_COMMANDS = {
    "bake": CommandEntry(
        "maps", "cnlmc.backends.maps.commands", "BakeCommand", "bake a material's procedural maps to image files"
    ),
    "preview": CommandEntry(
        "preview",
        "cnlmc.backends.preview.commands",
        "PreviewCommand",
        "render a material file to a PNG (offscreen OpenGL)",
    ),
    "ar": CommandEntry(
        "ar",
        "cnlmc.backends.ar.command",
        "ARCommand",
        "place the material on a printed marker in a photo or video",
    ),
    "sheet": CommandEntry(
        "maps", "cnlmc.backends.maps.commands", "SheetCommand", "a contact sheet PNG of every stdlib procedural graph"
    ),
}


class UnknownTarget(LookupError):
    def __init__(self, name: str, known: list[str]):
        super().__init__(f"unknown target '{name}' (known: {', '.join(known)}){did_you_mean(name, known)}")


class TargetUnavailable(LookupError):
    """The target exists but cannot load here (a missing optional dependency)."""


def _entry_points(group: str) -> dict[str, str]:
    """Installed plugins of an entry point group: name -> 'module' or 'module:attribute'."""
    from importlib.metadata import entry_points  # slow to import: only when plugins are asked for

    return {ep.name: ep.value for ep in entry_points(group=group)}


def available(include_plugins: bool = True) -> dict[str, str]:
    """Target name -> the module that provides it."""
    table = dict(BUILTIN_BACKENDS)
    if include_plugins:
        for name, module in _entry_points("cnlmc.backends").items():
            table.setdefault(name, module)
    return table


def _import(module: str, what: str, extra: str) -> ModuleType:
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise TargetUnavailable(f"{what} cannot load: {exc}; install it with: pip install 'cnlmc[{extra}]'") from None


def get_target(name: str) -> Target:
    """The Target called `name`; UnknownTarget (with did-you-mean) or TargetUnavailable."""
    table = available(include_plugins=name not in BUILTIN_BACKENDS)
    if name not in table:
        raise UnknownTarget(name, sorted(table))
    module = _import(table[name], f"target '{name}'", name)
    target = getattr(module, "TARGET", None)
    return target if isinstance(target, Target) else ModuleTarget(module)


def get_command(name: str) -> Command:
    """A fresh Command object for `cnlmc NAME`; TargetUnavailable when its backend cannot load."""
    return load_command(name, BUILTIN_COMMANDS[name])


def load_command(name: str, entry: CommandEntry) -> Command:
    """A fresh Command object from a listed entry (imports its module); TargetUnavailable when what
    it needs is not installed."""
    module = _import(entry.module, f"'cnlmc {name}'", entry.extra)
    command: Command = getattr(module, entry.cls)()
    return command


def plugin_command(name: str) -> Command | None:
    """The Command a plugin registers as `name` (entry point group 'cnlmc.commands',
    value 'module:Class'), or None. `cnlmc --help` lists built-in commands only: looking
    plugins up costs a scan of the installed packages, done when such a command runs."""
    value = _entry_points("cnlmc.commands").get(name)
    if value is None:
        return None
    module_name, _, attribute = value.partition(":")
    module = _import(module_name, f"'cnlmc {name}'", name)
    command: Command = getattr(module, attribute)()
    return command


class ModuleTarget(Target):
    """A target in the module form (NAME, DESCRIPTION, CAPABILITIES, emit(ir_dict, options_dict)):
    third-party plugins, and built-in modules not yet moved to the Target class."""

    def __init__(self, module: ModuleType):
        self.module = module
        self.name = module.NAME
        self.description = getattr(module, "DESCRIPTION", "")
        self.capabilities = module.CAPABILITIES

    def emit_ir(self, ir: Document | Mapping[str, Any], pairs: Mapping[str, object] | None = None) -> EmitResult:
        ir_dict = ir.to_ir() if isinstance(ir, Document) else dict(ir)
        result: EmitResult = self.module.emit(ir_dict, dict(pairs or {}))
        return result

    def emit(self, document: Document, options: Options) -> EmitResult:
        return self.emit_ir(document, {k: v for k, v in options.items() if v is not None})
