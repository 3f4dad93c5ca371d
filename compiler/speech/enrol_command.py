"""`cnlmc listen --enrol`: read the enrolment script aloud and write the voice file;
`--enrol-script` prints the sentences."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..commands import EXIT_OK
from ..errors import UsageError
from ..output import write_atomic
from .enrol import Aligner, Script, enrol_live, enrol_recording
from .recogniser import SpeechUnavailable, model_files
from .settings import SpeechSettings
from .voice import Voice, VoiceError, acoustic_model


def print_script() -> int:
    script = Script.bundled()
    print(f"Read these {len(script.sentences)} sentences aloud, in order, with a short pause after each:")
    for number, sentence in enumerate(script.sentences, 1):
        print(f"{number:2}. {sentence}")
    return EXIT_OK


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
        raise UsageError("enrolment stopped before the script was read; nothing was written") from None
    write_atomic(Path(args.voice), voice.to_bytes(), protect=[args.wav] if args.wav else [])
    print(
        f"wrote {args.voice}: your voice from {voice.seconds:.0f} s of speech ({voice.sentences} "
        f"recording{'s' if voice.sentences != 1 else ''}); use it with: cnlmc listen --voice {args.voice}",
        file=sys.stderr,
    )
    return EXIT_OK


def refuse_foreign(path: Path, wav: str | None) -> None:
    """Never replace a file that is not a voice file (an earlier voice is replaced: enrolling again)."""
    if wav and path.resolve() == Path(wav).resolve():
        raise UsageError(f"{path}: that is the recording being read; write the voice to another file")
    if path.exists():
        try:
            Voice.load(path, acoustic_model(model_files().acoustic))
        except VoiceError:
            raise UsageError(f"{path} exists and is not a voice file: not replaced (choose another name)") from None
