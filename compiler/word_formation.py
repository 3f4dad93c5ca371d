"""Word formation: how the tagger reads a word the lexicon does not know (issue #14).

The rules are data (word_formation*.toml in every lexicon layer, read by
cnlmc.word_formation_rules; the overlay's rules first). A word is tried, in order, as:

1. its hyphen dropped (sand-blasted -> sandblasted);
2. a negation prefix and an adjective (unpolished, non-glossy): the adjective's declared
   `opposite`, else "without X" (no effect);
3. a degree prefix and an adjective (semi-matte = slightly matte, high-shine = very shiny);
   a compound's first part of [compound_first] (hand-forged = forged: a manner; close-grained =
   fine-grained: a synonym's compound; heavy-rusted = strongly rusted: a degree);
4. a derivational suffix (wooden -> wood, mirror-like -> mirror, gold-coloured -> gold,
   roughish -> slightly rough);
5. a WordNet noun under a lexicon noun, or a WordNet synonym of an adjective (cnlmc.wordnet);
6. its known parts (matte-black = matte black; glued parts with linkers: eichen|dielen);
7. its adjective part when the other part says how (hand-hammered = hammered, rough-hewn = rough).

Forms of two or three words start at an unknown word: "not X", "not too X" (slightly X),
"semi matte", and a qualifier before another word ("kitchen cabinets": no effect).
Every reading carries a note saying how it was made; the tagger turns it into a NOTE.
Only unknown words come here, so the hot path of known words never does; a WordFormation
remembers what it read (bounded), and lives in lexicon.caches.word_formation.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Container, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .resemblance import Resemblance
from .spoken import Spoken
from .tagged import NOTE_CODE, Candidate
from .word_formation_rules import RESEMBLANCE_WORD_LISTS

if TYPE_CHECKING:  # imported when first needed: the tagger imports this module only for an unknown word
    from .lexicon import Lexicon
    from .typos import Slips
    from .wordnet import WordNet

__all__ = ["NOTE_CODE", "Part", "Reading", "Rules", "WordFormation"]

MAX_REMEMBERED = 4096  # readings kept; a full memo starts over
ENTRY_SLIP_LETTERS = 4  # an entry's later word may hold a slip from this many letters (its word before confirms it)

Lookup = Callable[[tuple[str, ...]], tuple[Candidate, ...]]  # the tagger's (memoised) look-up


@dataclass(frozen=True, slots=True)
class Part:
    """One tagged word of a reading: raw words first..last (relative to the first word read),
    characters start (in word first) to end (in word last, None: to its end)."""

    first: int
    last: int
    start: int
    end: int | None
    candidates: tuple[Candidate, ...]


@dataclass(frozen=True, slots=True)
class Reading:
    """How one or more raw words are read: the tagged parts (none: the words have no effect),
    how many raw words it takes, and the note that says how it was read."""

    parts: tuple[Part, ...]
    words: int
    note: str


class Rules:
    """Every layer's rules merged: lists joined in layer order (the overlay's first)."""

    def __init__(self, layers: Sequence[dict[str, Any]]) -> None:
        def joined(section: str, name: str) -> tuple[str, ...]:
            return tuple(dict.fromkeys(w for layer in layers for w in layer[section][name]))

        self.trailing = frozenset(joined("punctuation", "trailing"))
        self.leading = frozenset(joined("punctuation", "leading"))
        self.quotes = frozenset(joined("punctuation", "quotes"))
        self.number_marks = frozenset(joined("punctuation", "number_marks"))
        self.bracketed_suffixes = frozenset(joined("punctuation", "bracketed_suffixes"))  # 'white(ish)'
        self.emoticons = frozenset(joined("punctuation", "emoticons"))  # 'black leather :)'
        self.negation_words = frozenset(joined("negation", "words"))
        self.strict_negation = frozenset(joined("negation", "strict"))  # "nothing shiny", never "nothing else"
        self.negation_prefixes = joined("negation", "prefixes")
        self.softeners = frozenset(joined("negation", "softeners"))
        self.emphatic = tuple(tuple(e.split()) for e in joined("negation", "emphatic"))  # "at all"
        self.pointing = tuple(tuple(e.split()) for e in joined("negation", "pointing"))  # "without the shine"
        self.emphatic_before = frozenset(joined("negation", "emphatic_before"))  # "gar nicht"
        self.soft_adverb = next((x["negation"]["soft_adverb"] for x in layers if x["negation"]["soft_adverb"]), "")
        self.not_too = {k: v for layer in reversed(layers) for k, v in layer["negation"]["not_too"].items()}
        self.prefixes = {
            form: p["adverb"] for layer in reversed(layers) for p in layer["prefix"] for form in p["forms"]
        }
        self.prefix_alone = {  # 'medium oak': the shade a prefix word names standing alone
            form: p["alone"] for layer in reversed(layers) for p in layer["prefix"] for form in p["forms"] if p["alone"]
        }
        self.prefix_endings = {
            form: tuple(p["endings"]) for layer in reversed(layers) for p in layer["prefix"] for form in p["forms"]
        }
        self.suffixes = [s for layer in layers for s in layer["suffix"]]
        self.look_suffixes = tuple(dict.fromkeys(f for s in self.suffixes if s["look"] for f in s["forms"]))
        compounds = [layer["compounds"] for layer in layers]
        self.join = any(c["join"] for c in compounds)
        self.split = any(c["split"] for c in compounds)
        self.head_last = any(c["head_last"] for c in compounds)
        self.linkers = ("", *dict.fromkeys(k for c in compounds for k in c["linkers"]))
        self.min_part = min((c["min_part"] for c in compounds), default=3)
        self.heads = frozenset(h for c in compounds for h in c["heads"])
        self.postfix = any(c["postfix"] for c in compounds)  # 'Eiche geölt': describing words after the noun
        self.made_of = tuple(dict.fromkeys(w for c in compounds for w in c["made_of"]))  # 'Dielen aus Eiche'
        self.qualifiers = frozenset(joined("qualifiers", "words"))
        self.sizes = frozenset(joined("qualifiers", "sizes"))  # "wide oak floorboards"
        self.ordinary = frozenset(joined("qualifiers", "ordinary"))  # "plain white"
        self.liking = frozenset(joined("qualifiers", "liking"))  # "a nice warm terracotta"
        self.cost = frozenset(joined("qualifiers", "cost"))  # "a cheap pine shelf"
        self.imitation = frozenset(joined("qualifiers", "imitation"))  # "faux sheepskin", "recycled plastic"
        self.shapes = frozenset(joined("qualifiers", "shapes"))  # "hexagon floor tiles"
        self.purity = frozenset(joined("qualifiers", "purity"))  # "a clean bright white"
        self.patterns = frozenset(joined("qualifiers", "patterns"))  # "checkered tiles"
        self.fillers = frozenset(joined("qualifiers", "fillers"))  # "rougher again, a little"
        self.comparison = frozenset(joined("comparison", "words"))  # "lighter than oak"
        self.compared_current = frozenset(joined("comparison", "current"))  # "lighter than that"
        self.manners = frozenset(joined("compound_first", "manners"))
        self.participles = frozenset(joined("compound_first", "participles"))
        self.participle_endings = joined("compound_first", "participle_endings")
        self.first_synonyms = _merged_table(layers, "compound_first", "synonyms")
        self.homophones = _merged_table(layers, "homophones", "words")  # 'stainless steal
        self.typos = _merged_typos([layer["typos"] for layer in layers])
        self.first_degrees = _merged_table(layers, "compound_first", "degrees")
        firsts = {*self.manners, *self.first_synonyms, *self.first_degrees}
        self.first_parts = tuple(
            sorted(firsts, key=lambda w: (-len(w), w))
        )  # the longest first: 'heavily' before 'heavy'
        self.wordnet = _merged_wordnet([layer["wordnet"] for layer in layers])
        self.resemblance = _merged_resemblance([layer["resemblance"] for layer in layers])
        self.colour_heads = frozenset(self.resemblance["colour_heads"])
        self.colour_label_links = frozenset(self.resemblance["colour_label_links"])  # "colour is red"
        self.colour_head_before_feature = tuple(self.resemblance["colour_head_before_feature"])  # "coloured chips"
        self.like_heads = frozenset(self.resemblance["like_heads"])
        self.like_not_before = frozenset(self.resemblance["like_not_before"])  # "like a wedding ring"
        self.finish_heads = frozenset(self.resemblance["finish_heads"])
        suffix_forms = [f for s in self.suffixes for f in s["forms"]]
        suffix_forms += [f for name in ("forms", "colour_forms") for f in self.resemblance[name]]
        self.suffix_words = frozenset(f.lstrip("-") for f in suffix_forms)  # 'coloured', 'finished': not participles


class WordFormation:
    """Reads unknown words by the rules of one lexicon; see the module doc."""

    def __init__(self, lexicon: Lexicon, lookup: Lookup) -> None:
        self.lexicon = lexicon
        self.rules = Rules(lexicon.word_formation)
        self.lookup = lookup
        self.memo: dict[str, Reading | None] = {}
        self.wordnet_readings: WordNet | None = None  # read on first use
        self.resemblance = Resemblance(lexicon, self.rules.resemblance)
        self.spoken_words: Spoken | None = None  # made on first use
        self.slips: Slips | None = None  # made on the first unknown word a slip may explain

    @classmethod
    def of(cls, lexicon: Lexicon, lookup: Lookup) -> WordFormation:
        """The engine kept with `lexicon` (lexicon.caches.word_formation), made on first use."""
        found = lexicon.caches.word_formation
        if found is None:
            found = lexicon.caches.word_formation = cls(lexicon, lookup)
        return found

    # ------------------------------------------------------------ the tagger's entry points

    def read_at(self, words: Sequence[str]) -> Reading | None:
        """A reading of the unknown word words[0] (lower case), which may take the words after it."""
        first = words[0]
        rules = self.rules
        if len(words) > 1 and first in rules.manners:  # "hand painted", "machine cut"
            found = self._after_manner(f"{first} {words[1]}", first, words[1], 1)
            if found is not None:
                return found
        if len(words) > 1:  # "kitchen cabinets", "exterior paint", "plain white", "faux sheepskin"
            why = self._passed_reason(first)
            if why is not None:
                return Reading((), 1, f"read '{first}' as {why}")
        if len(words) > 1 and first in rules.first_synonyms:  # "close grained" = fine-grained
            same = rules.first_synonyms[first]
            compound = self._kept(self._known(f"{same}-{words[1]}"), ("ADJ",))
            if compound:
                note = f"read '{first} {words[1]}' as '{same}-{words[1]}' ('{first}' means '{same}' here)"
                return Reading((Part(0, 1, 0, None, compound),), 2, note)
        if first in rules.sizes and len(words) > 1 and not self._names_feature(words[1]):  # "wide oak floorboards"
            return Reading((), 1, f"read '{first}' as the size of the pieces: not drawn, no effect on the look")
        if len(words) > 1:
            named = self._resembling_colour_name(first, words[1])
            if named is not None:
                return named
            if first in rules.negation_words and self._negates_here(words) and not self._two_words(words):
                return self._negated_words(words)  # not 'no clear coat': the coat is what is taken off
            if first in rules.emphatic_before and words[1] in rules.negation_words:
                return self._emphatic_negation(words)
            adverb = rules.prefixes.get(first)
            if adverb is not None:
                return self._prefixed_word(first, adverb, words[1])
        return self.read(first)

    def _passed_reason(self, word: str) -> str | None:
        """Why a qualifier word is read past ('kitchen': where or what for), or None for other words."""
        rules = self.rules
        passed = (
            (rules.qualifiers, "saying where or what for: no effect on the look"),
            (rules.ordinary, "the ordinary kind: no effect on the look"),
            (rules.purity, "saying the colour is clean and unmixed: the colour itself"),
            (rules.shapes, "the shape of the pieces: not drawn (the tiles graph draws a rectangular grid)"),
            (rules.liking, "saying you like it: no effect on the look"),
            (rules.cost, "what it costs, not how it looks: no effect on the look"),
            (rules.imitation, "what it is made of, not how it looks: drawn as what follows"),
            (rules.patterns, "the pattern the pieces are laid in: not drawn (a running bond is drawn)"),
            (rules.fillers, "a word of the conversation: no effect on the look"),
        )
        return next((why for kind, why in passed if word in kind), None)

    def read_set_off(self, word: str) -> Reading | None:
        """A qualifier set off after the material as a list item ('European walnut, book-matched',
        'oak, kitchen grade'): read past with its note, as before the material."""
        why = self._passed_reason(word)
        return None if why is None else Reading((), 1, f"read '{word}' as {why}")

    def read_use_last(self, word: str, before: str) -> Reading | None:
        """A word saying where or what for, last on the line right after a word of the material
        ('mustard yellow accent', 'oak kitchen'): read past with its note; None for any other word,
        or after a preposition or an article ('tiles in the hallway': a place politeness reads past,
        'would be nice': a courtesy)."""
        from .suggest import teaching

        table = teaching()["politeness"]  # a place phrase's words: cnlmc.politeness reads it past whole
        if word not in self.rules.qualifiers or before in (*table["place_prepositions"], *table["place_articles"]):
            return None
        return self.read_set_off(word)

    def misplaced(self, word: str) -> tuple[str, str] | None:
        """(message, hint) for a word of the rules that found nothing to apply to ('not steel')."""
        rules = self.rules
        if word in rules.negation_words:
            message = f"'{word}' negates a finish or treatment word after it (glossy, polished, varnished)"
            return message, f"e.g. '{word} glossy plastic'; a colour or a material cannot be negated"
        if word in rules.prefixes:
            return f"'{word}' has no describing word after it", f"e.g. '{word} matte plastic'"
        if word in rules.qualifiers:
            return f"'{word}' says where or what for, not what it is made of", f"name the material: 'oak {word} table'"
        return None

    def read(self, word: str) -> Reading | None:
        """A reading of one unknown word, remembered."""
        memo = self.memo
        if word in memo:
            return memo[word]
        if len(memo) >= MAX_REMEMBERED:
            memo.clear()
        found = memo[word] = self._read(word)
        return found

    # ------------------------------------------------------------ one word

    def _read(self, word: str) -> Reading | None:
        rules = (
            self._homophone,
            self._joined,
            self._negated,
            self._prefixed,
            self._resembling,
            self._derived,
            self._compound_first,
            self._wordnet,
            self._feature_derived,
            self._split,
            self._head,
            self._slip,
        )
        for rule in rules:
            found = rule(word)
            if found is not None:
                return found
        return None

    def _names_feature(self, word: str) -> bool:
        """Whether the word is a feature ('large veins', 'large flakes': there a size is the
        feature's scale, not the pieces' size read past)."""
        return any(c.tag == "FEATURE" for c in self._known(word))

    def _known(self, word: str) -> tuple[Candidate, ...]:
        return self.lookup((word,)) if word else ()

    def _homophone(self, word: str) -> Reading | None:
        """A real word a spell-checker leaves that sounds like a lexicon word ('stainless steal')."""
        meant = self.rules.homophones.get(word)
        found = self._known(meant) if meant else ()
        return _whole(found, f"read '{word}' as '{meant}' (a word that sounds the same)") if found else None

    def _slip(self, word: str) -> Reading | None:
        """A slip of the keyboard ('brushd', 'alumnium'): the one lexicon word it is near (cnlmc.typos)."""
        meant = self.slip_of(word)
        found = self._known(meant) if meant else ()
        return _whole(found, f"read '{word}' as '{meant}' (a slip of the keyboard)") if found else None

    def slip_of(self, word: str) -> str | None:
        """The one lexicon word an unknown word is a slip of, or None (cnlmc.typos)."""
        slips = self.slips_index()
        return None if slips is None else slips.meant(word, lambda a, b: self._known(a) == self._known(b))

    def entry_slip(self, word: str, after: str, followers: Mapping[str, Container[str]]) -> str | None:
        """The first word of an entry of several words that an unknown word is a slip of, where the
        word after it is that entry's second ('stainls steel': stainless; one slip more than a word
        alone may hold, as the entry's second word confirms it), or None."""
        slips = self.slips_index()
        if slips is None or word in self.rules.comparison:
            return None
        heard = self.heard(after)[0] if not self._known(after) else after
        starts = [first for first, seconds in followers.items() if after in seconds or heard in seconds]
        return slips.meant_among(word, starts, extra=1, shortest=ENTRY_SLIP_LETTERS)

    def slips_index(self) -> Slips | None:
        """The slips index of these rules (None: this language reads no slips), made on first use."""
        rules = self.rules.typos
        if rules["off"] or not rules["reach"]:
            return None
        if self.slips is None:
            from .suggest import teaching
            from .typos import Slips, real_words

            never = set(teaching()["never_suggest"])  # a slip of 'whit' is not a crude word
            vocabulary = {w for form in self.lexicon.forms for w in form} - never
            self.slips = Slips(vocabulary, real_words(rules["file"]), rules["reach"], rules["vowels"])
        return self.slips

    def heard(self, word: str, among: Collection[str] = ()) -> tuple[str, str]:
        """The word an unknown word stands for inside an entry of several words ('stainless steal',
        'soft tuch'), and why: a word that sounds the same, a slip, or itself (""). `among`: the
        words the entry's word before it allows next; a slip of one of them is read from four
        letters, the word before confirming it ('sterling siver': silver, not river)."""
        sounds = self.rules.homophones.get(word)
        if sounds is not None:
            return sounds, "a word that sounds the same"
        slipped = self.slip_of(word)
        if (
            slipped is None
            and among
            and word not in self.rules.comparison
            and (slips := self.slips_index()) is not None
        ):
            slipped = slips.meant_among(word, sorted(among), extra=1, shortest=ENTRY_SLIP_LETTERS)
        return (slipped, "a slip of the keyboard") if slipped else (word, "")

    def _joined(self, word: str) -> Reading | None:
        if not self.rules.join or "-" not in word:
            return None
        joined = word.replace("-", "")
        found = self._known(joined)
        return _whole(found, f"read '{word}' as '{joined}'") if found else None

    def _wordnet(self, word: str) -> Reading | None:
        """A WordNet noun under a lexicon noun ("alder": wood), or a synonym of an adjective."""
        wordnet = self.wordnet()
        found = wordnet.noun(word) or wordnet.adjective(word)
        return None if found is None else _whole((found[0],), found[1])

    def wordnet(self) -> WordNet:
        """The WordNet readings of these rules, read on first use."""
        if self.wordnet_readings is None:
            from .wordnet import WordNet

            self.wordnet_readings = WordNet(self.rules.wordnet, self.lookup)
        return self.wordnet_readings

    def _negated(self, word: str) -> Reading | None:
        for prefix in self.rules.negation_prefixes:
            rest = word[len(prefix) :].lstrip("-")
            if word.startswith(prefix) and len(rest) >= self.rules.min_part:
                found = self._negation(word, rest, explicit="-" in word[: len(prefix) + 1])
                if found is not None:
                    return found
        return None

    def _negation(self, word: str, rest: str, explicit: bool) -> Reading | None:
        """'un' + rest: the opposite of an adjective, "without" a known word; an unknown rest
        only after an explicit hyphen ("non-slip": a property with no parameter)."""
        found = self._resolved(rest)
        adjective = next((c for c in found if c.tag == "ADJ"), None)
        if adjective is not None:
            return self._opposite_reading(word, 0, adjective, rest)
        if found:
            return Reading((), 1, f"read '{word}' as without '{rest}': the material as it is, no effect")
        if explicit:
            return Reading((), 1, f"read '{word}' as a property with no visual parameter here; it has no effect")
        return None

    def _opposite_reading(self, text: str, last: int, adjective: Candidate, word: str) -> Reading:
        entry = self.lexicon.entry("adjectives", adjective.key)
        opposite = None if entry is None else entry.get("opposite")
        if opposite is None:
            return Reading((), last + 1, f"read '{text}' as without '{word}' (no declared opposite): no effect")
        part = Part(0, last, 0, None, (Candidate("ADJ", opposite, "adjectives"),))
        said, of = self.spoken().word("adjectives", opposite), self.spoken().word("adjectives", adjective.key)
        return Reading((part,), last + 1, f"read '{text}' as '{said}' (the declared opposite of '{of}')")

    def spoken(self) -> Spoken:
        """The document language's words for what a note adds (cnlmc.spoken), made on first use."""
        if self.spoken_words is None:
            self.spoken_words = Spoken(self.lexicon)
        return self.spoken_words

    def _resolved(self, word: str) -> tuple[Candidate, ...]:
        """The candidates of a known word, or of a one-part reading of it."""
        found = self._known(word)
        if found:
            return found
        reading = self.read(word)
        if reading is not None and len(reading.parts) == 1:
            return reading.parts[0].candidates
        return ()

    def _prefixed(self, word: str) -> Reading | None:
        for form, adverb in self.rules.prefixes.items():
            if word.startswith(form):
                rest = word[len(form) :]
                hyphen = rest.startswith("-")
                rest = rest.lstrip("-")
                found = self._prefix_target(rest, self.rules.prefix_endings[form])
                if found:
                    start = len(word) - len(rest)
                    parts = (
                        Part(0, 0, 0, len(form), self._adverb(adverb)),
                        Part(0, 0, start, None, found),
                    )
                    sep = "-" if hyphen else ""
                    note = f"read '{word}' as '{adverb} {found[0].key}' ({form}{sep}: {adverb})"
                    return Reading(parts, 1, note)
        return None

    def _prefix_target(self, rest: str, endings: Sequence[str]) -> tuple[Candidate, ...]:
        """The adjective a degree prefix qualifies: the rest of the word, plus an ending ("shine" + "y")."""
        if len(rest) < self.rules.min_part:
            return ()
        stems = (rest, rest[:-1]) if rest.endswith("e") else (rest,)  # shine + y: shiny (the e drops)
        for ending in endings:
            for stem in stems if ending else (rest,):
                found = self._kept(self._resolved(stem + ending), ("ADJ",))
                if found:
                    return found
        return ()

    def _compound_first(self, word: str) -> Reading | None:
        """hand-forged = forged, salt-glazed = glazed (a manner), close-grained = fine-grained (a
        synonym's compound), heavy-rusted = strongly rusted (a degree): the [compound_first] rules."""
        split = self._first_and_rest(word)
        if split is None:
            return None
        first, rest = split
        start = len(word) - len(rest)
        same = self.rules.first_synonyms.get(first)
        if same is not None:
            found = self._kept(self._known(f"{same}-{rest}"), ("ADJ",))
            if found:
                return _whole(found, f"read '{word}' as '{same}-{rest}' ('{first}' means '{same}' here)")
        if first in self.rules.manners:
            return self._after_manner(word, first, rest, 0, start, hyphen="-" in word)
        adverb = self.rules.first_degrees.get(same or first)
        head = self._kept(self._resolved(rest), ("ADJ",))
        if adverb is not None and not head and "-" in word and self._is_participle(rest):  # 'fine-finished'
            return Reading((), 1, f"read '{word}' as saying how it was made ('{first}' {rest}): no effect on the look")
        if adverb is None or not head:
            return None
        parts = (Part(0, 0, 0, start, self._adverb(adverb)), Part(0, 0, start, None, head))
        return Reading(parts, 1, f"read '{word}' as '{adverb} {head[0].key}' ('{first}' is a degree: {adverb})")

    def _first_and_rest(self, word: str) -> tuple[str, str] | None:
        """The first part of the rules and the rest: at the hyphen, or glued when the rest is a
        describing word ('handpainted')."""
        if "-" in word:
            first, rest = word.split("-", 1)
            return (first, rest) if first in self.rules.first_parts and rest else None
        for first in self.rules.first_parts:
            rest = word[len(first) :]
            if word.startswith(first) and len(rest) >= self.rules.min_part:
                if any(c.tag == "ADJ" for c in self._resolved(rest)) or self._is_participle(rest):
                    return first, rest
        return None

    def _after_manner(
        self, text: str, first: str, rest: str, last: int, start: int = 0, hyphen: bool = True
    ) -> Reading | None:
        """The describing word after a manner ('hand'), or, for a participle the lexicon lacks, no effect."""
        head = self._kept(self._resolved(rest), ("ADJ",))
        if head:
            part = Part(last, last, start, None, head)
            note = f"read '{text}' as '{head[0].key}' ('{first}' says how it was made: no effect of its own)"
            return Reading((part,), last + 1, note)
        if (hyphen or last == 0) and self._is_participle(rest):  # 'factory-finished': 'finished' is no ADJ
            return Reading(
                (), last + 1, f"read '{text}' as saying how it was made ('{first}' {rest}): no effect on the look"
            )
        return None

    def _is_participle(self, word: str) -> bool:
        """A participle the lexicon may lack ('thrown', 'stitched'); not a suffix of the rules ('coloured')."""
        rules = self.rules
        if word in rules.suffix_words and word not in rules.participles:
            return False
        return word in rules.participles or (len(word) > 4 and word.endswith(rules.participle_endings))

    def _adverb(self, key: str) -> tuple[Candidate, ...]:
        return (Candidate("ADV", key, "adverbs"),)

    def _resembling(self, word: str) -> Reading | None:
        """X-y, X-ish, X-like, X-coloured on a noun X: resembling X (cnlmc.resemblance: its colour, or
        its surface for a surface class). A stem that is also a colour or a describing word keeps
        that reading (coppery: the colour 'copper', waxy: waxed; the suffix rules)."""
        rules = self.rules.resemblance
        for colour_only, forms in ((True, rules["colour_forms"]), (False, rules["forms"])):
            for form in forms:
                if word.endswith(form) and len(word) - len(form) >= self.rules.min_part - 1:  # ic(e)-y
                    found = self._resembled(word, word[: len(word) - len(form)].rstrip("-"), colour_only)
                    if found is not None:
                        return found
        return None

    def _resembling_colour_name(self, first: str, second: str) -> Reading | None:
        """'steely blue' = the named colour 'steel blue', 'steely grey' = 'steel grey': a resembling
        word before a colour word that, with the noun, names a colour."""
        rules = self.rules.resemblance
        for form in (*rules["colour_forms"], *rules["forms"]):
            if first.endswith(form) and len(first) - len(form) >= self.rules.min_part - 1:
                stem = first[: len(first) - len(form)].rstrip("-")
                for ending in rules["endings"] or ("",):
                    if len(stem + ending) < self.rules.min_part:
                        continue
                    found = self._kept(self.lookup((stem + ending, second)), ("COLOR",))
                    if found:
                        name = f"{stem + ending} {second}"
                        part = Part(0, 1, 0, None, found)
                        return Reading((part,), 2, f"read '{first} {second}' as the colour '{name}'")
        return None

    def _resembled(self, word: str, stem: str, colour_only: bool) -> Reading | None:
        resemblance = self.resemblance
        for base in _stems(stem, self.rules.resemblance["endings"] or ("",)):
            if len(base) < self.rules.min_part:
                continue
            found = self._known(base)
            noun = next((c for c in found if c.tag == "NOUN"), None)
            if noun is None and not found:  # 'stainless-like': a WordNet noun ("a kind of steel")
                kind = self.wordnet().noun(base)
                noun = None if kind is None else kind[0]
            if noun is None:
                continue
            deferred = ("COLOR",) if colour_only else ("COLOR", "ADJ")
            if any(c.tag in deferred for c in found):
                return None  # the suffix rules read it as that colour or describing word
            like = resemblance.colour(noun.key) if colour_only else resemblance.like(noun.key)
            if like is None:
                return None
            candidate, why = like
            like_what = base if noun.key == base else f"{base}, {noun.key}"
            return _whole((candidate,), f"read '{word}' as '{candidate.key}' (resembling {like_what}: {why})")
        return None

    def _derived(self, word: str) -> Reading | None:
        return self._suffixed(word, features=False)

    def _feature_derived(self, word: str) -> Reading | None:
        """'speckled', 'veiny': a feature's noun with a suffix, after WordNet ('sheeny' is shiny there)."""
        return self._suffixed(word, features=True)

    def _suffixed(self, word: str, features: bool) -> Reading | None:
        for rule in self.rules.suffixes:
            if (rule["reads_as"] == ["FEATURE"]) != features:
                continue
            for form in rule["forms"]:
                if not word.endswith(form) or len(word) - len(form) < self.rules.min_part - 1:
                    continue
                stem = word[: len(word) - len(form)]
                for ending in rule["endings"]:
                    if len(stem.rstrip("-") + ending) < self.rules.min_part:  # icy: ic + e = ice
                        continue
                    found = self._kept(self._known(stem + ending), rule["reads_as"])
                    if found and rule["exact"]:  # 'honest' is not 'hone'-est: the stem is its word's own name
                        found = tuple(c for c in found if c.key == stem.rstrip("-") + ending)
                    if found:
                        return self._derived_reading(word, stem, stem.rstrip("-") + ending, found, rule)
        return None

    def _derived_reading(
        self, word: str, stem: str, base: str, found: tuple[Candidate, ...], rule: dict[str, Any]
    ) -> Reading:
        """The stem's reading; an adjective under a suffix with an adverb ('roughish') is qualified by
        it, one under a suffix with a refinement ('silkier') is its comparative ('more silky')."""
        if rule["refine"] and found[0].tag == "ADJ":
            parts = (
                Part(0, 0, len(stem), None, (Candidate("REFINE", rule["refine"], "refinements"),)),
                Part(0, 0, 0, len(stem), self._kept(found, ("ADJ",))),
            )
            return Reading(parts, 1, f"read '{word}' as '{rule['refine']} {found[0].key}' ({rule['doc']})")
        adverb = rule["adverb"]
        if not adverb or found[0].tag not in ("ADJ", "SHADE"):
            return _whole(found, f"read '{word}' as '{base}' ({rule['doc']})")
        parts = (  # the adverb first for the grammar; each part keeps its own place in the word
            Part(0, 0, len(stem), None, self._adverb(adverb)),
            Part(0, 0, 0, len(stem), self._kept(found, (found[0].tag,))),
        )
        return Reading(parts, 1, f"read '{word}' as '{adverb} {found[0].key}' ({rule['doc']})")

    @staticmethod
    def _kept(found: tuple[Candidate, ...], tags: Sequence[str]) -> tuple[Candidate, ...]:
        return tuple(sorted((c for c in found if c.tag in tags), key=lambda c: tags.index(c.tag)))

    def _split(self, word: str) -> Reading | None:
        if not self.rules.split:
            return None
        if "-" in word:
            return self._split_hyphenated(word)
        return self._split_glued(word)

    def _split_hyphenated(self, word: str) -> Reading | None:
        parts, start = [], 0
        for piece in word.split("-"):  # an object is not a first part: wire-brushed is brushed (head_last)
            found = self._resolved(piece) if piece else ()
            if start == 0:
                found = tuple(c for c in found if c.tag != "OBJECT")
            if piece and not found:
                return None
            if piece:
                parts.append(Part(0, 0, start, start + len(piece), found))
            start += len(piece) + 1
        if len(parts) < 2:
            return None
        spaced = " ".join(p for p in word.split("-") if p)
        return Reading(tuple(parts), 1, f"read '{word}' as '{spaced}'")

    def _split_glued(self, word: str) -> Reading | None:
        """The longest known last part whose rest is known, directly or without a linker."""
        shortest = self.rules.min_part
        for cut in range(shortest, len(word) - shortest + 1):
            right = self._known(word[cut:])
            if not right:
                continue
            left = word[:cut]
            for linker in self.rules.linkers:
                if linker and not left.endswith(linker):
                    continue
                stem = left[: len(left) - len(linker)]
                found = self._known(stem) if len(stem) >= shortest else ()
                if found:
                    parts = (Part(0, 0, 0, cut, found), Part(0, 0, cut, None, right))
                    return Reading(parts, 1, f"read '{word}' as '{stem} {word[cut:]}'")
        return None

    def _head(self, word: str) -> Reading | None:
        """hand-hammered = hammered (the last part); rough-hewn = rough (the first part, when the
        rest is unknown): the adjective part of a hyphenated word whose other part says how."""
        if not self.rules.head_last or "-" not in word:
            return None
        first, head = word.split("-", 1)[0], word.rsplit("-", 1)[1]
        found = self._kept(self._known(head), ("ADJ",))
        if found:
            part = Part(0, 0, len(word) - len(head), None, found)
            return Reading((part,), 1, f"read '{word}' as '{head}' (its last part; the rest says how it was done)")
        found = self._kept(self._known(first), ("ADJ",))
        if found and not self._known(head):
            part = Part(0, 0, 0, len(first), found)
            return Reading((part,), 1, f"read '{word}' as '{first}' (its first part; the rest is not known)")
        return None

    # ------------------------------------------------------------ two or more words

    def _two_words(self, words: Sequence[str]) -> bool:
        """Whether the two words after the first name one entry ('no clear coat': the coat, not
        'clear' negated)."""
        return len(words) > 2 and bool(self.lookup((words[1], words[2])))

    def _negates_here(self, words: Sequence[str]) -> bool:
        """Whether the negation word negates what follows: a strict one ('nothing': negation
        `strict`) only a describing word right after it ('nothing shiny'), or after a softener
        ('nothing too shiny' = not too shiny); not 'nothing else'."""
        first, then = words[0], words[1]
        if first not in self.rules.strict_negation:
            return True
        if then in self.rules.softeners and len(words) > 2:
            then = words[2]
        return bool(self._kept(self._known(then), ("ADJ", "COLOR", "SHADE")))

    def _negated_words(self, words: Sequence[str]) -> Reading | None:
        """'not X' (X's opposite, or without X); 'not too X' = the soft adverb + X; 'not at all X',
        'not X at all' = 'not X' (the emphatic words are taken with it)."""
        before = self._emphatic_at(words, 1) or self._pointing_at(words)
        if before:  # 'not at all rusty': read as 'not rusty', the words between taken along
            found = self._negated_words([words[0], *words[1 + before :]])
            if found is None:
                return None
            parts = tuple(
                Part(p.first + before if p.first else 0, p.last + before, p.start, p.end, p.candidates)
                for p in found.parts
            )
            return Reading(parts, found.words + before, found.note)
        reading = self._plain_negation(words)
        after = self._emphatic_at(words, 2) if reading is not None and reading.words == 2 else 0
        if reading is None or not after:
            return reading
        parts = tuple(
            Part(p.first, p.last + after if p.last == 1 else p.last, p.start, p.end, p.candidates)
            for p in reading.parts
        )
        return Reading(parts, reading.words + after, reading.note)

    def _emphatic_negation(self, words: Sequence[str]) -> Reading | None:
        """'gar nicht X', 'überhaupt nicht X' = 'nicht X': the emphatic word before the negation is
        taken along with it ('but not' with nothing after it: no reading)."""
        if len(words) < 3:
            return None
        found = self._negated_words(words[1:])
        if found is None:
            return None
        parts = tuple(
            Part(p.first + 1 if p.first else 0, p.last + 1, p.start, p.end, p.candidates) for p in found.parts
        )
        return Reading(parts, found.words + 1, found.note.replace(f"'{words[1]} ", f"'{words[0]} {words[1]} ", 1))

    def _pointing_at(self, words: Sequence[str]) -> int:
        """How many words right after the negation only point at what it negates ('the' of
        'without the shine'): 0 when none do, or nothing follows them."""
        for phrase in sorted(self.rules.pointing, key=len, reverse=True):
            if tuple(words[1 : 1 + len(phrase)]) == phrase and len(words) > 1 + len(phrase):
                return len(phrase)
        return 0

    def _emphatic_at(self, words: Sequence[str], at: int) -> int:
        """How many words of an emphatic phrase ('at all') start at words[at]: 0 when none does."""
        for phrase in self.rules.emphatic:
            if tuple(words[at : at + len(phrase)]) == phrase and len(words) > at + len(phrase) - (at == 2):
                return len(phrase)
        return 0

    def _plain_negation(self, words: Sequence[str]) -> Reading | None:
        rules = self.rules
        if words[1] in rules.softeners and len(words) > 2 and rules.soft_adverb:
            found = self._resolved(words[2])
            if any(c.tag == "ADJ" for c in found):
                return self._not_too(words, found)
            if self._kept(found, ("COLOR", "SHADE")):
                text = " ".join(words[:3])  # "a warm cream, not too yellow", "oak, not too dark"
                return Reading((), 3, f"read '{text}' as a limit, not a change: the colour named is kept")
        found = self._resolved(words[1])
        adjective = next((c for c in found if c.tag == "ADJ"), None)
        if adjective is None:
            return self._negated_unknown(words, found)
        reading = self._opposite_reading(f"{words[0]} {words[1]}", 1, adjective, words[1])
        return Reading(tuple(Part(0, 1, 0, None, p.candidates) for p in reading.parts), reading.words, reading.note)

    def _not_too(self, words: Sequence[str], found: tuple[Candidate, ...]) -> Reading:
        """'not too shiny' = the finish between (negation `not_too`: satin, a set finish); any other
        word = the soft adverb + the word ('not too rough' = slightly rough, 'not too rusty' =
        slightly rusty)."""
        soft = self.rules.soft_adverb
        text = " ".join(words[:3])
        adjective = next(c for c in found if c.tag == "ADJ")
        between = self.rules.not_too.get(adjective.key)
        if between is not None:
            said = self.spoken().word("adjectives", between)
            finish = Part(0, 2, 0, None, (Candidate("ADJ", between, "adjectives"),))
            return Reading((finish,), 3, f"read '{text}' as '{said}' (the finish between)")
        adverb = Part(0, 1, 0, None, self._adverb(soft))
        target = Part(2, 2, 0, None, self._kept(found, ("ADJ",)))
        return Reading((adverb, target), 3, f"read '{text}' as '{soft} {words[2]}'")

    def _negated_unknown(self, words: Sequence[str], found: Sequence[Candidate]) -> Reading | None:
        """'white, not yellowed, plastic', 'grey, not red, slate': 'not' and a word that is no
        adjective (a colour, or a word the lexicon does not know), set off by a comma as a list item,
        is "without X": no effect, noted (an unknown word's spelling suggestions with it)."""
        if len(words) < 3 or words[2] not in _LIST_MARKS or not words[1].isalpha():
            return None
        suggestions = [] if found else self.lexicon.suggest(words[1])[:2]
        meant = f" (did you mean {' or '.join(repr(w) for w in suggestions)}?)" if suggestions else ""
        said = "" if found else ", a word the lexicon does not know"
        note = f"read '{words[0]} {words[1]}' as without '{words[1]}'{said}: no effect{meant}"
        return Reading((), 2, note)

    def _prefixed_word(self, first: str, adverb: str, second: str) -> Reading | None:
        found = self._prefix_target(second, self.rules.prefix_endings[first])
        if not found:
            return self.read(first)
        parts = (Part(0, 0, 0, None, self._adverb(adverb)), Part(1, 1, 0, None, found))
        return Reading(parts, 2, f"read '{first} {second}' as '{adverb} {found[0].key}' ({first}: {adverb})")


#: What sets a negated list item off after it ('white, not yellowed, plastic').
_LIST_MARKS = frozenset((",", ";", ")", "]"))


def _merged_wordnet(layers: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """The [wordnet] rules of all layers: the first file named, roots and adjectives joined."""
    roots: dict[str, str] = {}
    for layer in reversed(layers):  # the most specific layer's root wins
        roots.update(layer["noun_roots"])
    return {
        "file": next((layer["file"] for layer in layers if layer["file"]), ""),
        "noun_roots": roots,
        "adjectives": list(dict.fromkeys(a for layer in layers for a in layer["adjectives"])),
    }


def _merged_typos(layers: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """The [typos] rules of all layers: the first file, reach and vowel reach given; off when a
    layer says so."""
    return {
        "file": next((layer["file"] for layer in layers if layer["file"]), ""),
        "reach": next((layer["reach"] for layer in layers if layer["reach"]), []),
        "vowels": next((layer["vowels"] for layer in layers if layer["vowels"]), None),
        "off": any(layer["off"] for layer in layers),
    }


def _merged_table(layers: Sequence[dict[str, Any]], section: str, name: str) -> dict[str, str]:
    """A word table of every layer, the most specific layer's entry winning."""
    merged: dict[str, str] = {}
    for layer in reversed(layers):
        merged.update(layer[section][name])
    return merged


def _stems(stem: str, endings: Sequence[str]) -> list[str]:
    """The stem plus each ending, then undoubled ('plasticky': plastic, 'nutty': nut)."""
    out = [stem + ending for ending in endings]
    if len(stem) > 3 and (stem.endswith("ck") or (stem[-1] == stem[-2] and stem[-1] not in "aeiou")):
        out.append(stem[:-1])
    return out


def _merged_resemblance(layers: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """The [resemblance] rules of all layers: lists joined, the most specific layer's ladder and
    finish adjectives first."""
    merged: dict[str, Any] = {
        name: list(dict.fromkeys(w for layer in layers for w in layer[name])) for name in RESEMBLANCE_WORD_LISTS
    }
    merged["surface"] = next((layer["surface"] for layer in layers if layer["surface"]), [])
    finish: dict[str, str] = {}
    for layer in reversed(layers):
        finish.update(layer["finish_adjectives"])
    merged["finish_adjectives"] = finish
    return merged


def _whole(found: tuple[Candidate, ...], note: str) -> Reading:
    return Reading((Part(0, 0, 0, None, found),), 1, note)
