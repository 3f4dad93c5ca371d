"""The tagger: one line of text -> words tagged with their candidate parts of speech.

Words are matched against the lexicon longest-first ("stainless steel" before "steel",
"a bit" before "a"); a word that is not found is tried in its base forms (inflection
rules from the lexicon) and, hyphenated, as its spaced form ("blue-grey" as "blue grey"), then
read by the lexicon's word formation rules (cnlmc.word_formation: unpolished, semi-matte,
wooden, not glossy; each reading is a NOTE), then reported with "did you mean". A word may
carry several candidate tags ("gold": colour or noun); the parser picks the one the grammar
accepts. Decorative punctuation (a trailing '.', a leading bullet, enclosing quotes) is dropped.
Objects, class nouns and head words are then joined to the word they belong to (cnlmc.joins:
"oak planks" = oak, "walnut wood" = walnut, "satin finish steel" = satin steel).
"""

from __future__ import annotations

import re
from collections import OrderedDict
from collections.abc import Collection
from typing import TYPE_CHECKING

from .diagnostics import Diagnostic, Severity, did_you_mean, error
from .joins import COMPARED, Joiner, material_named_first, may_join, of_tag, others_of, takes_target
from .lexicon import Lexicon
from .spans import Span, line_span
from .tagged import NOTE_CODE, Candidate, Tagged, only_tag

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

#: 'w/' (with) is one token before a space or a word ('brass w/ patina', 'oak w/grain'); so is
#: '3d' ('3d printed'); else a word, a number, a mark
TOKEN_RE = re.compile(
    r"[wW]/(?=\s|$|[^\W\d_])|3[dD](?:-[^\W\d_]+)*(?![\w-])|[^\W\d_](?:[\w'’\-]*\w)?|\d+(?:\.\d+)?%?|[,;:&]|\S",
    re.UNICODE,
)
OPEN_TAGS = ("ADV", "SHADE", "COLOR", "PROP", "ADJ", "COAT", "NOUN", "REFINE")
# a word that is a feature and an adjective or coat reads as the feature where both parse: only a 'with'
# clause takes a feature ("with a matte finish": the surface; "with a blue glaze and fine cracks": two clauses)
_FEATURE_FIRST = tuple(t for tag in OPEN_TAGS for t in (("FEATURE", tag) if tag == "ADJ" else (tag,)))
TAG_PREFERENCE = {
    t: i
    for i, t in enumerate(("NAME", "COLON", "ARTICLE", "AND", "OR", "WITH", "OF", "COMMA", *_FEATURE_FIRST, "OBJECT"))
}


def raw_tokens(line: str) -> list[tuple[str, int]]:
    """(text, 0-based column) of each word or punctuation mark; '#' starts a comment."""
    plain = _plain_words(line)
    if plain is not None:
        return plain
    return _pattern_tokens(line)


def _pattern_tokens(line: str) -> list[tuple[str, int]]:
    """raw_tokens by the regular expression (any line that is not plain words)."""
    if "#" not in line:
        return [(match.group(), match.start()) for match in TOKEN_RE.finditer(line)]
    out = []
    for match in TOKEN_RE.finditer(line):
        if match.group() == "#":
            break
        out.append((match.group(), match.start()))
    return out


def _plain_words(line: str) -> list[tuple[str, int]] | None:
    """raw_tokens of a line of letter-only words between single spaces ('blue anodized aluminum',
    most phrases), without the regular expression; None for any other line. Exact: a run of
    letters (str.isalpha, the same Unicode test as the pattern's [^\\W\\d_]) is one TOKEN_RE word,
    and a space is no token."""
    out = []
    col = 0
    for word in line.split(" "):
        if not word.isalpha():  # punctuation, a digit, '#', another space or white space: the pattern
            return None
        out.append((word, col))
        col += len(word) + 1
    return out


RawToken = tuple[str, int]  # a word's text and 0-based column


def _named(tagged: list[Tagged], text: str, span: Span, colon: Tagged) -> None:
    """A line's name (NAME) and its colon, written ('hull: ...') or implied ('PT-02 ...')."""
    tagged.append(Tagged(text, span, (Candidate("NAME", text, "name"),)))
    tagged.append(colon)


_COLON = (Candidate("COLON", ":", "punct"),)  # the name's colon (a Candidate is frozen)
#: a finish schedule's code ('PT-02', 'FIN-07', 'WD3'): letters, an optional mark, digits
SCHEDULE_CODE = re.compile(r"[A-Za-z]{1,4}[-.]?\d{1,4}[A-Za-z]?")
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

    __slots__ = ("lexicon", "keywords", "followers", "lengths_from", "memo", "joiner")  # made for every document

    def __init__(self, lexicon: Lexicon, memo_size: int = MEMO_SIZE) -> None:
        self.lexicon = lexicon
        self.keywords = lexicon.keywords
        self.followers = lexicon.followers
        self.lengths_from = lexicon.lengths_from
        self.memo = WordMemo(memo_size)
        self.joiner = Joiner(lexicon, lambda: self.formation().rules)

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
        tagged: list[Tagged] = []
        diags: list[Diagnostic] = []
        raw = _plain_words(line)  # raw_tokens' common case: letters only, no mark to drop, no name
        i, raw_marks = 0, raw is None
        if raw is not None and len(raw) > 1 and self._letter_smiley(raw[-1][0].lower()):
            raw = raw[:-1]  # 'oak xD': a smiley of letters
        if raw is None:
            raw = _pattern_tokens(line)
            if raw and (
                not (raw[-1][0][0].isalnum() and raw[0][0][0].isalpha())
                or _without_emoticon(raw, self.formation().rules.emoticons) < len(raw)  # ':D', '<3'
            ):
                raw = self._undecorated(raw)
            if ":" in line:
                i = self._name_prefix(line, raw, line_no, offset, tagged)
            elif len(raw) > 1 and SCHEDULE_CODE.fullmatch(raw[0][0]) and not self._candidates((raw[0][0].lower(),)):
                i = self._code_name(raw, line_no, offset, tagged, diags)
            raw = raw[:i] + self._unquoted(raw[i:], line)  # the name keeps its marks
        remembered, followers, count = self.memo._entries, self.followers, len(raw)
        while i < count:
            text, col = raw[i]
            low = text.lower()
            seconds = followers.get(low)
            if seconds is None or i + 1 == count or not self._follows(raw[i + 1][0].lower(), seconds):
                key = (low,)  # the common case: a one-word entry (WordMemo.get written out)
                candidates = remembered.get(key)
                if candidates is not None:
                    remembered.move_to_end(key)
                else:
                    candidates = self._candidates(key)
                if candidates:
                    start = offset + col
                    tagged.append(Tagged(text, Span(start, start + len(text), line_no, col + 1), candidates))
                    i += 1
                    continue
            i += self._tag_at(raw, i, line_no, offset, tagged, diags)
        if not raw_marks and len(tagged) > 1 and of_tag(tagged[-1], "COMMA"):
            tagged.pop()  # a mark spoken at the end of a line: 'brushed steel period'
        if raw_marks:
            tagged = _one_mark_between(tagged)
            if len(tagged) > 2:
                material_named_first(tagged, diags, self.lexicon)  # 'walnut, dark, satin': satin describes the walnut
        if (
            may_join(tagged)
            or (_has_label_tags(tagged) and self.joiner.has_colour_label(tagged))
            or (diags and self.joiner.ends_in_a_finished_thing(tagged))
        ):
            tagged = self.joiner.joined(tagged, diags)
        if any(c.tag == "WITH" for t in tagged for c in t.candidates):  # 'white marble with grey'
            tagged = self.joiner.own_pattern_named(tagged, diags)
        if len(tagged) > 1:
            _last_target_describes(tagged, self.lexicon)
        return tagged, diags

    def formation(self) -> WordFormation:
        """The lexicon's word formation engine (made on first use, kept in lexicon.caches)."""
        found = self.lexicon.caches.word_formation  # WordFormation.of's own first step: most lines ask
        if found is not None:
            return found
        from .word_formation import WordFormation

        return WordFormation.of(self.lexicon, self._candidates)

    def _unquoted(self, raw: list[RawToken], line: str) -> list[RawToken]:
        """The words without quote marks around a word ('oak, light, "scandi" style'), a mark after a
        number kept (12" tile: inches), and a bracketed suffix glued to its word ('white(ish)')."""
        quotes = self.formation().rules.quotes - _LIST_ITEM_MARKS  # not the brackets: they set words off
        kept = [t for k, t in enumerate(raw) if t[0] not in quotes or (k and raw[k - 1][0][:1].isdigit())]
        return self._bracketed_suffixes(kept) if "(" in line else kept

    def _bracketed_suffixes(self, raw: list[RawToken]) -> list[RawToken]:
        """'white(ish)', 'grey (ish)': a suffix of the rules said in brackets right after its word (or
        after one space) is glued to it."""
        suffixes = self.formation().rules.bracketed_suffixes
        out: list[RawToken] = []
        i = 0
        while i < len(raw):
            text, col = raw[i]
            parts = [t for t, _c in raw[i + 1 : i + 4]]
            if (
                len(parts) == 3
                and parts[0] == "("
                and parts[1].lower() in suffixes
                and parts[2] == ")"
                and raw[i + 1][1] - (col + len(text)) <= 1  # 'grey (ish)': a space may stand before it
            ):
                out.append((text + parts[1], col))
                i += 4
                continue
            out.append(raw[i])
            i += 1
        return out

    def _letter_smiley(self, word: str) -> bool:
        """Whether a last word of letters is a smiley ('xD'); the rules are read only for a word the
        lexicon does not know (a line of known words stays on the hot path)."""
        return not self._candidates((word,)) and word in self.formation().rules.emoticons

    def _undecorated(self, raw: list[RawToken]) -> list[RawToken]:
        """The line's words without decorative punctuation: trailing marks ('.', '!', '...'), one
        leading bullet ('- ', '* ', '•') or list number ('1.', '2)'), quotes around the whole line
        (word_formation rules)."""
        rules = self.formation().rules
        lo, hi = 0, len(raw)
        for _round in range(2):  # '"Brushed steel".': the mark, then the quotes, then a mark inside
            hi = lo + _without_emoticon(raw[lo:hi], rules.emoticons)
            while hi - lo > 1 and raw[hi - 1][0].lower() in rules.trailing:
                hi -= 1
            if hi - lo > 1 and raw[lo][0] in rules.leading:
                lo += 1
            elif hi - lo > 2 and raw[lo][0].isdigit() and raw[lo + 1][0] in rules.number_marks:  # "1. oak"
                lo += 2
            if hi - lo > 2 and raw[lo][0] in rules.quotes and raw[hi - 1][0] in rules.quotes:
                lo, hi = lo + 1, hi - 1
        return raw[lo:hi]

    def _name_prefix(self, line: str, raw: list[RawToken], line_no: int, offset: int, tagged: list[Tagged]) -> int:
        """'hull: ...' -> NAME COLON; the name may be several words."""
        colon = 0
        if len(raw) > 1 and raw[1][0] == ":":
            colon = 1  # 'm12: ...', the common case
        else:
            for j, (t, _c) in enumerate(raw):
                if t == ":":
                    colon = j
                    break
        if not colon:
            return 0
        first_col, (last_text, last_col) = raw[0][1], raw[colon - 1]
        text = raw[0][0] if colon == 1 else " ".join([t for t, _c in raw[:colon]])  # 'm12', 'hull', 'deck two'
        span = line_span(line_no, first_col + 1, last_col + len(last_text) - first_col, offset)
        _named(tagged, text, span, Tagged(":", line_span(line_no, raw[colon][1] + 1, 1, offset), _COLON))
        return colon + 1

    def _code_name(
        self, raw: list[RawToken], line_no: int, offset: int, tagged: list[Tagged], diags: list[Diagnostic]
    ) -> int:
        """'PT-02 matt emulsion, off-white': a finish schedule's code first names the material, as
        'PT-02: ...' does (NAME and a colon implied on the space after it), with a note."""
        text, col = raw[0]
        span = line_span(line_no, col + 1, len(text), offset)
        _named(
            tagged, text, span, Tagged(":", line_span(line_no, col + len(text) + 1, 1, offset), _COLON, implied_by=span)
        )
        note = f"read '{text}' as the material's name (a schedule code), as '{text}: ...' names it"
        diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, note))
        return 1

    def _tag_at(
        self, raw: list[RawToken], i: int, line_no: int, offset: int, tagged: list[Tagged], diags: list[Diagnostic]
    ) -> int:
        """Tag the entry starting at raw[i], longest multi-word form first; returns how many words it took."""
        text = raw[i][0]
        lengths, slipped = self.lengths_from.get(text.lower()), None
        if lengths is None and i + 1 < len(raw) and text[:1].isalpha() and not self._candidates((text.lower(),)):
            slipped = self.formation().entry_slip(text.lower(), raw[i + 1][0].lower(), self.followers)
            lengths = self.lengths_from.get(slipped) if slipped else None  # 'stainls steel'
        for n in lengths or ():
            if i + n <= len(raw):
                said = tuple([t.lower() for t, _c in raw[i : i + n]])
                if slipped:
                    said = (slipped, *said[1:])
                candidates = self._candidates(said)
                if not candidates and n > 1:  # 'stainless steal': the entry that sounds the same
                    candidates = self._heard_entry(said, self._span(raw, i, n, line_no, offset), diags)
                if candidates and n > 1 and self._gives_way(raw, i, n):
                    continue  # "dull red wine": 'dull' then the noun 'red wine', not the colour 'dull red'
                if candidates:
                    if slipped:
                        note = f"read '{text}' as '{slipped}' (a slip of the keyboard)"
                        diags.append(Diagnostic(self._span(raw, i, 1, line_no, offset), Severity.NOTE, NOTE_CODE, note))
                    tagged.append(
                        Tagged(
                            " ".join([t for t, _c in raw[i : i + n]]),
                            self._span(raw, i, n, line_no, offset),
                            candidates,
                        )
                    )
                    return n
        candidates = self._candidates((text.lower(),))
        if candidates:
            tagged.append(Tagged(text, self._span(raw, i, 1, line_no, offset), candidates))
            return 1
        if text[0].isalpha():
            last = i + 1 == len(raw)
            if tagged and self._particle_of_participle(text, tagged[-1], diags):  # 'scratched up'
                return 1
            if (
                tagged
                and self.joiner.is_head(tagged[-1], text, last, tagged)  # "satin effect steel", "steel effect"
                and not self._comparison_starts(raw, i)
            ):
                tagged[-1] = self.joiner.with_head(
                    tagged[-1], text, self._span(raw, i, 1, line_no, offset), last, diags
                )
                return 1
            if tagged and self._after_comparative(text, tagged):  # "lighter than oak", "less glossy than glass"
                return self._than(raw, i, line_no, offset, tagged, diags)
            reading = self.formation().read_at([t.lower() for t, _c in raw[i : i + 5]])  # "not X in the least"
            if reading is None and _set_off(raw, i):  # "European walnut, book-matched"
                reading = self.formation().read_set_off(text.lower())
            elif reading is None and 0 < i == len(raw) - 1 and raw[i - 1][0][:1].isalpha():  # "mustard yellow accent"
                reading = self.formation().read_use_last(text.lower(), raw[i - 1][0].lower())
            if reading is not None:
                return self._formed(reading, raw, i, line_no, offset, tagged, diags)
        alone = self._prefix_alone(raw, i)  # 'medium oak': the mid tone ('medium rough': somewhat rough)
        if alone is not None:
            tagged.append(Tagged(text, self._span(raw, i, 1, line_no, offset), (Candidate("SHADE", alone, "shades"),)))
            return 1
        if self._possessor(raw, i, tagged):  # 'grandma's old oak table'
            diags.append(
                Diagnostic(
                    self._span(raw, i, 1, line_no, offset), Severity.NOTE, NOTE_CODE, _POSSESSOR_NOTE.format(text)
                )
            )
            return 1
        tagged.append(self._unknown(raw[i], line_no, offset, diags))
        return 1

    def _prefix_alone(self, raw: list[RawToken], i: int) -> str | None:
        """The shade a prefix word names when no describing word follows it for it to qualify
        (word formation [[prefix]] `alone`: 'medium oak', 'mid grey'; not 'medium rough')."""
        shade = self.formation().rules.prefix_alone.get(raw[i][0].lower())
        if shade is None or i + 1 == len(raw):
            return None
        after = self._candidates((raw[i + 1][0].lower(),))
        return shade if after and not any(c.tag in ("ADJ", "ADV", "PROP") for c in after) else None

    def _possessor(self, raw: list[RawToken], i: int, tagged: list[Tagged]) -> bool:
        """Whether an unknown word says whose the thing is ('grandma's', 'the kids', teaching.toml
        [possessors]): first in the line (after its name) or after an article, before more words."""
        if i + 1 == len(raw) or not raw[i + 1][0][:1].isalpha():
            return False
        if tagged and not any(of_tag(tagged[-1], tag) for tag in ("ARTICLE", "COLON")):
            return False
        return possessive(raw[i][0])

    def _particle_of_participle(self, text: str, before: Tagged, diags: list[Diagnostic]) -> bool:
        """'more scratched up', 'beaten up leather': a particle after a participle says nothing the
        participle does not (teaching.toml [politeness] participle_particles): read past, a note."""
        from .suggest import teaching

        if text.lower() not in teaching()["politeness"]["participle_particles"] or before.unknown:
            return False
        if not before.text.lower().endswith(("ed", "en")) or not any(c.tag == "ADJ" for c in before.candidates):
            return False
        note = f"read '{before.text} {text}' as '{before.text}'"
        diags.append(Diagnostic(before.span, Severity.NOTE, NOTE_CODE, note))
        return True

    def _follows(self, word: str, seconds: Collection[str]) -> bool:
        """Whether a word (or, for a word the lexicon lacks, the word it sounds like: 'steal') may
        follow as an entry's next word; a known word never reaches the word formation rules."""
        if word in seconds:
            return True
        return not self._candidates((word,)) and self.formation().heard(word, seconds)[0] in seconds

    def _heard_entry(self, said: tuple[str, ...], span: Span, diags: list[Diagnostic]) -> tuple[Candidate, ...]:
        """The entry of several words one of which sounds like what was written ('stainless steal'),
        with a note; () when there is none."""
        formation = self.formation()
        heard: list[tuple[str, str]] = []
        for k, w in enumerate(said):  # a later word is heard among the words its word before allows
            among = self.followers.get(heard[k - 1][0], ()) if k == 1 else ()
            heard.append(formation.heard(w, among) if not self._candidates((w,)) else (w, ""))
        meant = tuple([h for h, _why in heard])
        candidates = self._candidates(meant) if meant != said else ()
        if candidates:
            changed = [f"'{w}' as '{h}' ({why})" for w, (h, why) in zip(said, heard) if w != h]
            diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read {', '.join(changed)}"))
        return candidates

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
        after = i + reading.words
        item = after == len(raw) or raw[after][0] in _LIST_ITEM_MARKS or (tagged and of_tag(tagged[-1], "AND"))
        if not reading.parts and item:
            # "shiny, not rusty, iron", "polished and not tarnished silver": a whole list item goes, and
            # one separator with it ("wood, all grey": a word read past before another word leaves the
            # comma where it is)
            return reading.words + _dropped_separator(raw, after, tagged)
        return reading.words

    def _comparison_starts(self, raw: list[RawToken], i: int) -> bool:
        """'like' before 'a', 'my', 'the' ('gold like a wedding ring'): a comparison with a thing
        starts there, not the suffix of the word before ('leather like vinyl'); so before a
        possessive ('like grandad's wireless')."""
        rules = self.formation().rules
        return (
            raw[i][0].lower() in rules.like_heads
            and i + 1 < len(raw)
            and (raw[i + 1][0].lower() in rules.like_not_before or possessive(raw[i + 1][0]))
        )

    def _after_comparative(self, text: str, tagged: list[Tagged]) -> bool:
        """A comparison word ('than', 'als': word formation rules) right after a comparative, or
        after a comparative and its target ('less glossy than', 'more grain than')."""
        if text.lower() not in self.formation().rules.comparison:
            return False
        if any(c.tag == "REFINE" for c in tagged[-1].candidates):
            return True
        return (
            len(tagged) > 1
            and any(c.tag == "REFINE" for c in tagged[-2].candidates)
            and any(c.tag in COMPARED for c in tagged[-1].candidates)
        )

    def _than(
        self, raw: list[RawToken], i: int, line_no: int, offset: int, tagged: list[Tagged], diags: list[Diagnostic]
    ) -> int:
        """'lighter than oak', 'a bit shinier than the brushed steel': the comparison word (and an
        article after it) is read as the inline comparative 'lighter oak', the material named after
        it moved as a refinement line would move it; a note says so. The word before keeps only its
        comparative reading ('dunkler als Eiche': not the declined colour 'dunkler'). Returns the
        words taken."""
        at = len(tagged) - 1 if any(c.tag == "REFINE" for c in tagged[-1].candidates) else len(tagged) - 2
        for k, tags in ((at, ("REFINE",)), (at + 1, COMPARED)):  # the comparative, then its target if any
            if k < len(tagged):
                word = tagged[k]
                kept = tuple(c for c in word.candidates if c.tag in tags)
                tagged[k] = Tagged(word.text, word.span, kept, word.unknown)
        comparative = tagged[at]
        than = raw[i][0]
        said = " ".join(t.text for t in tagged[at:])
        current = self._compared_with_current(raw, i)
        if current:  # 'a lighter grey than that': the comparative alone, on the material above
            span = self._span(raw, i, current, line_no, offset)
            words = " ".join(w for w, _c in raw[i : i + current])
            note = f"read past '{words}': compared with the material above, '{said}' changes it"
            diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, note))
            return current
        taken = 2 if i + 1 < len(raw) and self.keywords.get(raw[i + 1][0].lower()) == "ARTICLE" else 1
        note = (
            f"read '{said} {than}' as '{said}' before the material: the material named after '{than}', "
            f"moved as a refinement line '{said}' under it would move it"
        )
        span = comparative.span.to(self._span(raw, i, taken, line_no, offset))
        diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, note))
        comparison = self.formation().rules.comparison
        if i + taken < len(raw) and raw[i + taken][0].lower() in comparison:  # 'lighter than than oak'
            twice = self._span(raw, i + taken, 1, line_no, offset)
            hint = f"write '{than}' once"
            diags.append(error(twice, "E002", f"'{raw[i + taken][0]}' a second time", (hint,)))
            return taken + 1
        finish = self._compared_finish(raw, i + taken, line_no, offset)
        if finish is not None:  # 'shinier than satin': the finish, not the cloth (cnlmc.passes.finish_ladder)
            tagged.append(finish)
            return taken + 1
        rest = raw[i + taken :]
        if not any(self._may_name_material(t) for t, _c in rest) and not self._names_colour(rest):  # 'lighter than'
            where = self._span(raw, i, 1, line_no, offset)
            message = f"'{said} {than}' compares with a material, and none is named after '{than}'"
            diags.append(error(where, "E003", message, (f"name the material after '{than}'",)))
        return taken

    def _compared_finish(self, raw: list[RawToken], at: int, line_no: int, offset: int) -> Tagged | None:
        """The word at `at` as a finish alone ('than satin', 'than gloss' at the line's end or before
        a mark or a joining word, 'but': a finish adjective that sets roughness), its other readings
        dropped; None for any other word."""
        after = raw[at + 1][0] if at + 1 < len(raw) else ""
        if at >= len(raw) or (after[:1].isalnum() and self.keywords.get(after.lower()) != "AND"):
            return None  # a word after the finish: compared with a material ('than satin paint')
        finishes = tuple(
            c
            for c in self._candidates((raw[at][0].lower(),))
            if c.tag == "ADJ" and self.lexicon.require("adjectives", c.key).set_value("roughness") is not None
        )
        return Tagged(raw[at][0], self._span(raw, at, 1, line_no, offset), finishes) if finishes else None

    def _compared_with_current(self, raw: list[RawToken], i: int) -> int:
        """How many words 'than that', 'than before' take (the comparison word and the material as it
        is, to the end of the line or a part mark); 0 for a comparison with a material."""
        rest = [w.lower() for w, _c in raw[i + 1 :]]
        end = next((k for k, w in enumerate(rest) if not w[0].isalnum()), len(rest))
        said = " ".join(rest[:end])
        return end + 1 if said and said in self.formation().rules.compared_current else 0

    def _names_colour(self, rest: list[RawToken]) -> bool:
        """'darker than navy': a colour after the comparison word is compared with (the line reads
        'darker navy', a colour on the everyday noun the implied-material reading adds)."""
        return any(w[0].isalpha() and any(c.tag == "COLOR" for c in self._candidates((w.lower(),))) for w, _c in rest)

    def _may_name_material(self, word: str) -> bool:
        """Whether a word after a comparison word may name (or be part of) the material compared with:
        a noun, an object or a coat, or a word the lexicon does not know (read later: E001 or a note)."""
        if not word[0].isalpha():
            return False
        found = self._candidates((word.lower(),))
        return not found or any(c.tag in _MATERIAL_WORDS for c in found)

    def _gives_way(self, raw: list[RawToken], i: int, n: int) -> bool:
        """Whether the form raw[i:i+n] gives way to a multi-word noun starting on its last word:
        only when the words before that noun are a form themselves ('dull' in 'dull red wine'), so
        'floral white beech' stays the colour 'floral white' on beech."""
        before = tuple([t.lower() for t, _c in raw[i : i + n - 1]])
        return bool(self._candidates(before)) and self._noun_starts_inside(raw, i + n - 1)

    def _noun_starts_inside(self, raw: list[RawToken], j: int) -> bool:
        """Whether a multi-word noun starts at raw[j] and runs past it to where a noun ends (the end
        of the line, a separator, or a word that follows a noun: 'with', 'or', 'and'): then a form
        ending at raw[j] gives way to it (the material is what a phrase names; a shorter form
        before it still tags): 'fine silver leaf with an anodic oxide' is 'fine' + 'silver leaf'."""
        for m in self.lengths_from.get(raw[j][0].lower(), ()):
            end = j + m
            if m > 1 and end <= len(raw) and (end == len(raw) or self._ends_a_noun(raw[end][0])):
                found = self._candidates(tuple([t.lower() for t, _c in raw[j:end]]))
                if any(c.tag == "NOUN" for c in found):
                    return True
        return False

    def _ends_a_noun(self, word: str) -> bool:
        """Whether `word` is a separator or a keyword that follows a noun (NOUN_FOLLOWERS)."""
        return not word[0].isalpha() or self.keywords.get(word.lower()) in NOUN_FOLLOWERS

    def _candidates(self, words: tuple[str, ...]) -> tuple[Candidate, ...]:
        entries = self.memo._entries  # WordMemo.get written out: a multi-word entry asks for several forms
        cached = entries.get(words)
        if cached is not None:
            entries.move_to_end(words)
        else:
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
        misplaced = self.formation().misplaced(text.lower()) if is_word else None
        if misplaced is not None:  # 'not' before a noun: a rule's word with nothing to apply to
            message, hint = misplaced
            diags.append(error(span, "E002", message, (hint,)))
            return Tagged(text, span, (), unknown=True)
        suggestions = self.lexicon.suggest(text) if is_word else []
        diags.append(error(span, "E001", _unknown_message(text), did_you_mean(suggestions), suggestions))
        return Tagged(text, span, self._guess(suggestions) if is_word else (), unknown=True)

    def _guess(self, suggestions: list[str]) -> tuple[Candidate, ...]:
        """Tags for an unknown word: those of its best suggestion, else any open tag."""
        for s in suggestions[:1]:
            found = others_of(self._candidates(tuple(s.split())))  # an object's reading is the tagger's, not a guess
            if found:
                return tuple(Candidate(c.tag, c.key, c.category) for c in found)
        return tuple(Candidate(t, "", "unknown") for t in OPEN_TAGS)


#: The readings of a comparative's target before 'than' ('less glossy than glass', 'more grain than pine').

#: The readings of a word that may name the material after a comparison word ('lighter than oak').
_MATERIAL_WORDS = frozenset(("NOUN", "OBJECT", "COAT"))

#: The readings of a separator a word with no effect leaves standing alone ("shiny, not rusty, iron").
_SEPARATORS = frozenset(("COMMA", "AND"))
#: keywords that may follow a noun: a multi-word noun that runs to one of them is a whole noun
NOUN_FOLLOWERS = frozenset(("WITH", "OR", "AND"))


def _last_target_describes(tagged: list[Tagged], lexicon: Lexicon) -> None:
    """'less mirror', 'a bit more satin, please': a word right after a comparative that takes a
    target ('less', 'more': not 'shinier', whose next word is the material, 'shinier satin'), that
    reads both as a describing word and as a material (not as a colour: 'darker walnut'), with no
    word after it that could name a material, is the comparative's target, the describing word; a
    material there would leave the comparative with nothing to move ("'less' of what?")."""
    for k in range(len(tagged) - 1, 0, -1):
        word = tagged[k]
        if word.unknown:
            continue  # its tags are guesses ('please', read past later)
        tags = {c.tag for c in word.candidates}
        if "ADJ" in tags and "NOUN" in tags and "COLOR" not in tags and takes_target(tagged[k - 1], lexicon):
            tagged[k] = Tagged(
                word.text,
                word.span,
                tuple(c for c in word.candidates if c.tag != "NOUN"),
                word.unknown,
                word.implied_by,
            )
            return
        if tags & {"NOUN", "OBJECT"}:
            return  # a material after it: 'less satin paint' is read as said


def _is_separator(word: Tagged) -> bool:
    return bool(word.candidates) and all(c.tag in _SEPARATORS for c in word.candidates)


def _set_off(raw: list[RawToken], i: int) -> bool:
    """Whether raw[i] stands alone as a list item: a mark before it, and a mark or the end after."""
    return i > 0 and raw[i - 1][0] in _LIST_ITEM_MARKS and (i + 1 == len(raw) or raw[i + 1][0] in _LIST_ITEM_MARKS)


_LIST_ITEM_MARKS = frozenset((",", ";", "(", ")", "[", "]"))


def _one_mark_between(tagged: list[Tagged]) -> list[Tagged]:
    """Marks that stand together set words off once: 'walnut (dark), matte' is 'walnut, dark, matte'
    (a closing bracket then a comma), as is 'walnut, dark,, matte'."""
    out: list[Tagged] = []
    for word in tagged:
        if out and only_tag(word, "COMMA") and only_tag(out[-1], "COMMA"):
            continue
        out.append(word)
    return out


def _dropped_separator(raw: list[RawToken], after: int, tagged: list[Tagged]) -> int:
    """After words read as having no effect ("not rusty"), the separator that set them off goes too:
    the one before them (popped from `tagged`), else a comma right after them (returns 1: that raw
    word is taken), so "shiny, not rusty, iron" is "shiny, iron" and "not rusty, iron" is "iron"; a
    separator of two words goes whole ("shiny, but not rusty, iron")."""
    if tagged and _is_separator(tagged[-1]):
        while tagged and _is_separator(tagged[-1]):  # ', but': both words
            tagged.pop()
        return 0
    if after < len(raw) and raw[after][0] in (",", ";"):
        return 1
    return 0


_POSSESSOR_NOTE = "read '{}' past: it says whose the thing is, not what it is made of"


def _unknown_message(text: str) -> str:
    if text[0].isalpha():
        from .suggest import teaching  # an unknown word only: the teaching tables load then

        if text.lower() in teaching()["measures"]["colour_codes"]:
            return f"'{text}' names a colour code: codes are not part of the language (say the colour in words, e.g. 'anthracite grey')"
        return f"unknown word '{text}'"
    if text[0].isdigit():
        return f"numbers are not part of the language: '{text}' (describe the look in words)"
    return f"unexpected character '{text}'"


def _has_label_tags(tagged: list[Tagged]) -> bool:
    """Whether some word may be a label ('colour: red', 'plastic, colour red'): a property or a
    name (checked before the word formation rules are read: most lines have neither)."""
    return any(c.tag in ("PROP", "NAME") for t in tagged for c in t.candidates)


def possessive(said: str) -> bool:
    """Whether a word says whose a thing is ('grandma's', 'the kids', 'my grandads'): an
    apostrophe's possessive, or a word for a person or pet with an 's' (teaching.toml [possessors])."""
    from .suggest import teaching

    table = teaching()["possessors"]
    word = said.lower().replace("’", "'")
    if word in table["not_possessive"]:
        return False
    if word.endswith(("'s", "s'")):
        return word[:-2].isalpha()
    return word.endswith("s") and (word[:-1] in table["people"] or word in table["people"])


EMOTICON_MARKS = 3  # the most tokens one emoticon spans (':-)' is three marks)


def _without_emoticon(raw: list[RawToken], emoticons: frozenset[str]) -> int:
    """How many of the tokens stay once smileys typed at the line's end are dropped ('black leather
    :)'): a run of marks, touching each other, that the rules name; at least one word stays."""
    hi = len(raw)
    while hi > 1:
        for n in range(min(EMOTICON_MARKS, hi - 1), 0, -1):
            run = raw[hi - n : hi]
            touching = all(a[1] + len(a[0]) == b[1] for a, b in zip(run, run[1:]))
            if touching and "".join(t for t, _c in run).lower() in emoticons:
                hi -= n
                break
        else:
            return hi
    return hi
