"""Reading word_formation*.toml: how the tagger reads a word the lexicon does not know (issue #14).

The file format is documented in stdlib/lexicon/word_formation.toml's header. `check_rules` checks
one file's table (every failure a LexiconError at FILE:LINE:COL) and returns it in a normal form
with every key present; `check_rule_names` checks, once all layers are merged, that the adverbs
the rules name exist. The rules are used by cnlmc.word_formation.
"""

from __future__ import annotations

from collections.abc import Mapping
from importlib import resources
from importlib.resources.abc import Traversable
from typing import Any

from .lexicon_schema import Checker, did_you_mean

__all__ = ["RULE_TAGS", "check_rule_names", "check_rules", "empty_rules", "wordnet_file"]

#: The tags a suffix rule may keep from its stem's reading (the grammar's open word classes).
RULE_TAGS = ("ADV", "SHADE", "COLOR", "PROP", "ADJ", "COAT", "NOUN", "FEATURE")

_LISTS = {
    "punctuation": ("trailing", "leading", "quotes", "number_marks", "bracketed_suffixes", "emoticons"),
    "negation": ("words", "prefixes", "softeners", "emphatic", "emphatic_before", "strict", "pointing"),
    "qualifiers": (
        "words",
        "sizes",
        "shapes",
        "ordinary",
        "purity",
        "liking",
        "cost",
        "imitation",
        "patterns",
        "fillers",
    ),
    "comparison": ("words", "current"),
    "properties": ("endings",),
}


def empty_rules() -> dict[str, Any]:
    """The normal form of a file with no rules at all."""
    return {
        "punctuation": {
            "trailing": [],
            "leading": [],
            "quotes": [],
            "number_marks": [],
            "bracketed_suffixes": [],
            "emoticons": [],
        },
        "negation": {
            "words": [],
            "prefixes": [],
            "softeners": [],
            "emphatic": [],
            "emphatic_before": [],
            "strict": [],
            "pointing": [],
            "soft_adverb": "",
            "not_too": {},
        },
        "qualifiers": {
            "words": [],
            "sizes": [],
            "shapes": [],
            "ordinary": [],
            "purity": [],
            "liking": [],
            "cost": [],
            "imitation": [],
            "patterns": [],
            "fillers": [],
        },
        "comparison": {"words": [], "current": []},
        "properties": {"endings": []},
        "compound_first": {
            "manners": [],
            "participles": [],
            "participle_endings": [],
            "synonyms": {},
            "degrees": {},
        },
        "prefix": [],
        "suffix": [],
        "compounds": {
            "join": False,
            "split": False,
            "linkers": [],
            "min_part": 3,
            "head_last": False,
            "heads": [],
            "postfix": False,
            "made_of": [],
        },
        "wordnet": {"file": "", "noun_roots": {}, "adjectives": []},
        "homophones": {"words": {}},
        "typos": {"file": "", "reach": [], "vowels": None, "off": False},
        "resemblance": {
            "forms": [],
            "endings": [],
            "colour_forms": [],
            "colour_heads": [],
            "colour_label_links": [],
            "colour_head_before_feature": [],
            "like_heads": [],
            "like_not_before": [],
            "finish_heads": [],
            "surface_classes": [],
            "surface": [],
            "finish_adjectives": {},
            "not_nearest": [],
        },
    }


def check_rules(c: Checker, data: dict[str, Any]) -> dict[str, Any]:
    """One word_formation file's table, checked, in the normal form of `empty_rules`."""
    rules = empty_rules()
    c.known_keys(data, tuple(rules), (), "section")
    for section, names in _LISTS.items():
        table = c.table(data.get(section, {}), (section,))
        allowed = (*names, "soft_adverb", "not_too") if section == "negation" else names
        c.known_keys(table, allowed, (section,))
        for name in names:
            rules[section][name] = _words(c, table.get(name, []), (section, name))
        if section == "negation":
            rules[section]["soft_adverb"] = c.string(table.get("soft_adverb", ""), (section, "soft_adverb"))
            pairs = c.table(table.get("not_too", {}), (section, "not_too"))
            rules[section]["not_too"] = {
                k.lower(): c.string(v, (section, "not_too", k), blank=False).lower() for k, v in pairs.items()
            }
    rules["prefix"] = [_prefix(c, raw, i) for i, raw in enumerate(c.array(data.get("prefix", []), ("prefix",)))]
    rules["suffix"] = [_suffix(c, raw, i) for i, raw in enumerate(c.array(data.get("suffix", []), ("suffix",)))]
    rules["compounds"] = _compounds(c, data.get("compounds", {}))
    rules["compound_first"] = _compound_first(c, data.get("compound_first", {}))
    rules["wordnet"] = _wordnet(c, data.get("wordnet", {}))
    rules["homophones"] = _homophones(c, data.get("homophones", {}))
    rules["typos"] = _typos(c, data.get("typos", {}))
    rules["resemblance"] = _resemblance(c, data.get("resemblance", {}))
    return rules


def _words(c: Checker, value: object, path: tuple[str | int, ...], blank: bool = False) -> list[str]:
    return [c.string(w, (*path, i), blank=blank).lower() for i, w in enumerate(c.array(value, path, "a list of words"))]


def _prefix(c: Checker, raw: object, i: int) -> dict[str, Any]:
    table = c.table(raw, ("prefix", i))
    c.known_keys(table, ("forms", "adverb", "endings", "alone", "doc"), ("prefix", i))
    return {
        "forms": _words(c, c.required(table, "forms", ("prefix", i)), ("prefix", i, "forms")),
        "endings": _words(c, table.get("endings", [""]), ("prefix", i, "endings"), blank=True),
        "adverb": c.string(c.required(table, "adverb", ("prefix", i)), ("prefix", i, "adverb"), blank=False),
        "alone": c.string(table.get("alone", ""), ("prefix", i, "alone"), blank=True),
        "doc": c.string(c.required(table, "doc", ("prefix", i)), ("prefix", i, "doc"), blank=False),
    }


def _suffix(c: Checker, raw: object, i: int) -> dict[str, Any]:
    path = ("suffix", i)
    table = c.table(raw, path)
    c.known_keys(table, ("forms", "endings", "reads_as", "look", "adverb", "refine", "exact", "doc"), path)
    look, exact = table.get("look", False), table.get("exact", False)
    for key, value in (("look", look), ("exact", exact)):
        if not isinstance(value, bool):
            c.fail((*path, key), f"expected true or false, got {value!r:.40}")
    reads_as = _words(c, c.required(table, "reads_as", path), (*path, "reads_as"))
    for k, tag in enumerate(reads_as):
        c.choice(tag.upper(), RULE_TAGS, (*path, "reads_as", k), "tag")
    return {
        "forms": _words(c, c.required(table, "forms", path), (*path, "forms")),
        "endings": _words(c, table.get("endings", [""]), (*path, "endings"), blank=True),
        "reads_as": [tag.upper() for tag in reads_as],
        "look": look,
        "exact": exact,
        "adverb": c.string(table.get("adverb", ""), (*path, "adverb")),
        "refine": c.string(table.get("refine", ""), (*path, "refine")),
        "doc": c.string(c.required(table, "doc", path), (*path, "doc"), blank=False),
    }


def _compounds(c: Checker, raw: object) -> dict[str, Any]:
    table = c.table(raw, ("compounds",))
    out: dict[str, Any] = dict(empty_rules()["compounds"])
    c.known_keys(table, tuple(out), ("compounds",))
    for flag in ("join", "split", "head_last", "postfix"):
        value = table.get(flag, out[flag])
        if not isinstance(value, bool):
            c.fail(("compounds", flag), f"expected true or false, got {value!r:.40}")
        out[flag] = value
    out["linkers"] = _words(c, table.get("linkers", []), ("compounds", "linkers"))
    out["heads"] = _words(c, table.get("heads", []), ("compounds", "heads"))
    out["made_of"] = _words(c, table.get("made_of", []), ("compounds", "made_of"))
    out["min_part"] = int(c.number(table.get("min_part", out["min_part"]), ("compounds", "min_part"), 1, 20))
    return out


def _homophones(c: Checker, raw: object) -> dict[str, Any]:
    """[homophones]: a word a spell-checker leaves that sounds like a lexicon word ('steal': steel)."""
    path: tuple[str | int, ...] = ("homophones",)
    table = c.table(raw, path)
    c.known_keys(table, ("words",), path)
    pairs = c.table(table.get("words", {}), (*path, "words"))
    return {"words": {k.lower(): c.string(v, (*path, "words", k), blank=False).lower() for k, v in pairs.items()}}


def _typos(c: Checker, raw: object) -> dict[str, Any]:
    """[typos]: file (the real words never read as a slip, in stdlib/data), reach (a list of
    {letters, edits}: a word of at least `letters` letters may be `edits` slips from the lexicon
    word it is read as), vowels ({letters, edits}: a word of at least `letters` letters spelt with
    up to `edits` vowels changed), off (true: this layer's language reads no slips; cnlmc.typos)."""
    path: tuple[str | int, ...] = ("typos",)
    table = c.table(raw, path)
    c.known_keys(table, ("file", "reach", "vowels", "off"), path)
    name = c.string(table.get("file", ""), (*path, "file"))
    if name and not wordnet_file(name).is_file():
        c.fail((*path, "file"), f"no file '{name}' in stdlib/data (scripts/gen_real_words.py writes one)")
    reach = []
    for i, step in enumerate(c.array(table.get("reach", []), (*path, "reach"))):
        step = c.table(step, (*path, "reach", i))
        c.known_keys(step, ("letters", "edits"), (*path, "reach", i))
        reach.append({key: _count(c, step.get(key), (*path, "reach", i, key)) for key in ("letters", "edits")})
    vowels = None
    if "vowels" in table:
        step = c.table(table["vowels"], (*path, "vowels"))
        c.known_keys(step, ("letters", "edits"), (*path, "vowels"))
        vowels = {key: _count(c, step.get(key), (*path, "vowels", key)) for key in ("letters", "edits")}
    off = table.get("off", False)
    if not isinstance(off, bool):
        c.fail((*path, "off"), "must be true or false")
    return {"file": name, "reach": reach, "vowels": vowels, "off": off}


def _count(c: Checker, value: object, path: tuple[str | int, ...]) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        c.fail(path, "must be a whole number, 0 or more")
    return value


def _compound_first(c: Checker, raw: object) -> dict[str, Any]:
    """[compound_first]: the first part of a compound participle (hand-forged, close-grained)."""
    path: tuple[str | int, ...] = ("compound_first",)
    table = c.table(raw, path)
    out: dict[str, Any] = dict(empty_rules()["compound_first"])
    c.known_keys(table, tuple(out), path)
    for name in ("manners", "participles", "participle_endings"):
        out[name] = _words(c, table.get(name, []), (*path, name))
    for name in ("synonyms", "degrees"):
        pairs = c.table(table.get(name, {}), (*path, name))
        out[name] = {k.lower(): c.string(v, (*path, name, k), blank=False).lower() for k, v in pairs.items()}
    return out


def _wordnet(c: Checker, raw: object) -> dict[str, Any]:
    """[wordnet] file (in stdlib/data), noun_roots (WordNet root -> noun), adjectives (whose synonyms count)."""
    table = c.table(raw, ("wordnet",))
    c.known_keys(table, ("file", "noun_roots", "adjectives"), ("wordnet",))
    name = c.string(table.get("file", ""), ("wordnet", "file"))
    if name and not wordnet_file(name).is_file():
        c.fail(("wordnet", "file"), f"no file '{name}' in stdlib/data (scripts/gen_wordnet_aliases.py writes one)")
    roots = c.table(table.get("noun_roots", {}), ("wordnet", "noun_roots"))
    return {
        "file": name,
        "noun_roots": {k: c.string(v, ("wordnet", "noun_roots", k), blank=False) for k, v in roots.items()},
        "adjectives": _words(c, table.get("adjectives", []), ("wordnet", "adjectives")),
    }


#: the [resemblance] keys that are lists of words (the layers' lists are joined: cnlmc.word_formation)
RESEMBLANCE_WORD_LISTS = (
    "forms",
    "endings",
    "colour_forms",
    "colour_heads",
    "colour_label_links",
    "colour_head_before_feature",
    "like_heads",
    "like_not_before",
    "finish_heads",
    "surface_classes",
    "not_nearest",
)


def _resemblance(c: Checker, raw: object) -> dict[str, Any]:
    """[resemblance]: what "like X" means for a noun X, by its class (cnlmc.resemblance)."""
    path: tuple[str | int, ...] = ("resemblance",)
    table = c.table(raw, path)
    out: dict[str, Any] = dict(empty_rules()["resemblance"])
    c.known_keys(table, tuple(out), path)
    for name in RESEMBLANCE_WORD_LISTS:
        blank = name == "endings"  # an ending may be '' (the word itself)
        out[name] = _words(c, table.get(name, []), (*path, name), blank=blank)
    ladder = []
    for i, step in enumerate(c.array(table.get("surface", []), (*path, "surface"), "a list of [roughness, adjective]")):
        pair = c.array(step, (*path, "surface", i), "[roughness, adjective]")
        if len(pair) != 2:
            c.fail((*path, "surface", i), 'expected [roughness, adjective], e.g. [0.5, "satin"]')
        ladder.append(
            (c.number(pair[0], (*path, "surface", i, 0), 0.0, 1.0), c.string(pair[1], (*path, "surface", i, 1)))
        )
    if [r for r, _a in ladder] != sorted(r for r, _a in ladder):
        c.fail((*path, "surface"), "the steps must be in rising roughness")
    out["surface"] = ladder
    adjectives = c.table(table.get("finish_adjectives", {}), (*path, "finish_adjectives"))
    out["finish_adjectives"] = {
        k: c.string(v, (*path, "finish_adjectives", k), blank=False) for k, v in adjectives.items()
    }
    return out


def wordnet_file(name: str) -> Traversable:
    """A WordNet alias file of the package's stdlib/data folder."""
    return resources.files("cnlmc.stdlib").joinpath("data").joinpath(name)


def check_rule_names(c: Checker, rules: Mapping[str, Any], raw: Mapping[str, Mapping[str, Any]]) -> None:
    """Every adverb, noun and adjective a rule names must be in the merged lexicon (raw entries by category)."""
    adverbs = raw["adverbs"]
    for root, noun in rules["wordnet"]["noun_roots"].items():
        if noun not in raw["nouns"]:
            c.fail(("wordnet", "noun_roots", root), f"no noun named '{noun}'{did_you_mean(noun, raw['nouns'])}")
    adjective_forms = {f.lower() for k, e in raw["adjectives"].items() for f in (k, *e.data.get("aliases", ()))}
    resemblance = rules["resemblance"]
    named_adjectives: list[tuple[tuple[str | int, ...], str]] = [
        (("resemblance", "surface", i, 1), a) for i, (_r, a) in enumerate(resemblance["surface"])
    ]
    named_adjectives += [
        (("resemblance", "finish_adjectives", k), a) for k, a in resemblance["finish_adjectives"].items()
    ]
    for key, finish in rules["negation"]["not_too"].items():
        named_adjectives += [(("negation", "not_too"), key), (("negation", "not_too", key), finish)]
    for apath, adjective in named_adjectives:
        if adjective not in raw["adjectives"]:
            c.fail(apath, f"no adjective named '{adjective}'{did_you_mean(adjective, raw['adjectives'])}")
    for i, word in enumerate(rules["wordnet"]["adjectives"]):
        if word not in adjective_forms:
            c.fail(("wordnet", "adjectives", i), f"no adjective named '{word}'")
    named: list[tuple[tuple[str | int, ...], str]] = [
        (("prefix", i, "adverb"), p["adverb"]) for i, p in enumerate(rules["prefix"])
    ]
    named += [(("suffix", i, "adverb"), s["adverb"]) for i, s in enumerate(rules["suffix"]) if s["adverb"]]
    named += [(("compound_first", "degrees", k), a) for k, a in rules["compound_first"]["degrees"].items()]
    if rules["negation"]["soft_adverb"]:
        named.append((("negation", "soft_adverb"), rules["negation"]["soft_adverb"]))
    for path, name in named:
        if name not in adverbs:
            c.fail(path, f"no adverb named '{name}'{did_you_mean(name, adverbs)}")
    for i, p in enumerate(rules["prefix"]):
        if p["alone"] and p["alone"] not in raw["shades"]:
            c.fail(("prefix", i, "alone"), f"no shade named '{p['alone']}'{did_you_mean(p['alone'], raw['shades'])}")
