"""End to end: `cnlmc compile phrase.txt --target glsl -o out/` writes the four files."""

from __future__ import annotations

import json
import subprocess

from tests.helpers import run_cnlmc


def test_cli_writes_library_standalone_and_sidecar(tmp_path, glslang):
    source = tmp_path / "phrase.txt"
    source.write_text("lightly brushed, blue anodized aluminum\n")
    out = tmp_path / "out"
    done = run_cnlmc("compile", str(source), "--target", "glsl", "-o", str(out), "--option", "fresnel=f82")
    assert done.returncode == 0, done.stderr
    stem = "lightly_brushed_blue_anodized_aluminum"
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [*(f"{stem}{s}" for s in (".glsl", ".frag", ".vert", ".glsl.json")), "textures"]
    )
    assert "warning[W202]" in done.stderr  # the normal map must be baked: said, not dropped
    (sampler,) = json.loads((out / f"{stem}.glsl.json").read_text())["samplers"]
    assert (out / sampler["file"]).is_file() and sampler["file"].endswith(f"{stem}_normal.png")  # and written
    assert json.loads((out / f"{stem}.glsl.json").read_text())["options"]["fresnel"] == "f82"
    for name in (f"{stem}.frag", f"{stem}.vert"):
        assert subprocess.run([glslang, str(out / name)], capture_output=True).returncode == 0


def test_cli_rejects_an_unknown_option_value(tmp_path):
    source = tmp_path / "phrase.txt"
    source.write_text("gold\n")
    done = run_cnlmc("compile", str(source), "--target", "glsl", "--option", "fresnel=fast")
    assert done.returncode != 0 and "exact, f82, schlick" in done.stderr
