"""'Did you mean' for unknown words: the lexicon's FormIndex against measuring every form (its
peer: the same answer, what cnlmc did before the index), in one process.

    .venv/bin/python bench/suggest_bench.py [--lines 300] [--words 1500]

Prints, with the load average (the machine is shared; compare the ratios):
- microseconds per suggestion for made-up words (bench/lsp_memory.py's: 5-9 letters) and for
  typos of the lexicon's own words (two letters changed), short (one edit allowed) and long;
- seconds to compile a document of LINES lines of made-up words with each (the suggestion memo
  and the tagger's memo emptied first), and per line. Goal (#13): <= 0.3 s for 300 lines on a
  quiet machine, about 1 ms a line.
"""

from __future__ import annotations

import argparse
import os
import random
import string
import sys
import time
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from lsp_memory import unknown_words_document

from cnlmc.api import compile_source, lexicon_for
from cnlmc.lexicon import CATEGORY_TAGS, Lexicon
from cnlmc.suggest import FormIndex


class ScanningIndex(FormIndex):
    """The peer: every form measured for every word."""

    def closest(self, word: str, categories, limit: int, scan: bool = False) -> list[str]:
        return super().closest(word, categories, limit, scan=True)


def indexes(lexicon: Lexicon) -> tuple[FormIndex, FormIndex]:
    forms = {" ".join(f): {e.category for e in hits} for f, hits in lexicon.forms.items()}
    return FormIndex(forms), ScanningIndex(forms)


def typos_of_forms(index: FormIndex, count: int, seed: int = 3) -> list[str]:
    rng = random.Random(seed)
    words = []
    for form in rng.sample([f for f in index.forms if " " not in f and len(f) >= 4], count):
        letters = list(form)
        for _ in range(2):
            letters[rng.randrange(len(letters))] = rng.choice(string.ascii_lowercase)
        words.append("".join(letters))
    return words


def per_word_us(index: FormIndex, words: list[str]) -> float:
    everything = tuple(CATEGORY_TAGS)
    t0 = time.perf_counter()
    for word in words:
        index.closest(word, everything, 3)
    return (time.perf_counter() - t0) / max(1, len(words)) * 1e6


def compile_seconds(lexicon: Lexicon, index: FormIndex, text: str) -> float:
    lexicon.caches.suggestion_index = index
    lexicon.caches.suggestions.clear()
    lexicon.caches.tagger = None
    t0 = time.perf_counter()
    compile_source(text, "<bench>", lexicon)
    return time.perf_counter() - t0


def row(label: str, measure: Callable[[FormIndex], float], fast: FormIndex, peer: FormIndex, unit: str) -> None:
    a, b = measure(fast), measure(peer)
    print(f"{label:44s} index {a:10.1f} {unit}   every form {b:10.1f} {unit}   x{b / a:6.1f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=300)
    parser.add_argument("--words", type=int, default=1500)
    args = parser.parse_args()

    lexicon = lexicon_for()
    compile_source("zorblat steel\nblu plastic", "<warm-up>", lexicon)
    fast, peer = indexes(lexicon)
    fast.closest("warmupwarmupwarmup", tuple(CATEGORY_TAGS), 3)  # builds both of its indexes
    fast.closest("warm", tuple(CATEGORY_TAGS), 3)
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; {len(fast.forms)} forms")
    made_up = unknown_words_document(7, args.words // 5 + 1).split()[: args.words]
    typos = typos_of_forms(fast, min(args.words, 1500))
    for name, words in (("made-up words", made_up), ("typos of forms", typos)):
        for label, short in (("<= 7 letters", True), (">= 8 letters", False)):
            chosen = [w for w in words if (len(w) <= 7) == short]
            row(f"{name} {label} (n={len(chosen)}), per word", lambda i, c=chosen: per_word_us(i, c), fast, peer, "us")
    text = unknown_words_document(11, args.lines)
    row(f"compile {args.lines} lines of made-up words", lambda i: compile_seconds(lexicon, i, text), fast, peer, "s ")
    seconds = compile_seconds(lexicon, fast, text)
    print(f"  with the index: {seconds / args.lines * 1000:.2f} ms a line (goal ~1 ms on a quiet machine)")


if __name__ == "__main__":
    main()
