"""Generate stdlib/data/wordnet_aliases.toml: "teak is a kind of wood", "lustrous ~ glossy", from WordNet 3.0.

Reads the WordNet 3.0 database files (WNDB format, wndb(5WN)) directly as text, with no
dependency: data.noun, index.noun, data.adj, index.adj. Debian/Ubuntu install them with

    apt-get install -y wordnet-base wordnet-sense-index        # -> /usr/share/wordnet

and then (from the repository root)

    .venv/bin/python scripts/gen_wordnet_aliases.py             # rewrite stdlib/data/wordnet_aliases.toml
    .venv/bin/python scripts/gen_wordnet_aliases.py --check     # exit 1 when the committed file is stale
    .venv/bin/python scripts/gen_wordnet_aliases.py --wordnet DIR   # another WNDB folder

What it extracts
- nouns: every lemma under the material roots below (their transitive hyponyms), plus every noun
  of the stdlib lexicon (stdlib/lexicon/nouns_*.toml keys and aliases) that WordNet knows:
  word -> {kind_of = hypernym lemmas from the word up to its root ("teak" -> ["wood"]),
  root, synset (NLTK-style name lemma.n.NN), gloss (its first clause, at most 120 characters)}.
  A word under several roots keeps the sense WordNet lists first (the most frequent).
- adjectives: every stdlib adjective (stdlib/lexicon/adjectives.toml keys and aliases) that
  WordNet knows: word -> {synonyms, antonyms} of its first (most frequent) sense, plus `senses`,
  every sense with its own synset, gloss, synonyms (same synset + similar-to cluster) and antonyms
  (direct, or through the head adjective for a satellite).
- missing: the stdlib words WordNet does not have.

Provenance: Princeton University, "WordNet 3.0" (2006), https://wordnet.princeton.edu/ ;
George A. Miller (1995), "WordNet: A Lexical Database for English", CACM 38(11): 39-41;
Christiane Fellbaum (1998, ed.), "WordNet: An Electronic Lexical Database", MIT Press.
Licence: the WordNet 3.0 licence (BSD-style; "WordNet 3.0 Copyright 2006 by Princeton
University. All rights reserved."; free use, copy, modify and distribute with the notice kept),
https://wordnet.princeton.edu/license-and-commercial-use . English only.

Deterministic: the output depends only on the WordNet files and the stdlib lexicon files; all
lists are sorted. compiler/wordnet.py reads it for unknown words (issue #14); CI has no
WordNet, so the tests check only the committed file's shape.
"""

from __future__ import annotations

import argparse
import re
import sys
import tomllib
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "stdlib" / "data" / "wordnet_aliases.toml"
WORDNET = Path("/usr/share/wordnet")

# the material roots: (name, WordNet 3.0 noun synset offset, a lemma that synset must contain)
ROOTS = (
    ("wood", 15098161, "wood"),
    ("rock", 14696793, "rock"),
    ("stone", 4326084, "stone"),
    ("gemstone", 14699752, "gem"),
    ("mineral", 14662574, "mineral"),
    ("metal", 14625458, "metal"),
    ("alloy", 14586769, "alloy"),
    ("fabric", 3309808, "fabric"),
    ("leather", 14759722, "leather"),
    ("plastic", 14592610, "plastic"),
    ("glass", 14881303, "glass"),
    ("ceramic", 2997391, "ceramic"),
    ("building material", 14786479, "building_material"),
    ("paint", 3875218, "paint"),
)

GLOSS_CHARS = 120


@dataclass
class Synset:
    offset: int
    pos: str  # n, a, s
    words: list[str]  # lemmas as in the file (underscores; adjective markers removed)
    pointers: list[tuple[str, int, str, int, int]]  # (symbol, offset, pos, source word, target word)
    gloss: str
    names: list[str] = field(default_factory=list)


#: lemmas this short are chemical symbols and abbreviations ('v', 'u', 'in', 'co', 'pc'): a person
#: typing them means 'very', 'you', a preposition, never vanadium or indium; none is aliased.
SYMBOL_LENGTH = 2


def parse_data(path: Path) -> dict[int, Synset]:
    """A WNDB data.* file -> offset -> Synset (wndb(5WN): offset lex_filenum ss_type w_cnt ...)."""
    out: dict[int, Synset] = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("  "):  # the licence header
                continue
            head, _, gloss = line.partition(" | ")
            t = head.split()
            offset, ss_type, w_cnt = int(t[0]), t[2], int(t[3], 16)
            i = 4
            words = []
            for _ in range(w_cnt):
                words.append(re.sub(r"\((a|p|ip)\)$", "", t[i]))
                i += 2
            p_cnt = int(t[i])
            i += 1
            ptrs = []
            for _ in range(p_cnt):
                sym, off, pos, st = t[i], int(t[i + 1]), t[i + 2], t[i + 3]
                ptrs.append((sym, off, pos, int(st[:2], 16), int(st[2:], 16)))
                i += 4
            out[offset] = Synset(offset, ss_type, words, ptrs, gloss.strip())
    return out


def parse_index(path: Path) -> dict[str, list[int]]:
    """A WNDB index.* file -> lemma -> synset offsets in sense order (most frequent first)."""
    out: dict[str, list[int]] = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("  "):
                continue
            t = line.split()
            synset_cnt, p_cnt = int(t[2]), int(t[3])
            offsets = t[4 + p_cnt + 2 :]
            assert len(offsets) == synset_cnt, line
            out[t[0]] = [int(o) for o in offsets]
    return out


def sense_names(data: dict[int, Synset], index: dict[str, list[int]], pos: str) -> None:
    """Give each synset its NLTK-style name: first lemma . pos . sense number of that lemma."""
    for syn in data.values():
        lemma = syn.words[0].lower()
        offsets = index.get(lemma, [])
        n = offsets.index(syn.offset) + 1 if syn.offset in offsets else 1
        syn.names = [f"{lemma}.{'s' if syn.pos == 's' else pos}.{n:02d}"]


def word(lemma: str) -> str:
    return lemma.replace("_", " ").lower()


def short_gloss(gloss: str) -> str:
    first = gloss.split(";")[0].strip().strip('"').strip()
    return first if len(first) <= GLOSS_CHARS else first[: GLOSS_CHARS - 1].rsplit(" ", 1)[0] + "…"


def hyponym_paths(data: dict[int, Synset], root: int) -> dict[int, list[int]]:
    """Synset offset -> the path of offsets from its parent up to the root (BFS: shortest paths)."""
    paths: dict[int, list[int]] = {root: []}
    queue = deque([root])
    while queue:
        cur = queue.popleft()
        for sym, off, pos, _, _ in data[cur].pointers:
            if sym == "~" and pos == "n" and off not in paths:
                paths[off] = [cur, *paths[cur]]
                queue.append(off)
    return paths


def hypernym_path(data: dict[int, Synset], start: int, targets: set[int]) -> list[int] | None:
    """The shortest hypernym path from `start` up to one of `targets` (BFS over @ and @i), or None."""
    prev: dict[int, int | None] = {start: None}
    queue = deque([start])
    while queue:
        cur = queue.popleft()
        if cur in targets and cur != start:
            path = []
            node: int | None = prev[cur]
            path.append(cur)
            while node is not None and node != start:
                path.append(node)
                node = prev[node]
            return list(reversed(path))
        for sym, off, pos, _, _ in data[cur].pointers:
            if sym in ("@", "@i") and pos == "n" and off not in prev:
                prev[off] = cur
                queue.append(off)
    return None


def stdlib_words(prefix: str) -> list[str]:
    """Keys and aliases of stdlib/lexicon/<prefix>*.toml (lower case)."""
    words: set[str] = set()
    for path in sorted((ROOT / "stdlib" / "lexicon").glob(f"{prefix}*.toml")):
        with open(path, "rb") as f:
            table = tomllib.load(f)
        for key, entry in table.items():
            if isinstance(entry, dict):
                words.add(key.lower())
                words.update(a.lower() for a in entry.get("aliases", []))
    return sorted(words)


def lemma_key(w: str) -> str:
    return w.strip().lower().replace(" ", "_")


def noun_entries(
    data: dict[int, Synset], index: dict[str, list[int]], extra: list[str]
) -> tuple[dict[str, dict[str, object]], list[str]]:
    root_of = {off: name for name, off, _ in ROOTS}
    for name, off, lemma in ROOTS:
        if lemma not in data[off].words:
            raise SystemExit(f"WordNet data differ from 3.0: synset {off} ({name}) lacks '{lemma}'")
    # candidates: (word, synset offset, path to root, root name, root order)
    candidates: dict[str, list[tuple[int, int, int, list[int], str]]] = {}
    for order, (name, off, _) in enumerate(ROOTS):
        for syn_off, path in hyponym_paths(data, off).items():
            for lemma in data[syn_off].words:
                w = word(lemma)
                if len(w) <= SYMBOL_LENGTH:  # chemical symbols ('v' vanadium, 'in' indium): never a user's noun
                    continue
                senses = index.get(lemma.lower(), [])
                sense = senses.index(syn_off) if syn_off in senses else 99
                candidates.setdefault(w, []).append((sense, order, len(path), path, name))
                del w
    out: dict[str, dict[str, object]] = {}
    for w, cands in candidates.items():
        sense, _, _, path, root = min(cands, key=lambda c: (c[0], c[1], c[2], c[3]))
        syn = data[index[lemma_key(w)][sense]] if sense != 99 else None
        if syn is None:
            continue
        out[w] = entry(data, syn, path, root)
    missing = []
    targets = set(root_of)
    for w in extra:
        if w in out:
            continue
        offsets = index.get(lemma_key(w))
        if not offsets:
            missing.append(w)
            continue
        best = None
        for off in offsets:  # the first sense that reaches a material root, else the first sense
            path = hypernym_path(data, off, targets)
            if path is not None:
                best = (off, path)
                break
        if best is None:
            off = offsets[0]
            chain = hypernym_path(
                data, off, {o for o, s in data.items() if not any(p[0] in ("@", "@i") for p in s.pointers)}
            )
            out[w] = entry(data, data[off], chain or [], None)
        else:
            off, path = best
            out[w] = entry(data, data[off], path, root_of[path[-1]] if path else None)
    return out, missing


def entry(data: dict[int, Synset], syn: Synset, path: list[int], root: str | None) -> dict[str, object]:
    e: dict[str, object] = {"kind_of": [word(data[o].words[0]) for o in path]}
    if root is not None:
        e["root"] = root
    e["synset"] = syn.names[0]
    e["gloss"] = short_gloss(syn.gloss)
    return e


def adjective_entries(
    data: dict[int, Synset], index: dict[str, list[int]], words: list[str]
) -> tuple[dict[str, dict[str, object]], list[str]]:
    out: dict[str, dict[str, object]] = {}
    missing = []
    for w in words:
        key = lemma_key(w)
        offsets = index.get(key)
        if not offsets:
            missing.append(w)
            continue
        senses = []
        for off in offsets:
            syn = data[off]
            synonyms = {word(x) for x in syn.words}
            antonyms: set[str] = set()
            heads = []
            for sym, target, _, src, tgt in syn.pointers:
                if sym == "&":
                    synonyms.update(word(x) for x in data[target].words)
                    if syn.pos == "s":
                        heads.append(target)
                if sym == "!" and (src == 0 or syn.words[src - 1].lower() == key):
                    antonyms.add(word(data[target].words[tgt - 1] if tgt else data[target].words[0]))
            for head in heads:  # a satellite's antonyms are its head's (indirect antonyms)
                for sym, target, _, _, tgt in data[head].pointers:
                    if sym == "!":
                        antonyms.add(word(data[target].words[tgt - 1] if tgt else data[target].words[0]))
            synonyms.discard(word(key))
            senses.append(
                {
                    "synset": syn.names[0],
                    "gloss": short_gloss(syn.gloss),
                    "synonyms": sorted(synonyms - antonyms),
                    "antonyms": sorted(antonyms),
                }
            )
        out[w] = {"synonyms": senses[0]["synonyms"], "antonyms": senses[0]["antonyms"], "senses": senses}
    return out, missing


# ----------------------------------------------------------------------------------------- TOML


def q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def arr(items: list[str]) -> str:
    return "[" + ", ".join(q(i) for i in items) + "]"


def inline(d: dict[str, object]) -> str:
    parts = []
    for k, v in d.items():
        parts.append(f"{k} = {arr(v) if isinstance(v, list) else q(str(v))}")  # type: ignore[arg-type]
    return "{ " + ", ".join(parts) + " }"


HEADER = """\
# WordNet-derived aliases for materials and finishes: hypernyms of material nouns and synonyms /
# antonyms of the stdlib's adjectives.
# GENERATED by scripts/gen_wordnet_aliases.py from WordNet 3.0's WNDB files (Debian wordnet-base):
# do not edit; rerun the script (its docstring says how).
#
# Source: Princeton University, "WordNet 3.0" (2006), https://wordnet.princeton.edu/ ;
# G. A. Miller (1995), CACM 38(11):39-41; C. Fellbaum (ed., 1998), WordNet, MIT Press.
# Licence: WordNet 3.0 licence (BSD-style), "WordNet 3.0 Copyright 2006 by Princeton University.
# All rights reserved." https://wordnet.princeton.edu/license-and-commercial-use
# English only. Read by compiler/wordnet.py for words the lexicon does not know, as the [wordnet]
# rules of stdlib/lexicon/word_formation.toml say; every reading says so in a note ("read 'gabbro'
# as a kind of rock (WordNet 3.0: ...)"); the lexicon stays the authority.
#
# [nouns]       word -> kind_of (hypernym lemmas, nearest first, ending at the root), root (one of
#               [meta].roots; absent when the word reaches none), synset (NLTK-style), gloss.
# [adjectives]  word -> synonyms / antonyms of its first (most frequent) sense, and every sense.
# [missing]     stdlib words WordNet does not have.
"""


def render(
    nouns: dict[str, dict[str, object]],
    adjectives: dict[str, dict[str, object]],
    missing_nouns: list[str],
    missing_adjectives: list[str],
) -> str:
    lines = [HEADER, "[meta]"]
    lines.append('source = "WordNet 3.0, Princeton University (2006)"')
    lines.append('licence = "WordNet 3.0 licence (BSD-style), Copyright 2006 by Princeton University"')
    lines.append('url = "https://wordnet.princeton.edu/"')
    lines.append('generator = "scripts/gen_wordnet_aliases.py"')
    lines.append("roots = " + arr([name for name, _, _ in ROOTS]))
    lines.append("")
    lines.append("[missing]")
    lines.append("nouns = " + arr(sorted(missing_nouns)))
    lines.append("adjectives = " + arr(sorted(missing_adjectives)))
    lines.append("")
    lines.append("[nouns]")
    for w in sorted(nouns):
        lines.append(f"{q(w)} = {inline(nouns[w])}")
    lines.append("")
    for w in sorted(adjectives):
        a = adjectives[w]
        lines.append(f"[adjectives.{q(w)}]")
        lines.append(f"synonyms = {arr(a['synonyms'])}")  # type: ignore[arg-type]
        lines.append(f"antonyms = {arr(a['antonyms'])}")  # type: ignore[arg-type]
        lines.append("senses = [")
        for s in a["senses"]:  # type: ignore[attr-defined]
            lines.append(f"  {inline(s)},")
        lines.append("]")
        lines.append("")
    return "\n".join(lines)


def generate(wordnet: Path = WORDNET) -> str:
    for name in ("data.noun", "index.noun", "data.adj", "index.adj"):
        if not (wordnet / name).exists():
            raise SystemExit(
                f"{wordnet / name} not found: install WordNet 3.0 "
                "(apt-get install -y wordnet-base wordnet-sense-index) or pass --wordnet DIR"
            )
    nouns_data, nouns_index = parse_data(wordnet / "data.noun"), parse_index(wordnet / "index.noun")
    adj_data, adj_index = parse_data(wordnet / "data.adj"), parse_index(wordnet / "index.adj")
    sense_names(nouns_data, nouns_index, "n")
    sense_names(adj_data, adj_index, "a")
    nouns, missing_nouns = noun_entries(nouns_data, nouns_index, stdlib_words("nouns_"))
    adjectives, missing_adjectives = adjective_entries(adj_data, adj_index, stdlib_words("adjectives"))
    return render(nouns, adjectives, missing_nouns, missing_adjectives)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="Generate stdlib/data/wordnet_aliases.toml from WordNet 3.0.")
    ap.add_argument("--wordnet", type=Path, default=WORDNET, help="folder of the WNDB files (data.noun, ...)")
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--check", action="store_true", help="exit 1 when the committed file differs from a fresh one")
    args = ap.parse_args(argv)
    text = generate(args.wordnet)
    if args.check:
        same = args.out.exists() and args.out.read_text("utf-8") == text
        print(f"{args.out}: {'current' if same else 'STALE: rerun scripts/gen_wordnet_aliases.py'}")
        return 0 if same else 1
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text, "utf-8")
    with open(args.out, "rb") as f:
        data = tomllib.load(f)
    print(f"wrote {args.out}: {len(data['nouns'])} nouns, {len(data['adjectives'])} adjectives")
    return 0


if __name__ == "__main__":
    sys.exit(main())
