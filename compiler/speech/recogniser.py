"""pocketsphinx constrained to the lexicon's grammar: audio -> the best complete phrase, its
confidence and alternatives. pocketsphinx (optional extra 'speech') is imported only here."""

from __future__ import annotations

import itertools
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .settings import SpeechSettings

if TYPE_CHECKING:
    from .grammar import Grammar
    from .voice import Voice


FIRST, LATER = "first", "later"  # the searches: an utterance that starts a material, one said after it
MIN_SECONDS = 0.1  # shorter audio is no phrase: 'undo', the shortest, takes 0.4 s at 190 wpm


class SpeechUnavailable(RuntimeError):
    """pocketsphinx (or the audio library) is not installed: what to install."""


def pocketsphinx_module() -> Any:
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
    language_model: Path  # the en-US n-gram model (word frequencies: cnlmc.speech.prior)


def model_files() -> ModelFiles:
    """The en-US model pocketsphinx ships inside its wheel (no download)."""
    root = Path(pocketsphinx_module().get_model_path())
    return ModelFiles(root / "en-us" / "en-us", root / "en-us" / "cmudict-en-us.dict", root / "en-us" / "en-us.lm.bin")


def _written_means(folder: Path, voice: Voice) -> Path:
    from .sphinx_files import gaussians_bytes

    path = folder / "means"
    path.write_bytes(gaussians_bytes(voice.means))
    return path


@dataclass(frozen=True)
class Hypothesis:
    """What was heard: the best complete phrase, its confidence (its share of the n-best list's
    probability, 0-1), and the next best phrases."""

    text: str
    confidence: float
    alternatives: tuple[str, ...]


@dataclass
class Votes:
    """A phrase of the n-best list (as first heard) and how many of its paths say it."""

    text: str
    paths: int


class Recogniser:
    """The grammar loaded in pocketsphinx; decode() one utterance at a time. A first pass searches
    with the settings' narrow beams (fast); when it reaches no complete phrase, a second pass with
    the wide beams of `settings.retry` (made on first need) searches the utterance again. `later`,
    when given, is the grammar searched for utterances said after a material (refining=True): the
    same phrases weighed for that context (cnlmc.speech.branches). `voice`, when given, is an enrolled
    speaker's voice (cnlmc.speech.voice): its adapted means replace the model's."""

    def __init__(
        self,
        grammar: Grammar,
        dictionary: str,
        settings: SpeechSettings,
        later: Grammar | None = None,
        voice: Voice | None = None,
    ):
        self.settings = settings
        self.voice = voice
        self.search = {**settings.decoder, **(settings.voice_decoder if voice is not None else {})}
        wide = {**self.search, **settings.retry}
        self.retry = wide if wide != self.search else None  # no second pass that would search the same way
        if later is not None and [t[:2] for t in later.transitions] != [t[:2] for t in grammar.transitions]:
            raise ValueError("the later grammar must have the first one's structure (one FSG checks both)")
        self.grammar_texts = {FIRST: grammar.fsg_text(FIRST), LATER: (later or grammar).fsg_text(LATER)}
        self.dictionary = dictionary
        self.decoder, self.fsg = self._loaded(self.search)
        self.wide: Any = None

    def _loaded(self, search: dict[str, float | bool | str]) -> tuple[Any, Any]:
        """A decoder with the grammars and these search settings, and the first grammar as it read it."""
        ps = pocketsphinx_module()
        with tempfile.TemporaryDirectory(prefix="cnlmc-speech-") as folder:
            dict_path = Path(folder) / "words.dict"
            dict_path.write_text(self.dictionary, "utf-8")
            if self.voice is not None:  # read when the decoder is made: the folder may go after
                search = {**search, "mean": str(_written_means(Path(folder), self.voice))}
            config = ps.Config(
                hmm=str(model_files().acoustic),
                dict=str(dict_path),
                samprate=self.settings.sample_rate,
                loglevel="FATAL",
                **search,
            )
            decoder = ps.Decoder(config)
            read = {}
            for name, text in self.grammar_texts.items():
                fsg_path = Path(folder) / f"{name}.fsg"
                fsg_path.write_text(text, "utf-8")  # read back: the reader closes null transitions
                read[name] = decoder.read_fsg(str(fsg_path))
                decoder.add_fsg(name, read[name])
        return decoder, read[FIRST]

    def decode(self, samples: bytes, refining: bool = False) -> Hypothesis | None:
        """16-bit mono PCM at the settings' sample rate -> the hypothesis; None when no complete
        phrase of the grammar was heard (by either pass). `refining`: a material is already there
        (the later grammar is searched). The audio first gets its noise floor
        (cnlmc.speech.noise_floor)."""
        if len(samples) < 2 * self.settings.sample_rate * MIN_SECONDS:
            return None  # too short to be a phrase (pocketsphinx fails on an empty utterance)
        samples = self.settings.noise_floor.apply(samples, self.settings.sample_rate)
        search = LATER if refining else FIRST
        heard = self._search(self.decoder, samples, search)
        if heard is None and self.retry is not None:
            if self.wide is None:
                self.wide = self._loaded(self.retry)[0]
            heard = self._search(self.wide, samples, search)
        return heard

    def _search(self, decoder: Any, samples: bytes, search: str) -> Hypothesis | None:
        """One pass. When the best path ends short of a complete phrase (pocketsphinx then returns
        a partial one: 'more' for a British 'darker'), the best complete phrase of the n-best list
        is taken instead."""
        decoder.activate_search(search)
        decoder.start_utt()
        try:
            decoder.process_raw(samples, no_search=False, full_utt=True)
        finally:  # an utterance left open breaks every later one (pocketsphinx keeps its state)
            decoder.end_utt()
        best = decoder.hyp()
        text = " ".join(best.hypstr.split()) if best is not None else ""
        votes = self._votes(decoder)
        if text and self.fsg.accept(text):
            meaning = self._meaning(text)
            votes.setdefault(meaning, Votes(text, 1))
        elif votes:
            meaning = next(iter(votes))  # the best scoring complete path
        else:
            return None
        return Hypothesis(votes[meaning].text, *self._ranked(meaning, votes))

    def _votes(self, decoder: Any) -> dict[str, Votes]:
        """The complete phrases of the first `nbest_paths` n-best paths, best first: meaning -> votes."""
        found: dict[str, Votes] = {}
        try:
            for entry in itertools.islice(decoder.nbest() or (), self.settings.nbest_paths):
                text = " ".join((entry.hypstr or "").split())
                if text and self.fsg.accept(text):
                    votes = found.setdefault(self._meaning(text), Votes(text, 0))
                    votes.paths += 1
        except RuntimeError:  # no lattice for this utterance
            pass
        return found

    def _ranked(self, best: str, votes: dict[str, Votes]) -> tuple[float, tuple[str, ...]]:
        """The best phrase's share of the complete n-best paths (1 when it is the only one heard),
        and the other phrases, most voted first."""
        total = sum(v.paths for v in votes.values())
        confidence = votes[best].paths / total
        others = tuple(votes[m].text for m in sorted(votes, key=lambda m: -votes[m].paths) if m != best)
        return confidence, others[: self.settings.alternatives]

    def _meaning(self, text: str) -> str:
        """The phrase without its articles, which never change the material: 'with a clear coat'
        and 'with clear coat' are one alternative, not two."""
        return " ".join(w for w in text.split() if w not in self.settings.articles)
