"""stdlib/speech/speech.toml: what may be said, the grammar's bounds and the confidence threshold."""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources
from typing import Any

from .noise_floor import NoiseFloor


def speech_data(name: str) -> str:
    """The text of a bundled file of stdlib/speech/."""
    return resources.files("cnlmc.stdlib").joinpath("speech").joinpath(name).read_text("utf-8")


@dataclass(frozen=True)
class SpeechSettings:
    max_form_words: int
    british_variants: bool
    survey_colour_max_words: int
    categories: tuple[str, ...]
    articles: tuple[str, ...]
    and_word: str
    or_word: str
    with_word: str
    undo: tuple[str, ...]
    max_groups: int
    max_clause_groups: int
    max_clauses: int
    max_items: int
    branch_smoothing: float  # added to each branch's count (cnlmc.speech.branches)
    prior_exponent: float
    min_confidence: float
    alternatives: int
    sample_rate: int
    spellings: tuple[tuple[str, str], ...]
    nbest_paths: int
    decoder: dict[str, float | bool | str]
    noise_floor: NoiseFloor
    retry: dict[str, float | bool]  # the second pass's search settings (empty: no second pass)
    voice_decoder: dict[str, float | bool | str]  # what changes in the search for an enrolled voice

    def same_spelling(self, one: str, other: str) -> bool:
        """Whether two forms differ only by spelling (British/American: 'aluminium', 'aluminum')."""
        return _spelled(one, self.spellings) == _spelled(other, self.spellings)

    @classmethod
    def bundled(cls) -> SpeechSettings:
        data: dict[str, Any] = tomllib.loads(speech_data("speech.toml"))
        vocabulary, grammar, recogniser = data["vocabulary"], data["grammar"], data["recogniser"]
        return cls(
            max_form_words=int(vocabulary["max_form_words"]),
            british_variants=bool(vocabulary["british_variants"]),
            survey_colour_max_words=int(vocabulary["survey_colour_max_words"]),
            categories=tuple(vocabulary["categories"]),
            articles=tuple(grammar["articles"]),
            and_word=str(grammar["and"]),
            or_word=str(grammar["or"]),
            with_word=str(grammar["with"]),
            undo=tuple(grammar["undo"]),
            max_groups=int(grammar["max_groups"]),
            max_clause_groups=int(grammar["max_clause_groups"]),
            max_clauses=int(grammar["max_clauses"]),
            max_items=int(grammar["max_items"]),
            branch_smoothing=float(grammar["branch_smoothing"]),
            prior_exponent=float(grammar["prior_exponent"]),
            min_confidence=float(recogniser["min_confidence"]),
            alternatives=int(recogniser["alternatives"]),
            sample_rate=int(recogniser["sample_rate"]),
            nbest_paths=int(recogniser["nbest_paths"]),
            decoder={str(k): _search_value(v) for k, v in recogniser["decoder"].items()},
            spellings=tuple((str(a), str(b)) for a, b in data["vocabulary"]["spellings"]),
            noise_floor=_noise_floor(recogniser["noise_floor"]),
            retry={str(k): float(v) for k, v in recogniser.get("retry", {}).items()},
            voice_decoder={str(k): _search_value(v) for k, v in recogniser.get("voice", {}).items()},
        )


def _noise_floor(table: dict[str, Any]) -> NoiseFloor:
    return NoiseFloor(
        below_speech_db=float(table["below_speech_db"]),
        frame_ms=float(table["frame_ms"]),
        speech_percentile=float(table["speech_percentile"]),
        pause_percentile=float(table["pause_percentile"]),
        seed=int(table["seed"]),
        slope=float(table["slope"]),
    )


def _search_value(value: Any) -> float | bool | str:
    """A pocketsphinx setting as speech.toml gives it: a switch, a text (warp_params) or a number."""
    return value if isinstance(value, bool | str) else float(value)


def _spelled(form: str, spellings: tuple[tuple[str, str], ...]) -> str:
    for old, new in spellings:
        form = form.replace(old, new)
    return form
