"""Words said as a refinement of a document (the studio's refine box, a spoken utterance after the
first): the line to add below its last material.

Describing words alone start a material of their own (cnlmc.implied: 'purple' = purple paint), but
said as a refinement they mean a change of the material there: they are added as the change line
'make it purple' (teaching.toml [politeness] changes). Anything else is added as it was said."""

from __future__ import annotations

from .api import Result, compile_source
from .lexicon import Lexicon
from .suggest import teaching

__all__ = ["refined"]


def refined(document: str, words: str, lexicon: Lexicon, name: str, seed: int = 0) -> tuple[str, Result]:
    """The document with `words` added as a refinement line, and its compile result."""
    base = document.rstrip("\n")
    text = f"{base}\n{words}"
    trial = compile_source(text, name, lexicon, seed)
    if len(trial.materials) > len(compile_source(base, name, lexicon, seed).materials):
        text = f"{base}\n{teaching()['politeness']['changes'][0]} {words}"  # 'make it': the first listed
        trial = compile_source(text, name, lexicon, seed)
    return text, trial
