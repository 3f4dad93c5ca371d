"""The IR: a versioned, target-independent JSON form of the compiled materials (docs/ir.md)."""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Iterator, Mapping, Sequence
from functools import cached_property
from json.encoder import c_make_encoder, encode_basestring  # type: ignore[attr-defined]
from typing import Any

from .conventions import alpha_of
from .diagnostics import Diagnostic
from .flake_params import flake_params
from .formulas import ROUNDING, round6, round6_list, rounded
from .lexicon import Entry
from .params import COAT_PARAMS, Params, params_by_model
from .sheen_colour import sheen_params
from .state import MaterialState, WordLists, same_texts, words_key
from .subsurface import subsurface_ir

JSONDict = dict[str, Any]

IR_VERSION = 1

PARAMS_BY_MODEL = params_by_model()  # base model -> the parameters it always has, from the table


def material_ir(state: MaterialState, convention: str, rounded_optics: dict[tuple[str, str], list[float]]) -> JSONDict:
    """One material's IR; `rounded_optics` (the lexicon's, see LexiconCaches) keeps its nouns' lists rounded."""
    model = state.model
    assert model is not None, "select_model runs before the IR is made"
    rounded_lists: dict[str, list[float]] = {}
    return {
        "name": state.name,
        **({"label": state.label} if state.label else {}),
        "phrase": state.phrase,
        "variant": state.variant,
        "model": model,
        "params": _params(state, model, convention, rounded_optics, rounded_lists),
        "maps": rounded(state.maps) if state.maps else {},
        "provenance": _provenance(state, rounded_lists),
    }


def _params(
    state: MaterialState,
    model: JSONDict,
    convention: str,
    rounded_optics: dict[tuple[str, str], list[float]],
    rounded_lists: dict[str, list[float]],
) -> JSONDict:
    """The parameters the model uses, rounded; `rounded_lists` gets each list parameter rounded here
    (param -> its rounded list), for the provenance step that set it (_provenance)."""
    p, base, noun = state.params, model["base"], state.noun
    noun_data = noun.data if noun is not None else {}
    out: JSONDict = {}
    for k in PARAMS_BY_MODEL[base]:
        if k in p:
            value = p[k]
            kind = type(value)
            if kind is float:  # most values: round6, its common case written out (as round6_list has it)
                y = value * 1e6
                if -1e12 < y < 1e12:
                    n = (y + ROUNDING) - ROUNDING
                    if -0.499 < y - n < 0.499:
                        out[k] = n / 1e6
                        continue
                out[k] = round6(value)
            elif kind is not list:
                out[k] = rounded(value)
            elif noun is not None and noun_data.get(k) is value:  # straight from the lexicon: rounded once
                found = rounded_optics.get((noun.key, k))  # _noun_list's common case, without its call
                out[k] = list(found) if found is not None else _noun_list(rounded_optics, noun, k)
            else:
                out[k] = rounded_lists[k] = round6_list(value)
    if model["diffuse"] == "oren_nayar":
        out["diffuse_roughness"] = rounded(p.get("diffuse_roughness", Params.diffuse_roughness))
    if base != "diffuse":
        aniso = p.get("anisotropy", Params.anisotropy) if model["anisotropic"] else 0.0
        out["alpha"] = round6_list(alpha_of(p["roughness"], aniso, convention))
        out["alpha_convention"] = convention
    if model["anisotropic"]:
        out["anisotropy"] = rounded(p["anisotropy"])
        out["anisotropy_rotation"] = rounded(p.get("anisotropy_rotation", Params.anisotropy_rotation))
    out["coat"] = _coat(state.coat, convention) if model["coat"] else None
    if p.get("sheen_color") is not None:  # each of the three adds nothing without its own parameters
        out.update(sheen_params(p))
    if p.get("subsurface") is not None:
        out.update(subsurface_ir(p))
    if p.get("flake_color") is not None:
        out.update(flake_params(p))
    return out


def _noun_list(rounded_optics: dict[tuple[str, str], list[float]], noun: Entry, param: str) -> list[float]:
    """round6_list of a noun's list value (a metal's optics), made once per lexicon."""
    found = rounded_optics.get((noun.key, param))
    if found is None:
        found = rounded_optics[noun.key, param] = round6_list(noun.data[param])
    return list(found)  # a copy: whoever reads the IR may change it


COAT_NAMES = tuple(s.name for s in COAT_PARAMS)  # the coat's IR fields, in the table's order


def _coat(coat: JSONDict | None, convention: str) -> JSONDict:
    """The coat's table entries, rounded; its alpha from its roughness in the material's convention."""
    assert coat is not None, "a model with a coat has the coat's values"
    alpha = alpha_of(coat["roughness"], 0.0, convention)
    out: JSONDict = {}
    for name in COAT_NAMES:  # rounded() of the entries as they are read: no dict made to be rounded again
        value = alpha if name == "alpha" else coat[name]
        out[name] = round6(value) if type(value) is float else rounded(value)
    return out


def _provenance(state: MaterialState, rounded_lists: dict[str, list[float]]) -> dict[str, list[JSONDict]]:
    """param -> its steps in JSON form; steps naming the same words share their word lists. A step
    whose value is its parameter's own list (the last colour step of the base colour) takes a copy
    of what _params rounded (`rounded_lists`) instead of rounding the list again: the same object
    rounds to the same list."""
    shared: dict[int | tuple[int, ...], WordLists] = {}
    out: dict[str, list[JSONDict]] = {}
    params = state.params
    for param, steps in state.provenance.items():
        made: list[JSONDict] = []
        out[param] = made
        for step in steps:  # state.step_json, written out: a material has a dozen steps
            words = step.words
            if len(words) == 1:  # most steps: one word (words_key and Span.as_list written out)
                word = words[0]
                span = word.span
                lists = shared.get(span.start)
                if lists is None or lists[0][0] != word.text:  # an implied word starts where its implier does
                    col = span.col
                    lists = shared[span.start] = ([word.text], [[span.line, col, col + (span.end - span.start)]])
            else:
                key = words_key(words)
                lists = shared.get(key)
                if lists is None or not same_texts(lists[0], words):
                    lists = shared[key] = ([w.text for w in words], [w.span.as_list() for w in words])
            value = step.value
            if step.source:  # lexicon values are exact
                made.append(
                    {"rule": step.rule, "words": lists[0], "spans": lists[1], "value": value, "source": step.source}
                )
            else:
                kind = type(value)
                if kind is float:
                    value = round6(value)
                elif kind is list:
                    done = rounded_lists.get(param) if value is params.get(param) else None
                    value = list(done) if done is not None else round6_list(value)
                elif kind is not str:  # a graph's or a coat's name is kept as it is
                    value = rounded(value)
                made.append({"rule": step.rule, "words": lists[0], "spans": lists[1], "value": value})
    return out


def document_head(source_name: str, lexicon_sources: Iterable[str]) -> JSONDict:
    """The document's fields before its materials (ir_version, source, lexicon, colour_space)."""
    return {
        "ir_version": IR_VERSION,
        "source": source_name,
        "lexicon": list(lexicon_sources),
        "colour_space": "linear Rec.709",
    }


def document_ir(
    materials: Sequence[Mapping[str, Any]],
    diagnostics: list[Diagnostic],
    source_name: str,
    lexicon_sources: Iterable[str],
) -> JSONDict:
    return {
        **document_head(source_name, lexicon_sources),
        "materials": materials,
        "diagnostics": [d.to_json() for d in diagnostics],
    }


def json_text(value: object) -> str:
    """JSON text of an IR value, on one line, as the IR file has it: DEL, the C1 controls and
    U+2028/U+2029 written as \\u escapes. The encoder leaves them raw (valid JSON), but a terminal
    reads C1 as commands (U+009B is CSI) and JavaScript reads U+2028 as a line end. They occur only
    inside strings, so escaping the text is exact."""
    if type(value) is str:
        return terminal_safe(encode_basestring(value))  # what the encoder does with a string
    return terminal_safe("".join(_ENCODE(value, 0)) if _ENCODE is not None else _ENCODER.encode(value))


def terminal_safe(text: str) -> str:
    """JSON text with DEL, the C1 controls and U+2028/U+2029 as \\u escapes (exact: they occur
    only inside JSON strings); the IR, the AST printed by --emit ast."""
    if text.isascii() and "\x7f" not in text:  # the common case: two C scans, no regular expression
        return text
    if _UNSAFE_ON_TERMINAL.search(text) is None:
        return text
    return _UNSAFE_ON_TERMINAL.sub(_escaped, text)


def _escaped(match: re.Match[str]) -> str:
    return f"\\u{ord(match.group()):04x}"


_UNSAFE_ON_TERMINAL = re.compile("[\x7f-\x9f\u2028\u2029]")


def _plain(value: object) -> Any:
    """Read-only records (a diagnostic is a mapping proxy) as plain JSON objects."""
    if isinstance(value, Mapping):
        return dict(value)
    raise TypeError(f"{type(value).__name__} is not JSON")


#: what json.dumps(value, ensure_ascii=False, default=_plain) makes anew on every call (it holds no
#: state), without its check for circular references: an IR is made of fresh containers (or read
#: from JSON) and has none, and the check costs a dictionary insert and delete per container,
#: a sixth of the encoding of a material with its provenance
_ENCODER = json.JSONEncoder(ensure_ascii=False, check_circular=False, default=_plain)

#: _ENCODER's C encoder, made once: `_ENCODER.encode(value)` makes this same object anew on every
#: call (JSONEncoder.iterencode with _one_shot) and joins what it returns; made once, a material's
#: text costs a few microseconds less, a small value (null, a variant) about half (#13 speed).
#: None where Python has no C accelerator (then _ENCODER.encode does it all).
_ENCODE = (
    c_make_encoder(None, _plain, encode_basestring, None, ": ", ", ", False, False, True)
    if c_make_encoder is not None
    else None
)


class EncodedMaterial(Mapping[str, Any]):
    """A material's IR already checked and written as its JSON text (json_text): what a worker
    process hands back (cnlmc.parallel). The IR writer copies `text` as it is; read as a mapping,
    it is the material's IR object (decoded on first use)."""

    def __init__(self, text: str) -> None:
        self.text = text

    @cached_property
    def _value(self) -> JSONDict:
        value: JSONDict = json.loads(self.text)
        return value

    def __getitem__(self, key: str) -> Any:
        return self._value[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._value)

    def __len__(self) -> int:
        return len(self._value)
