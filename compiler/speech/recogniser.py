"""pocketsphinx constrained to the lexicon's grammar: audio -> the best complete phrase, its
confidence and alternatives. pocketsphinx (optional extra 'speech') is imported only here."""

from __future__ import annotations

import math
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .settings import SpeechSettings

if TYPE_CHECKING:
    from .grammar import Grammar


class SpeechUnavailable(RuntimeError):
    """pocketsphinx (or the audio library) is not installed: what to install."""


def _pocketsphinx() -> Any:
    try:
        import pocketsphinx  # type: ignore[import-untyped]
    except ImportError as exc:
        raise SpeechUnavailable(
            f"speech input needs pocketsphinx ({exc}); install it with: pip install 'cnlmc[speech]'"
        ) from None
    return pocketsphinx


@dataclass(frozen=True)
class ModelFiles:
    acoustic: Path  # the en-US acoustic model folder
    dictionary: Path  # the CMU pronouncing dictionary


def model_files() -> ModelFiles:
    """The en-US model pocketsphinx ships inside its wheel (no download)."""
    root = Path(_pocketsphinx().get_model_path())
    return ModelFiles(root / "en-us" / "en-us", root / "en-us" / "cmudict-en-us.dict")


@dataclass(frozen=True)
class Hypothesis:
    """What was heard: the best complete phrase, its confidence (its share of the n-best list's
    probability, 0-1), and the next best phrases."""

    text: str
    confidence: float
    alternatives: tuple[str, ...]


class Recogniser:
    """One pocketsphinx decoder with the grammar loaded; decode() one utterance at a time."""

    def __init__(self, grammar: Grammar, dictionary: str, settings: SpeechSettings) -> None:
        ps = _pocketsphinx()
        self.settings = settings
        with tempfile.TemporaryDirectory(prefix="cnlmc-speech-") as folder:
            dict_path = Path(folder) / "words.dict"
            fsg_path = Path(folder) / "cnlmc.fsg"
            dict_path.write_text(dictionary, "utf-8")
            fsg_path.write_text(grammar.fsg_text(), "utf-8")  # read back: the reader closes null transitions
            config = ps.Config(
                hmm=str(model_files().acoustic),
                dict=str(dict_path),
                samprate=settings.sample_rate,
                loglevel="FATAL",
                **settings.decoder,
            )
            self.decoder = ps.Decoder(config)
            self.fsg = self.decoder.read_fsg(str(fsg_path))
        self.decoder.add_fsg("cnlmc", self.fsg)
        self.decoder.activate_search("cnlmc")

    def decode(self, samples: bytes) -> Hypothesis | None:
        """16-bit mono PCM at the settings' sample rate -> the hypothesis; None when no complete
        phrase of the grammar was heard."""
        decoder = self.decoder
        decoder.start_utt()
        decoder.process_raw(samples, no_search=False, full_utt=True)
        decoder.end_utt()
        best = decoder.hyp()
        text = " ".join(best.hypstr.split()) if best is not None else ""
        if not text or not self.fsg.accept(text):
            return None
        confidence, others = self._ranked(text)
        return Hypothesis(text, confidence, others)

    def _ranked(self, best: str) -> tuple[float, tuple[str, ...]]:
        """The best phrase's share of the n-best probability mass, and the other complete phrases."""
        scores: dict[str, int] = {}
        best = self._meaning(best)
        try:
            for count, entry in enumerate(self.decoder.nbest()):
                text = " ".join((entry.hypstr or "").split())
                if text and self._meaning(text) not in scores and self.fsg.accept(text):
                    scores[self._meaning(text)] = entry.score
                if count >= self.settings.nbest_paths or len(scores) > self.settings.alternatives:
                    break
        except RuntimeError:  # no lattice for this utterance
            return 1.0, ()
        scores.setdefault(best, max(scores.values(), default=0))
        top = max(scores.values())
        logmath = self.decoder.logmath
        weights = {t: math.exp(logmath.log_to_ln(s - top) * self.settings.confidence_scale) for t, s in scores.items()}
        others = tuple(t for t in sorted(scores, key=lambda t: -scores[t]) if t != best)
        return weights[best] / sum(weights.values()), others[: self.settings.alternatives]

    def _meaning(self, text: str) -> str:
        """The phrase without its articles, which never change the material: 'with a clear coat'
        and 'with clear coat' are one alternative, not two."""
        return " ".join(w for w in text.split() if w not in self.settings.articles)
