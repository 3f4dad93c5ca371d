"""Enrolment: sentences read aloud, aligned to their known words by pocketsphinx, make a Voice
(cnlmc.speech.voice). The sentences are stdlib/speech/enrol.toml's: everyday English, not the
material language, so the voice learns the speaker's sounds rather than the test phrases' words.

A recording of the whole script (one WAV, the sentences read in order, a pause after each) is cut
at its longest pauses into one part per sentence, each aligned to its sentence. From the
microphone each sentence is prompted and recorded on its own."""

from __future__ import annotations

import tempfile
import tomllib
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .audio import split_at_pauses
from .pronounce import Pronunciations
from .recogniser import model_files, pocketsphinx_module
from .settings import SpeechSettings, speech_data
from .sphinx_files import read_cepstra
from .voice import AcousticModel, Aligned, Voice, VoiceError, acoustic_model, adapted_means

FRAMES_PER_SECOND = 100  # the front end's frame rate (10 ms)


@dataclass(frozen=True)
class Script:
    """What a speaker reads to enrol, and how strongly the statistics move the model."""

    sentences: tuple[str, ...]
    mllr_prior_frames: float
    map_prior: float
    min_seconds: float  # less aligned speech than this is refused (too little to adapt from)

    @classmethod
    def bundled(cls) -> Script:
        data = tomllib.loads(speech_data("enrol.toml"))
        return cls(
            tuple(" ".join(s.split()) for s in data["sentences"]),
            float(data["mllr_prior_frames"]),
            float(data["map_prior"]),
            float(data["min_seconds"]),
        )

    def words(self) -> set[str]:
        return {w for s in self.sentences for w in s.split()}


class Aligner:
    """pocketsphinx forced alignment with the recogniser's front end (the same warp, noise floor and
    beams), logging the cepstra it computed so adaptation sees exactly the recogniser's features."""

    def __init__(self, settings: SpeechSettings, script: Script) -> None:
        self.settings = settings
        self.model = acoustic_model(model_files().acoustic)
        pronunciations = Pronunciations(
            script.words(), model_files().dictionary, espeak=False, british=settings.british_variants
        )
        if pronunciations.missing:
            raise VoiceError(
                f"the enrolment script has words without a pronunciation: {sorted(pronunciations.missing)}"
            )
        self.dictionary = pronunciations.dictionary_text()

    def align(self, pcm: bytes, text: str) -> Aligned | None:
        """The frames of `pcm` aligned to `text`; None when pocketsphinx cannot follow it."""
        samples = self.settings.noise_floor.apply(pcm, self.settings.sample_rate)
        with tempfile.TemporaryDirectory(prefix="cnlmc-enrol-") as folder:
            decoder = self._decoder(Path(folder))
            try:
                decoder.set_align_text(text)
                _decode(decoder, samples)
                decoder.set_alignment()
                _decode(decoder, samples)
                alignment = decoder.get_alignment()
            except RuntimeError:
                return None
            logs = sorted((Path(folder) / "cepstra").glob("*.mfc"))
            if alignment is None or not logs:
                return None
            cepstra = read_cepstra(logs[-1], self.model.spec.ceplen)
        return self._frames(alignment, cepstra)

    def _decoder(self, folder: Path) -> Any:
        ps = pocketsphinx_module()
        (folder / "cepstra").mkdir()
        (folder / "words.dict").write_text(self.dictionary, "utf-8")
        config = ps.Config(
            hmm=str(model_files().acoustic),
            dict=str(folder / "words.dict"),
            samprate=self.settings.sample_rate,
            loglevel="FATAL",
            mfclogdir=str(folder / "cepstra"),
            **self.settings.decoder,
        )
        return ps.Decoder(config)

    def _frames(self, alignment: Any, cepstra: np.ndarray) -> Aligned | None:
        codebooks: list[int] = []
        senones: list[int] = []
        for word in alignment:
            for phone in word:
                codebook = self.model.codebook(phone.name)
                for state in phone:
                    codebooks += [codebook] * state.duration
                    senones += [int(state.name)] * state.duration
        count = min(len(codebooks), len(cepstra))
        if count == 0:
            return None
        return Aligned(cepstra[:count], np.array(codebooks[:count]), np.array(senones[:count]))


def _decode(decoder: Any, samples: bytes) -> None:
    decoder.start_utt()
    try:
        decoder.process_raw(samples, no_search=False, full_utt=True)
    finally:
        decoder.end_utt()


def voice_from(aligned: Iterable[Aligned], script: Script, model: AcousticModel | None = None) -> Voice:
    """The voice adapted from aligned sentences (VoiceError when there is too little speech)."""
    model = model or acoustic_model(model_files().acoustic)
    sentences = list(aligned)
    frames = sum(len(s.codebooks) for s in sentences)
    seconds = frames / FRAMES_PER_SECOND
    if seconds < script.min_seconds:
        raise VoiceError(
            f"only {seconds:.0f} s of speech could be aligned to the script (at least {script.min_seconds:.0f} s "
            "are needed): read every sentence of `cnlmc listen --enrol-script` in order, a pause after each"
        )
    means = adapted_means(model, sentences, script.mllr_prior_frames, script.map_prior)
    return Voice(means, model.fingerprint, len(sentences), seconds, frames)


def enrol_recording(pcm: bytes, aligner: Aligner, script: Script) -> Voice:
    """A recording of the whole script read in order: cut at its longest pauses into one part per
    sentence, each aligned to its sentence (a part that cannot be followed is left out); when it has
    too few pauses, aligned as one text."""
    parts = split_at_pauses(pcm, aligner.settings.sample_rate, len(script.sentences))
    if parts is not None:
        aligned = [aligner.align(part, text) for part, text in zip(parts, script.sentences)]
    else:
        aligned = [aligner.align(pcm, " ".join(script.sentences))]
    return voice_from([a for a in aligned if a is not None], script, aligner.model)


def enrol_live(segments: Iterator[bytes], aligner: Aligner, script: Script, tell: Callable[[str], None]) -> Voice:
    """From the microphone: each sentence prompted, then the utterances heard are aligned to it,
    each alone and all of them joined (a sentence read with a pause inside comes as two); asked
    for again when it cannot be followed, up to `ATTEMPTS` utterances, then left out (and said so)."""
    aligned: list[Aligned] = []
    count = len(script.sentences)
    for number, sentence in enumerate(script.sentences, 1):
        heard: list[bytes] = []
        found: Aligned | None = None
        while found is None and len(heard) < ATTEMPTS:
            tell(f"[{number}/{count}] read{' again' if heard else ''}: {sentence}")
            heard.append(next(segments))
            found = aligner.align(heard[-1], sentence)
            if found is None and len(heard) > 1:
                found = aligner.align(b"".join(heard), sentence)
        if found is None:
            tell(f"[{number}/{count}] could not follow that sentence; going on without it")
        else:
            aligned.append(found)
    return voice_from(aligned, script, aligner.model)


ATTEMPTS = 2  # readings of one sentence from the microphone before going on
