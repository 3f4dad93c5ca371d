"""`cnlmc listen`: speak a material (from the microphone, or a WAV file with --from).

Light on purpose: the CLI imports this module on every start; pocketsphinx and the audio library
load only when the command runs."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from cnlmc.backends.registry import Command, TargetUnavailable, UnknownTarget, get_target

from ..cli import FRONT_END_COMMANDS
from ..commands import EXIT_ERRORS, EXIT_OK, add_lexicon_arguments, deliver, lexicon_of, print_notes, run_target
from ..errors import UsageError

if TYPE_CHECKING:
    from .voice import Voice


class ListenCommand(Command):
    name = "listen"
    help = FRONT_END_COMMANDS[name].help
    writes_stdout = True

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument(
            "--from", dest="wav", metavar="FILE.wav", help="a recording to read instead of the microphone"
        )
        parser.add_argument("--target", "-t", default="ir", help="backend: see `cnlmc targets` (default: ir)")
        parser.add_argument("-o", "--output", help="output file or folder (default: stdout)")
        parser.add_argument(
            "--min-confidence",
            type=float,
            metavar="P",
            help="apply an utterance only at or above this confidence, 0-1 (default: stdlib/speech/speech.toml)",
        )
        parser.add_argument(
            "--grammar",
            action="store_true",
            help="print the recogniser's grammar (Sphinx FSG) for a session's first utterance and stop",
        )
        parser.add_argument("--option", action="append", default=[], metavar="KEY=VALUE", help="a backend option")
        parser.add_argument(
            "--voice",
            metavar="FILE",
            help="your enrolled voice: the recogniser adapted to your speech (with --enrol: the file it writes)",
        )
        parser.add_argument(
            "--enrol",
            action="store_true",
            help="read the enrolment script aloud (microphone, or --from a recording of it) and write --voice FILE",
        )
        parser.add_argument(
            "--enrol-script", action="store_true", help="print the sentences --enrol asks you to read, and stop"
        )
        add_lexicon_arguments(parser)

    def run(self, args: argparse.Namespace) -> int:
        if args.enrol_script or args.enrol:
            from .enrol_command import enrol, print_script, refuse_unused

            refuse_unused(args)
            return print_script() if args.enrol_script else enrol(args)
        from .audio import microphone, read_wav, utterances
        from .listen import SOURCE_NAME, Listener
        from .model import SpeechModel
        from .recogniser import SpeechUnavailable

        try:
            target = get_target(args.target)
        except (UnknownTarget, TargetUnavailable) as exc:
            raise UsageError(str(exc)) from None
        lexicon = lexicon_of(args)
        folders = [spec for spec in args.lexicon if Path(spec).is_dir()]
        try:
            voice = load_voice(args.voice)
            model = SpeechModel.of(lexicon, folders)
            if args.grammar:
                sys.stdout.write(model.grammar.fsg_text())
                return EXIT_OK
            if model.unsayable:
                words = " ".join(sorted(model.unsayable)[:10])
                print(f"note: no pronunciation for: {words}; add them to speech/pronunciations.toml", file=sys.stderr)
            rate = model.settings.sample_rate
            audio = utterances(read_wav(args.wav, rate), rate) if args.wav else microphone(rate)
            recogniser = model.recogniser(voice)
            threshold = model.settings.min_confidence if args.min_confidence is None else args.min_confidence
            listener = Listener(lexicon, model.settings.undo, threshold, args.seed)
            if not args.wav:
                print("listening: say a material, then refinements ('darker', 'undo'); Ctrl-C ends", file=sys.stderr)
            try:
                for pcm in audio:
                    for message in listener.hear(recogniser.decode(pcm, refining=bool(listener.lines))).messages:
                        print(message, file=sys.stderr)
            except KeyboardInterrupt:
                pass
        except SpeechUnavailable as exc:
            raise UsageError(str(exc)) from None
        if listener.result is None:
            print("cnlmc listen: no material was applied", file=sys.stderr)
            return EXIT_ERRORS
        print(f"material ({SOURCE_NAME}):", *(f"  {line}" for line in listener.lines), sep="\n", file=sys.stderr)
        emitted = run_target(target, listener.result, args)
        if emitted is None:
            return EXIT_ERRORS
        print_notes(emitted)
        return deliver(emitted.artifacts, args.output, protect=[args.wav] if args.wav else [])


def load_voice(path: str | None) -> Voice | None:
    """The enrolled voice of --voice (a UsageError saying what to do when it cannot be used)."""
    if path is None:
        return None
    from .recogniser import model_files
    from .voice import Voice, VoiceError, acoustic_model

    try:
        return Voice.load(path, acoustic_model(model_files().acoustic))
    except VoiceError as exc:
        raise UsageError(str(exc)) from None
