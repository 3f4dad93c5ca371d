"""Edges of the medium's exports: a zero mean free path in glTF (KHR_materials_volume requires
attenuationDistance > 0, checked by the Khronos validator) and the preview's shared constants."""

from __future__ import annotations

import copy
import dataclasses
import json
import shutil
import subprocess
from pathlib import Path

import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.preview.subsurface import settings

ROOT = Path(__file__).resolve().parents[2]


def validate_gltf(path: Path) -> dict:
    node = shutil.which("node")
    validator = ROOT / "tools" / "js" / "validate_gltf.js"
    if node is None or not (ROOT / "tools" / "js" / "node_modules" / "gltf-validator").exists():
        pytest.skip("node or gltf-validator missing: run scripts/setup.sh (npm ci in tools/js)")
    run = subprocess.run([node, str(validator), str(path)], capture_output=True, text=True, timeout=120, check=False)
    return json.loads(run.stdout)["reports"][0]


def test_a_zero_radius_medium_writes_no_zero_attenuation_distance(tmp_path):
    result = compile_source("wax\n")
    assert result.ok
    ir = copy.deepcopy(result.ir)
    ir["materials"][0]["params"]["subsurface"]["radius"] = [0.0, 0.0, 0.0]
    artifact = emit(ir, "gltf", {"output": "zero.glb", "mesh": "sphere"}).artifacts[0]
    path = tmp_path / "zero.glb"
    path.write_bytes(artifact.content)
    report = validate_gltf(path)
    assert (report["errors"], report["warnings"]) == (0, 0), report["messages"][:5]
    length = int.from_bytes(artifact.content[12:16], "little")
    document = json.loads(artifact.content[20 : 20 + length])
    extensions = document["materials"][0].get("extensions", {})
    assert "KHR_materials_volume" not in extensions  # no light travels inside: an opaque body
    assert extensions["KHR_materials_diffuse_transmission"]["diffuseTransmissionFactor"] == 0.0


def test_the_preview_constants_cannot_be_changed_by_a_caller():
    shared = settings()
    with pytest.raises(dataclasses.FrozenInstanceError):
        shared.profile_u_max = 5.0  # type: ignore[misc]
    assert settings() is shared and settings().profile_u_max == 0.95  # data/subsurface.toml [profile] u_max
    assert 0.0 < shared.default_thickness_m < 0.01
