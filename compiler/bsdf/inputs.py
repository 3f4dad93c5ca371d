"""The reference's entry points take a typed `Material` or an IR material dict: coerced here, once.

A dict is read for its `model` and `params` only (names, maps and provenance do not shade), and
its values are checked for type, not range: the reference takes physical values the IR's ranges
leave out (a glass seen from inside has ior < 1).
Per-lane alpha arrays (a renderer's lanes under a roughness map) pass through unvalidated:
they are the one value of the IR that a caller may widen to an array.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..material import Material, Model, coat_from_ir, params_from_ir
from ..params import Coat, Params

MaterialLike = Material | Mapping[str, Any]


def as_material(material: MaterialLike) -> Material:
    """The typed material: as given, or validated from its IR dict."""
    if isinstance(material, Material):
        return material
    params = material["params"]
    lanes = params.get("alpha")
    if isinstance(lanes, np.ndarray) or (isinstance(lanes, tuple) and any(isinstance(a, np.ndarray) for a in lanes)):
        params = {k: v for k, v in params.items() if k != "alpha"}
    typed = Material.from_ir({"model": material["model"], "params": params}, ranged=False)
    if params is not material["params"]:
        return dataclasses.replace(typed, params=dataclasses.replace(typed.params, alpha=lanes))
    return typed


def as_params(params: Params | Mapping[str, Any], model: Model | None = None) -> Params:
    """Typed params, for the helpers that take a params object alone."""
    if isinstance(params, Params):
        return params
    return params_from_ir(params, model or Model("conductor", "ggx", False, False, None), ranged=False)


def as_coat(coat: Coat | Mapping[str, Any], convention: str = "squared") -> Coat:
    """A typed coat; a dict's scalar alpha stands for the isotropic pair."""
    if isinstance(coat, Coat):
        return coat
    alpha = coat.get("alpha")
    if alpha is not None and np.ndim(alpha) == 0:
        coat = {**coat, "alpha": [alpha, alpha]}
    return coat_from_ir(coat, convention, "coat", ranged=False)
