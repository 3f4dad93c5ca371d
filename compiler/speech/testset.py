"""The speech test set: phrases of the language (stdlib/speech/test_phrases.toml) spoken by
espeak-ng in several voices and speeds, clean and with white noise at a set SNR (sox), and how a
recognised phrase is scored against what was said (phrase-exact, and the IR it compiles to).

espeak-ng and sox run as external programs (tests/speech and bench/speech.py); nothing here is
used by `cnlmc listen` itself."""

from __future__ import annotations

import math
import random
import shutil
import subprocess
import tomllib
import wave
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..api import compile_source
from ..lexicon import Lexicon
from .listen import Listener
from .recogniser import Hypothesis
from .settings import speech_data

VOICES = ("en-us", "en-gb", "en-us+f3", "en-us+m3")  # American, British, a female voice, another male
SPEEDS = (130, 160, 190)  # words per minute
SNR_DB = 20.0
IR_FIELDS = ("model", "params", "maps", "variant")  # what a material is, not where its words stood


@dataclass(frozen=True)
class Utterance:
    text: str
    voice: str
    speed: int
    noisy: bool
    refinement: bool  # said after the base material (a refinement or "undo")

    @property
    def cell(self) -> tuple[str, int, str]:
        return self.voice, self.speed, "noise" if self.noisy else "clean"

    def file_name(self) -> str:
        return f"{self.voice}_{self.speed}_{'n' if self.noisy else 'c'}_{self.text.replace(' ', '_')}.wav"


@dataclass(frozen=True)
class Phrases:
    materials: tuple[str, ...]
    refinements: tuple[str, ...]
    base: str

    @classmethod
    def bundled(cls, full: bool) -> Phrases:
        data: dict[str, Any] = tomllib.loads(speech_data("test_phrases.toml"))
        materials, refinements = data["materials"], data["refinements"]
        if not full:
            materials, refinements = materials[: data["test_materials"]], refinements[: data["test_refinements"]]
        return cls(tuple(materials), tuple(refinements), str(data["base"]))

    @classmethod
    def held_out(
        cls, lexicon: Lexicon, sayable: Callable[[str], bool], exclude: Phrases, seed_key: str = "seed"
    ) -> Phrases:
        """Phrases drawn (seeded) from the lexicon's own `example` fields, per category as
        test_phrases.toml's [held_out] says: never looked at while tuning, only scored. An example
        is kept when the grammar can say it; it is a refinement when it names no material alone."""
        spec = held_out_spec()
        draw = random.Random(int(spec[seed_key]))
        seen = {*exclude.materials, *exclude.refinements}
        materials: list[str] = []
        refinements: list[str] = []
        for category, count in spec["per_category"].items():
            examples = sorted({_spoken(e.get("example", "")) for e in lexicon.entries.get(category, {}).values()})
            candidates = [t for t in examples if t and t not in seen and sayable(t)]
            for text in draw.sample(candidates, min(count, len(candidates))):
                seen.add(text)
                named = compile_source(text, "<held-out>", lexicon).materials
                (materials if named else refinements).append(text)
        return cls(tuple(materials), tuple(refinements), exclude.base)

    def joined(self, other: Phrases) -> Phrases:
        return Phrases(self.materials + other.materials, self.refinements + other.refinements, self.base)

    def utterances(self, voices: tuple[str, ...], speeds: tuple[int, ...], noisy: tuple[bool, ...]) -> list[Utterance]:
        said = [(t, False) for t in self.materials] + [(t, True) for t in self.refinements]
        return [Utterance(t, v, s, n, r) for n in noisy for v in voices for s in speeds for t, r in said]


def held_out_spec() -> dict[str, Any]:
    """test_phrases.toml's [held_out]: the seeds and how many phrases per category."""
    data: dict[str, Any] = tomllib.loads(speech_data("test_phrases.toml"))
    return dict(data["held_out"])


def _spoken(example: str) -> str:
    return " ".join(example.lower().replace(",", " ").split())


def tools_missing() -> list[str]:
    return [tool for tool in ("espeak-ng", "sox") if shutil.which(tool) is None]


def synthesize(utterance: Utterance, folder: Path, rate: int) -> Path:
    """The utterance as a 16-bit mono WAV at `rate` in `folder` (made once, then reused)."""
    clean = folder / Utterance(utterance.text, utterance.voice, utterance.speed, False, False).file_name()
    if not clean.exists():
        raw = folder / f"espeak_{clean.name}"
        _run(["espeak-ng", "-v", utterance.voice, "-s", str(utterance.speed), "-w", str(raw), utterance.text])
        _run(["sox", str(raw), "-r", str(rate), "-c", "1", "-b", "16", str(clean)])
        raw.unlink()
    if not utterance.noisy:
        return clean
    noisy = folder / utterance.file_name()
    if not noisy.exists():
        add_noise(clean, noisy, SNR_DB)
    return noisy


def read_aloud(sentences: tuple[str, ...], voice: str, speed: int, folder: Path, rate: int) -> Path:
    """The enrolment script read by an espeak-ng voice as one WAV at `rate`: the sentences in order,
    half a second of silence after each, as `cnlmc listen --enrol-script` asks a reader to pause
    (what `cnlmc listen --enrol --from` reads)."""
    out = folder / f"enrol_{voice}_{speed}.wav"
    if not out.exists():
        pause = folder / "pause.wav"
        _run(["sox", "-n", "-r", str(rate), "-c", "1", "-b", "16", str(pause), "trim", "0", str(READING_PAUSE_S)])
        said = [synthesize(Utterance(s, voice, speed, False, False), folder, rate) for s in sentences]
        _run(["sox", *(str(p) for part in said for p in (part, pause)), str(out)])
    return out


READING_PAUSE_S = 0.5  # the test reader's pause after each sentence of the enrolment script


def add_noise(clean: Path, out: Path, snr_db: float) -> None:
    """White noise (sox synth) mixed in at `snr_db` below the speech's RMS (over its voiced part)."""
    pcm = read_pcm(clean)
    samples = np.frombuffer(pcm, dtype="<i2").astype(np.float64) / 32768.0
    voiced = samples[np.abs(samples) > 0.01]
    rms = float(np.sqrt(np.mean(voiced**2))) if voiced.size else 0.0
    volume = rms * math.sqrt(3.0) * 10 ** (-snr_db / 20)  # sox's white noise is uniform in [-1, 1]: RMS 1/sqrt(3)
    noise = out.with_name(f"noise_{out.name}")
    with wave.open(str(clean)) as w:
        seconds, rate = w.getnframes() / w.getframerate(), w.getframerate()
    _run(
        [
            "sox",
            "-n",
            "-r",
            str(rate),
            "-c",
            "1",
            "-b",
            "16",
            str(noise),
            "synth",
            f"{seconds:.3f}",
            "whitenoise",
            "vol",
            f"{volume:.6f}",
        ]
    )
    _run(["sox", "-m", "-v", "1", str(clean), "-v", "1", str(noise), str(out)])
    noise.unlink()


def read_pcm(path: Path) -> bytes:
    with wave.open(str(path)) as w:
        return bytes(w.readframes(w.getnframes()))


def _run(command: list[str]) -> None:
    """Run a tool; sox in its repeatable mode (-R: its dither seeded), so that the same utterance is
    the same audio in every run (unseeded dither made a test decode flip about once in many runs)."""
    if command[0] == "sox":
        command = ["sox", "-R", *command[1:]]
    subprocess.run(command, check=True, capture_output=True, timeout=60)


class Scorer:
    """Whether a recognised phrase means what was said: the session's IR after it, compared with the
    IR after the words said (compiled by the same Listener that `cnlmc listen` uses)."""

    def __init__(self, lexicon: Lexicon, phrases: Phrases, undo: tuple[str, ...]) -> None:
        self.lexicon = lexicon
        self.phrases = phrases
        self.undo = undo
        self.expected: dict[tuple[str, bool], Any] = {}

    def session_ir(self, text: str | None, refinement: bool) -> Any:
        listener = Listener(self.lexicon, self.undo, 0.0)
        if refinement:
            listener.hear(Hypothesis(self.phrases.base, 1.0, ()))
            listener.hear(Hypothesis("darker", 1.0, ()))  # so that "undo" has a line to drop
        if text is not None:
            listener.hear(Hypothesis(text, 1.0, ()))
        if listener.result is None:
            return None
        return [{k: m.get(k) for k in IR_FIELDS} for m in listener.result.materials]

    def ir_equal(self, utterance: Utterance, heard: str | None) -> bool:
        key = (utterance.text, utterance.refinement)
        if key not in self.expected:
            self.expected[key] = self.session_ir(utterance.text, utterance.refinement)
        return heard is not None and self.session_ir(heard, utterance.refinement) == self.expected[key]
