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

from dataclasses import dataclass, field

POLICIES = ("exact", "approximate", "bake", "drop", "error")
# Options the compiler passes to every backend, beside the user's --option KEY=VALUE pairs.
COMPILER_OPTIONS = ("seed", "output")
POLICY_CODES = {"approximate": "W201", "bake": "W202", "drop": "W203", "error": "E201"}


def material_features(material: dict) -> list[str]:
    """The features of an IR material, in the vocabulary of capability tables."""
    model, params = material["model"], material["params"]
    features = [f"model.{model['base']}"]
    if model["distribution"]:
        features.append(f"distribution.{model['distribution']}")
    if model["anisotropic"]:
        features.append("anisotropic")
    if model["diffuse"] == "oren_nayar":
        features.append("diffuse.oren_nayar")
    if model["coat"]:
        features.append("coat")
        if any(abs(c - 1.0) > 1e-6 for c in params["coat"]["color"]):
            features.append("coat.color")
    features += [f"maps.{role}" for role in material["maps"]]
    return features


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
    artifacts: list
    notes: list = field(default_factory=list)


def unsupported(notes: list, target: str, capabilities: dict, material: dict, feature: str) -> str:
    """Apply the capability policy for one feature of one material; returns the policy."""
    policy, reason = capabilities.get(feature, ("error", f"'{feature}' is not supported"))
    if policy == "exact":
        return policy
    note = Note(target, material["name"], feature, policy, reason)
    if policy == "error":
        raise BackendRefused(note.text())
    notes.append(note)
    return policy


def check_material(notes: list, target: str, capabilities: dict, material: dict) -> dict[str, str]:
    """Run every feature of a material through its policy; feature -> policy applied."""
    return {f: unsupported(notes, target, capabilities, material, f) for f in material_features(material)}
