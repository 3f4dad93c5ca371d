"""What a target can express, and the one path for what it cannot.

Every backend publishes CAPABILITIES: feature -> (policy, reason). Policies:
  exact        the target expresses the feature as the IR means it
  approximate  the target gets the nearest thing it has (the reason says what)
  bake         a procedural part is baked into images first
  drop         the target has no way to show it; it is left out, with a note
  error        the backend refuses the material
Backends call `unsupported()` for every feature a material uses that is not exact; the
notes become warnings (code W2xx) so nothing is dropped silently.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from cnlmc.material import Material

POLICIES = ("exact", "approximate", "bake", "drop", "error")
POLICY_CODES = {"approximate": "W201", "bake": "W202", "drop": "W203", "error": "E201"}


def material_features(material: Material | Mapping[str, Any]) -> list[str]:
    """The features of a material (typed, or its IR dict), in the vocabulary of capability tables."""
    if isinstance(material, Mapping):
        material = Material.from_ir(dict(material))
    model, coat = material.model, material.params.coat
    features = [f"model.{model.base}" if model.subsurface is None else f"subsurface.{model.subsurface}"]
    if model.distribution:
        features.append(f"distribution.{model.distribution}")
    if model.anisotropic:
        features.append("anisotropic")
    if model.diffuse == "oren_nayar":
        features.append("diffuse.oren_nayar")
    if model.coat:
        features.append("coat")
        if coat is not None and any(abs(c - 1.0) > 1e-6 for c in coat.color):
            features.append("coat.color")
    features += _layer_features(material)
    return features + [f"maps.{role}" for role in material.maps]


def _layer_features(material: Material) -> list[str]:
    """The layers a word adds over or under the base: a fibre sheen, paint flakes (docs/bsdf.md)."""
    p = material.params
    sheen = p.sheen_color is not None and max(p.sheen_color) > 0.0
    flakes = p.flake_color is not None and max(p.flake_color) > 0.0 and p.flake_density > 0.0
    return [name for name, on in (("sheen", sheen), ("flakes", flakes)) if on]


ALL_FEATURES = (
    "model.diffuse",
    "model.dielectric",
    "model.conductor",
    "model.glass",
    "distribution.ggx",
    "distribution.ward",
    "anisotropic",
    "diffuse.oren_nayar",
    "coat",
    "coat.color",
    "sheen",
    "flakes",
    "subsurface.volume",  # a dielectric boundary around a medium (docs/subsurface.md), in place of model.dielectric
    "subsurface.thin",  # a thin-walled translucent sheet of it
    "maps.base_color",
    "maps.normal",
    "maps.roughness",
    "maps.mask",
    "maps.metallic",
)


class BackendRefused(Exception):
    """A material uses a feature whose policy is 'error' for this target."""


@dataclass(frozen=True)
class Note:
    target: str
    material: str
    feature: str
    policy: str
    message: str

    @property
    def code(self) -> str:
        return POLICY_CODES[self.policy]

    def text(self) -> str:
        return f"{self.target}: {self.material}: {self.feature}: {self.message}"


@dataclass
class EmitResult:
    """What a target's emit returns: the files (base.Artifact) and the capability notes."""

    artifacts: list[Any]
    notes: list[Note] = field(default_factory=list)


Capabilities = Mapping[str, tuple[str, str]]


def material_name(material: Material | Mapping[str, Any]) -> str:
    return str(material["name"]) if isinstance(material, Mapping) else material.name


def unsupported(
    notes: list[Note], target: str, capabilities: Capabilities, material: Material | Mapping[str, Any], feature: str
) -> str:
    """Apply the capability policy for one feature of one material; returns the policy."""
    policy, reason = capabilities.get(feature, ("error", f"'{feature}' is not supported"))
    if policy == "exact":
        return policy
    note = Note(target, material_name(material), feature, policy, reason)
    if policy == "error":
        raise BackendRefused(note.text())
    notes.append(note)
    return policy


def check_material(
    notes: list[Note], target: str, capabilities: Capabilities, material: Material | Mapping[str, Any]
) -> dict[str, str]:
    """Run every feature of a material through its policy; feature -> policy applied."""
    return {f: unsupported(notes, target, capabilities, material, f) for f in material_features(material)}
