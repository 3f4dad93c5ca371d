"""Audio in: a WAV file or the microphone, as 16-bit mono PCM at the recogniser's rate, split into
utterances at pauses (pocketsphinx's Segmenter, a voice-activity detector)."""

from __future__ import annotations

import io
import wave
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import UsageError
from ..inputs import read_bytes
from .noise_floor import frame_levels
from .recogniser import SpeechUnavailable, pocketsphinx_module

MAX_WAV_BYTES = 256 << 20  # our choice: about 2 hours of 16 kHz speech


def read_wav(path: str, rate: int) -> bytes:
    """A WAV file as 16-bit mono PCM at `rate` (other rates and channel counts are converted)."""
    data = read_bytes(path, limit=MAX_WAV_BYTES, what="WAV file")
    try:
        with wave.open(io.BytesIO(data)) as w:
            width, channels, source_rate = w.getsampwidth(), w.getnchannels(), w.getframerate()
            frames = w.readframes(w.getnframes())
    except (wave.Error, EOFError) as exc:
        raise UsageError(
            f"{path}: not a PCM WAV file ({exc}); convert it with: sox IN -r 16000 -c 1 -b 16 OUT.wav"
        ) from None
    if width not in (1, 2, 4):
        raise UsageError(f"{path}: {8 * width}-bit samples are not supported; convert it with: sox IN -b 16 OUT.wav")
    return to_pcm16(frames, width, channels, source_rate, rate)


def to_pcm16(frames: bytes, width: int, channels: int, source_rate: int, rate: int) -> bytes:
    kind = {1: np.uint8, 2: np.int16, 4: np.int32}[width]
    samples = np.frombuffer(frames, dtype=kind).astype(np.float64)
    if width == 1:
        samples = (samples - 128.0) * 256.0
    elif width == 4:
        samples /= 65536.0
    samples = samples.reshape(-1, channels).mean(axis=1) if channels > 1 else samples
    if source_rate != rate and samples.size:
        times = np.arange(int(samples.size * rate / source_rate)) * (source_rate / rate)
        samples = np.interp(times, np.arange(samples.size), samples)
    return bytes(np.clip(np.round(samples), -32768, 32767).astype("<i2").tobytes())


SEGMENT_WINDOW = 0.5  # seconds: the segmenter's window (our choice, as `listen` has used)


def _segmenter(rate: int) -> Any:
    """pocketsphinx's voice-activity segmenter: half-second windows, 90 % of a window voiced."""
    return pocketsphinx_module().Segmenter(sample_rate=rate, window=SEGMENT_WINDOW, ratio=0.9)


def utterances(pcm: bytes, rate: int) -> Iterator[bytes]:
    """The speech segments of `pcm`, in order."""
    segmenter = _segmenter(rate)
    for segment in segmenter.segment(io.BytesIO(pcm)):
        yield bytes(segment.pcm)


def speech_span(pcm: bytes, rate: int) -> bytes:
    """The part of one recorded utterance from where its speech starts to where it ends, a
    segmenter window wider on each side (the segmenter's ends fall up to a window inside the
    speech: 'white varnished oak' cut to 'white varnished gold'), the rest of the silence before
    and after a button press cut; the whole of it when no speech is found."""
    segmenter = _segmenter(rate)
    spans = [(segment.start_time, segment.end_time) for segment in segmenter.segment(io.BytesIO(pcm))]
    if not spans:
        return pcm
    first, last = max(0.0, spans[0][0] - SEGMENT_WINDOW), spans[-1][1] + SEGMENT_WINDOW
    start, end = (int(round(seconds * rate)) * 2 for seconds in (first, last))
    return pcm[start:end]


def microphone(rate: int) -> Iterator[bytes]:
    """Utterances from the default input device until interrupted (Ctrl-C); a UsageError at once
    when there is no input device."""
    sounddevice = _sounddevice()
    try:
        device = sounddevice.query_devices(kind="input")
    except (ValueError, sounddevice.PortAudioError):
        device = None
    if not device:
        raise UsageError("no audio input device here (no microphone found); give a recording with --from FILE.wav")
    return _recorded(sounddevice, rate)


def _recorded(sounddevice: Any, rate: int) -> Iterator[bytes]:
    segmenter = _segmenter(rate)
    with sounddevice.RawInputStream(samplerate=rate, channels=1, dtype="int16") as stream:
        for segment in segmenter.segment(_StreamReader(stream)):
            yield bytes(segment.pcm)


class _StreamReader:
    """A sounddevice input stream read as a file of bytes (what Segmenter reads)."""

    def __init__(self, stream: Any) -> None:
        self.stream = stream

    def read(self, size: int) -> bytes:
        data, _overflowed = self.stream.read(size // 2)
        return bytes(data)


def _sounddevice() -> Any:
    try:
        import sounddevice  # type: ignore[import-untyped]
    except (ImportError, OSError) as exc:  # OSError: the PortAudio library is missing
        raise SpeechUnavailable(
            f"the microphone needs sounddevice and PortAudio ({exc}); install them with: "
            "pip install 'cnlmc[speech]' and apt-get install libportaudio2; or give --from FILE.wav"
        ) from None
    return sounddevice


def is_wav(path: str) -> bool:
    return Path(path).suffix.lower() in (".wav", ".wave")


PAUSE_FRAME_S = 0.01  # the level is measured every 10 ms
PAUSE_SHARE = 1 / 3  # a pause is under a third of the way (in dB) from the quiet frames to the loud ones
LEVEL_PERCENTILES = (10.0, 90.0)  # the quiet frames' level (the room) and the loud frames' (the speech)
LEVEL_RANGE_DB = 80.0  # digital silence counts as this far under the speech
MIN_PAUSE_S = 0.15  # shorter quiet stretches are inside a sentence (stops, closures)


def split_at_pauses(pcm: bytes, rate: int, parts: int) -> list[bytes] | None:
    """A recording of `parts` sentences read with a pause after each, cut in the middle of its
    `parts - 1` longest pauses; None when it has fewer. A pause: at least MIN_PAUSE_S of frames
    whose level is under PAUSE_SHARE of the way from the room's level to the speech's, in dB (so
    a noisy room's pauses count as well as a synthesiser's digital silence)."""
    size = max(1, int(rate * PAUSE_FRAME_S))
    levels = frame_levels(np.frombuffer(pcm, dtype="<i2").astype(np.float64), size)
    count = levels.size
    if parts < 1 or count < 2:
        return None
    room, speech = np.percentile(levels, LEVEL_PERCENTILES)
    if speech <= 0.0:
        return None  # silence throughout
    decibels = 20 * np.log10(np.maximum(levels, speech * 10 ** (-LEVEL_RANGE_DB / 20)) / speech)
    floor = max(20 * np.log10(max(room, 1e-12) / speech), -LEVEL_RANGE_DB)
    quiet = decibels < floor * (1 - PAUSE_SHARE)
    pauses = [run for run in _runs(quiet) if run[1] - run[0] >= MIN_PAUSE_S / PAUSE_FRAME_S]
    inner = [run for run in pauses if run[0] > 0 and run[1] < count]  # not the silence at either end
    if len(inner) < parts - 1:
        return None
    longest = sorted(sorted(inner, key=lambda run: run[0] - run[1])[: parts - 1])
    cuts = [0, *(((start + end) // 2) * size * 2 for start, end in longest), len(pcm)]
    return [pcm[a:b] for a, b in zip(cuts, cuts[1:])]


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """[start, end) of each run of True."""
    edges = np.diff(np.concatenate(([0], flags.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist()))
