"""Friendly syntax errors learned from grammar/bad_examples.toml.

Each example phrase is parsed once; the parser state and token type where it fails become
the key for its message. A user's error with the same key gets that message.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources

from .parser import ParseFailure, parse_tagged
from .tagger import Tagger


@dataclass(frozen=True)
class Mistake:
    message: str
    hint: str


def _read_table() -> list[dict]:
    import tomllib

    text = resources.files("cnlmc.grammar").joinpath("bad_examples.toml").read_text("utf-8")
    return tomllib.loads(text)["mistake"]


def learn(lexicon) -> dict:
    """(state, token type) -> Mistake, from every example phrase (first example wins)."""
    tagger, table = Tagger(lexicon), {}
    for row in _read_table():
        mistake = Mistake(row["message"], row["hint"])
        for phrase in row["phrases"]:
            key = _failure_key(tagger, phrase)
            if key is not None:
                table.setdefault(key, mistake)
    return table


def _failure_key(tagger: Tagger, phrase: str):
    tagged, _diags = tagger.tag_line(phrase, 1, 0)
    try:
        parse_tagged([t for t in tagged if t.candidates])
    except ParseFailure as failure:
        return failure.key
    return None


def known_mistake(lexicon, failure: ParseFailure) -> Mistake | None:
    table = getattr(lexicon, "_mistakes", None)
    if table is None:
        table = lexicon._mistakes = learn(lexicon)
    return table.get(failure.key)
