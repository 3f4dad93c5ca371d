"""Frozen records that are quick to make: the spans and AST nodes made for every phrase.

`@record` is `@dataclass(frozen=True)` (equality, hashing, asdict, repr, assignment raises)
with a different __init__: the generated one sets each field through object.__setattr__,
which is about twice as slow as writing the instance's __dict__ as this one does.
"""

from __future__ import annotations

from dataclasses import MISSING, dataclass, fields


def record(cls):
    cls = dataclass(frozen=True)(cls)
    cls.__init__ = _fast_init(cls)
    return cls


def _fast_init(cls):
    params, defaults = [], {}
    for f in fields(cls):
        if f.default is not MISSING:
            defaults[f"_default_{f.name}"] = f.default
            params.append(f"{f.name}=_default_{f.name}")
        elif f.default_factory is not MISSING:
            raise TypeError(f"{cls.__name__}.{f.name}: a record field cannot have a default factory")
        else:
            params.append(f.name)
    body = "".join(f"\n    d['{f.name}'] = {f.name}" for f in fields(cls))
    source = f"def __init__(self, {', '.join(params)}):\n    d = self.__dict__{body}\n"
    namespace: dict = {}
    exec(source, dict(defaults), namespace)
    init = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    return init
