"""The typed IR: frozen records the backends receive, validated once by `from_ir` (docs/ir.md).

    doc = Document.from_ir(ir_dict)        # raises ValueError naming the path of a bad value
    for m in doc.materials: m.params.ior   # absent parameters hold the table's default
    "ior" in m.params.present              # whether the IR JSON has it
    doc.to_ir() == ir_dict                 # exactly the JSON form it came from

`Material.from_ir` also takes the short hand-written form the numpy reference's tests use
(`model` and `params` only); the other material fields then default to empty values.
Change a value with `dataclasses.replace`; `Material.key` is a content hash for caches.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import sys
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from functools import cached_property
from types import MappingProxyType
from typing import Any

from .conventions import alpha_of
from .params import (
    BASES,
    COAT_PARAMS,
    DIFFUSE_LOBES,
    DISTRIBUTIONS,
    PARAM_NAMES,
    PARAMS,
    RGB,
    SUBSURFACE_MODELS,
    SUBSURFACE_PARAMS,
    Coat,
    Params,
    ParamSpec,
    Subsurface,
)

__all__ = ["RGB", "Coat", "Document", "MapRef", "Material", "Model", "Params", "Provenance", "Subsurface", "Variant"]

JSON = Any
MAP_ROLES = ("base_color", "normal", "roughness", "metallic", "mask")
COLOUR_SPACE = "linear Rec.709"


# -- validation helpers: each names the path of the value it rejects


def _fail(path: str, expected: str, value: object) -> ValueError:
    return ValueError(f"{path}: expected {expected}, got {value!r}")


_BIGGEST = sys.float_info.max


def _is_number(value: object) -> bool:
    """A finite int or float (the IR has no NaN or infinity: docs/ir.md, "Finite numbers")."""
    return isinstance(value, (int, float)) and not isinstance(value, bool) and -_BIGGEST <= value <= _BIGGEST


def _fmt(x: float) -> str:
    return f"{x:g}"


def _number(value: object, path: str, bounds: tuple[float, float] | None = None) -> float:
    if bounds is None:
        if not _is_number(value):
            raise _fail(path, "a number", value)
        return value  # type: ignore[return-value]
    low, high = bounds
    if not (_is_number(value) and low <= value <= high):  # type: ignore[operator]
        raise _fail(path, f"a number in [{_fmt(low)}, {_fmt(high)}]", value)
    return value  # type: ignore[return-value]


def _numbers(value: object, n: int, path: str, bounds: tuple[float, float] | None) -> tuple[float, ...]:
    if not isinstance(value, (list, tuple)) or len(value) != n:
        raise _numbers_fail(value, n, path, bounds)
    low, high = bounds if bounds is not None else (-_BIGGEST, _BIGGEST)
    for v in value:
        if not _is_number(v) or not low <= v <= high:
            raise _numbers_fail(value, n, path, bounds)
    return tuple(value)


def _numbers_fail(value: object, n: int, path: str, bounds: tuple[float, float] | None) -> ValueError:
    what = f"a list of {n} numbers" + (f" in [{_fmt(bounds[0])}, {_fmt(bounds[1])}]" if bounds else "")
    return _fail(path, what, value)


def _string(value: object, path: str) -> str:
    if not isinstance(value, str):
        raise _fail(path, "a string", value)
    return value


def _choice(value: object, choices: tuple[Any, ...], path: str) -> Any:
    if value not in choices:
        raise _fail(path, "one of " + ", ".join(json.dumps(c) for c in choices), value)
    return value


def _boolean(value: object, path: str) -> bool:
    if not isinstance(value, bool):
        raise _fail(path, "true or false", value)
    return value


def _object(value: object, path: str) -> Mapping[str, Any]:
    if type(value) is not dict and not isinstance(value, Mapping):  # a dict, the common case, without the ABC check
        raise _fail(path, "an object", value)
    return value


_LEAVES = (str, float, int, bool, type(None))


def freeze_json(value: JSON) -> JSON:
    """JSON -> read-only: objects become mapping proxies, arrays tuples (exact type tests first)."""
    kind = type(value)
    if kind in _LEAVES:
        return value
    if kind is dict or isinstance(value, Mapping):
        return MappingProxyType({k: freeze_json(v) for k, v in value.items()})
    if kind is list or kind is tuple:
        return tuple([freeze_json(v) for v in value])
    return value


def _thaw(value: JSON) -> JSON:
    """The inverse of freeze_json (or a copy of plain JSON): fresh dicts and lists the caller may change."""
    kind = type(value)
    if kind in _LEAVES:
        return value
    if kind is MappingProxyType or isinstance(value, Mapping):
        return {k: _thaw(v) for k, v in value.items()}
    if kind is tuple or kind is list:
        return [_thaw(v) for v in value]
    return value


# -- the records


@dataclass(frozen=True)
class Model:
    base: str
    distribution: str | None
    anisotropic: bool
    coat: bool
    diffuse: str | None
    subsurface: str | None = None  # "volume" | "thin"; absent from the IR when null (docs/subsurface.md)

    @classmethod
    def from_ir(cls, d: object, path: str = "model") -> Model:
        d = _object(d, path)
        return cls(
            base=_choice(d.get("base"), BASES, f"{path}.base"),
            distribution=_choice(d.get("distribution"), DISTRIBUTIONS, f"{path}.distribution"),
            anisotropic=_boolean(d.get("anisotropic", False), f"{path}.anisotropic"),
            coat=_boolean(d.get("coat", False), f"{path}.coat"),
            diffuse=_choice(d.get("diffuse"), DIFFUSE_LOBES, f"{path}.diffuse"),
            subsurface=_choice(d.get("subsurface"), SUBSURFACE_MODELS, f"{path}.subsurface"),
        )

    def to_ir(self) -> dict[str, JSON]:
        out = dataclasses.asdict(self)
        if self.subsurface is None:
            del out["subsurface"]
        return out


def _value(spec: ParamSpec, value: object, path: str, ranged: bool = True) -> Any:
    """One table value from JSON, checked against its row (its range too, when `ranged`)."""
    if value is None and spec.optional:
        return None
    bounds = spec.range if ranged else None
    if spec.kind == "number":
        return _number(value, path, bounds)
    if spec.kind == "rgb":
        return _numbers(value, 3, path, bounds)
    if spec.kind == "alpha":
        return _numbers(value, 2, path, bounds)
    if spec.kind == "enum":
        return _choice(value, spec.choices, path)
    if spec.kind == "str":
        return _string(value, path)
    raise _fail(path, spec.kind, value)


def _json_value(value: Any) -> JSON:
    return list(value) if isinstance(value, tuple) else value


COAT_NAMES = frozenset(s.name for s in COAT_PARAMS)


def _no_unknown_keys(d: Mapping[str, Any], known: frozenset[str], path: str) -> None:
    for key in d:
        if key not in known:
            raise ValueError(f"{path}.{key}: not a parameter of the table (cnlmc.params): {', '.join(sorted(known))}")


def coat_from_ir(d: object, convention: str, path: str, ranged: bool = True) -> Coat:
    """A coat; its alpha, when absent, from its roughness in the base's convention."""
    d = _object(d, path)
    if ranged:
        _no_unknown_keys(d, COAT_NAMES, path)
    values = {s.name: _value(s, d[s.name], f"{path}.{s.name}", ranged) for s in COAT_PARAMS if s.name in d}
    if "alpha" not in values:
        values["alpha"] = tuple(alpha_of(values.get("roughness", Coat.roughness), 0.0, convention))
    return Coat(**values)


def coat_to_ir(coat: Coat) -> dict[str, JSON]:
    return {s.name: _json_value(getattr(coat, s.name)) for s in COAT_PARAMS}


SUBSURFACE_NAMES = frozenset(s.name for s in SUBSURFACE_PARAMS)


def subsurface_from_ir(d: object, path: str, ranged: bool = True) -> Subsurface:
    """The medium under the boundary (docs/subsurface.md)."""
    d = _object(d, path)
    if ranged:
        _no_unknown_keys(d, SUBSURFACE_NAMES, path)
    return Subsurface(
        **{s.name: _value(s, d[s.name], f"{path}.{s.name}", ranged) for s in SUBSURFACE_PARAMS if s.name in d}
    )


def subsurface_to_ir(medium: Subsurface) -> dict[str, JSON]:
    return {s.name: _json_value(getattr(medium, s.name)) for s in SUBSURFACE_PARAMS}


def params_from_ir(d: object, model: Model, path: str = "params", ranged: bool = True) -> Params:
    """Params from the IR's params object; absent keys hold the table's default (alpha: derived).

    `ranged=False` checks types only, and skips keys the table lacks: the numpy reference takes
    physical values beyond the IR's ranges (a glass seen from inside has ior < 1)."""
    d = _object(d, path)
    if ranged:
        _no_unknown_keys(d, PARAM_NAMES, path)
    values: dict[str, Any] = {}
    convention = _value(
        _ALPHA_CONVENTION, d.get("alpha_convention", Params.alpha_convention), f"{path}.alpha_convention"
    )
    for s in PARAMS:
        if s.name not in d:
            continue
        where = f"{path}.{s.name}"
        if s.kind == "coat":
            values[s.name] = None if d[s.name] is None else coat_from_ir(d[s.name], convention, where, ranged)
        elif s.kind == "subsurface":
            values[s.name] = None if d[s.name] is None else subsurface_from_ir(d[s.name], where, ranged)
        else:
            values[s.name] = _value(s, d[s.name], where, ranged)
    if "alpha" not in values:
        aniso = values.get("anisotropy", Params.anisotropy) if model.anisotropic else 0.0
        values["alpha"] = tuple(alpha_of(values.get("roughness", Params.roughness), aniso, convention))
    return Params(**values, present=frozenset(d))


def params_to_ir(params: Params) -> dict[str, JSON]:
    """The params object with the keys the IR had, in IR order."""
    out: dict[str, JSON] = {}
    for s in PARAMS:
        if s.name in params.present:
            value = getattr(params, s.name)
            if isinstance(value, Coat):
                out[s.name] = coat_to_ir(value)
            elif isinstance(value, Subsurface):
                out[s.name] = subsurface_to_ir(value)
            else:
                out[s.name] = _json_value(value)
    return out


def _spec(name: str) -> ParamSpec:
    return next(s for s in PARAMS if s.name == name)


_ALPHA_CONVENTION = _spec("alpha_convention")


@dataclass(frozen=True)
class MapRef:
    graph: str
    output: str
    params: Mapping[str, float]
    seed: int

    @classmethod
    def from_ir(cls, d: object, path: str) -> MapRef:
        d = _object(d, path)
        params = _object(d.get("params", {}), f"{path}.params")
        for name, value in params.items():
            if not _is_number(value):
                raise _fail(f"{path}.params.{name}", "a number", value)
        seed = d.get("seed", 0)
        if not isinstance(seed, int) or isinstance(seed, bool):
            raise _fail(f"{path}.seed", "an integer", seed)
        return cls(
            graph=_string(d.get("graph"), f"{path}.graph"),
            output=_string(d.get("output"), f"{path}.output"),
            params=MappingProxyType(dict(params)),
            seed=seed,
        )

    def to_ir(self) -> dict[str, JSON]:
        return {"graph": self.graph, "output": self.output, "params": dict(self.params), "seed": self.seed}


@dataclass(frozen=True)
class Variant:
    group: str
    name: str
    choices: tuple[str, ...]

    @classmethod
    def from_ir(cls, d: object, path: str) -> Variant:
        d = _object(d, path)
        choices = d.get("choices")
        if not isinstance(choices, list) or not all(isinstance(c, str) for c in choices):
            raise _fail(f"{path}.choices", "a list of strings", choices)
        return cls(_string(d.get("group"), f"{path}.group"), _string(d.get("name"), f"{path}.name"), tuple(choices))

    def to_ir(self) -> dict[str, JSON]:
        return {"group": self.group, "name": self.name, "choices": list(self.choices)}


def _maps_from_ir(d: object, path: str) -> Mapping[str, MapRef]:
    d = _object(d, path)
    for role in d:
        _choice(role, MAP_ROLES, f"{path} role")
    return MappingProxyType({role: MapRef.from_ir(ref, f"{path}.{role}") for role, ref in d.items()})


Step = Mapping[str, Any]


class Provenance(Mapping[str, tuple[Step, ...]]):
    """param -> the steps that set it ({"rule", "words", "spans", "value"[, "source"]}), read-only.

    Backends seldom read it, so the validated JSON is kept as it came and frozen on first read
    (a deep freeze of every step costs more than the rest of typing a material)."""

    __slots__ = ("_json", "_frozen")

    def __init__(self, steps: Mapping[str, list[Step]]) -> None:
        self._json = steps
        self._frozen: Mapping[str, tuple[Step, ...]] | None = None

    def _view(self) -> Mapping[str, tuple[Step, ...]]:
        if self._frozen is None:
            self._frozen = freeze_json(self._json)
        return self._frozen

    def __getitem__(self, param: str) -> tuple[Step, ...]:
        return self._view()[param]

    def __iter__(self) -> Iterator[str]:
        return iter(self._json)

    def __len__(self) -> int:
        return len(self._json)

    def __repr__(self) -> str:
        return f"Provenance({dict(self._view())!r})"

    def to_ir(self) -> dict[str, JSON]:
        """Fresh JSON the caller may change."""
        thawed: dict[str, JSON] = _thaw(self._json if self._frozen is None else self._frozen)
        return thawed


def _provenance_from_ir(d: object, path: str) -> Provenance:
    d = _object(d, path)
    for name, steps in d.items():
        if not isinstance(steps, list) or not all(type(s) is dict or isinstance(s, Mapping) for s in steps):
            raise _fail(f"{path}.{name}", "a list of steps", steps)
    return Provenance(dict(d))


@dataclass(frozen=True)
class Material:
    name: str
    phrase: str
    variant: Variant | None
    model: Model
    params: Params
    maps: Mapping[str, MapRef]
    provenance: Provenance
    label: str = ""  # the name as written, when `name` could not keep it (IR key "label", optional)

    @classmethod
    def from_ir(cls, d: object, path: str = "", ranged: bool = True) -> Material:
        """A material from its IR object, validated; `path` prefixes error messages.

        `ranged=False`: parameter types are checked, not their ranges (see params_from_ir)."""
        at = f"{path}." if path else ""
        d = _object(d, path or "material")
        model = Model.from_ir(d.get("model"), f"{at}model")
        variant = d.get("variant")
        return cls(
            name=_string(d.get("name", ""), f"{at}name"),
            phrase=_string(d.get("phrase", ""), f"{at}phrase"),
            variant=None if variant is None else Variant.from_ir(variant, f"{at}variant"),
            model=model,
            params=params_from_ir(d.get("params"), model, f"{at}params", ranged),
            maps=_maps_from_ir(d.get("maps", {}), f"{at}maps"),
            provenance=_provenance_from_ir(d.get("provenance", {}), f"{at}provenance"),
            label=_string(d.get("label", ""), f"{at}label"),
        )

    def to_ir(self) -> dict[str, JSON]:
        return {
            "name": self.name,
            **({"label": self.label} if self.label else {}),
            "phrase": self.phrase,
            "variant": None if self.variant is None else self.variant.to_ir(),
            "model": self.model.to_ir(),
            "params": params_to_ir(self.params),
            "maps": {role: ref.to_ir() for role, ref in self.maps.items()},
            "provenance": self.provenance.to_ir(),
        }

    @cached_property
    def key(self) -> str:
        """A content hash of model, params and maps (not the name): equal looks share it."""
        content = [self.model.to_ir(), params_to_ir(self.params), {r: m.to_ir() for r, m in self.maps.items()}]
        return hashlib.sha256(json.dumps(content, sort_keys=True).encode()).hexdigest()[:16]


_DOCUMENT_KEYS = ("ir_version", "source", "lexicon", "colour_space", "materials", "diagnostics")


@dataclass(frozen=True)
class Document:
    ir_version: int
    source: str
    lexicon: tuple[str, ...]
    colour_space: str
    materials: tuple[Material, ...]
    diagnostics: tuple[Mapping[str, Any], ...]

    @classmethod
    def from_ir(cls, d: object) -> Document:
        """The whole IR document, validated once."""
        d = _object(d, "document")
        for key in _DOCUMENT_KEYS:
            if key not in d:
                raise ValueError(f"{key}: missing (an IR document has {', '.join(_DOCUMENT_KEYS)})")
        version = d["ir_version"]
        if version != 1 or isinstance(version, bool):
            raise _fail("ir_version", "1", version)
        lexicon, materials, diagnostics = d["lexicon"], d["materials"], d["diagnostics"]
        if not isinstance(lexicon, list) or not all(isinstance(s, str) for s in lexicon):
            raise _fail("lexicon", "a list of strings", lexicon)
        if not isinstance(materials, list):
            raise _fail("materials", "a list", materials)
        if not isinstance(diagnostics, list) or not all(isinstance(x, Mapping) for x in diagnostics):
            raise _fail("diagnostics", "a list of objects", diagnostics)
        return cls(
            ir_version=version,
            source=_string(d["source"], "source"),
            lexicon=tuple(lexicon),
            colour_space=_choice(d["colour_space"], (COLOUR_SPACE,), "colour_space"),
            materials=tuple(Material.from_ir(m, f"materials[{i}]") for i, m in enumerate(materials)),
            diagnostics=tuple(freeze_json(x) for x in diagnostics),
        )

    def to_ir(self) -> dict[str, JSON]:
        return {
            "ir_version": self.ir_version,
            "source": self.source,
            "lexicon": list(self.lexicon),
            "colour_space": self.colour_space,
            "materials": [m.to_ir() for m in self.materials],
            "diagnostics": [_thaw(x) for x in self.diagnostics],
        }
