"""Joining tagged words into the entry they mean (issue #14), after a line is tagged.

Object nouns (objects.toml) never reach the parser: after a material noun they join it ("oak
planks" = oak), before a noun they say what the thing is ("roof tiles" = tiles), before other
words they say how or what for ("wire brushed oak", "car window"), alone they read as their
material ("planks" = wood). A noun followed by its own class is the noun ("walnut wood"); a head
word ('finish', 'look': word_formation rules) belongs to the word before it ("satin finish
steel", "brushed steel look"); a noun read by a look suffix before another noun only describes
its look ("leather-look vinyl"). Each join is a NOTE. `may_join` is the cheap test the tagger
runs on every line; only lines it accepts are looked at further.
"""

from __future__ import annotations

from collections.abc import Callable
from itertools import takewhile
from typing import TYPE_CHECKING, Any

from .diagnostics import Diagnostic, Severity
from .spans import Span
from .tagged import NOTE_CODE, Candidate, Tagged, only_tag, written_text

if TYPE_CHECKING:
    from .lexicon import Lexicon
    from .resemblance import Resemblance
    from .spoken import Spoken
    from .word_formation import Rules

__all__ = ["HEAD_HOLDERS", "Joiner", "implied_comma", "may_join", "of_tag", "others", "others_of", "takes_target"]

#: The readings a head word ("finish", "look") joins: before the noun (False) or at the line's end (True).
HEAD_HOLDERS = {False: ("ADJ", "COLOR", "NOUN"), True: ("NOUN",)}
#: words after which a word is a verb of a question or request, not an object ('can we', 'can it')
SPEAKERS = frozenset(("we", "it", "you", "i", "they", "this", "that", "these", "those"))


class Joiner:
    """Joins the tagged words of a line by the lexicon's objects, noun classes and word formation
    rules (`rules` gives them; they are made on first use)."""

    __slots__ = ("artifacts", "lexicon", "resembling", "rules", "spoken_words")

    def __init__(self, lexicon: Lexicon, rules: Callable[[], Rules]) -> None:
        self.lexicon = lexicon
        self.rules = rules
        self.resembling: Resemblance | None = None  # made on first use
        self.artifacts: frozenset[str] | None = None  # WordNet's artifact nouns, read on first use
        self.spoken_words: Spoken | None = None  # made on first use

    def spoken(self) -> Spoken:
        """The document language's words for what a note adds ('Stahl mit': cnlmc.spoken)."""
        if self.spoken_words is None:
            from .spoken import Spoken

            self.spoken_words = Spoken(self.lexicon)
        return self.spoken_words

    def resemblance(self) -> Resemblance:
        """What a noun lends when it describes another material (cnlmc.resemblance)."""
        if self.resembling is None:
            from .resemblance import Resemblance

            self.resembling = Resemblance(self.lexicon, self.rules().resemblance)
        return self.resembling

    def joined(self, tagged: list[Tagged], diags: list[Diagnostic]) -> list[Tagged]:
        """Objects and class nouns joined to their material: "oak planks" = oak, "roof tiles" =
        tiles, "planks" = wood, "walnut wood" = walnut; each with a note."""
        if any(t.unknown or of_tag(t, "OF") or of_tag(t, "WITH") for t in tagged):
            tagged = self._made_of(tagged, diags)
        out: list[Tagged] = []
        formed: list[tuple[Tagged, Tagged]] = []  # (the joined noun, its object word): 'marble tiles'
        looks: list[tuple[Tagged, Tagged]] = []  # (the noun, the look word): 'marble-effect laminate'
        mark_after_thing = False  # 'sofa, green velvet': the listing's comma goes with the thing
        skip = 0  # label words read past ('colour: red'): how many more to pass
        for k, word in enumerate(tagged):
            before = out[-1] if out else None
            if skip:
                skip -= 1
                if skip == 0 and of_tag(word, "COLOR"):  # 'colour tea': the colour, not the drink
                    word = Tagged(word.text, word.span, of_tag(word, "COLOR"), word.unknown)
                else:  # a link read past with the label ('colour is brown'): no error of its own
                    diags[:] = [d for d in diags if not (d.code == "E001" and d.span == word.span)]
                    continue
            if mark_after_thing and only_tag(word, "COMMA"):
                mark_after_thing = False
                continue
            mark_after_thing = False
            if word.unknown and self._names_use(word, tagged[k + 1 :], diags):  # "guitar varnish", "boat paint"
                continue
            if before is not None and self._contents_of(before, word):  # 'white ceramic coffee mug'
                note = f"read '{before.text}' as what the {word.text} holds, not what it is made of"
                diags.append(Diagnostic(before.span, Severity.NOTE, NOTE_CODE, note))
                out.pop()
                before = out[-1] if out else None
            if word.unknown or (before is not None and before.unknown):  # its tags are guesses: E001 says so
                if before is not None and self._is_artifact_after(before, word, tagged[k + 1 :]):
                    out[-1] = self._artifact(before, word, diags)
                elif before is not None and self._is_artifact_after_finish(before, word, tagged[k + 1 :]):
                    self._finish_on_artifact(before, word, diags)  # 'white enamel dial': the enamel
                elif before is not None and self._is_described_artifact(out, word, tagged[k + 1 :]):
                    out.append(self._painted_artifact(word, diags))  # 'a red bike': red paint
                elif not word.unknown and of_tag(word, "OBJECT") and not of_tag(word, "NOUN"):
                    out.append(self._object_alone(word, []))  # 'blorf tiles': E001 alone says what is wrong
                else:
                    out.append(word)
                continue
            nouns = of_tag(word, "NOUN")
            if _more_things(out, word, tagged[:k]):  # "copper pots and pans": the pans are copper too
                note = f"read '{out[-1].text} {word.text}' as more things of the same material"
                diags.append(Diagnostic(_joined_span(out[-1], word), Severity.NOTE, NOTE_CODE, note))
                out.pop()
                continue
            if (
                before is not None
                and of_tag(before, "OBJECT")
                and not others(before)
                and k + 1 == len(tagged)
                and word.span.start - before.span.end <= 1  # 'a glass of merlot' is the wine
                and self._colour_of_the_thing(before, word)
            ):  # 'jumper cream', 'cushion charcoal': the colour of the thing, not a material
                out[-1] = self._object_alone(before, diags)
                out.append(Tagged(word.text, word.span, of_tag(word, "COLOR"), word.unknown))
            elif before is not None and of_tag(before, "OBJECT") and not others(before) and nouns:
                out[-1] = self._join(before, word, nouns, f"'{word.text}' ('{before.text}' names the object)", diags)
                formed.append((out[-1], word if of_tag(word, "OBJECT") else before))  # 'floor tiles': the tiles
            elif (
                before is not None
                and of_tag(before, "NOUN")
                and self._is_look(before)
                and (nouns or of_tag(word, "OBJECT"))
            ):
                thing = word if nouns else self._object_alone(word, diags)  # 'wood-look tiles': tiles of ceramic tile
                out[-1:] = self._look_of(before, thing, looks)
                if not nouns:
                    formed.append((out[-1], word))
            elif (
                before is not None
                and of_tag(word, "OBJECT")
                and not _noun_next(tagged, k)
                and self._colour_of_the_thing(word, before)
            ):  # 'cream jumper', 'charcoal cushion': the colour of the thing, not its material
                out[-1] = Tagged(before.text, before.span, of_tag(before, "COLOR"), before.unknown)
                out.append(self._object_alone(word, diags))
                formed.append((out[-1], word))
            elif before is not None and of_tag(word, "OBJECT") and of_tag(before, "NOUN") and not _noun_next(tagged, k):
                made = of_tag(before, "NOUN")
                out[-1] = self._join(before, word, made, f"'{made[0].key}' (the material of the {word.text})", diags)
                formed.append((out[-1], word))
                looks[:] = [
                    (out[-1] if noun is before else noun, look) for noun, look in looks
                ]  # 'oak effect vinyl flooring'
            elif (label := self._colour_label(before, word, tagged[k + 1 :])) is not None:
                skip = label  # 'plastic, colour red', 'colour: red', 'glass colour tea': the colour after it
                note = f"read '{word.text}' as naming the colour after it"
                diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))
                if before is not None and only_tag(before, "ARTICLE"):  # 'wood, the colour is brown'
                    out.pop()
                    before = out[-1] if out else None
                if before is not None and of_tag(before, "NOUN") and k + 1 < len(tagged):
                    out.append(implied_comma(tagged[k + 1]))  # 'plastic colour red' = 'plastic, red
            elif before is not None and self.is_head(before, word.text, _ends_noun(tagged, k, out), out):
                out[-1] = self.with_head(before, word.text, word.span, _ends_noun(tagged, k, out), diags)
            elif before is not None and nouns and self._finish_noun(before) is not None:
                out[-1:] = self._finish_of(before, word, diags)
                _plating_first(out)
            elif before is not None and nouns and (same := _same_entry(before, word, nouns)):
                out[-1] = self._join(before, word, same, f"'{same[0].key}' (both words name it)", diags)
            elif before is not None and nouns and self._is_class_of(before, nouns):
                made = of_tag(before, "NOUN")
                out[-1] = self._join(before, word, made, f"'{made[0].key}' ('{word.text}' is its class)", diags)
            elif before is not None and nouns and self._is_kind_of(before, nouns):
                reading = f"'{nouns[0].key}' (made of {before.text}: the first noun says what the second is made of)"
                out[-1] = self._join(before, word, nouns, reading, diags)
            elif before is not None and nouns and self._is_class_of(word, of_tag(before, "NOUN")):
                reading = f"'{nouns[0].key}' ('{before.text}' is its class, said first)"  # 'plastic ABS', 'wood oak'
                out[-1] = self._join(before, word, nouns, reading, diags)
            elif of_tag(word, "OBJECT"):
                if k + 1 < len(tagged) and of_tag(tagged[k + 1], "NOUN") and not tagged[k + 1].unknown:
                    out.append(word)  # "roof tiles": joined to the noun next (not an unknown word's guess)
                elif k + 1 < len(tagged) and tagged[k + 1].text.lower() in SPEAKERS:
                    out.append(word)  # "can we ...", "can it be ...": a question, read as politeness
                elif (
                    not others(word)
                    and _describes_a_coat(tagged[k + 1 :])  # not 'floor, varnish' nor 'floor and varnish'
                    and self._coat_alone(tagged[k + 1 :]) is not None
                ):
                    out.extend(self._coat_on_object(word, tagged[k + 1 :], diags))  # "floor varnish"
                elif not others(word) and self._named_later(word, _main_words(tagged[k + 1 :])):
                    note = f"read '{word.text}' as saying how or what for, not what: the material is named later"
                    diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))  # "wire brushed oak"
                    mark_after_thing = all(
                        of_tag(w, "ARTICLE") for w in out
                    )  # 'my worktop, black granite': it opens a listing
                else:
                    out.append(self._object_alone(word, diags))
                    formed.append((out[-1], word))
            else:
                out.append(word)
        for noun, thing in formed:
            if not any(made is noun for made, _ in looks):  # 'marble effect tiles': the look draws the pattern
                self._form_feature(out, noun, thing, diags)
        for noun, look in looks:
            self._look_clause(out, noun, look)
        if len(out) > 2 and (self._coat_after_mark(out, diags) or self._describing_after_slash(out, diags)):
            pass  # 'Walnut, satin lacquer', 'Oak / natural oil': a listing's finish after its material
        elif len(out) > 2 and self._is_coat_finish(out):
            self._coat_after(out, diags)
        elif len(out) > 2 and _layer_of(out, diags) and self._coat_alone(out) is not None:
            self._coat_on_substrate(out, diags)  # "a coat of satin varnish"
        elif self._coat_alone(out) is not None:
            self._coat_on_substrate(out, diags)
        elif (finish := self._finish_alone(out)) is not None:
            self._finish_on_substrate(out, finish, diags)  # "blue glaze", "red enamel"
        _feature_colour_list(out, diags)
        _feature_with_finish_head(out, diags)  # 'with a wood grain effect': the grain
        self._coloured_feature(out, diags)  # 'terrazzo with coloured chips'
        if len(out) > 3:
            _feature_then_colour(out, diags, self.spoken().with_word)  # 'granite, speckled grey'
        if len(out) > 1:
            _feature_first(out, diags, self.lexicon, self.spoken().with_word)
        if len(out) > 1 and _ends_in_describing(out) and self.rules().postfix:
            self._postfix(out, diags)
        return out

    def _made_of(self, tagged: list[Tagged], diags: list[Diagnostic]) -> list[Tagged]:
        """'Dielen aus Eiche', 'Rohre aus verzinktem Stahl', 'buttons made of brass' (an object, a
        `made_of` phrase of the rules, describing words, a material noun) = the material with its
        describing words; the phrase's E001s go."""
        for phrase in self.rules().made_of:
            words = tuple(phrase.split())
            for k in range(1, len(tagged) - len(words)):
                thing, said = tagged[k - 1], tagged[k : k + len(words)]
                if not of_tag(thing, "OBJECT") or tuple(t.text.lower() for t in said) != words:
                    continue
                if not all(t.unknown or of_tag(t, "OF") or of_tag(t, "WITH") for t in said):
                    continue  # 'in' is a 'with' word elsewhere ('steel in charcoal'), here the material's
                j = k + len(words)
                while (
                    j < len(tagged)
                    and not of_tag(tagged[j], "NOUN")
                    and any(c.tag in DESCRIBING for c in tagged[j].candidates)
                ):
                    j += 1
                if j == len(tagged) or tagged[j].unknown or not of_tag(tagged[j], "NOUN"):
                    continue
                if of_tag(tagged[-1], "COAT") and any(c.key == _LAYER for c in of_tag(thing, "COAT")):
                    continue  # 'a coat of satin varnish': a layer of a coat (_layer_of), not satin
                return self._made_of_join(tagged, k - 1, k + len(words), j, diags)
        return tagged

    def _made_of_join(
        self, tagged: list[Tagged], thing: int, after: int, noun: int, diags: list[Diagnostic]
    ) -> list[Tagged]:
        spans = {t.span for t in tagged[thing + 1 : after]}
        diags[:] = [d for d in diags if not (d.span in spans and d.code == "E001")]
        material = tagged[noun]
        made = of_tag(material, "NOUN")
        said = " ".join(t.text for t in tagged[thing : noun + 1])
        note = f"read '{said}' as '{made[0].key}' (the material of the {tagged[thing].text})"
        diags.append(Diagnostic(tagged[thing].span.to(material.span), Severity.NOTE, NOTE_CODE, note))
        named = " ".join(
            t.text for t in (*tagged[thing:after], material)
        )  # 'cloak of wool': its describing words stay theirs
        joined = Tagged(named, material.span, made)
        return [*tagged[:thing], *tagged[after:noun], joined, *tagged[noun + 1 :]]

    def _postfix(self, out: list[Tagged], diags: list[Diagnostic]) -> None:
        """'Eiche geölt', 'Stahl gebürstet', 'Marmor poliert mit grauen Adern' (rules `postfix`, German):
        describing words after the noun, at the end of the line or before its 'with', with no comma,
        read as after a comma (the grammar's postfix form)."""
        end = next((k for k, t in enumerate(out) if of_tag(t, "WITH")), len(out))
        start = end
        while (  # 'Buche massiv, geölt': a comma may stand inside the run, not right after the noun
            start > 0
            and not of_tag(out[start - 1], "NOUN")
            and any(c.tag in ("ADJ", "ADV", "AND", "COLOR", "SHADE", "COMMA") for c in out[start - 1].candidates)
        ):
            start -= 1
        while start < end and (of_tag(out[start], "AND") or of_tag(out[start], "COMMA")):
            if of_tag(out[start], "COMMA"):
                return  # 'Eiche, geölt': the comma is there already
            start += 1
        if start == 0 or start == end or not of_tag(out[start - 1], "NOUN") or out[start - 1].unknown:
            return
        if any(of_tag(t, "COMMA") for t in out[:start]):
            return
        first = out[start]
        comma = implied_comma(first)
        said = " ".join(t.text for t in out[start:end]).replace(" ,", ",")
        noun = out[start - 1].text
        note = f"read '{noun} {said}' as '{noun}, {said}' (describing words after the noun)"
        diags.append(Diagnostic(out[start - 1].span.to(out[end - 1].span), Severity.NOTE, NOTE_CODE, note))
        out.insert(start, comma)

    def _is_artifact_after(self, before: Tagged, word: Tagged, rest: list[Tagged]) -> bool:
        """An unknown word after a material noun, last on the line, that WordNet 3.0 lists as an
        artifact ("pewter tankard"): the thing made of the material."""
        if before.unknown or not self._artifact_run(rest) or not of_tag(before, "NOUN") or not word.text.isalpha():
            return False
        return self._artifact_name(word.text.lower()) is not None

    def ends_in_a_finished_thing(self, tagged: list[Tagged]) -> bool:
        """Whether the line ends in a WordNet artifact after a finish substance ('white enamel dial'),
        which may_join does not see (it reads no lexicon)."""
        return len(tagged) > 1 and self._is_artifact_after_finish(tagged[-2], tagged[-1], [])

    def _is_artifact_after_finish(self, before: Tagged, word: Tagged, rest: list[Tagged]) -> bool:
        """A WordNet artifact after a finish substance named as the material ('white enamel dial',
        'celadon glaze bowl': Joiner._finish_alone reads it on its substrate)."""
        if before.unknown or not word.unknown or not word.text.isalpha() or not self._artifact_run(rest):
            return False
        return self._substance(before) is not None and self._artifact_name(word.text.lower()) is not None

    def _finish_on_artifact(self, before: Tagged, word: Tagged, diags: list[Diagnostic]) -> None:
        """The thing after a finish read past, its error gone, with a note."""
        diags[:] = [d for d in diags if not (d.span == word.span and d.code in ("E001", "E002"))]
        name = self._artifact_name(word.text.lower())
        note = f"read '{before.text} {word.text}' as '{before.text}' (the finish of the {word.text}: WordNet 3.0 lists '{name}' as an artifact)"
        diags.append(Diagnostic(before.span.to(word.span), Severity.NOTE, NOTE_CODE, note))

    def _coloured_feature(self, out: list[Tagged], diags: list[Diagnostic]) -> None:
        """'terrazzo with coloured chips': a colour head ('coloured') in a 'with' clause right before a
        feature says its pieces have colours: read as word formation's `colour_head_before_feature`
        ('colourful'; the graph draws one colour), with a note; elsewhere ('red coloured plastic') it
        stays the colour's head."""
        with_at = next((k for k, t in enumerate(out) if of_tag(t, "WITH")), None)
        rules = self.rules()
        if with_at is None or not rules.colour_head_before_feature:
            return
        for k in range(with_at + 1, len(out) - 1):
            word, feature = out[k], out[k + 1]
            if not (only_tag(word, "PROP") and word.text.lower() in rules.colour_heads and of_tag(feature, "FEATURE")):
                continue
            said = rules.colour_head_before_feature[0]
            reading = tuple(Candidate(e.tag, e.key, e.category) for e in self.lexicon.lookup((said,)) if e.tag == "ADV")
            if reading:
                out[k] = Tagged(word.text, word.span, reading)
                note = f"read '{word.text} {feature.text}' as {said} {feature.text} (the pattern draws one colour)"
                diags.append(Diagnostic(word.span.to(feature.span), Severity.NOTE, NOTE_CODE, note))

    def _artifact_run(self, rest: list[Tagged]) -> bool:
        """Whether the words after a thing's name are the rest of it ('guitar neck', 'phone case':
        unknown words WordNet lists as artifacts) up to the line's end, a comma or a 'with' clause
        ('copper bar top, aged a bit', 'bronze case with patina')."""
        for t in rest:
            if only_tag(t, "COMMA") or of_tag(t, "WITH"):
                return True
            if not (t.unknown and t.text.isalpha() and self._artifact_name(t.text.lower())):
                return False
        return True

    def _is_described_artifact(self, out: list[Tagged], word: Tagged, rest: list[Tagged]) -> bool:
        """An unknown word WordNet 3.0 lists as an artifact after describing words and no material
        ('a red bike', 'a red bike with a glossy clear coat'), last on the line or before a clause."""
        said = [t for t in out if t.text[:1].isalnum() and not of_tag(t, "ARTICLE")]
        if not said or not word.text.isalpha() or any(t.unknown or of_tag(t, "NOUN") for t in out):
            return False
        if not all(any(c.tag in DESCRIBING for c in t.candidates) for t in said):
            return False
        if rest and not of_tag(rest[0], "WITH") and not self._artifact_run(rest):
            return False
        return self._artifact_name(word.text.lower()) is not None

    def _painted_artifact(self, word: Tagged, diags: list[Diagnostic]) -> Tagged:
        """The thing read as the everyday noun colours go on (paint), its E001 gone, with a note."""
        from .suggest import everyday_noun

        noun = everyday_noun()
        diags[:] = [d for d in diags if not (d.span == word.span and d.code == "E001")]
        name = self._artifact_name(word.text.lower())
        note = (
            f"read '{word.text}' as the thing its colour and finish are on: {noun} "
            f"(WordNet 3.0 lists '{name}' as an artifact; name its material to choose another)"
        )
        diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))
        return Tagged(word.text, word.span, (Candidate("NOUN", noun, "nouns"),))

    def _artifact_name(self, word: str) -> str | None:
        """The WordNet artifact `word` is, also in a plural (-s, -es, -ies)."""
        if self.artifacts is None:
            self.artifacts = _artifact_words()
        for form in (word, word[:-1] if word.endswith("s") else "", word[:-2] if word.endswith("es") else ""):
            if form and form in self.artifacts:
                return form
        if word.endswith("ies") and word[:-3] + "y" in self.artifacts:
            return word[:-3] + "y"
        return None

    def _names_use(self, word: Tagged, rest: list[Tagged], diags: list[Diagnostic]) -> bool:
        """An unknown word WordNet 3.0 lists as an artifact, before a material noun or coat (maybe
        after more such words: 'table top laminate'), says where or on what the material is used
        ('guitar varnish', 'boat paint'): it goes, its E001 with it, and a note says how it was read.
        A word that is not a WordNet noun ('blu', 'brushd') keeps its E001 and "did you mean"; a noun one
        edit from a describing word ('bike': the colour 'bile') says so in the note's hint."""
        name = self._artifact_name(word.text.lower()) if word.text.isalpha() else None
        if name is None:
            return False
        j = 0
        while (
            j < len(rest) and rest[j].unknown and rest[j].text.isalpha() and self._artifact_name(rest[j].text.lower())
        ):
            j += 1
        if j == len(rest) or rest[j].unknown or not any(c.tag in _USED_ON for c in rest[j].candidates):
            return False
        error = next((d for d in diags if d.span == word.span and d.code == "E001"), None)
        near = () if error is None else self._near_describing(word.text.lower(), error.suggestions)
        diags[:] = [d for d in diags if d is not error]
        note = (
            f"read '{word.text}' as where the material is used: no effect on the look "
            f"(WordNet 3.0 lists '{name}' as an artifact)"
        )
        hints = (f"did you mean '{near[0]}'?",) if near else ()
        diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note, hints, near))
        return True

    def _near_describing(self, word: str, suggestions: tuple[str, ...]) -> tuple[str, ...]:
        """The suggestions one edit from `word` that are describing words ('bike': the colour 'bice'):
        a real noun is read as a noun, but the note still offers them."""
        from rapidfuzz.distance import OSA  # loaded already: the suggestions came from it (cnlmc.suggest)

        return tuple(
            s
            for s in suggestions
            if OSA.distance(word, s) == 1 and any(e.tag in DESCRIBING for e in self.lexicon.lookup(tuple(s.split())))
        )

    def _artifact(self, before: Tagged, word: Tagged, diags: list[Diagnostic]) -> Tagged:
        """The material, with a note saying WordNet named the thing; the word's error goes (E001, or
        E002 for a word that says where it is used: 'oak kitchen', 'chrome trim')."""
        diags[:] = [d for d in diags if not (d.span == word.span and d.code in ("E001", "E002"))]
        made = of_tag(before, "NOUN")
        name = self._artifact_name(word.text.lower())
        reading = f"'{made[0].key}' (the material of the {word.text}: WordNet 3.0 lists '{name}' as an artifact)"
        return self._join(before, Tagged(word.text, word.span, made), made, reading, diags)

    def _is_coat_finish(self, out: list[Tagged]) -> bool:
        """'powder coat finish steel', 'clear coat finish steel': a coat, a finish head, the material last."""
        coat, head, noun = out[-3:]
        return (
            head.text.lower() in self.rules().finish_heads
            and bool(of_tag(noun, "NOUN"))
            and all(c.tag == "COAT" for c in coat.candidates)
            and not any(c.tag == "WITH" for t in out for c in t.candidates)
        )

    def _coat_after(self, out: list[Tagged], diags: list[Diagnostic]) -> None:
        """The coat named as a finish goes after the material in a 'with' clause (the head word stands
        for the 'with'), with the describing words right before it: 'glossy powder coat finish
        steel' = steel with a glossy powder coat."""
        coat, head, noun = out[-3:]
        start = len(out) - 3
        while start > 0 and all(c.tag in DESCRIBING for c in out[start - 1].candidates):
            start -= 1
        coat_words = out[start:-2]
        with_word = Tagged(head.text, head.span, (Candidate("WITH", "with", "keyword"),))
        coat_text = " ".join(t.text for t in coat_words)
        reading = f"{noun.text} {self.spoken().with_word} {coat_text}"
        note = f"read '{coat_text} {head.text} {noun.text}' as '{reading}' (the coat is the finish)"
        diags.append(Diagnostic(coat_words[0].span.to(noun.span), Severity.NOTE, NOTE_CODE, note))
        out[start:] = [noun, with_word, *coat_words]

    def _coat_after_mark(self, out: list[Tagged], diags: list[Diagnostic]) -> bool:
        """'Walnut, satin lacquer', 'Oak / natural oil', 'Beech - clear varnish' (a product listing:
        the material, a comma, slash or dash, then its finish): the material with that coat, the
        mark read as 'with', and a note. Only for a coat last, describing words between, and before
        the mark one material noun with only describing words before it (not 'red or blue paint')."""
        last = out[-1]
        if not of_tag(last, "COAT") or last.unknown:
            return False
        k = len(out) - 2
        while k > 0 and any(c.tag in DESCRIBING for c in out[k].candidates):  # a word that may describe: 'Satin'
            k -= 1
        mark = out[k]
        if k < 1 or mark.text not in LISTING_MARKS or not of_tag(out[k - 1], "NOUN") or of_tag(out[k - 1], "ADJ"):
            return False  # 'a satin, dark green powder coat': 'satin' describes the coat
        if not _only_describing(out[: k - 1]):
            return False
        noun, finish = out[k - 1], [_describing(t) for t in out[k + 1 : -1]]
        finish.append(Tagged(last.text, last.span, of_tag(last, "COAT"), last.unknown))
        with_word = Tagged(mark.text, mark.span, (Candidate("WITH", "with", "keyword"),))
        said = " ".join(t.text for t in finish)
        mark_said = f"{mark.text} " if mark.text in ",;" else f" {mark.text} "  # 'Walnut, satin', 'Walnut / Satin'
        note = f"read '{noun.text}{mark_said}{said}' as '{noun.text} {self.spoken().with_word} {said}' (the finish after the material)"
        diags.append(Diagnostic(noun.span.to(last.span), Severity.NOTE, NOTE_CODE, note))
        out[k:] = [with_word, *finish]
        return True

    def _describing_after_slash(self, out: list[Tagged], diags: list[Diagnostic]) -> bool:
        """'Oak / Natural Oil', 'Steel / brushed': a slash after the material, then only describing
        words (none may be an alternative material), is the comma of describing words after the
        noun ('Oak, natural oiled'), with a note."""
        k = next((i for i, t in enumerate(out) if t.text == "/"), -1)
        if k < 1 or k == len(out) - 1 or not of_tag(out[k - 1], "NOUN"):
            return False
        after = out[k + 1 :]
        if not _only_describing(after, article=False):
            return False
        if not _only_describing(out[: k - 1]):
            return False
        said = " ".join(t.text for t in after)
        note = f"read '{out[k - 1].text} / {said}' as '{out[k - 1].text}, {said}' (the finish after the material)"
        diags.append(Diagnostic(out[k - 1].span.to(after[-1].span), Severity.NOTE, NOTE_CODE, note))
        out[k] = Tagged(",", out[k].span, (Candidate("COMMA", ",", "keyword"),))
        return True

    def _coat_alone(self, out: list[Tagged]) -> str | None:
        """The substrate of a coat named as the whole material ('satin varnish', 'red powder coating',
        'glossy clear lacquer'): a coat last (not also a noun: 'wax'), describing words before it (a
        word that may describe: 'satin'; no 'with'), and the coat's entry declares the noun it is
        usually on (coats.toml `substrate`)."""
        if not out:
            return None
        last = out[-1]
        coats = of_tag(last, "COAT")
        if not coats or last.unknown or of_tag(last, "NOUN"):
            return None
        entry = self.lexicon.entry("coats", coats[0].key)
        if entry is None:
            return None
        # before a pigmented coat read as its adjective a feature may stand ('speckled powder coat':
        # _feature_first makes it a clause); in a 'with' clause only describing words do
        allowed = _BEFORE_A_COAT | {"FEATURE"} if entry.get("adjective") else _BEFORE_A_COAT - {"PROP"}
        first = _comparative_at(out)  # 'lighter than satin varnish': the comparative the tagger kept
        if any(t.unknown or of_tag(t, "COAT") for t in out[:-1]):
            return None  # 'varnish varnish': a coat is not a describing word of another
        if not all(any(c.tag in allowed for c in t.candidates) for k, t in enumerate(out[:-1]) if k != first):
            return None
        substrate = entry.get("substrate")
        return None if substrate is None else str(substrate)

    def _coat_on_object(self, word: Tagged, rest: list[Tagged], diags: list[Diagnostic]) -> list[Tagged]:
        """'floor varnish', 'car clear coat': an object before a coat named alone is what the coat is on,
        its usual material: 'wood with varnish' (the object's material and a 'with'; the coat follows)."""
        material = self.lexicon.require("objects", of_tag(word, "OBJECT")[0].key).data["material"]
        said = " ".join(t.text for t in rest)
        spoken = self.spoken()
        reading = f"{spoken.word('nouns', material)} {spoken.with_word} {said}"
        note = f"read '{word.text} {said}' as '{reading}' (the usual material of '{word.text}', coated)"
        diags.append(Diagnostic(word.span.to(rest[-1].span), Severity.NOTE, NOTE_CODE, note))
        s = rest[0].span  # the 'with': empty, inside the next word (the parser keys words by start)
        with_word = Tagged("with", Span(s.start + 1, s.start + 1, s.line, s.col + 1), _WITH, implied_by=rest[-1].span)
        return [Tagged(word.text, word.span, (Candidate("NOUN", material, "nouns"),)), with_word]

    def _coat_on_substrate(self, out: list[Tagged], diags: list[Diagnostic]) -> None:
        """'satin varnish' = 'wood with a satin varnish': the coat's usual substrate, then the coat
        with its describing words in a 'with' clause; a note says so (a name before stays first)."""
        substrate = self._coat_alone(out)
        assert substrate is not None
        start = next((k + 1 for k, t in enumerate(out) if of_tag(t, "COLON")), 0)
        comparative = _comparative_at(out)
        if comparative is not None:  # 'lighter than satin varnish': the comparative stays before the substrate
            start = self._past_target(out, comparative)
        coat = out[-1]
        words = out[start:]
        said = "".join(t.text if of_tag(t, "COMMA") else f" {t.text}" for t in words).strip()
        s = coat.span  # the added words start inside the coat's word, where no word starts (the parser keys
        # words by start); the noun ends where the coat does, so a 'with' put after it (_feature_first) is free
        noun_span = Span(s.start + 2, s.end, s.line, s.col + 2)
        noun = Tagged(substrate, noun_span, (Candidate("NOUN", substrate, "nouns"),), implied_by=s)
        adjective = self.lexicon.require("coats", of_tag(coat, "COAT")[0].key).get("adjective")
        spoken = self.spoken()
        on = spoken.word("nouns", substrate)
        if adjective is not None:  # 'red powder coating' = red powder-coated steel: the pigment is the surface
            reading = f"{said.removesuffix(coat.text)}{spoken.word('adjectives', adjective)} {on}"
            out[start:] = [*words[:-1], Tagged(coat.text, s, (Candidate("ADJ", adjective, "adjectives"),)), noun]
        else:
            reading = f"{on} {spoken.with_word} {said}"
            with_word = Tagged("with", Span(s.start + 1, s.start + 1, s.line, s.col + 1), _WITH, implied_by=s)
            out[start:] = [noun, with_word, *words]
        note = (
            f"read '{said}' as '{reading}' (a coat named alone: on {on}, what it is usually on; "
            "name the material to choose another)"
        )
        diags.append(Diagnostic(words[0].span.to(coat.span), Severity.NOTE, NOTE_CODE, note))

    def _finish_alone(self, out: list[Tagged]) -> tuple[str, str] | None:
        """The adjective and substrate of a finish substance named as the whole material ('blue glaze',
        'red enamel', 'Glasur'): the last word is a describing word whose entry declares the words
        naming its substance and the noun it is usually on (adjectives `substances`, `substrate`), or
        a feature drawn by such an adjective; only describing words before it."""
        if not out or out[-1].unknown or of_tag(out[-1], "NOUN") or of_tag(out[-1], "COAT"):
            return None
        start = next((k + 1 for k, t in enumerate(out) if of_tag(t, "COLON")), 0)
        if not all(_describes_a_finish(t) for t in out[start:-1]):
            return None
        return self._substance(out[-1])

    def _substance(self, word: Tagged) -> tuple[str, str] | None:
        """(adjective, substrate) when `word` names a finish substance, else None."""
        text = word.text.lower().split("-")[0]  # 'glaze-finished': the word formation's 'glaze'
        keys = [c.key for c in of_tag(word, "ADJ") if text in self._adjective_field(c.key, "substances")]
        for c in of_tag(word, "FEATURE"):  # 'glaze', 'Glasur', 'Beize': the feature names the substance
            feature = self.lexicon.entry("features", c.key)
            if feature is not None and feature.get("adjective"):
                keys.append(str(feature.get("adjective")))
        for key in keys:
            substrate = self._adjective_field(key, "substrate")
            if substrate:
                return key, str(substrate)
        return None

    def _adjective_field(self, key: str, field: str) -> Any:
        entry = self.lexicon.entry("adjectives", key)
        return () if entry is None or entry.get(field) is None else entry.get(field)

    def _finish_on_substrate(self, out: list[Tagged], finish: tuple[str, str], diags: list[Diagnostic]) -> None:
        """'blue glaze' = 'blue glazed ceramic': the finish word is its adjective, on the noun it is
        usually on (after it, with the span of the word implying it); a note says so."""
        adjective, substrate = finish
        start = next((k + 1 for k, t in enumerate(out) if of_tag(t, "COLON")), 0)
        last = out[-1]
        s = last.span
        at = min(s.start + 2, s.end)  # inside the word, where no word starts (the parser keys words by start)
        noun = Tagged(
            substrate,
            Span(at, s.end, s.line, s.col + at - s.start),
            (Candidate("NOUN", substrate, "nouns"),),
            implied_by=s,
        )
        said = "".join(t.text if of_tag(t, "COMMA") else f" {t.text}" for t in out[start:]).strip()
        spoken = self.spoken()
        on = spoken.word("nouns", substrate)
        reading = f"{said.removesuffix(last.text)}{spoken.word('adjectives', adjective)} {on}"
        note = (
            f"read '{said}' as '{reading}' (a finish named alone: on {on}, what it is usually on; "
            "name the material to choose another)"
        )
        diags.append(Diagnostic(out[start].span.to(s), Severity.NOTE, NOTE_CODE, note))
        out[-1:] = [Tagged(last.text, s, (Candidate("ADJ", adjective, "adjectives"),)), noun]

    def _past_target(self, out: list[Tagged], comparative: int) -> int:
        """Where the words after a comparative start, past its target when it takes one ('more
        yellow than satin varnish': 'yellow'; 'lighter' names its own)."""
        after = comparative + 1
        if (
            takes_target(out[comparative], self.lexicon)
            and after < len(out) - 1
            and any(c.tag in COMPARED for c in out[after].candidates)
        ):
            return after + 1
        return after

    def _form_feature(self, out: list[Tagged], noun: Tagged, thing: Tagged, diags: list[Diagnostic]) -> None:
        """An object whose form is a pattern ('tiles': objects.toml `feature` = grout) draws it: the
        feature clause after its material noun ('white tiles' = ceramic tile with grout), first among
        the clauses, when the noun ends the material part of the line and the material has no colour
        pattern of its own ('marble tiles' keep marble's veins)."""
        objects = of_tag(thing, "OBJECT")
        entry = self.lexicon.entry("objects", objects[0].key) if objects else None
        key = entry.get("feature") if entry is not None else None
        if entry is None or key is None or noun not in out or not of_tag(noun, "NOUN"):
            return
        if self._noun_class(noun) in (entry.get("sheet_classes") or ()):
            return  # 'stainless steel splashback': one sheet, no grout
        if self._own_pattern(noun):  # 'slate tiles': slate's own colour, the joints in relief
            key = entry.get("patterned_feature")
            if key is None:
                return
        said = {c.key for t in out[out.index(noun) + 1 :] for c in of_tag(t, "FEATURE")}
        if said & {entry.get("feature"), entry.get("patterned_feature")}:
            return  # 'tiles with grout', 'marble tiles with dark grout': said already
        if self._feature_clause(out, noun, key, thing.span):
            note = f"read '{thing.text}' as laid {thing.text}: with {key}"
            diags.append(Diagnostic(thing.span, Severity.NOTE, NOTE_CODE, note))

    def _feature_clause(self, out: list[Tagged], noun: Tagged, key: str, implied_by: Span) -> bool:
        """The feature clause 'with KEY' after the material noun (see _clause_after_noun)."""
        return self._clause_after_noun(out, noun, [(key, (Candidate("FEATURE", key, "features"),))], implied_by)

    def _look_of(self, look: Tagged, noun: Tagged, looks: list[tuple[Tagged, Tagged]]) -> list[Tagged]:
        """'marble-effect laminate', 'wood-look tiles': the noun, with the look of the other said as
        its finish clause ('laminate with a marble effect', drawn and noted by cnlmc.passes.features:
        the look's colour, unless the line names one, and the feature that draws its pattern)."""
        made = Tagged(noun.text, noun.span, of_tag(noun, "NOUN"), noun.unknown)
        looks.append((made, look))
        return [made]

    def _look_clause(self, out: list[Tagged], noun: Tagged, look: Tagged) -> None:
        """The finish clause 'with a LOOK effect' after the noun (see _clause_after_noun)."""
        looked = of_tag(look, "NOUN")
        self._clause_after_noun(out, noun, [(looked[0].key, looked), ("effect", _FINISH)], look.span)

    def _clause_after_noun(
        self, out: list[Tagged], noun: Tagged, said: list[tuple[str, tuple[Candidate, ...]]], implied_by: Span
    ) -> bool:
        """The clause 'with' + `said` after the material noun, first among the clauses (after a colour
        said with 'in': 'tiles in deep green'), each word implied by `implied_by` and placed inside the
        word before it (the parser keys words by start); False when the words after the noun are not
        clauses."""
        if noun not in out:
            return False
        n = out.index(noun)
        rest = out[n + 1 :]
        last = noun
        read_past_later = bool(rest) and (
            rest[0].unknown or _a_place(rest)
        )  # 'tiles behind the hob', 'of the bathroom'
        if read_past_later:
            rest = []
        elif rest and of_tag(rest[0], "COMMA") and _describing_only(rest):  # 'white tiles, glossy': the clause last
            n, last, rest = len(out) - 1, rest[-1], []
        elif rest and not of_tag(rest[0], "WITH"):
            return False
        coloured = _in_colour_length(rest)
        after = rest[coloured - 1] if coloured else last
        n, rest = n + coloured, rest[coloured:]
        s = after.span
        clause = [Tagged("with", Span(s.end, s.end, s.line, s.col + s.end - s.start), _WITH, implied_by=implied_by)]
        for k, (text, candidates) in enumerate(said, start=1):
            at = min(s.start + k, max(s.end - 1, s.start))
            clause.append(Tagged(text, Span(at, at, s.line, s.col + at - s.start), candidates, implied_by=implied_by))
        if rest and not _a_place(rest):  # 'tiles in the hallway': a place, read past later, joins no clause
            w = rest[0].span
            clause.append(Tagged("and", Span(w.start + 1, w.start + 1, w.line, w.col + 1), _AND, implied_by=implied_by))
        out[n + 1 : n + 1] = clause
        return True

    def _noun_class(self, noun: Tagged) -> str | None:
        entry = self.lexicon.entry("nouns", of_tag(noun, "NOUN")[0].key)
        return None if entry is None else entry.get("class")

    def _own_pattern(self, noun: Tagged) -> bool:
        """Whether the material draws a colour pattern of its own (marble's veins, granite's grains):
        a map slot holds one graph, so its own pattern is kept and the laying pattern left out."""
        entry = self.lexicon.entry("nouns", of_tag(noun, "NOUN")[0].key)
        maps = entry.get("maps") if entry is not None else None
        return bool(maps and "base_color" in maps)

    def _join(
        self, a: Tagged, b: Tagged, candidates: tuple[Candidate, ...], reading: str, diags: list[Diagnostic]
    ) -> Tagged:
        span = a.span.to(b.span)
        text = f"{a.text} {b.text}"
        diags.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, f"read '{text}' as {reading}"))
        return Tagged(text, span, candidates, a.unknown or b.unknown)

    def own_pattern_named(self, tagged: list[Tagged], diags: list[Diagnostic]) -> list[Tagged]:
        """'white marble with grey', 'black granite with white': a 'with' clause of a colour alone
        on a material that draws a pattern of its own names the colour of that pattern's feature
        (features.toml: a feature of colour "map" whose graph is the material's own: veins,
        speckles), not a second colour of the material; the feature's word is implied after the
        colour, with a note. The line as it was otherwise."""
        at = next((k for k, w in enumerate(tagged) if of_tag(w, "WITH")), None)
        if at is None or at == 0 or at + 1 >= len(tagged):
            return tagged
        said = [w for w in tagged[at + 1 :] if not only_tag(w, "ARTICLE")]  # to the line's end: not a list
        if not said or not of_tag(said[-1], "COLOR") or any(w.unknown for w in said):
            return tagged
        if not all(of_tag(w, "COLOR") or of_tag(w, "SHADE") or of_tag(w, "ADV") for w in said):
            return tagged
        noun = next((w for w in reversed(tagged[:at]) if of_tag(w, "NOUN")), None)
        feature = self._pattern_feature(noun) if noun is not None else None
        if noun is None or feature is None:
            return tagged
        last = said[-1]
        span = Span(last.span.end, last.span.end, last.span.line, last.span.col + len(last.text))
        implied = Tagged(feature, span, (Candidate("FEATURE", feature, "features"),), implied_by=last.span)
        note = f"read 'with {written_text(said)}' as 'with {written_text(said)} {feature}': the colour of {noun.text}'s own {feature}"
        diags.append(Diagnostic(tagged[at].span.to(last.span), Severity.NOTE, NOTE_CODE, note))
        k = tagged.index(last) + 1
        return [*tagged[:k], implied, *tagged[k:]]

    def _pattern_feature(self, noun: Tagged) -> str | None:
        """The feature that draws the noun's own colour pattern (marble: veins), or None."""
        entry = self.lexicon.entry("nouns", of_tag(noun, "NOUN")[0].key)
        maps = entry.get("maps") if entry is not None else None
        graph = maps.get("base_color", {}).get("graph") if maps else None
        if graph is None:
            return None
        for key, feature in self.lexicon.all_of("features").items():
            feature_maps = feature.get("maps") or {}
            if feature.get("colour") == "map" and feature_maps.get("base_color", {}).get("graph") == graph:
                return key
        return None

    def has_colour_label(self, tagged: list[Tagged]) -> bool:
        """Whether a line says 'colour' as a label before a colour ('colour: red'; see _colour_label)."""
        return any(
            self._colour_label(tagged[k - 1] if k else None, word, tagged[k + 1 :]) is not None
            for k, word in enumerate(tagged)
        )

    def _colour_label(self, before: Tagged | None, word: Tagged, after: list[Tagged]) -> int | None:
        """'colour' said as a label before the colour it names ('plastic, colour red', 'colour:
        red', 'colour is dark bordeaux', 'glass colour tea'): how many words after it are read
        past with it (':' or 'is'; then 1 for the colour itself, 0 for a shade), or None when the
        word is no such label ('cream colour paint': the colour of the word before)."""
        if word.text.lower() not in self.rules().colour_heads or not (of_tag(word, "PROP") or of_tag(word, "NAME")):
            return None
        if before is not None and (of_tag(before, "COLOR") or of_tag(before, "SHADE") or of_tag(before, "ADJ")):
            return None
        at = 0
        links = self.rules().colour_label_links
        while at < len(after) and (only_tag(after[at], "COLON") or after[at].text.lower() in links):
            at += 1
        if at >= len(after) or after[at].unknown:
            return None
        if of_tag(after[at], "COLOR"):
            return at + 1  # the colour itself comes through the skip, as a colour
        return at if of_tag(after[at], "SHADE") else None

    def is_head(self, before: Tagged, text: str, last: bool, line: list[Tagged]) -> bool:
        """A head word (word_formation rules) that belongs to the word before it: after a
        describing word before the noun ("satin finish steel"), or after the noun at the end of
        the line ("brushed steel look") — never after a 'with': there the clause's feature reads it
        ("steel with a walnut finish", "oak with a glossy finish and fine scratches")."""
        low = text.lower()
        if before.unknown:
            return False  # its readings are guesses ('please tone': no colour named 'please')
        if low in self.rules().colour_heads:  # "sand coloured", "cream colored", "light colour": anywhere
            return any(c.tag in ("COLOR", "NOUN", "SHADE") for c in before.candidates) or _colour_describing(before)
        if low in self.rules().like_heads:  # "leather like vinyl", "mirror like steel"
            return not last and any(c.tag in HEAD_HOLDERS[False] for c in before.candidates)
        if low not in self.rules().heads:
            return False
        if any(c.tag == "WITH" for t in line for c in t.candidates):
            return False
        return any(c.tag in HEAD_HOLDERS[last] for c in before.candidates)

    def _holders(self, head: str, last: bool) -> tuple[str, ...]:
        """The readings the joined word keeps: a finish names a description wherever it stands ('a
        satin finish' at the end of a change line: satin, not the cloth; it joins there only a word
        that may be a material, as any head does); other heads at the line's end a material ('a
        brushed steel look')."""
        return HEAD_HOLDERS[False] if head in self.rules().finish_heads else HEAD_HOLDERS[last]

    def with_head(self, before: Tagged, text: str, span: Span, last: bool, diags: list[Diagnostic]) -> Tagged:
        joined = before.span.to(span)
        if text.lower() in self.rules().colour_heads and (of_tag(before, "COLOR") or of_tag(before, "NOUN")):
            return self._coloured(before, text, joined, diags)
        if text.lower() in self.rules().like_heads and not any(c.tag in ("ADJ", "COLOR") for c in before.candidates):
            return self._resembling(before, text, joined, diags)
        note = f"read '{before.text} {text}' as '{before.text}' ('{text}' names what it describes)"
        diags.append(Diagnostic(joined, Severity.NOTE, NOTE_CODE, note))
        colour_head = text.lower() in self.rules().colour_heads  # 'light colour', 'natural colour': the word itself
        holders = ("SHADE", "ADJ") if colour_head else self._holders(text.lower(), last)
        kept = tuple(c for c in before.candidates if c.tag in holders)
        # 'satin finish': the finish, never the fabric (at the line's end too: 'a satin finish')
        if any(c.tag == "ADJ" for c in kept):
            kept = tuple(c for c in kept if c.tag != "NOUN")
        return Tagged(f"{before.text} {text}", joined, kept, before.unknown)

    def _coloured(self, before: Tagged, text: str, joined: Span, diags: list[Diagnostic]) -> Tagged:
        """'cream colored' = the colour cream; 'brass coloured' = the named colour nearest to brass's."""
        colours = of_tag(before, "COLOR")
        found = None if colours else self.resemblance().colour(of_tag(before, "NOUN")[0].key)
        if found is not None:
            colours = (found[0],)
            note = f"read '{before.text} {text}' as '{found[0].key}' (the colour of {before.text}: {found[1]})"
        else:
            note = f"read '{before.text} {text}' as the colour '{colours[0].key}'"
        diags.append(Diagnostic(joined, Severity.NOTE, NOTE_CODE, note))
        return Tagged(f"{before.text} {text}", joined, colours, before.unknown)

    def _resembling(self, before: Tagged, text: str, joined: Span, diags: list[Diagnostic]) -> Tagged:
        """'leather like vinyl' = matte vinyl: what the noun lends (cnlmc.resemblance), spaced."""
        found = self.resemblance().like(of_tag(before, "NOUN")[0].key)
        if found is None:  # a noun with nothing to lend: the noun, as before
            return Tagged(f"{before.text} {text}", joined, of_tag(before, "NOUN"), before.unknown)
        candidate, why = found
        note = f"read '{before.text} {text}' as '{candidate.key}' (resembling {before.text}: {why})"
        diags.append(Diagnostic(joined, Severity.NOTE, NOTE_CODE, note))
        return Tagged(f"{before.text} {text}", joined, (candidate,), before.unknown)

    def _finish_noun(self, before: Tagged) -> Candidate | None:
        """The noun of 'chrome finish' (a noun, not a describing word, joined to a finish head)."""
        head = before.text.rsplit(" ", 1)[-1].lower()
        if " " not in before.text or head not in self.rules().finish_heads:
            return None
        if any(c.tag == "ADJ" for c in before.candidates):
            return None
        return next(iter(of_tag(before, "NOUN")), None)

    def _finish_of(self, before: Tagged, word: Tagged, diags: list[Diagnostic]) -> list[Tagged]:
        """'chrome finish steel' = chrome plated steel, 'gold finish plastic' = gold plated plastic
        (a metal finish is a plating, also when the metal names a colour), 'walnut finish MDF' = MDF
        in walnut's colour: the finish, not a second material (cnlmc.resemblance)."""
        noun = self._finish_noun(before)
        colours = of_tag(before, "COLOR")
        material = of_tag(word, "NOUN")[0].key
        found = None if noun is None else self.resemblance().finish(noun.key, material, plating_only=bool(colours))
        if found is None and colours:  # 'walnut finish MDF': a colour word of another class keeps its colour
            found = (colours[0], f"the colour '{colours[0].key}' on {word.text}")
        if noun is None or found is None:
            return [before, word]
        diags[:] = [d for d in diags if not (d.span == before.span and d.code == NOTE_CODE)]  # the head's own note
        candidate, why = found
        noun_text, head_text = before.text.rsplit(" ", 1)
        text = f"{before.text} {word.text}"
        meaning = f"{noun_text} {candidate.key}" if candidate.tag == "ADJ" else candidate.key
        note = f"read '{text}' as '{meaning} {word.text}' ({why})"
        diags.append(Diagnostic(before.span.to(word.span), Severity.NOTE, NOTE_CODE, note))
        if candidate.tag == "COLOR":
            return [Tagged(before.text, before.span, (candidate,), before.unknown), word]
        s = before.span
        head_start = s.end - len(head_text)
        noun_span = Span(s.start, s.start + len(noun_text), s.line, s.col)
        head_span = Span(head_start, s.end, s.line, s.col + head_start - s.start)
        return [Tagged(noun_text, noun_span, (noun,)), Tagged(head_text, head_span, (candidate,)), word]

    def _named_later(self, word: Tagged, rest: list[Tagged]) -> bool:
        """Whether an object says how or what for while a later word names the material ('wire
        brushed oak', 'car window'): a noun follows, or an object follows one that is not a building
        product ('butcher block countertop': the product names the countertop's material)."""
        rest = list(
            takewhile(lambda t: not t.unknown, rest)
        )  # from an unknown word on: read past ('tiles for a floor')
        if any(of_tag(t, "NOUN") for t in rest):
            return True
        if not any(of_tag(t, "OBJECT") for t in rest):
            return False
        entries = [self.lexicon.entry(c.category, c.key) for c in of_tag(word, "OBJECT")]
        return not any(e is not None and e.get("product") for e in entries)

    def _contents_of(self, before: Tagged, word: Tagged) -> bool:
        """Whether a noun before a thing is what the thing holds: a drink before a vessel ('coffee
        mug', 'wine bottle', 'milk jug': teaching.toml [things] `drinks`, `vessels`); 'cream mug' is
        its colour and 'a glass of merlot' the wine (other readings)."""
        from .suggest import teaching

        if before.unknown or word.unknown or not of_tag(word, "OBJECT") or not of_tag(before, "NOUN") or others(word):
            return False
        table = teaching()["things"]
        return before.text.lower() in table["drinks"] and word.text.lower() in table["vessels"]

    def _colour_of_the_thing(self, thing: Tagged, word: Tagged) -> bool:
        """Whether a noun that is also a colour, said with an object, is the thing's colour: its
        class is one no thing is made of (teaching.toml [things] `colour_classes`) and the thing is
        one people dye or upholster (its usual material's class in `dyed_classes`): 'jumper cream',
        'cream jumper', 'chocolate sofa'; 'chocolate bar', 'coffee mug', 'slate tiles' keep theirs."""
        from .suggest import teaching

        if not of_tag(word, "COLOR") or not of_tag(word, "NOUN") or others(thing):
            return False
        table = teaching()["things"]
        usual = self.lexicon.require("objects", of_tag(thing, "OBJECT")[0].key).data["material"]
        if thing.text.lower().endswith(" of") or usual in table["serving_materials"]:
            return False  # 'a glass of merlot', 'a pint of stout': a serving is named for what is in it
        never, dressed = set(table["colour_classes"]), set(table["dyed_classes"])
        usual_entry = self.lexicon.entry("nouns", usual)
        kind = usual_entry.get("class") if usual_entry is not None else None
        entries = [self.lexicon.entry("nouns", c.key) for c in of_tag(word, "NOUN")]
        return kind in dressed and all(e is not None and e.get("class") in never for e in entries)

    def _object_alone(self, word: Tagged, diags: list[Diagnostic]) -> Tagged:
        """An object with no material noun beside it: its other readings, else its material."""
        kept = others(word)
        if kept:
            return Tagged(word.text, word.span, kept, word.unknown)
        key = of_tag(word, "OBJECT")[0].key
        material = self.lexicon.require("objects", key).data["material"]
        note = f"read '{word.text}' as '{self.spoken().word('nouns', material)}' (the usual material of '{word.text}')"
        diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))
        return Tagged(word.text, word.span, (Candidate("NOUN", material, "nouns"),), word.unknown)

    def _is_look(self, before: Tagged) -> bool:
        """'leather-like' (a noun only) before another noun: a look suffix (word_formation rules,
        `look = true`); 'mirror-like' is an adjective too, and stays one."""
        if any(c.tag in ("ADJ", "COLOR") for c in before.candidates):
            return False
        return before.text.lower().replace(" ", "-").endswith(self.rules().look_suffixes)  # 'stainless look' too

    def _is_class_of(self, before: Tagged, nouns: tuple[Candidate, ...]) -> bool:
        """'walnut wood': the second noun is the class of the first."""
        entries = [self.lexicon.entry("nouns", c.key) for c in of_tag(before, "NOUN")]
        classes = {e.get("class") for e in entries if e is not None}
        return any(c.key in classes for c in nouns)

    def _is_kind_of(self, before: Tagged, nouns: tuple[Candidate, ...]) -> bool:
        """'cotton canvas', 'pine plywood': a noun before a noun of a class the lexicon's setting
        `compound_classes` pairs it with (settings.toml) says what the second is made of; a word
        that is a describing word too ('satin') keeps that reading."""
        if any(c.tag == "ADJ" for c in before.candidates):
            return False
        pairs = set(self.lexicon.settings.get("compound_classes", ()))
        firsts = [self.lexicon.entry("nouns", c.key) for c in of_tag(before, "NOUN")]
        seconds = [self.lexicon.entry("nouns", c.key) for c in nouns]
        return any(
            a.get("class") == b.get("class") in pairs or f"{a.get('class')}>{b.get('class')}" in pairs
            for a in firsts
            if a is not None
            for b in seconds
            if b is not None
        )


_COMMA = (Candidate("COMMA", ",", "keyword"),)
_WITH = (Candidate("WITH", "with", "keyword"),)
_AND = (Candidate("AND", "and", "keyword"),)
_FINISH = (Candidate("FEATURE", "finish", "features"),)
#: The readings of the words that may come before a coat named as the whole material ('a glossy, red powder coat').
_BEFORE_A_COAT = frozenset(("ADV", "ADJ", "COLOR", "SHADE", "ARTICLE", "COMMA", "AND", "OR", "NAME", "COLON", "PROP"))

#: The readings of a comparative's target the tagger keeps before 'than' (also read by the tagger).
COMPARED = frozenset(("COLOR", "ADJ", "PROP", "SHADE"))  # "more dark than oak": a shade compared too
#: The readings of the words a comparative at the start of a line may follow ('m1: a bit lighter').
_BEFORE_A_COMPARATIVE = frozenset(("NAME", "COLON", "ADV", "ARTICLE"))


def _comparative_at(out: list[Tagged]) -> int | None:
    """Where a comparative (only a REFINE reading, as the tagger keeps it before 'than') stands at the
    start of the material, after a name and adverbs only; None when there is none."""
    for k, word in enumerate(out):
        if word.candidates and all(c.tag == "REFINE" for c in word.candidates):  # 'glänzender': also declined
            return k
        if not all(c.tag in _BEFORE_A_COMPARATIVE for c in word.candidates):
            return None
    return None


def _describes_a_finish(word: Tagged) -> bool:
    """Whether a word before a finish substance named alone describes it: every reading a describing
    word, or one among them ('cream enamel', 'satin glaze': 'cream' and 'satin' are also nouns)."""
    if word.unknown:
        return False
    tags = [c.tag for c in word.candidates]
    return any(tag in DESCRIBING for tag in tags) or all(tag in _BEFORE_A_COAT for tag in tags)


def _describes_a_coat(rest: list[Tagged]) -> bool:
    """Whether the first word after an object may start a coat named alone: a describing word or
    the coat itself ('floor varnish', 'car clear coat', 'floor satin varnish'), not a separator."""
    return bool(rest) and any(c.tag in DESCRIBING or c.tag in ("COAT", "PROP") for c in rest[0].candidates)


#: The readings of describing words a plating ('nickel plated', from 'nickel finish') may move before.
DESCRIBING = frozenset(("ADV", "ADJ", "COLOR", "SHADE"))


def takes_target(word: Tagged, lexicon: Lexicon) -> bool:
    """Whether the word is a comparative that needs a target ('less', 'more': refinements.toml
    target "any"; 'lighter' names its own)."""
    entries = [lexicon.entry("refinements", c.key) for c in word.candidates if c.tag == "REFINE"]
    return any(e is not None and e.get("target") == "any" for e in entries)


def material_named_first(out: list[Tagged], diags: list[Diagnostic], lexicon: Lexicon) -> None:
    """'walnut, dark, satin', 'walnut; satin': a listing that opens with a material noun and then,
    after a comma, names only describing words reads every word after the mark as describing the
    material named first, also one that may be a material itself ('satin' the fabric), with a note
    (only where the first noun is also a colour, 'walnut' may be the satin's colour, and a hard
    material a finish is said of: FINISHED_CLASSES; 'ivory, silk' stays ivory silk)."""
    first = out[0]
    if not of_tag(first, "NOUN") or not any(c.tag in DESCRIBING for c in first.candidates):
        return  # a noun that is no colour ('oak, satin') is read as the material already
    entry = lexicon.entry("nouns", of_tag(first, "NOUN")[0].key)
    if entry is None or entry.get("class") not in FINISHED_CLASSES:
        return  # 'ivory, silk', 'cream, silk': the colour of the silk
    if out[1].text not in (",", ";"):
        return
    rest = [t for t in out[2:] if not (of_tag(t, "COMMA") or of_tag(t, "AND"))]
    if not rest or any(t.unknown or not any(c.tag in DESCRIBING for c in t.candidates) for t in rest):
        return
    for k in range(2, len(out)):
        word = out[k]
        if of_tag(word, "NOUN") and any(c.tag == "ADJ" for c in word.candidates):  # 'satin': not 'silver' the colour
            describing = tuple(c for c in word.candidates if c.tag != "NOUN")
            out[k] = Tagged(word.text, word.span, describing, word.unknown, word.implied_by)
            note = f"read '{word.text}' as describing the {out[0].text} (the material named first)"
            diags.append(Diagnostic(word.span, Severity.NOTE, NOTE_CODE, note))


def _only_describing(words: list[Tagged], article: bool = True) -> bool:
    """Whether every word reads only as a describing word (or an article)."""
    allowed = (*DESCRIBING, "ARTICLE") if article else tuple(DESCRIBING)
    return all(t.candidates and all(c.tag in allowed for c in t.candidates) for t in words)


def _describing(word: Tagged) -> Tagged:
    """The word with its describing readings only ('Satin' before a coat: not the fabric)."""
    return Tagged(word.text, word.span, tuple(c for c in word.candidates if c.tag in DESCRIBING), word.unknown)


#: the marks a product listing sets a finish off by ('Walnut / Satin Lacquer', 'Oak - natural oil')
#: material classes a finish word is said of after a comma ('walnut, satin'), not the colour of a cloth
FINISHED_CLASSES = frozenset(("wood", "stone", "metal", "plastic"))
LISTING_MARKS = frozenset((",", "/", "-", "–", "—", ";"))


#: The readings of the word after a noun that says where the material is used ('guitar varnish').
_USED_ON = frozenset(("NOUN", "COAT", "OBJECT"))


#: The generic coat entry: 'a coat of varnish' names the layer of the coat after 'of'.
_LAYER = "coat"


def _layer_of(out: list[Tagged], diags: list[Diagnostic]) -> bool:
    """'a coat of varnish', 'a coat of satin lacquer': the generic coat word and 'of' before a line
    that ends in another coat go (the coat after 'of' is the layer), with a note; True when they did."""
    last = out[-1]
    if not any(c.tag == "COAT" and c.key != _LAYER for c in last.candidates):
        return False
    for k in range(len(out) - 2):
        if any(c.tag == "COAT" and c.key == _LAYER for c in out[k].candidates) and of_tag(out[k + 1], "OF"):
            said = " ".join(t.text for t in out[k:])
            note = f"read '{said}' as '{' '.join(t.text for t in out[k + 2 :])}' (a layer of it)"
            diags.append(Diagnostic(out[k].span.to(last.span), Severity.NOTE, NOTE_CODE, note))
            del out[k : k + 2]
            return True
    return False


def _plating_first(out: list[Tagged]) -> None:
    """'brushed nickel finish steel': the plating pair (noun + plated, the last three entries
    with the material) moves before the describing words ahead of it, where the grammar takes a
    noun that says what a word is made of ("nickel plated brushed steel"; the order of describing
    words does not change the numbers)."""
    if len(out) < 4 or not of_tag(out[-2], "ADJ") or not of_tag(out[-3], "NOUN") or of_tag(out[-3], "COLOR"):
        return
    start = len(out) - 3
    while start > 0 and any(c.tag in DESCRIBING for c in out[start - 1].candidates):
        start -= 1
    if start < len(out) - 3:
        out[start:] = [out[-3], out[-2], *out[start:-3], out[-1]]


def _ends_in_describing(out: list[Tagged]) -> bool:
    """Whether the words before the first 'with' (or the line's end) end in a describing word or a
    colour that is no noun."""
    end = next((k for k, t in enumerate(out) if of_tag(t, "WITH")), len(out))
    if end < 2:
        return False
    last = out[end - 1]  # 'Eiche geölt', 'Schiefer dunkelgrau' (a colour that is no noun)
    return bool(of_tag(last, "ADJ")) or (
        any(c.tag in ("COLOR", "SHADE") for c in last.candidates) and not of_tag(last, "NOUN")
    )


def _feature_with_finish_head(out: list[Tagged], diags: list[Diagnostic]) -> None:
    """'laminate with a wood grain effect', 'a speckle look': a feature, then a word of the finish
    feature ('effect', 'look', 'finish') that only names it as a look: the feature, the head read
    past with a note (a noun before the head is a look of that material: Joiner._look_of)."""
    for k in range(len(out) - 1, 0, -1):
        head, before = out[k], out[k - 1]
        if not _only_finish(head) or not any(c.tag == "FEATURE" and c.key != "finish" for c in before.candidates):
            continue
        if k + 1 < len(out) and not (of_tag(out[k + 1], "COMMA") or of_tag(out[k + 1], "AND")):
            continue
        note = f"read '{before.text} {head.text}' as '{before.text}'"
        diags.append(Diagnostic(before.span.to(head.span), Severity.NOTE, NOTE_CODE, note))
        del out[k]


def _only_finish(word: Tagged) -> bool:
    return bool(word.candidates) and all(c.tag == "FEATURE" and c.key == "finish" for c in word.candidates)


def _feature_colour_list(out: list[Tagged], diags: list[Diagnostic]) -> None:
    """'flecks of red and green', 'veins of gold, grey and white': a feature's graph draws one colour
    (its color_r/g/b), so the first colour after 'of' is the feature's and the others are left out,
    with a note that says so (an 'and' before anything but a colour stays the clause's joint)."""
    for k in range(2, len(out)):
        first_end = _colour_end(out, k) if of_tag(out[k - 1], "OF") and of_tag(out[k - 2], "FEATURE") else None
        if first_end is not None:
            end: int | None = first_end
            dropped_start = first_end
            while end is not None and end + 1 < len(out) and _is_joint(out[end]):
                after = _colour_end(out, end + 1)
                if after is None:
                    break
                end = after
            if end is not None and end > dropped_start:
                left = out[dropped_start:end]
                words = ", ".join(t.text for t in left if not _is_joint(t))
                first = " ".join(t.text for t in out[k:dropped_start])
                said = "".join(t.text if of_tag(t, "COMMA") else f" {t.text}" for t in left)
                note = (
                    f"read '{out[k - 2].text} of {first}{said}' as "
                    f"'{out[k - 2].text} of {first}': one colour is drawn for the {out[k - 2].text}; "
                    f"'{words}' left out"
                )
                diags.append(Diagnostic(left[0].span.to(left[-1].span), Severity.NOTE, NOTE_CODE, note))
                del out[dropped_start:end]
            return


#: The readings of the words a feature named before the material may take with it ('fine grain', 'gold vein').
FEATURE_WORDS = frozenset(("ADV", "COLOR", "SHADE"))
#: The readings of the material's own describing words a feature may stand before ('speckled white ceramic').
MATERIAL_WORDS = frozenset(("ADV", "COLOR", "SHADE", "ADJ"))


def _feature_first(out: list[Tagged], diags: list[Diagnostic], lexicon: Lexicon, with_text: str = "with") -> None:
    """'fine grain walnut', 'gold vein marble', 'speckled granite': a feature (with its degree or colour
    words) right before the material noun, before any 'with', is the feature clause ('walnut with fine
    grain'), put first among the clauses after the noun ('speckled granite with a polished finish' =
    'granite with speckles and with a polished finish'); a word that is also a describing word or a
    noun ('patina': patinated) keeps that reading."""
    n = next((k for k, t in enumerate(out) if of_tag(t, "WITH") or of_tag(t, "COMMA")), len(out)) - 1
    if n < 1 or not of_tag(out[n], "NOUN") or out[n].unknown or any(t.unknown for t in out[:n]):
        return
    f = n - 1  # the feature, maybe before the material's own describing words ('speckled white ceramic')
    while f > 0 and not of_tag(out[f], "FEATURE") and all(c.tag in MATERIAL_WORDS for c in out[f].candidates):
        f -= 1
    feature = out[f]
    if not of_tag(feature, "FEATURE") or any(c.tag in ("ADJ", "NOUN") for c in feature.candidates):
        return
    entry = lexicon.entry("features", of_tag(feature, "FEATURE")[0].key)
    tint = entry is not None and entry.get("colour") == "base" and not entry.get("coat")
    if entry is None or tint or not (entry.get("maps") or entry.get("adjective")):
        return  # a tint, a cast, a hint before a material is not a look the words draw (a glaze with a coat is)
    rest = out[n + 1 :]
    if rest and not of_tag(rest[0], "WITH"):
        return
    noun = out[n]
    start = f
    while start > 0 and any(c.tag in FEATURE_WORDS for c in out[start - 1].candidates):
        start -= 1
    if start > 0 and of_tag(out[start - 1], "REFINE"):
        return  # 'more grain oak': the comparative's target
    words, own = out[start : f + 1], out[f + 1 : n]
    said = " ".join(t.text for t in words)
    typed = (*own, noun) if noun.implied_by is None else own  # 'fine grain powder coating': no 'steel' typed
    named = " ".join(t.text for t in typed)
    as_clause = " ".join(_feature_noun(t, entry.key) if t is feature else t.text for t in words)
    note = f"read '{said} {named}' as '{named} {with_text} {as_clause}' (a feature named before the material)"
    diags.append(Diagnostic(words[0].span.to(noun.span), Severity.NOTE, NOTE_CODE, note))
    at, col = noun.span.end, noun.span.col + noun.span.end - noun.span.start  # the clause's 'with': at the noun's end
    said_span = words[0].span.to(words[-1].span)
    with_word = Tagged("with", Span(at, at, noun.span.line, col), _WITH, implied_by=said_span)
    joint = []
    if rest:  # 'and' before the clauses that follow: a span of its own (inside that 'with': no word starts there)
        w = rest[0].span
        joint = [Tagged("and", Span(w.start + 1, w.start + 1, w.line, w.col + 1), _AND, implied_by=said_span)]
    out[start:] = [*own, noun, with_word, *words, *joint, *rest]


def _feature_then_colour(out: list[Tagged], diags: list[Diagnostic], with_text: str = "with") -> None:
    """'granite, speckled grey', 'stoneware, speckled oatmeal': after the material and a comma, a
    feature said as a participle, then a colour to the line's end, is the material in that colour
    with the feature ('grey granite with speckles'), as 'speckled grey granite' reads; a note says
    so. Any other line is left as it is."""
    if len(out) < 4 or not of_tag(out[0], "NOUN") or out[0].unknown or not only_tag(out[1], "COMMA"):
        return
    feature = out[2]
    if not only_tag(feature, "FEATURE") or not feature.text.lower().endswith("ed"):
        return
    colour = out[3:]
    if _colour_end(colour, 0) != len(colour) or any(t.unknown for t in colour):
        return
    noun = out[0]
    said = f"{feature.text} {' '.join(t.text for t in colour)}"
    note = f"read '{noun.text}, {said}' as '{' '.join(t.text for t in colour)} {noun.text} {with_text} {feature.text}'"
    diags.append(Diagnostic(noun.span.to(colour[-1].span), Severity.NOTE, NOTE_CODE, note))
    at = colour[-1].span  # the 'with': empty, after the colour (the parser keys words by where they start)
    with_word = Tagged(
        "with", Span(at.end, at.end, at.line, at.col + at.end - at.start), _WITH, implied_by=feature.span
    )
    out[:] = [*colour, noun, with_word, feature]


def _feature_noun(word: Tagged, key: str) -> str:
    """How the note names a feature said as a participle: 'marbled', 'speckled' -> its own noun
    ('veins', 'speckles'); a noun form stays as written ('grain', 'gold vein')."""
    return key if word.text.lower().endswith("ed") else word.text


def _is_joint(word: Tagged) -> bool:
    return bool(of_tag(word, "AND") or of_tag(word, "COMMA"))


def _colour_end(out: list[Tagged], k: int) -> int | None:
    """The index after a colour (SHADE* COLOR) starting at k, or None."""
    while k < len(out) and of_tag(out[k], "SHADE") and not of_tag(out[k], "COLOR"):
        k += 1
    return k + 1 if k < len(out) and of_tag(out[k], "COLOR") else None


def _artifact_words() -> frozenset[str]:
    """stdlib/data/wordnet_artifacts.toml (scripts/gen_wordnet_artifacts.py): WordNet's artifact nouns."""
    import tomllib
    from importlib import resources

    path = resources.files("cnlmc.stdlib").joinpath("data").joinpath("wordnet_artifacts.toml")
    return frozenset(tomllib.loads(path.read_text("utf-8"))["words"])


def may_join(tagged: list[Tagged]) -> bool:
    """Whether a line has an object, two nouns side by side, or a head word ('finish', 'look':
    a COAT or FEATURE reading) before another word or after a noun (see Joiner.joined); or ends in
    an unknown word after a noun ("pewter tankard") or with no noun ("a red bike"), or, with no
    'with' or comma, in a describing word after a noun ("Eiche geölt")."""
    noun_before = noun_seen = noun_before_last = described_noun = with_seen = unknown_seen = shade_before = False
    feature_before = False  # 'a wood grain effect': a feature, then the finish head
    plain = True  # no 'with', no comma
    final = tagged[-1] if tagged else None
    for word in tagged:
        noun = head = describing = feature = False
        if word.unknown:
            unknown_seen = True
        for candidate in word.candidates:
            tag = candidate.tag
            if tag == "OBJECT":
                return True
            if tag == "NOUN":
                noun = True
            elif tag == "COAT" or tag == "FEATURE" or tag == "PROP":  # PROP: 'coloured' (colour + -ed)
                head = True
                feature = feature or tag == "FEATURE"
            elif tag == "ADJ":
                describing = True
            elif tag == "WITH" or tag == "COMMA":
                if tag == "WITH":
                    if described_noun and plain:  # "Marmor poliert mit grauen Adern"
                        return True
                    with_seen = True
                if tag == "WITH" or not described_noun:  # "Buche massiv, geölt": a comma in the run stays plain
                    plain = False
        if (noun and noun_before) or (head and (word is not final or noun_before or shade_before or feature_before)):
            return True  # shade_before: 'oak, dark colour' ends in its colour head
        feature_before = feature
        shade_before = any(c.tag in ("SHADE", "COLOR") for c in word.candidates)
        described_noun = describing and (noun_before or described_noun)
        noun_before_last, noun_before = noun_before, noun
        noun_seen = noun_seen or noun
    if final is None:
        return False
    if final.unknown:  # "pewter tankard"; "a red bike" (a described thing); "red phone case" (a thing of two words)
        return noun_before_last or not noun_seen or (len(tagged) > 1 and tagged[-2].unknown)
    final_tags = [c.tag for c in final.candidates]
    if "COAT" in final_tags and not with_seen:
        return True  # "satin varnish": a coat named as the whole material
    if unknown_seen:
        return True  # "bike paint": an unknown word may say where the material is used
    if not noun_seen and not with_seen and ("ADJ" in final_tags or "FEATURE" in final_tags):
        return True  # "blue glaze": perhaps a finish substance named as the whole material
    colour_last = ("COLOR" in final_tags or "SHADE" in final_tags) and "NOUN" not in final_tags  # "Schiefer dunkelgrau"
    return plain and noun_seen and ("ADJ" in final_tags or colour_last)


def _same_entry(before: Tagged, word: Tagged, nouns: tuple[Candidate, ...]) -> tuple[Candidate, ...]:
    """The noun readings two different words side by side share ('HPL laminate', 'inox stainless
    steel': two names of one material); () for a repeat ('gold gold') or none shared."""
    if before.text.lower() == word.text.lower():
        return ()
    keys = {c.key for c in of_tag(before, "NOUN")}
    return tuple(c for c in nouns if c.key in keys)


def _describing_only(words: list[Tagged]) -> bool:
    """Whether words after a noun only describe it, set off by commas or not ('white tiles, glossy')."""
    said = [w for w in words if not of_tag(w, "COMMA")]
    return (
        bool(said)
        and not any(w.unknown for w in said)
        and all(any(c.tag in DESCRIBING for c in w.candidates) and not of_tag(w, "NOUN") for w in said)
    )


def _more_things(out: list[Tagged], word: Tagged, said: list[Tagged]) -> bool:
    """Whether `word` is an object after 'and' after a material named by its object ('copper pots
    and pans', 'pots and pans', 'oak tables and chairs'; `said`: the words before it as tagged):
    another thing made of that material, not a second one."""
    if len(out) < 2 or not of_tag(word, "OBJECT") or others(word) or not of_tag(out[-1], "AND"):
        return False
    return bool(of_tag(out[-2], "NOUN")) and bool(of_tag(said[-2], "OBJECT"))


def _joined_span(first: Tagged, last: Tagged) -> Span:
    return Span(first.span.start, last.span.end, first.span.line, first.span.col)


def _main_words(words: list[Tagged]) -> list[Tagged]:
    """The words before the first 'with' or 'and': a noun in a clause ('a backsplash with white
    grout') names what the clause adds, an object after 'and' another thing ('pots and pans'), not
    the material of the phrase."""
    end = next((k for k, t in enumerate(words) if of_tag(t, "WITH") or of_tag(t, "AND")), len(words))
    return words[:end]


def _colour_describing(word: Tagged) -> bool:
    """A describing word that says a colour before 'colour' ('natural colour': teaching.toml
    [things] `colour_describing`); other adjectives before it ('rusty coloured') are not read so."""
    from .suggest import teaching

    return word.text.lower() in teaching()["things"]["colour_describing"]


def implied_comma(first: Tagged) -> Tagged:
    """A comma implied before `first`: on the space before it, a span of its own (the parser keys
    words by where they start)."""
    at = first.span.start - 1
    return Tagged(",", Span(at, at + 1, first.span.line, first.span.col - 1), _COMMA, implied_by=first.span)


def of_tag(word: Tagged, tag: str) -> tuple[Candidate, ...]:
    return tuple(c for c in word.candidates if c.tag == tag)


def others(word: Tagged) -> tuple[Candidate, ...]:
    """The readings of a word that are not objects."""
    return others_of(word.candidates)


def others_of(candidates: tuple[Candidate, ...]) -> tuple[Candidate, ...]:
    return tuple(c for c in candidates if c.tag != "OBJECT")


def _noun_next(tagged: list[Tagged], k: int) -> bool:
    """'eggshell wall paint': the object word before a material noun names that noun's object (the
    wall the paint is for), not the object made of the word before it."""
    after = tagged[k + 1] if k + 1 < len(tagged) else None
    return after is not None and not after.unknown and bool(of_tag(after, "NOUN")) and not of_tag(after, "OBJECT")


def _ends_noun(tagged: list[Tagged], k: int, out: list[Tagged]) -> bool:
    """Whether a head word at k ends the line after its noun ('brushed steel look': the noun holds
    it); after a comma the word before it describes ('brass, satin finish': the adjective)."""
    return k + 1 == len(tagged) and not (len(out) > 1 and of_tag(out[-2], "COMMA"))


def _a_place(words: list[Tagged]) -> bool:
    """Whether the words say only where the material is used ('in the hallway'), which
    cnlmc.politeness reads past."""
    from .politeness import is_place
    from .suggest import teaching

    return is_place([w.text.lower() for w in words if w.text[:1].isalnum()], teaching()["politeness"])


def _in_colour_length(rest: list[Tagged]) -> int:
    """How many words after the noun say its colour with 'in' ('in deep green', 'in a soft grey'):
    the 'with' word, an article, shades, adverbs and colours up to the end or the next 'with'; 0
    when the words after it are anything else."""
    if not rest or not of_tag(rest[0], "WITH"):
        return 0
    j = 1 + (len(rest) > 1 and bool(of_tag(rest[1], "ARTICLE")))
    start = j
    while j < len(rest) and any(of_tag(rest[j], tag) for tag in ("COLOR", "SHADE", "ADV")):
        j += 1
    ends = j == len(rest) or of_tag(rest[j], "WITH")
    return j if ends and j > start and any(of_tag(t, "COLOR") for t in rest[start:j]) else 0
