"""A noise floor under the speech: audio quieter than `below_speech_db` under the speech's level in
its pauses (a synthesiser's digital silence, a gated microphone) gets low white noise under every
sample, so that its pauses and its empty frequency bands look like the recordings the acoustic
model was trained on. Input that already has such a floor (a room, a microphone, 20 dB SNR) is left
almost as it is: only the missing part of the floor's power is added.

Measured on bench/speech.py's tuning split (docs/speech.md): espeak-ng's clean utterances went
from 32.5 % to 50 % IR-equal with a floor 30 dB under the speech (45 % at 40 dB, 50 % at 20 dB);
noise only in the exact zeros did nothing (30 %): the gain is the floor under the speech (a
formant synthesiser leaves whole frequency bands empty). Noise added again under the noisy ones
(already at 20 dB) lost 2-5 points, hence 'only the missing part'."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class NoiseFloor:
    below_speech_db: float  # the floor's level under the speech's (0: off)
    frame_ms: float  # frames the levels are measured over
    speech_percentile: float  # the speech's level: this percentile of the frames' RMS
    pause_percentile: float  # the pauses' level: this percentile of the frames' RMS
    seed: int  # the noise is the same for the same audio (results repeat)
    slope: float = 1.0  # the noise's power falls as 1/f**slope (0: white, 1: pink, 2: brown)

    def apply(self, pcm: bytes, rate: int) -> bytes:
        """16-bit mono PCM with the floor raised where it is missing (the input when it is not)."""
        samples = np.frombuffer(pcm, dtype="<i2").astype(np.float64)
        missing = self.missing_rms(samples, rate)
        if missing <= 0.0:
            return pcm
        noise = coloured_noise(samples.size, rate, self.slope, np.random.default_rng(self.seed)) * missing
        return bytes(np.clip(np.round(samples + noise), -32768, 32767).astype("<i2").tobytes())

    def missing_rms(self, samples: np.ndarray, rate: int) -> float:
        """The RMS of the noise to add so that the pauses reach the floor (0 when they do)."""
        levels = frame_levels(samples, max(1, int(rate * self.frame_ms / 1000)))
        if not self.below_speech_db or levels.size < 2:
            return 0.0
        speech = float(np.percentile(levels, self.speech_percentile))
        pause = float(np.percentile(levels, self.pause_percentile))
        target = speech * 10 ** (-self.below_speech_db / 20)
        return float(np.sqrt(max(0.0, target**2 - pause**2)))


def frame_levels(samples: np.ndarray, size: int) -> np.ndarray:
    """The RMS of each whole frame of `size` samples."""
    count = samples.size // size
    levels: np.ndarray = np.sqrt(np.mean(samples[: count * size].reshape(count, size) ** 2, axis=1))
    return levels


def coloured_noise(size: int, rate: int, slope: float, rng: np.random.Generator) -> np.ndarray:
    """`size` samples of unit-RMS noise whose power spectrum falls as 1/f**slope (white noise
    shaped in the frequency domain; the DC bin takes the lowest frequency's gain)."""
    white = rng.normal(0.0, 1.0, size)
    if not slope or size < 4:
        return white
    spectrum = np.fft.rfft(white)
    frequencies = np.fft.rfftfreq(size, 1.0 / rate)
    frequencies[0] = frequencies[1]
    spectrum *= frequencies ** (-slope / 2.0)
    noise = np.fft.irfft(spectrum, size)
    rms = float(np.sqrt(np.mean(noise**2)))
    return noise / rms if rms > 0.0 else white
