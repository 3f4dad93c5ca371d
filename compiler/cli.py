"""The `cnlmc` command line. Exit codes: 0 ok, 1 compile errors, 2 usage, 70 internal error.

The language's own subcommands are in cnlmc.commands (compile, explain, targets, lsp) and in the
front ends of their areas (build, serve, listen: `FRONT_END_COMMANDS`); a backend's subcommands
(bake, sheet, preview, ar) are listed by the registry (`BUILTIN_COMMANDS`): both tables list a
command by name, module, class and help, in the same form, and load it only when it is chosen.
Only the subcommand that runs is imported and declares its arguments: a cold `cnlmc compile`
loads nothing of the others (docs/language.md, Speed). The modules are imported by main() with
the cyclic garbage collector paused (they are long-lived objects and no garbage), then frozen.
A plugin's subcommand (entry point group 'cnlmc.commands') is looked up when no other matches.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import TYPE_CHECKING

from cnlmc.backends.registry import CommandEntry

from .errors import EXIT_INTERNAL, EXIT_OK, EXIT_USAGE, UsageError

if TYPE_CHECKING:
    from cnlmc.backends.registry import Command

__all__ = ["FRONT_END_COMMANDS", "build_parser", "main"]


#: The front ends of the language's areas, after cnlmc.commands' own, in the order `cnlmc --help`
#: lists them (backends' commands follow): listed like backends' commands, imported when chosen.
FRONT_END_COMMANDS: dict[str, CommandEntry] = {
    "build": CommandEntry(  # cnlmc.batch: catalogues to targets (#20)
        "build",
        "cnlmc.batch.command",
        "BuildCommand",
        "build every material of a catalogue to targets, incrementally, in parallel (or on Dask)",
    ),
    "serve": CommandEntry(  # cnlmc.studio: the web studio (#17); aiohttp loads when it runs
        "studio",
        "cnlmc.studio.command",
        "ServeCommand",
        "open the studio: type a phrase in the browser, see it live, refine, export, view in AR",
    ),
    "listen": CommandEntry(  # cnlmc.speech (#18); pocketsphinx loads when it runs
        "speech",
        "cnlmc.speech.command",
        "ListenCommand",
        "speak a material: the first phrase starts it, later ones refine it ('darker', 'undo')",
    ),
}


def chosen_command(argv: Sequence[str]) -> str | None:
    """The subcommand the arguments name: the first that is not an option."""
    return next((arg for arg in argv if not arg.startswith("-")), None)


def build_parser(argv: Sequence[str] = ()) -> argparse.ArgumentParser:
    """The parser, with the arguments of the subcommand `argv` names (the others are listed by
    name and help only)."""
    from cnlmc.backends.registry import BUILTIN_COMMANDS, load_command, plugin_command

    from .commands import LANGUAGE_COMMANDS

    parser = argparse.ArgumentParser(
        prog="cnlmc",
        description="Compile material phrases such as "
        "'lightly brushed, blue anodized aluminum' into renderable materials.",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    chosen = chosen_command(argv)
    for command in LANGUAGE_COMMANDS:
        language_parser = sub.add_parser(command.name, help=command.help)
        if command.name == chosen:
            _add(language_parser, command)
    for name, entry in (*FRONT_END_COMMANDS.items(), *BUILTIN_COMMANDS.items()):
        listed_parser = sub.add_parser(name, help=entry.help)
        if name == chosen:
            with _loading():
                _add(listed_parser, load_command(name, entry))
    if chosen is not None and chosen not in {
        *(c.name for c in LANGUAGE_COMMANDS),
        *FRONT_END_COMMANDS,
        *BUILTIN_COMMANDS,
    }:
        with _loading():
            plugin = plugin_command(chosen)
        if plugin is not None:
            _add(sub.add_parser(plugin.name, help=plugin.help), plugin)
    return parser


def _language_command_names() -> set[str]:
    """The language's own subcommands: their extension modules (if any) load after the freeze."""
    from .commands import LANGUAGE_COMMANDS

    return {c.name for c in LANGUAGE_COMMANDS} | set(FRONT_END_COMMANDS)


def _add(parser: argparse.ArgumentParser, command: Command) -> None:
    command.add_arguments(parser)
    parser.set_defaults(
        handler=command.run, writes_stdout=getattr(command, "writes_stdout", False)
    )  # a plugin may not say


@contextmanager
def _loading() -> Iterator[None]:
    """A backend command that cannot load here is a usage error (which extra to install)."""
    from cnlmc.backends.registry import TargetUnavailable

    try:
        yield
    except TargetUnavailable as exc:
        raise UsageError(str(exc)) from None


def _check_stdout_output(args: argparse.Namespace, command: str | None) -> None:
    """`-o -` where a command cannot write to standard output (its `writes_stdout` is False: it
    writes images, folders or packages): a usage error, never a file named '-'."""
    if getattr(args, "output", None) == "-" and not args.writes_stdout:
        raise UsageError(
            f"-o - (standard output) is for `cnlmc compile`; `cnlmc {command}` writes files: "
            "give -o FILE or -o FOLDER (a file named '-' is -o ./-)"
        )


def main(argv: Sequence[str] | None = None) -> int:
    arguments = sys.argv[1:] if argv is None else list(argv)
    try:
        from .cache import collection_paused, freeze_long_lived

        with collection_paused():  # the modules the command needs and its parser: long-lived, no garbage
            args = build_parser(arguments).parse_args(arguments)
            # a long-running entry point: what is loaded so far stays out of the GC's way; a backend's or
            # a plugin's command has loaded its extension modules by now (they see their objects freed at exit)
            freeze_long_lived(unfreeze_at_exit=chosen_command(arguments) not in _language_command_names())
        _check_stdout_output(args, chosen_command(arguments))
        code: int = args.handler(args)
        return code
    except UsageError as exc:
        from .diagnostics import visible

        print(f"cnlmc: error: {visible(str(exc))}", file=sys.stderr)  # it may echo a file name
        return EXIT_USAGE
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except Exception as exc:  # the last line of defence: never a traceback
        from .diagnostics import visible

        print(
            f"cnlmc: internal error: {type(exc).__name__}: {visible(str(exc))}\nplease report this with the input that caused it",
            file=sys.stderr,
        )
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
