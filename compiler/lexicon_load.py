"""Reading lexicon folders into a Lexicon: bounded reads, TOML errors with positions, schema checks.

A user's folder is untrusted: every .toml file in it is read through `cnlmc.inputs.read_bytes`
(a FIFO, a device such as a link to /dev/zero, a folder named x.toml or a link loop is refused,
naming the file), at most `max_bytes` bytes in all per folder (CNLMC_LEXICON_MAX_BYTES, 16 MiB
by default) and `MAX_FILES` files; names starting with '.' (editor temporaries) are skipped.
Every entry is checked against stdlib/schema.toml (cnlmc.lexicon_schema), then every name one
entry gives another (cnlmc.lexicon_refs); each error is a LexiconError naming FILE:LINE:COL.
"""

from __future__ import annotations

import os
import re
import tomllib
from collections.abc import Iterable, Mapping
from functools import lru_cache
from importlib import resources
from importlib.resources.abc import Traversable
from pathlib import Path
from types import MappingProxyType
from typing import Any

from .errors import UsageError
from .inputs import DEFAULT_MAX_BYTES, InputTooLarge, decode_utf8, read_bytes
from .lexicon_model import CATEGORY_TAGS, SPECIAL_FILES, Entry, Lexicon, keyword_table
from .lexicon_refs import RawEntry, References
from .lexicon_schema import MAX_TEXT, Checker, LexiconError, check_entry, check_required, did_you_mean
from .lexicon_source import SourceText, dotted

Folder = Path | Traversable  # a lexicon folder or file: the user's, or inside the installed package
FILE_KINDS = (*CATEGORY_TAGS, *SPECIAL_FILES)
MAX_FILES = 256  # .toml files in one lexicon folder
MAX_BYTES_VARIABLE = "CNLMC_LEXICON_MAX_BYTES"
TOML_POSITION = re.compile(r"\s*\(at line (\d+), column (\d+)\)$")


def max_bytes() -> int:
    """The byte budget of one user lexicon folder (CNLMC_LEXICON_MAX_BYTES, else 16 MiB)."""
    text = os.environ.get(MAX_BYTES_VARIABLE, "")
    try:
        return max(1, int(text)) if text else DEFAULT_MAX_BYTES
    except ValueError:
        raise LexiconError(f"{MAX_BYTES_VARIABLE}={text!r}: expected a number of bytes") from None


def schema() -> dict[str, Any]:
    text = resources.files("cnlmc.stdlib").joinpath("schema.toml").read_text("utf-8")
    return tomllib.loads(text)


def category_of(stem: str) -> str | None:
    for category in FILE_KINDS:
        if stem == category or stem.startswith(category + "_"):
            return category
    return None


# ---------------------------------------------------------------- reading one folder


class FolderReader:
    """Lists and reads one folder's .toml files within a byte budget (None: trusted package data)."""

    def __init__(self, folder: Folder, budget: int | None) -> None:
        self.folder = folder
        self.budget = budget

    def files(self) -> list[Folder]:
        try:
            found = [p for p in self.folder.iterdir() if p.name.endswith(".toml") and not p.name.startswith(".")]
        except OSError as exc:
            raise LexiconError(f"{self.folder}: cannot list the lexicon folder: {exc.strerror}") from None
        if len(found) > MAX_FILES:
            raise LexiconError(f"{self.folder}: {len(found)} .toml files; a lexicon folder holds at most {MAX_FILES}")
        return sorted(found, key=lambda p: p.name)

    def read(self, path: Folder) -> SourceText:
        name = str(path)
        if self.budget is None:
            return SourceText(name, path.read_text("utf-8"))
        try:
            data = read_bytes(name, limit=self.budget, what="lexicon file", option=f"{MAX_BYTES_VARIABLE}=")
        except InputTooLarge:
            raise LexiconError(
                f"{name}: the lexicon folder {self.folder} holds more than {self.budget} bytes of .toml files "
                f"(the limit); raise it with the environment variable {MAX_BYTES_VARIABLE}=N"
            ) from None
        except UsageError as exc:
            raise LexiconError(str(exc)) from None
        self.budget -= len(data)
        try:
            return SourceText(name, decode_utf8(data, name))
        except UsageError as exc:
            raise LexiconError(str(exc)) from None


def parse_toml(source: SourceText) -> dict[str, Any]:
    """The file's table, or a LexiconError at the line and column tomllib names."""
    try:
        return tomllib.loads(source.text)
    except tomllib.TOMLDecodeError as exc:
        raise LexiconError(_toml_message(source, str(exc))) from None
    except RecursionError:
        raise LexiconError(f"{source.name}:1:1: not valid TOML: arrays or tables nested too deeply") from None


def _toml_message(source: SourceText, message: str) -> str:
    duplicates = source.positions.duplicates
    if message.startswith(("Cannot overwrite", "Cannot declare")) and duplicates:
        path, offset = duplicates[0]
        line, column = source.line_col(offset)
        first, _ = source.locate(path)
        return f"{source.name}:{line}:{column}: not valid TOML: key '{dotted(path)}' is defined twice (first on line {first})"
    match = TOML_POSITION.search(message)
    if match is not None:
        return f"{source.name}:{match[1]}:{match[2]}: not valid TOML: {message[: match.start()]}"
    line, column = source.line_col(len(source.text))
    return f"{source.name}:{line}:{column}: not valid TOML: {TOML_POSITION.sub('', message)}"


# ---------------------------------------------------------------- layers


class Builder:
    """Accumulates layers, most specific first; a field already set is never replaced."""

    def __init__(self) -> None:
        self.schema = schema()
        self.raw: dict[str, dict[str, RawEntry]] = {c: {} for c in CATEGORY_TAGS}
        self.settings: dict[str, Any] = {}
        self.inflections: list[tuple[str, str]] = []
        self.keywords: dict[str, str] = {}
        self.word_formation: list[dict[str, Any]] = []  # each layer's rules, most specific first
        self.word_formation_checkers: list[Checker] = []  # the file each of those came from
        self.sources: list[str] = []

    def add_layer(self, folder: Folder, bundled: bool, strict: bool) -> None:
        """`bundled`: package data (read without a budget); `strict`: a new entry must be complete here."""
        self.sources.append(str(folder))
        reader = FolderReader(folder, None if bundled else max_bytes())
        for path in reader.files():
            self._add_file(path, reader, strict)

    def _add_file(self, path: Folder, reader: FolderReader, strict: bool) -> None:
        stem = path.name[:-5]
        category = category_of(stem)
        if category is None:
            close = did_you_mean(stem.split("_")[0], FILE_KINDS)
            raise LexiconError(
                f"{path}:1:1: unknown lexicon file{close}: its name must be one of {', '.join(FILE_KINDS)}, "
                f"or start with one of them and '_' (nouns_studio.toml)"
            )
        source = reader.read(path)
        data = parse_toml(source)
        checker = Checker(source)
        if category == "inflections":  # every layer's rules, the most specific layer's first
            self.inflections += _inflection_rules(checker, data)
        elif category == "keywords":  # a language's closed-class words (and, or, with, articles)
            self.keywords = {**_keywords(checker, data), **self.keywords}
        elif category == "word_formation":  # how unknown words are read (cnlmc.word_formation_rules)
            from .word_formation_rules import check_rules

            self.word_formation.append(check_rules(checker, data))
            self.word_formation_checkers.append(checker)
        elif category == "settings":
            check_entry(checker, data, self.schema["settings"]["fields"], (), partial=True, common=False)
            self.settings = {**data, **self.settings}
        else:
            self._add_entries(checker, category, data, strict)

    def _add_entries(self, c: Checker, category: str, data: dict[str, Any], strict: bool) -> None:
        fields = self.schema[category]["fields"]
        for key, entry in data.items():
            if not key.strip():
                c.fail((key,), "an entry needs a name: [name] with at least one word")
            if len(key) > MAX_TEXT:
                c.fail((key,), f"a name of {len(key)} characters; at most {MAX_TEXT} are allowed")
            known = key in self.raw[category]
            check_entry(c, entry, fields, (key,), partial=known or not strict)
            self._merge(category, key, entry, c.source)

    def _merge(self, category: str, key: str, entry: dict[str, Any], source: SourceText) -> None:
        current = self.raw[category].get(key)
        if current is None:
            self.raw[category][key] = RawEntry(dict(entry), source, dict.fromkeys(entry, source))
            return
        for name, value in entry.items():
            if name not in current.data:
                current.data[name] = value
                current.field_sources[name] = source
        aliases = set(current.data.get("aliases", [])) | set(entry.get("aliases", []))
        current.data["aliases"] = sorted(aliases)

    def add_colour_names(self) -> None:
        """The xkcd colour survey's names (stdlib/data/colour_names.toml) as the everyday colours,
        under every folder (an entry a folder has wins); see add_survey_colours."""
        path = colour_names_file()
        source = SourceText(str(path), path.read_text("utf-8"))
        add_survey_colours(self, tomllib.loads(source.text), source)

    def check(self) -> None:
        """Entries added only by a user layer must carry every required field; every name must exist."""
        for category, by_key in self.raw.items():
            fields = self.schema[category]["fields"]
            for key, entry in by_key.items():
                check_required(Checker(entry.source), entry.data, fields, (key,), by_key)
        References(self.raw).check()
        if self.word_formation:
            from .word_formation_rules import check_rule_names

            for checker, rules in zip(self.word_formation_checkers, self.word_formation, strict=True):
                check_rule_names(checker, rules, self.raw)

    def build(self) -> Lexicon:
        entries = {c: {k: _finish(c, k, e) for k, e in by.items()} for c, by in self.raw.items()}
        return Lexicon(entries, self.settings, self.inflections, self.sources, self.keywords, self.word_formation)


# ---------------------------------------------------------------- the xkcd colour survey

SURVEY = "xkcd colour survey (Munroe 2010, https://xkcd.com/color/rgb/, CC0 1.0)"


@lru_cache(maxsize=1)
def _survey_names() -> dict[str, str]:
    names = tomllib.loads(colour_names_file().read_text("utf-8"))
    return {name: str(row["hex"]) for name, row in names.items() if row.get("source") == "xkcd"}


def survey_hex(name: str) -> str | None:
    """The colour survey's hex code for a name ('rust': #a83c09), or None."""
    return _survey_names().get(name)


def colour_names_file() -> Traversable:
    return resources.files("cnlmc.stdlib").joinpath("data").joinpath("colour_names.toml")


def colour_rules_file() -> Traversable:
    """stdlib/data/colour_rules.toml: which survey words stay colours beside another category, the
    -ish shades, the colours that mix into compounds, shade directions and everyday aliases."""
    return resources.files("cnlmc.stdlib").joinpath("data").joinpath("colour_rules.toml")


def add_survey_colours(builder: Builder, names: dict[str, Any], source: SourceText) -> None:
    """Each survey name not already a colour: its hex, "gray" and "a b" (for "a/b") aliases, a doc
    citing the survey. A single word that another category has ("dark", "rust", "steel") stays
    that category's only, but for the rules' noun_colours and ish_colours (colour_rules_file). The survey's "dark X" / "light X" / "pale X" / "deep X" is kept only
    if it is darker / lighter than X in OKLab L, else it is X with the shade's OKLab operations.
    Hyphenated compounds of two mix_colours the survey lacks ("red-blue") are their OKLab midpoint
    (the tagger reads a hyphenated word the lexicon lacks as its spaced form: "blue-grey")."""
    from . import colour

    rules = colour_rules()
    colours = builder.raw["colours"]
    others = {f for c, by in builder.raw.items() if c != "colours" for k, e in by.items() for f in _forms(k, e)}
    others -= {*rules["noun_colours"], *rules["ish_colours"]}
    named = {f: k for k, e in colours.items() for f in _forms(k, e)}  # form -> the entry it names
    known = set(named)
    added: set[str] = set()
    for name, row in names.items():
        if row.get("source") != "xkcd":
            continue
        if "/" in name:  # "blue/green": '/' is not a word character; the spaced form, unless the survey has it
            name = name.replace("/", " ")
            if name in names:
                continue
        if name not in colours and ((" " not in name and name in others) or name in known):
            continue
        if name.split(" ", 1)[0] in rules["describing_first"] and name not in colours:
            continue  # "metallic blue": the describing word (flakes) and the colour, not a swatch
        variants = {name.replace("grey", "gray")}
        variants |= set(rules["extra_aliases"].get(name, ()))
        aliases = sorted(v for v in variants - {name} if v not in names and v not in known)
        hex_code = row["hex"]
        entry = {
            "hex": hex_code,
            "aliases": aliases,
            "doc": f"'{name}' ({hex_code}) in the {SURVEY}{'' if row is names.get(name) else ' (written with a slash there)'}.",
            "example": f"{name} plastic",
            "source": SURVEY,
        }
        builder._merge("colours", name, entry, source)
        added.add(name)
    for name in sorted(added):
        first, _, rest = name.partition(" ")
        direction = rules["shade_directions"].get(first)
        if direction is None or rest not in colours or first not in builder.raw["shades"]:
            continue
        if colours[name].field_sources.get("hex") is not source:  # a folder's own value stays
            continue
        base = colour.hex_to_linear(colours[rest].data["hex"])
        own = colours[name].data
        drifted = _hue_drifted(own["hex"], colours[rest].data["hex"], rules)
        if (
            colour.linear_to_oklab(colour.hex_to_linear(own["hex"]))[0] - colour.linear_to_oklab(base)[0]
        ) * direction > 0 and not drifted:
            continue
        shifted = colour.linear_to_hex(colour.apply_ops(base, builder.raw["shades"][first].data["ops"]))
        why = "drifts from its hue" if drifted else f"is not {'darker' if direction < 0 else 'lighter'} than it"
        own["doc"] = (
            f"'{name}': {rest} with the shade '{first}' ({shifted}); the {SURVEY} has {own['hex']}, which {why}."
        )
        own["hex"] = shifted
    for name in sorted(added):  # "very dark brown" (#1d0200, a red-black): 'very' on dark brown
        first, _, rest = name.partition(" ")
        if (
            first in rules["drifted_degrees"]
            and rest in colours
            and _hue_drifted(colours[name].data["hex"], colours[rest].data["hex"], rules)
        ):
            del colours[name]
    for a in rules["mix_colours"]:
        for b in rules["mix_colours"]:
            name, spaced = f"{a}-{b}", f"{a} {b}"
            if (
                a == b
                or spaced in colours
                or named.get(spaced.replace("grey", "gray"), name) != name  # another entry's name (a layer's own
                # alias of this compound, such as German's 'beige gold' of 'beige-gold', is not)
                or a not in colours
                or b not in colours
            ):
                continue
            mixed = colour.linear_to_hex(
                colour.mix_oklab(
                    colour.hex_to_linear(colours[a].data["hex"]), colour.hex_to_linear(colours[b].data["hex"])
                )
            )
            gray = name.replace("grey", "gray")
            entry = {
                "hex": mixed,
                "aliases": [gray] if gray != name else [],
                "doc": f"'{name}': the OKLab midpoint of {a} and {b} ({mixed}); the survey has no '{spaced}'.",
                "example": f"{a}-{b} plastic",
                "source": f"computed from the {SURVEY}",
            }
            builder._merge("colours", name, entry, source)


def _hue_drifted(hex_code: str, base_hex: str, rules: Mapping[str, Any]) -> bool:
    """Whether a survey compound's hue lies further from its colour's than a shade moves it
    (colour_rules.toml shade_hue_degrees); never for colours too grey to have a hue."""
    from . import colour

    gap = colour.hue_gap(
        colour.hex_to_linear(hex_code), colour.hex_to_linear(base_hex), float(rules["shade_hue_min_chroma"])
    )
    return gap is not None and gap > float(rules["shade_hue_degrees"])


@lru_cache(maxsize=1)
def colour_rules() -> Mapping[str, Any]:
    """stdlib/data/colour_rules.toml, read once per process (immutable package data)."""
    return MappingProxyType(tomllib.loads(colour_rules_file().read_text(encoding="utf-8")))


def _forms(key: str, entry: RawEntry) -> list[str]:
    return [key.lower(), *(a.lower() for a in entry.data.get("aliases", []))]


def _finish(category: str, key: str, raw: RawEntry) -> Entry:
    data = raw.data
    if category == "colours" and "rgb" not in data:
        from .colour import hex_to_linear

        data = {**data, "rgb": hex_to_linear(data["hex"])}
    return Entry(category, key, data, raw.source.name)


def _inflection_rules(c: Checker, data: dict[str, Any]) -> list[tuple[str, str]]:
    """rules = [["ies", "y"], ...]: a suffix (not empty) and what replaces it."""
    c.known_keys(data, ("rules",), ())
    rules = []
    for i, rule in enumerate(c.array(data.get("rules", []), ("rules",), "a list of [suffix, replacement] pairs")):
        if not isinstance(rule, list) or len(rule) != 2:
            c.fail(("rules", i), f'expected a pair [suffix, replacement], e.g. ["ies", "y"], got {rule!r:.60}')
        suffix = c.string(rule[0], ("rules", i, 0), blank=False)
        rules.append((suffix, c.string(rule[1], ("rules", i, 1))))
    return rules


def _keywords(c: Checker, data: dict[str, Any]) -> dict[str, str]:
    """[terminals] AND = ["und"], ...: a language's closed-class words by grammar terminal."""
    terminals = sorted(set(keyword_table().values()))
    c.known_keys(data, ("terminals",), ())
    table = c.table(c.required(data, "terminals", ()), ("terminals",), f"a table of {', '.join(terminals)}")
    c.known_keys(table, terminals, ("terminals",), "grammar terminal")
    for terminal, words in table.items():
        for i, word in enumerate(c.array(words, ("terminals", terminal), "a list of words")):
            c.string(word, ("terminals", terminal, i), blank=False)
    return keyword_table(data)


# ---------------------------------------------------------------- folders and overlays


def stdlib_folder() -> Traversable:
    return resources.files("cnlmc.stdlib").joinpath("lexicon")


def available_overlays() -> list[str]:
    root = resources.files("cnlmc.stdlib").joinpath("overlays")
    return sorted(p.name for p in root.iterdir() if p.is_dir())


def overlay_folder(name: str) -> Traversable:
    if name not in available_overlays():
        raise LexiconError(_not_an_overlay(name))
    return resources.files("cnlmc.stdlib").joinpath("overlays").joinpath(name)


def _not_an_overlay(name: str) -> str:
    """Why `name` is neither a lexicon folder nor an overlay: a file, a broken link, or a typo."""
    available = ", ".join(available_overlays())
    if os.path.lexists(name) or os.sep in name or name.endswith(".toml"):
        what = "does not exist" if not os.path.lexists(name) else _what_it_is(Path(name))
        return (
            f"{name}: not a lexicon folder ({what}); --lexicon takes a folder of .toml files "
            f"(nouns_studio.toml, ...) or an overlay name ({available})"
        )
    close = did_you_mean(name, available_overlays())  # " (did you mean 'x'?)"
    return f"no lexicon overlay named '{name}' (available: {available}){'; ' + close[2:-1] if close else ''}"


def _what_it_is(path: Path) -> str:
    try:
        path.stat()
    except OSError as exc:
        return f"cannot be followed: {exc.strerror}"
    return "it is a file" if path.is_file() else "it is not a folder"


def overlay_names(overlay: str | tuple[str, ...] | None) -> tuple[str, ...]:
    names = (overlay,) if isinstance(overlay, str) else tuple(overlay or ())
    return tuple(n for n in names if n and n != "stdlib")


def user_folder(folder: str | Path) -> Path:
    path = Path(folder)
    try:
        if path.is_dir():
            return path
    except OSError:
        pass
    raise LexiconError(
        _not_an_overlay(str(folder)) if os.path.lexists(path) else f"{path}: lexicon path is not a folder"
    )


def load(user_paths: Iterable[str | Path], overlay: str | tuple[str, ...] | None) -> Lexicon:
    """User folders first, then the overlays in order, then the bundled stdlib."""
    builder = Builder()
    for folder in user_paths:
        builder.add_layer(user_folder(folder), bundled=False, strict=False)
    for name in overlay_names(overlay):
        builder.add_layer(overlay_folder(name), bundled=True, strict=False)
    builder.add_layer(stdlib_folder(), bundled=True, strict=True)
    builder.add_colour_names()
    builder.check()
    return builder.build()
