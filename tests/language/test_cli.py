"""The CLI end to end, as a user runs it: exit codes, stdout/stderr, files."""

import json
from pathlib import Path

import pytest

from tests.helpers import EXAMPLES
from tests.helpers import run_cnlmc as cnlmc


def test_compile_to_ir_on_stdout():
    r = cnlmc("compile", str(EXAMPLES / "anodized.cnl"), "--target", "ir")
    assert r.returncode == 0, r.stderr
    ir = json.loads(r.stdout)
    assert ir["ir_version"] == 1
    assert [m["name"] for m in ir["materials"]] == ["hull", "deck"]


def test_compile_from_stdin_to_a_file(tmp_path):
    out = tmp_path / "m.json"
    r = cnlmc("compile", "-", "-o", str(out), stdin="polished brass\n")
    assert r.returncode == 0
    assert json.loads(out.read_text())["materials"][0]["name"] == "polished_brass"


def test_errors_exit_1_and_write_nothing(tmp_path):
    out = tmp_path / "m.json"
    out.write_text("previous")
    r = cnlmc("compile", "-", "-o", str(out), stdin="polished bras\n")
    assert r.returncode == 1
    assert "<stdin>:1:10: error[E001]: unknown word 'bras'" in r.stderr
    assert "did you mean 'brass'?" in r.stderr
    assert out.read_text() == "previous"
    assert "Traceback" not in r.stderr


def test_unknown_target_is_a_usage_error_with_did_you_mean():
    r = cnlmc("compile", "-", "--target", "i", stdin="steel")
    assert r.returncode == 2
    assert "unknown target 'i'" in r.stderr


def test_missing_file_is_a_usage_error():
    r = cnlmc("compile", "no/such/file.cnl")
    assert r.returncode == 2
    assert "cannot read 'no/such/file.cnl'" in r.stderr


def test_binary_input_is_refused_cleanly():
    r = cnlmc("compile", "-", stdin=b"\x00\xff\xfe")
    assert r.returncode == 2
    assert b"not a text file" in r.stderr and b"Traceback" not in r.stderr


def test_emit_tokens_and_ast():
    r = cnlmc("compile", "-", "--emit", "tokens", stdin="gold plated steel")
    assert r.stdout.splitlines()[0] == "1:1\tCOLOR|NOUN\tgold"
    r = cnlmc("compile", "-", "--emit", "ast", stdin="gold plated steel")
    ast = json.loads(r.stdout)
    assert ast[0]["node"] == "Material" and ast[0]["nouns"][0]["key"] == "steel"


def test_explain_lists_words_and_rules():
    r = cnlmc("explain", "-", "--lexicon", "paper", stdin="lightly brushed aluminum")
    assert r.returncode == 0
    assert "adjectives.brushed: roughness *= 1.2 (weight 0.5)" in r.stdout
    assert "lightly brushed" in r.stdout


def test_unknown_overlay_is_a_usage_error():
    r = cnlmc("compile", "-", "--lexicon", "papr", stdin="steel")
    assert r.returncode == 2
    assert "no lexicon overlay named 'papr' (available: de, paper); did you mean 'paper'?" in r.stderr


@pytest.mark.parametrize("text", ["", "\n\n", "# only a comment\n", "   "])
def test_empty_input_compiles_to_nothing(text):
    r = cnlmc("compile", "-", stdin=text)
    assert r.returncode == 0
    assert json.loads(r.stdout)["materials"] == []


@pytest.mark.slow  # ~30-70 s: a megabyte through the whole pipeline in a fresh process
def test_one_megabyte_of_input_is_handled(tmp_path):
    text = ("lightly brushed, blue anodized aluminum\n" * 26000)[:1_000_000]
    out = tmp_path / "big.json"
    text = text.rsplit("\n", 1)[0] + "\n"  # whole lines only
    r = cnlmc("compile", "-", "-o", str(out), stdin=text, timeout=300)
    assert r.returncode == 0 and "Traceback" not in r.stderr
    assert len(json.loads(out.read_text())["materials"]) == text.count("\n")


def test_a_very_long_line_is_an_error_not_a_hang():
    r = cnlmc("compile", "-", stdin="brushed " * 5000 + "steel")
    assert r.returncode == 1
    assert "line is too long" in r.stderr


def test_unicode_positions_and_messages():
    r = cnlmc("compile", "-", stdin="🙂 brushed alumínio\n")
    assert r.returncode == 1
    assert "<stdin>:1:1: error[E001]: unexpected character '🙂'" in r.stderr
    assert "unknown word 'alumínio'" in r.stderr and "Traceback" not in r.stderr


def test_written_files_get_the_usual_permissions(tmp_path):
    out = tmp_path / "m.json"
    r = cnlmc("compile", "-", "-o", str(out), stdin="steel")
    assert r.returncode == 0
    assert out.stat().st_mode & 0o777 == 0o666 & ~_umask()


def _umask():
    import os

    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_emit_ir_stops_at_the_ir_whatever_the_target():
    r = cnlmc("compile", "-", "--target", "glsl", "--emit", "ir", stdin="steel")
    assert r.returncode == 0
    assert json.loads(r.stdout)["ir_version"] == 1


def test_a_result_without_files_says_so(tmp_path: Path) -> None:
    """`--target maps` of a material without procedural maps writes nothing, and says so."""
    run = cnlmc("compile", "-", "--target", "maps", "-o", str(tmp_path / "out") + "/", stdin="red plastic\n")
    assert run.returncode == 0, run.stderr
    assert "nothing to write" in run.stderr
    assert not (tmp_path / "out").exists()
