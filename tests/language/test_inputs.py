"""cnlmc.inputs: bounded reading of input files, and the CLI refusing what it cannot read."""

import io
import os
import socket
import subprocess
import sys

import pytest

from cnlmc.errors import UsageError
from cnlmc.inputs import DEFAULT_MAX_BYTES, InputTooLarge, NotAFile, NotUTF8, input_name, read_text
from tests.helpers import run_cnlmc as cnlmc

posix_only = pytest.mark.skipif(os.name != "posix", reason="devices and FIFOs are POSIX")


def test_reads_a_regular_file(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_bytes(b"\xef\xbb\xbfpolished brass\n")
    assert read_text(str(path)) == "polished brass\n"
    assert DEFAULT_MAX_BYTES >= 16 * 1024 * 1024


def test_the_limit_is_exact(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_bytes(b"x" * 100)
    assert read_text(str(path), limit=100) == "x" * 100
    with pytest.raises(InputTooLarge) as caught:
        read_text(str(path), limit=99)
    message = str(caught.value)
    assert str(path) in message and "100 bytes" in message and "99 bytes" in message and "--max-bytes" in message
    assert isinstance(caught.value, UsageError)


def test_bad_utf8_names_line_and_column(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_bytes(b"steel\r\nbr\xc3ss\n")
    with pytest.raises(NotUTF8, match=r"m\.cnl:2:3: not UTF-8"):
        read_text(str(path))


def test_a_folder_is_refused(tmp_path):
    with pytest.raises(NotAFile, match="it is a folder"):
        read_text(str(tmp_path))


def test_a_missing_file_is_a_usage_error(tmp_path):
    with pytest.raises(UsageError, match="cannot read '.*missing': No such file"):
        read_text(str(tmp_path / "missing"))


@posix_only
def test_a_device_is_refused_without_reading():
    with pytest.raises(NotAFile, match="it is a device"):
        read_text("/dev/zero")


@posix_only
def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(NotAFile, match=r"FIFO \(named pipe\)"):
        read_text(str(fifo))


@posix_only
def test_a_socket_is_refused(tmp_path):
    path = tmp_path / "s"
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        with pytest.raises(NotAFile, match="it is a socket"):
            read_text(str(path))


def test_stdin_is_bounded(monkeypatch):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"y" * 50)))
    with pytest.raises(InputTooLarge, match="<stdin>: .*more than 10 bytes"):
        read_text("-", limit=10)
    assert input_name("-") == "<stdin>" and input_name("a.cnl") == "a.cnl"


# ---------------------------------------------------------------- through the CLI (#13)


@posix_only
def test_compile_dev_zero_is_refused():
    r = cnlmc("compile", "/dev/zero")
    assert r.returncode == 2, r.stderr
    assert "cnlmc: error: cannot read '/dev/zero': it is a device; a material file must be a regular file" in r.stderr
    assert "Traceback" not in r.stderr


@posix_only
def test_compile_a_fifo_is_refused_not_blocked(tmp_path):
    fifo = tmp_path / "pipe.cnl"
    os.mkfifo(fifo)
    r = cnlmc("compile", str(fifo))
    assert r.returncode == 2, r.stderr
    assert "it is a FIFO (named pipe); a material file must be a regular file" in r.stderr
    assert "give '-'" in r.stderr


@posix_only
def test_stdin_from_dev_zero_stops_at_the_limit():
    """`cnlmc compile - < /dev/zero`: an endless standard input is read up to the limit, then refused."""
    with open("/dev/zero", "rb") as zero:
        r = subprocess.run(
            [sys.executable, "-m", "cnlmc", "compile", "-", "--max-bytes", "1000"],
            stdin=zero,
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
        )
    assert r.returncode == 2, r.stderr
    assert "<stdin>: the input is too large (more than 1000 bytes" in r.stderr
    assert "--max-bytes N" in r.stderr


def test_too_large_file_names_size_limit_and_option(tmp_path):
    path = tmp_path / "big.cnl"
    path.write_text("polished brass\n" * 100)
    r = cnlmc("compile", str(path), "--max-bytes", "1000")
    assert r.returncode == 2
    assert f"{path}: the input is too large (1500 bytes; the limit is 1000 bytes" in r.stderr
    assert "raise the limit with --max-bytes N" in r.stderr
    assert cnlmc("compile", str(path), "--max-bytes", "1500").returncode == 0


def test_stdin_still_works():
    r = cnlmc("compile", "-", stdin="polished brass\n")
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("command", ["compile", "explain", "bake", "preview"])
def test_every_source_command_takes_max_bytes(tmp_path, command):
    path = tmp_path / "m.cnl"
    path.write_text("polished brass\n" * 10)
    extra = ["-o", str(tmp_path / "out")] if command == "bake" else []
    r = cnlmc(command, str(path), "--max-bytes", "10", *extra)
    assert r.returncode == 2, r.stderr
    assert "the input is too large (150 bytes; the limit is 10 bytes" in r.stderr


@pytest.mark.parametrize("value", ["0", "-5", "lots"])
def test_max_bytes_must_be_a_positive_count(value):
    r = cnlmc("compile", "-", "--max-bytes", value, stdin="steel")
    assert r.returncode == 2
    assert "--max-bytes" in r.stderr and "Traceback" not in r.stderr


def test_bad_utf8_through_the_cli(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_bytes(b"steel\nbrass \xff\n")
    r = cnlmc("compile", str(path))
    assert r.returncode == 2
    assert f"{path}:2:7: not UTF-8 text" in r.stderr


def test_nul_bytes_are_not_text(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_bytes(b"steel\x00\n")
    with pytest.raises(NotUTF8, match="not a text file"):
        read_text(str(path))


@posix_only
def test_a_closed_stdin_is_a_usage_error():
    r = subprocess.run(
        ["/bin/sh", "-c", f"'{sys.executable}' -m cnlmc compile - <&-"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert r.returncode == 2, r.stderr
    assert "cannot read standard input" in r.stderr and "Traceback" not in r.stderr
