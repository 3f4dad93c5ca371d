"""Where a place or a use said at a line's end starts ('a glossier black| for the bonnet', 'a
lighter grey| for the hallway'): read past by cnlmc.document and cnlmc.implied so the words before
it read as they would alone. The words are data (teaching.toml [hedges])."""

from __future__ import annotations

import re

from .lexicon import Lexicon
from .phrase_patterns import alternatives
from .suggest import teaching

__all__ = ["place_at"]


def place_at(text: str, lexicon: Lexicon) -> int | None:
    """Where a place or a use said to the line's end starts ('a glossier black| for the bonnet'):
    a context word ([hedges] `context_pointing`, or a one-word `context` such as 'for'), a pointing
    word and what follows, whose last word is no material ('steel on the oak' has none); None."""
    table = teaching()["hedges"]
    single = [w for w in table["context"] if " " not in w]  # 'for' (the kitchen), 'wie'
    lead = [w for w in [*table["context_pointing"], *single] if w not in table["context_after_noun"]]
    pattern = rf"\s(?:{alternatives(lead)})\s+(?:{alternatives(table['pointing_words'])})\s+\S.*$"
    found = re.search(pattern, text, re.IGNORECASE)
    if found is None:
        return None
    last = text[found.start() :].split()[-1].strip(".,!?").lower()
    if any(e.category == "nouns" for e in lexicon.lookup((last,))):
        return None
    return found.start()
