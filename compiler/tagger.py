"""The tagger: one line of text -> words tagged with their candidate parts of speech.

Words are matched against the lexicon longest-first ("stainless steel" before "steel",
"a bit" before "a"); a word that is not found is tried in its base forms (inflection
rules from the lexicon) and, hyphenated, as its spaced form ("blue-grey" as "blue grey"), then
read by the lexicon's word formation rules (cnlmc.word_formation: unpolished, semi-matte,
wooden, not glossy; each reading is a NOTE), then reported with "did you mean". A word may
carry several candidate tags ("gold": colour or noun); the parser picks the one the grammar
accepts. Decorative punctuation (a trailing '.', a leading bullet, enclosing quotes) is dropped.
Object nouns (objects.toml) never reach the parser: after a material noun they join it ("oak
planks" = oak), alone they read as their material ("planks" = wood); a noun followed by its own
class ("walnut wood") is the noun.
"""

from __future__ import annotations

import re
from collections import OrderedDict
from typing import TYPE_CHECKING

from .diagnostics import Diagnostic, Severity, did_you_mean, error
from .lexicon import Lexicon
from .spans import Span, line_span
from .tagged import NOTE_CODE, Candidate, Tagged

if TYPE_CHECKING:  # imported on first use: only a line with an unknown word or punctuation needs it
    from .word_formation import Reading, WordFormation

__all__ = [
    "MEMO_SIZE",
    "OPEN_TAGS",
    "TAG_PREFERENCE",
    "TOKEN_RE",
    "Candidate",
    "Tagged",
    "Tagger",
    "WordMemo",
    "raw_tokens",
]

TOKEN_RE = re.compile(r"[^\W\d_](?:[\w'’\-]*\w)?|\d+(?:\.\d+)?%?|[,;:&]|\S", re.UNICODE)
OPEN_TAGS = ("ADV", "SHADE", "COLOR", "PROP", "ADJ", "COAT", "NOUN", "REFINE")
# a word that is a feature and a coat reads as the feature where both parse ("with a matte finish": the surface)
_FEATURE_FIRST = tuple(t for tag in OPEN_TAGS for t in (("FEATURE", tag) if tag == "COAT" else (tag,)))
TAG_PREFERENCE = {
    t: i for i, t in enumerate(("NAME", "COLON", "ARTICLE", "AND", "OR", "WITH", "COMMA", *_FEATURE_FIRST, "OBJECT"))
}


def raw_tokens(line: str) -> list[tuple[str, int]]:
    """(text, 0-based column) of each word or punctuation mark; '#' starts a comment."""
    if "#" not in line:
        return [(match.group(), match.start()) for match in TOKEN_RE.finditer(line)]
    out = []
    for match in TOKEN_RE.finditer(line):
        if match.group() == "#":
            break
        out.append((match.group(), match.start()))
    return out


RawToken = tuple[str, int]  # a word's text and 0-based column
#: The readings a head word ("finish", "look") joins: before the noun (False) or at the line's end (True).
HEAD_HOLDERS = {False: ("ADJ", "COLOR", "NOUN"), True: ("NOUN",)}
WordKey = tuple[str, ...]  # the lower-case words of a (multi-word) form

#: How many word forms a Tagger remembers (known, inflected and unknown ones alike). An entry is
#: a few hundred bytes, so a memo this full holds a few MB; the least recently used goes first.
MEMO_SIZE = 20_000


class WordMemo:
    """Word form -> its candidates, least recently used first out beyond `limit` entries."""

    __slots__ = ("_entries", "limit")

    def __init__(self, limit: int = MEMO_SIZE) -> None:
        self._entries: OrderedDict[WordKey, tuple[Candidate, ...]] = OrderedDict()
        self.limit = limit

    def get(self, key: WordKey) -> tuple[Candidate, ...] | None:
        entries = self._entries
        found = entries.get(key)
        if found is not None:
            entries.move_to_end(key)
        return found

    def put(self, key: WordKey, candidates: tuple[Candidate, ...]) -> None:
        entries = self._entries
        entries[key] = candidates
        entries.move_to_end(key)
        if len(entries) > self.limit:
            entries.popitem(last=False)

    def __len__(self) -> int:
        return len(self._entries)

    def __contains__(self, key: object) -> bool:
        return key in self._entries


class Tagger:
    """Tags lines against one lexicon; what it learns about words is kept in its own bounded memo
    (`memo`, a WordMemo of MEMO_SIZE entries). `Tagger.of(lexicon)` is the lexicon's shared one."""

    __slots__ = ("lexicon", "keywords", "followers", "lengths_from", "memo")  # made for every document

    def __init__(self, lexicon: Lexicon, memo_size: int = MEMO_SIZE) -> None:
        self.lexicon = lexicon
        self.keywords = lexicon.keywords
        self.followers = lexicon.followers
        self.lengths_from = lexicon.lengths_from
        self.memo = WordMemo(memo_size)

    @classmethod
    def of(cls, lexicon: Lexicon) -> Tagger:
        """The tagger kept with `lexicon` (lexicon.caches.tagger), made on first use: its memo is
        warm for every document compiled with that lexicon and stays within MEMO_SIZE entries."""
        tagger = lexicon.caches.tagger
        if tagger is None:
            tagger = lexicon.caches.tagger = cls(lexicon)
        return tagger

    def tag_line(self, line: str, line_no: int, offset: int) -> tuple[list[Tagged], list[Diagnostic]]:
        """Return (tagged words, diagnostics) for one line of source."""
        raw = raw_tokens(line)
        if raw and not (raw[-1][0][0].isalnum() and raw[0][0][0].isalpha()):
            raw = self._undecorated(raw)
        tagged: list[Tagged] = []
        diags: list[Diagnostic] = []
        i = self._name_prefix(line, raw, line_no, offset, tagged) if ":" in line else 0
        memo, followers, count = self.memo, self.followers, len(raw)
        while i < count:
            text, col = raw[i]
            low = text.lower()
            seconds = followers.get(low)
            if seconds is None or i + 1 == count or raw[i + 1][0].lower() not in seconds:
                candidates = memo.get((low,))  # the common case: a one-word entry
                if candidates is None:
                    candidates = self._candidates((low,))
                if candidates:
                    start = offset + col
                    tagged.append(Tagged(text, Span(start, start + len(text), line_no, col + 1), candidates))
                    i += 1
                    continue
            i += self._tag_at(raw, i, line_no, offset, tagged, diags)
        if _may_join(tagged):
            tagged = self._joined_objects(tagged, diags)
        return tagged, diags

    def formation(self) -> WordFormation:
        """The lexicon's word formation engine (made on first use, kept in lexicon.caches)."""
        from .word_formation import WordFormation

        return WordFormation.of(self.lexicon, self._candidates)

    def _undecorated(self, raw: list[RawToken]) -> list[RawToken]:
        """The line's words without decorative punctuation: trailing marks ('.', '!', '...'), one
        leading bullet ('- ', '* ', '•') or list number ('1.', '2)') and quotes around the whole
        line (word_formation rules)."""
        rules = self.formation().rules
        lo, hi = 0, len(raw)
        for _round in range(2):  # '"Brushed steel".': the mark, then the quotes, then a mark inside
            while hi - lo > 1 and raw[hi - 1][0] in rules.trailing:
                hi -= 1
            if hi - lo > 1 and raw[lo][0] in rules.leading:
                lo += 1
            elif hi - lo > 2 and raw[lo][0].isdigit() and raw[lo + 1][0] in rules.number_marks:  # "1. oak"
                lo += 2
            if hi - lo > 2 and raw[lo][0] in rules.quotes and raw[hi - 1][0] in rules.quotes:
                lo, hi = lo + 1, hi - 1
        return raw[lo:hi]

    def _joined_objects(self, tagged: list[Tagged], diags: list[Diagnostic]) -> list[Tagged]:
        """Objects and class nouns joined to their material: "oak planks" = oak, "roof tiles" =
        tiles, "planks" = wood, "walnut wood" = walnut; each with a note."""
        out: list[Tagged] = []
        for k, word in enumerate(tagged):
            before = out[-1] if out else None
            if word.unknown or (before is not None and before.unknown):  # its tags are guesses: E001 says so
                out.append(word)
                continue
            nouns = _of_tag(word, "NOUN")
            if before is not None and _of_tag(before, "OBJECT") and not _others(before) and nouns:
                out[-1] = self._join(before, word, nouns, f"'{word.text}' ('{before.text}' names the object)", diags)
            elif before is not None and _of_tag(word, "OBJECT") and _of_tag(before, "NOUN"):
                made = _of_tag(before, "NOUN")
                out[-1] = self._join(before, word, made, f"'{made[0].key}' (the material of the {word.text})", diags)
            elif before is not None and self._is_head(before, word.text, k + 1 == len(tagged), out):
                out[-1] = self._with_head(before, word.text, word.span, k + 1 == len(tagged), diags)
            elif before is not None and nouns and self._is_class_of(before, nouns):
                made = _of_tag(before, "NOUN")
                out[-1] = self._join(before, word, made, f"'{made[0].key}' ('{word.text}' is its class)", diags)
            elif before is not None and nouns and _of_tag(before, "NOUN") and self._is_look(before):
                look = f"the look of {_of_tag(before, 'NOUN')[0].key} is not drawn on it"
                out[-1] = self._join(before, word, nouns, f"'{nouns[0].key}' ({look})", diags)
            elif _of_tag(word, "OBJECT"):
                if k + 1 < len(tagged) and _of_tag(tagged[k + 1], "NOUN"):
                    out.append(word)  # "roof tiles": joined to the noun next
                elif not _others(word) and any(_of_tag(t, "NOUN") or _of_tag(t, "OBJECT") for t in tagged[k + 1 :]):
                    note = f"read '{word.text}' as saying how or what for, not what: the material is named later"
                    diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))  # "wire brushed oak"
                else:
                    out.append(self._object_alone(word, diags))
            else:
                out.append(word)
        return out

    def _join(
        self, a: Tagged, b: Tagged, candidates: tuple[Candidate, ...], reading: str, diags: list[Diagnostic]
    ) -> Tagged:
        span = a.span.to(b.span)
        text = f"{a.text} {b.text}"
        diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read '{text}' as {reading}"))
        return Tagged(text, span, candidates, a.unknown or b.unknown)

    def _is_head(self, before: Tagged, text: str, last: bool, line: list[Tagged]) -> bool:
        """A head word (word_formation rules) that belongs to the word before it: after a
        describing word before the noun ("satin finish steel"), or after the noun at the end of
        the line ("brushed steel look") — not in a 'with' clause ("steel with a walnut finish")."""
        if text.lower() not in self.formation().rules.heads:
            return False
        if last and any(c.tag == "WITH" for t in line for c in t.candidates):
            return False
        tags = HEAD_HOLDERS[last]
        return any(c.tag in tags for c in before.candidates)

    def _with_head(self, before: Tagged, text: str, span: Span, last: bool, diags: list[Diagnostic]) -> Tagged:
        joined = before.span.to(span)
        note = f"read '{before.text} {text}' as '{before.text}' ('{text}' names what it describes)"
        diags.append(Diagnostic(joined, Severity.NOTE, NOTE_CODE, note))
        kept = tuple(c for c in before.candidates if c.tag in HEAD_HOLDERS[last])
        return Tagged(f"{before.text} {text}", joined, kept, before.unknown)

    def _object_alone(self, word: Tagged, diags: list[Diagnostic]) -> Tagged:
        """An object with no material noun beside it: its other readings, else its material."""
        others = _others(word)
        if others:
            return Tagged(word.text, word.span, others, word.unknown)
        key = _of_tag(word, "OBJECT")[0].key
        material = self.lexicon.require("objects", key).data["material"]
        note = f"read '{word.text}' as '{material}' (the usual material of '{word.text}')"
        diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))
        return Tagged(word.text, word.span, (Candidate("NOUN", material, "nouns"),), word.unknown)

    def _is_look(self, before: Tagged) -> bool:
        """'leather-like' (a noun only) before another noun: a look suffix (word_formation rules,
        `look = true`); 'mirror-like' is an adjective too, and stays one."""
        if any(c.tag in ("ADJ", "COLOR") for c in before.candidates):
            return False
        return before.text.lower().endswith(self.formation().rules.look_suffixes)

    def _is_class_of(self, before: Tagged, nouns: tuple[Candidate, ...]) -> bool:
        """'walnut wood': the second noun is the class of the first."""
        entries = [self.lexicon.entry("nouns", c.key) for c in _of_tag(before, "NOUN")]
        classes = {e.get("class") for e in entries if e is not None}
        return any(c.key in classes for c in nouns)

    def _name_prefix(self, line: str, raw: list[RawToken], line_no: int, offset: int, tagged: list[Tagged]) -> int:
        """'hull: ...' -> NAME COLON; the name may be several words."""
        if ":" not in line:
            return 0
        colon = next((j for j, (t, _c) in enumerate(raw) if t == ":"), None)
        if not colon:
            return 0
        first_col, (last_text, last_col) = raw[0][1], raw[colon - 1]
        text = " ".join(t for t, _c in raw[:colon])
        span = line_span(line_no, first_col + 1, last_col + len(last_text) - first_col, offset)
        tagged.append(Tagged(text, span, (Candidate("NAME", text, "name"),)))
        tagged.append(
            Tagged(":", line_span(line_no, raw[colon][1] + 1, 1, offset), (Candidate("COLON", ":", "punct"),))
        )
        return colon + 1

    def _tag_at(
        self, raw: list[RawToken], i: int, line_no: int, offset: int, tagged: list[Tagged], diags: list[Diagnostic]
    ) -> int:
        """Tag the entry starting at raw[i], longest multi-word form first; returns how many words it took."""
        text = raw[i][0]
        for n in self.lengths_from.get(text.lower(), ()):
            if i + n <= len(raw):
                candidates = self._candidates(tuple([t.lower() for t, _c in raw[i : i + n]]))
                if candidates:
                    tagged.append(
                        Tagged(
                            " ".join(t for t, _c in raw[i : i + n]), self._span(raw, i, n, line_no, offset), candidates
                        )
                    )
                    return n
        candidates = self._candidates((text.lower(),))
        if candidates:
            tagged.append(Tagged(text, self._span(raw, i, 1, line_no, offset), candidates))
            return 1
        if text[0].isalpha():
            last = i + 1 == len(raw)
            if tagged and self._is_head(tagged[-1], text, last, tagged):  # "satin effect steel", "steel effect"
                tagged[-1] = self._with_head(tagged[-1], text, self._span(raw, i, 1, line_no, offset), last, diags)
                return 1
            reading = self.formation().read_at([t.lower() for t, _c in raw[i : i + 3]])
            if reading is not None:
                return self._formed(reading, raw, i, line_no, offset, tagged, diags)
        tagged.append(self._unknown(raw[i], line_no, offset, diags))
        return 1

    def _formed(
        self,
        reading: Reading,
        raw: list[RawToken],
        i: int,
        line_no: int,
        offset: int,
        tagged: list[Tagged],
        diags: list[Diagnostic],
    ) -> int:
        """Tag the parts of a word formation reading of raw[i:]; its note says how it was read."""
        for part in reading.parts:
            first_text, first_col = raw[i + part.first]
            last_text, last_col = raw[i + part.last]
            start = first_col + part.start
            end = last_col + (len(last_text) if part.end is None else part.end)
            if part.first == part.last:
                text = first_text[part.start : part.end]
            else:
                text = " ".join(t for t, _c in raw[i + part.first : i + part.last + 1])
            tagged.append(Tagged(text, line_span(line_no, start + 1, end - start, offset), part.candidates))
        diags.append(
            Diagnostic(self._span(raw, i, reading.words, line_no, offset), Severity.NOTE, NOTE_CODE, reading.note)
        )
        return reading.words

    def _candidates(self, words: tuple[str, ...]) -> tuple[Candidate, ...]:
        cached = self.memo.get(words)
        if cached is None:
            cached = self._find_candidates(words)
            self.memo.put(words, cached)
        return cached

    def _find_candidates(self, words: tuple[str, ...]) -> tuple[Candidate, ...]:
        found = self._exact(words)
        if not found and len(words) == 1:
            for base in self.lexicon.base_forms(words[0]):
                found = self._exact((base,))
                if found:
                    break
        if not found and len(words) == 1 and "-" in words[0]:  # "blue-grey", "off-white": the spaced form
            found = self._exact(tuple(part for part in words[0].split("-") if part))
        if not found and len(words) > 1:  # "cinder blocks": the last word in its base forms
            for base in self.lexicon.base_forms(words[-1]):
                found = self._exact((*words[:-1], base))
                if found:
                    break
        return tuple(sorted(found, key=lambda c: TAG_PREFERENCE[c.tag]))

    def _exact(self, words: tuple[str, ...]) -> list[Candidate]:
        found = [Candidate(e.tag, e.key, e.category) for e in self.lexicon.lookup(words)]
        if len(words) == 1 and words[0] in self.keywords:
            found.append(Candidate(self.keywords[words[0]], words[0], "keyword"))
        return found

    @staticmethod
    def _span(raw: list[RawToken], i: int, n: int, line_no: int, offset: int) -> Span:
        first_col = raw[i][1]
        last_text, last_col = raw[i + n - 1]
        return line_span(line_no, first_col + 1, last_col + len(last_text) - first_col, offset)

    def _unknown(self, token: RawToken, line_no: int, offset: int, diags: list[Diagnostic]) -> Tagged:
        text, col = token
        span = line_span(line_no, col + 1, len(text), offset)
        is_word = text[0].isalpha()
        suggestions = self.lexicon.suggest(text) if is_word else []
        diags.append(error(span, "E001", _unknown_message(text), did_you_mean(suggestions), suggestions))
        return Tagged(text, span, self._guess(suggestions) if is_word else (), unknown=True)

    def _guess(self, suggestions: list[str]) -> tuple[Candidate, ...]:
        """Tags for an unknown word: those of its best suggestion, else any open tag."""
        for s in suggestions[:1]:
            found = _others_of(self._candidates(tuple(s.split())))  # an object's reading is the tagger's, not a guess
            if found:
                return tuple(Candidate(c.tag, c.key, c.category) for c in found)
        return tuple(Candidate(t, "", "unknown") for t in OPEN_TAGS)


def _may_join(tagged: list[Tagged]) -> bool:
    """Whether a line has an object, two nouns side by side, or a head word ('finish', 'look':
    a COAT or FEATURE reading) before another word or after a noun (see Tagger._joined_objects)."""
    noun_before = False
    final = tagged[-1] if tagged else None
    for word in tagged:
        noun = head = False
        for candidate in word.candidates:
            tag = candidate.tag
            if tag == "OBJECT":
                return True
            if tag == "NOUN":
                noun = True
            elif tag == "COAT" or tag == "FEATURE":
                head = True
        if (noun and noun_before) or (head and (word is not final or noun_before)):
            return True
        noun_before = noun
    return False


def _of_tag(word: Tagged, tag: str) -> tuple[Candidate, ...]:
    return tuple(c for c in word.candidates if c.tag == tag)


def _others(word: Tagged) -> tuple[Candidate, ...]:
    """The readings of a word that are not objects."""
    return _others_of(word.candidates)


def _others_of(candidates: tuple[Candidate, ...]) -> tuple[Candidate, ...]:
    return tuple(c for c in candidates if c.tag != "OBJECT")


def _unknown_message(text: str) -> str:
    if text[0].isalpha():
        return f"unknown word '{text}'"
    if text[0].isdigit():
        return f"numbers are not part of the language: '{text}' (describe the look in words)"
    return f"unexpected character '{text}'"
