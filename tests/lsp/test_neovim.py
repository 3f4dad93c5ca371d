"""A real editor as the client: headless Neovim opens a .cnl file with the server attached."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

NVIM = shutil.which("nvim")
SCRIPT = Path(__file__).parent / "nvim" / "client.lua"
DOCUMENT = "hull: lightly brushed, blue anodized aluminum\nblu plastic\npolished brushed steel\n"

pytestmark = [
    pytest.mark.lsp,
    pytest.mark.skipif(NVIM is None, reason="nvim is not installed (apt-get install -y neovim)"),
]


@pytest.fixture(scope="module")
def nvim_results(tmp_path_factory):
    folder = tmp_path_factory.mktemp("nvim")
    document = folder / "hull.cnl"
    document.write_text(DOCUMENT, "utf-8")
    out = folder / "results.json"
    env = {
        **os.environ,
        "CNLMC_FILE": str(document),
        "CNLMC_OUT": str(out),
        "CNLMC_LSP_CMD": json.dumps([sys.executable, "-m", "cnlmc", "lsp"]),
    }
    proc = subprocess.run(
        [NVIM, "--headless", "-u", "NONE", "-i", "NONE", "-c", f"luafile {SCRIPT}"],
        env=env,
        capture_output=True,
        text=True,
        timeout=90,
        cwd=folder,
    )
    assert out.exists(), f"nvim wrote no results: {proc.stdout}\n{proc.stderr}"
    results = json.loads(out.read_text("utf-8"))
    assert results["errors"] == [], results["errors"]
    return results


def test_filetype_is_cnl(nvim_results):
    assert nvim_results["filetype"] == "cnl"


def test_diagnostics_in_neovim(nvim_results):
    found = {(d["code"], d["lnum"], d["col"], d["end_col"]) for d in nvim_results["diagnostics"]}
    assert ("E001", 1, 0, 3) in found
    assert ("W101", 2, 0, 8) in found  # on 'polished': applied after 'brushed' (canonical order), it wins


def test_hover_in_neovim(nvim_results):
    assert "**blue** — colour" in nvim_results["hover"]
    assert "model: conductor" in nvim_results["hover"]


def test_completion_in_neovim(nvim_results):
    items = sorted(nvim_results["completion"], key=lambda item: item["sortText"])
    labels = [item["label"] for item in items]
    assert "brushed" in labels and "aluminum" not in labels
    brushed = next(item for item in items if item["label"] == "brushed")
    assert items[0]["sortText"][:2] == brushed["sortText"][:2] == "0_"  # adjectives first


def test_diagnostics_follow_buffer_edits(nvim_results):
    codes = [d["code"] for d in nvim_results["diagnostics_after_edit"]]
    assert "E001" not in codes and "W101" in codes
