"""`cnlmc listen --enrol`: read the enrolment script aloud and write the voice file;
`--enrol-script` prints the sentences."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..commands import EXIT_OK
from ..errors import UsageError
from ..output import destination, write_atomic
from .enrol import Aligner, Script, enrol_live, enrol_recording
from .recogniser import SpeechUnavailable
from .settings import SpeechSettings
from .voice import VoiceError, is_voice_file

NOT_FOR_ENROLMENT = {
    "target": "--target",
    "output": "-o",
    "grammar": "--grammar",
    "min_confidence": "--min-confidence",
    "option": "--option",
}  # what --enrol would leave unused: refused


def print_script() -> int:
    script = Script.bundled()
    print(f"Read these {len(script.sentences)} sentences aloud, in order, with a short pause after each:")
    for number, sentence in enumerate(script.sentences, 1):
        print(f"{number:2}. {sentence}")
    return EXIT_OK


def refuse_unused(args: argparse.Namespace) -> None:
    """--enrol and --enrol-script take no compile options (they would be silently unused)."""
    given = [
        flag for name, flag in NOT_FOR_ENROLMENT.items() if getattr(args, name, None) not in (None, [], False, "ir")
    ]
    if args.enrol and args.enrol_script:
        given.append("--enrol-script")
    if given:
        what = "--enrol-script" if args.enrol_script and not args.enrol else "--enrol"
        raise UsageError(f"{what} writes no material: {', '.join(given)} cannot be used with it")


def enrol(args: argparse.Namespace) -> int:
    from .audio import microphone, read_wav

    if not args.voice:
        raise UsageError("--enrol needs --voice FILE: where to write the voice (e.g. --voice me.voice)")
    refuse_foreign(Path(args.voice), args.wav)
    script = Script.bundled()
    settings = SpeechSettings.bundled()
    rate = settings.sample_rate
    try:
        aligner = Aligner(settings, script)
        if args.wav:
            pcm = read_wav(args.wav, rate)
            voice = enrol_recording(pcm, aligner, script)
        else:
            segments = microphone(rate)
            print("enrolling: read each sentence when it is shown; Ctrl-C stops", file=sys.stderr)
            voice = enrol_live(segments, aligner, script, lambda line: print(line, file=sys.stderr))
    except (VoiceError, SpeechUnavailable) as exc:
        raise UsageError(str(exc)) from None
    except (KeyboardInterrupt, StopIteration):
        raise UsageError("enrolment stopped before it was done; nothing was written") from None
    write_atomic(Path(args.voice), voice.to_bytes(), protect=[args.wav] if args.wav else [])
    print(
        f"wrote {args.voice}: your voice from {voice.seconds:.0f} s of speech ({voice.sentences} of "
        f"{len(script.sentences)} sentences followed); use it with: cnlmc listen --voice {args.voice}",
        file=sys.stderr,
    )
    return EXIT_OK


def refuse_foreign(path: Path, wav: str | None) -> None:
    """Before the reading: the voice can be written there, and what is there now is a voice file
    (of any version: enrolling again replaces it) or nothing; never the recording, never another file."""
    real = destination(path, [wav] if wav else [])
    if real.exists() and not is_voice_file(real):
        raise UsageError(f"{path} exists and is not a voice file: not replaced (choose another name)")
