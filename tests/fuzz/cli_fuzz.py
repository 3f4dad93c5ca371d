"""What the CLI fuzz suite (tests/fuzz/test_cli_targets.py) is made of: documents written the way
users and attackers write them, `--option KEY=VALUE` pairs drawn from each target's declared
options (valid and invalid), the CLI run in a sandbox, and the checks every run must pass.

- `Vocabulary.stdlib()`: the real lexicon's words (nouns, adjectives, adverbs, colours, shades,
  coats, refinements, properties and their aliases).
- `documents(vocabulary)`: a hypothesis strategy of whole source texts: material lines (named or
  not, `or` variants, coats), refinement lines, comments, blank lines, random unicode, control
  characters and terminal escapes, very long words, every kind of line end.
- `option_pairs(options)`: `--option` arguments for a target's declared `Option`s; valid values are
  kept cheap (small images), invalid ones are anything a user could type.
- `Sandbox`: one run's folders (cwd, out, home, tmp) under a private root; `run_cli(argv, stdin)`
  calls `cnlmc.cli.main` in process as `python -m cnlmc` would run it (stdin/stdout/stderr as
  UTF-8 byte streams, SystemExit codes), `run_subprocess` runs the real command.
- `check_run(run, sandbox)`: the contract of every run (exit code, no traceback, no raw control
  characters, no file outside the output folder, no leftover temps, every 'wrote' file there).
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import traceback
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st

from cnlmc.backends.base import Option
from cnlmc.lexicon import load_lexicon

#: exit codes a run may end with: 0 ok, 1 errors in the input, 2 usage; 70 (internal error) is a bug
ALLOWED_EXITS = {0, 1, 2}

# ------------------------------------------------------------------------------------ words


@dataclass(frozen=True)
class Vocabulary:
    """The stdlib lexicon's surface forms by category (keys and aliases)."""

    nouns: tuple[str, ...]
    adjectives: tuple[str, ...]
    adverbs: tuple[str, ...]
    colours: tuple[str, ...]
    shades: tuple[str, ...]
    coats: tuple[str, ...]
    refinements: tuple[str, ...]
    properties: tuple[str, ...]

    @classmethod
    def stdlib(cls) -> Vocabulary:
        lexicon = load_lexicon()

        def forms(category: str) -> tuple[str, ...]:
            words: list[str] = []
            for key, entry in sorted(lexicon.all_of(category).items()):
                words.append(key)
                words.extend(str(alias) for alias in entry.get("aliases", ())[:2])
            return tuple(words)

        return cls(*(forms(c) for c in ("nouns", "adjectives", "adverbs", "colours", "shades", "coats")),
                   forms("refinements"), forms("properties"))  # fmt: skip


# ------------------------------------------------------------------------------ documents

#: what attackers put in text: terminal escapes (CSI, OSC title, bell), C0/C1 controls, bidi overrides
ESCAPES = (
    "\x1b[2J",
    "\x1b]0;title\x07",
    "\x1b[31m",
    "\x07",
    "\x08",
    "\x7f",
    "\x9b2J",
    "\x85",
    "\u202e",
    "\u2066",
    "\x00",
    "\x0b",
    "\x1a",
)
#: characters the compiler treats as ordinary (cnlmc.lines) but that end lines elsewhere
ODD_SPACES = ("\f", "\u2028", "\u2029", "\x85", "\u00a0", "\u200b", "\ufeff", "\t")
LINE_ENDS = ("\n", "\n", "\n", "\r\n", "\r", "\n\f", "\u2028", "\n\n")
#: combining marks, right-to-left, emoji (with joiners and skin tones), CJK, a BOM
UNICODE_BITS = (
    "e\u0301\u0308",
    "\u05e9\u05dc\u05d5\u05dd",
    "\u0627\u0644\u0639",
    "🔥",
    "👩🏽\u200d🚀",
    "名前",
    "Ω",
    "ı",
)
NAMES = ("hull", "deck", "a", "y", "red", "y__red", "名前 ünïcødé 🔥 Ω", "CON", "..", "a/b", "x" * 300, "-o")

any_text = st.text(st.characters(exclude_categories=("Cs",)), max_size=24)


def separated(parts: list[str], joiner: str = " ") -> str:
    return joiner.join(p for p in parts if p)


def material_phrases(words: Vocabulary) -> st.SearchStrategy[str]:
    """[adverb] [modifiers] noun [with a ... coat]; a modifier may be 'A or B' (variants)."""
    word = st.one_of(
        st.sampled_from(words.adjectives),
        st.sampled_from(words.colours),
        st.builds(separated, st.lists(st.sampled_from(words.shades), max_size=1), st.sampled_from(words.colours)),
        st.builds(separated, st.lists(st.sampled_from(words.adverbs), max_size=1), st.sampled_from(words.adjectives)),
    )
    alternatives = st.one_of(
        st.lists(st.sampled_from(words.colours), min_size=2, max_size=3, unique=True),
        st.lists(st.sampled_from(words.adjectives), min_size=2, max_size=3, unique=True),
    )
    modifier = st.one_of(word, word, word, alternatives.map(" or ".join))
    coat = st.builds(
        lambda mods, coat: separated(["with a", *mods, coat]),
        st.lists(word, max_size=2),
        st.sampled_from(words.coats),
    )
    return st.builds(
        lambda mods, comma, noun, coat: separated([(", " if comma else " ").join(mods), noun, coat]),
        st.lists(modifier, max_size=3),
        st.sampled_from((False, False, False, True)),
        st.sampled_from(words.nouns),
        st.one_of(st.just(""), st.just(""), coat),
    )


def names() -> st.SearchStrategy[str]:
    return st.one_of(
        st.sampled_from(NAMES),
        st.builds(lambda a, b: a + b, st.sampled_from(NAMES), st.sampled_from(ESCAPES + UNICODE_BITS)),
        any_text.filter(lambda t: ":" not in t),
    )


def material_lines(words: Vocabulary, hostile: bool = False) -> st.SearchStrategy[str]:
    name = names() if hostile else st.sampled_from(NAMES[:7])
    named = st.builds(lambda name, phrase: f"{name}: {phrase}", name, material_phrases(words))
    return st.one_of(material_phrases(words), named)


def refinement_lines(words: Vocabulary) -> st.SearchStrategy[str]:
    """'darker', 'darker blue', 'more grain', 'less diffuse', repeated on consecutive lines at times."""
    line = st.builds(
        lambda refinement, after: separated([refinement, after]),
        st.sampled_from(words.refinements + ("more", "less")),
        st.one_of(st.just(""), st.sampled_from(words.properties), st.sampled_from(words.colours)),
    )
    return st.builds(lambda text, times: "\n".join([text] * times), line, st.integers(1, 40))


def hostile_lines(words: Vocabulary) -> st.SearchStrategy[str]:
    """Random unicode, escapes, very long words and lines, comments holding any of those."""
    mixed = st.lists(
        st.one_of(
            st.sampled_from(ESCAPES + ODD_SPACES + UNICODE_BITS),
            st.sampled_from(words.nouns + words.adjectives + words.colours),
            any_text,
        ),
        max_size=8,
    ).map("".join)
    long_word = st.builds(lambda c, n: c * n, st.sampled_from(("a", "é", "🔥", "x\u0301", "-")), st.integers(200, 5000))
    long_line = st.builds(
        lambda word, n: " ".join([word] * n), st.sampled_from(words.adjectives + words.nouns), st.integers(50, 400)
    )
    content = st.one_of(mixed, long_word, long_line, any_text)
    return st.one_of(content, content.map(lambda text: "# " + text))


def clean_lines(words: Vocabulary) -> st.SearchStrategy[str]:
    """What a careful user writes: materials, refinements below them, comments, blank lines."""
    return st.one_of(
        material_lines(words),
        material_lines(words),
        material_lines(words),
        refinement_lines(words),
        st.sampled_from(("", "   ", "# a comment", "#")),
    )


def hostile_document_lines(words: Vocabulary) -> st.SearchStrategy[str]:
    return st.one_of(
        clean_lines(words),
        material_lines(words, hostile=True),
        hostile_lines(words),
        st.builds(lambda line, bit: line + bit, material_lines(words), st.sampled_from(ESCAPES + ODD_SPACES)),
    )


def documents(words: Vocabulary) -> st.SearchStrategy[str]:
    """A whole source text, careful or hostile: lines joined by mixed line ends, a BOM or a
    missing last line end at times."""

    def join(lines: list[str], ends: list[str], bom: bool, last: str) -> str:
        text = "".join(line + ends[i % len(ends)] for i, line in enumerate(lines))
        return ("\ufeff" if bom else "") + text + last

    def document(lines: st.SearchStrategy[str], ends: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        return st.builds(
            join,
            st.lists(lines, min_size=1, max_size=8),
            st.lists(ends, min_size=1, max_size=3),
            st.booleans(),
            st.sampled_from(("", "", "no end", "steel", "\r")),
        )

    careful = document(clean_lines(words), st.sampled_from(("\n", "\r\n", "\r")))
    return st.one_of(careful, document(hostile_document_lines(words), st.sampled_from(LINE_ENDS)))


# -------------------------------------------------------------------------------- options

#: valid values of options whose declared range would allow an expensive run (big images, long renders)
CHEAP = {
    "size": ("8", "16", "32"),
    "map_size": ("8", "16"),
    "resolution": ("1", "16", "16384"),
    "spp": ("1", "4", "1048576"),
    "max_depth": ("1", "8", "1024"),
    "mesh": ("sphere", "teapot", "shader_ball", "cube", "missing.obj", "../../etc/passwd", "sphere\x1b[2J"),
    "env": ("studio", "sky", "sun", "missing.hdr", ""),
    "tier": ("analytic", "splitsum", "fis4", "mc2", "mc0", "fis-1", "mc99999999999", "bogus", "mc1e3"),
    "budget_ms": ("0.001", "5"),
    "envmap": ("", "sky.hdr", "a\x1b[2J.exr", '"/><shape type="x'),
    "root": ("Root", "名前", "1abc", "a b", "", "/World/Looks", "Root\x1b]0;x\x07"),
    "intrinsics": ("100,100,80,60", "0,0,0,0", "1,2,3", "nan,1,1,1", "1e308,1e308,1,1", "a,b,c,d"),
    "dist": ("0,0,0,0", "0.1,0,0,0,0", "1e308,0,0,0", "1,2", ""),
    "material": ("0", "1", "-1", "hull", "nosuch", "99999999999999999999"),
    "marker_id": ("0", "1", "-1", "1000000"),
    "marker_length": ("0.1", "1", "1e-300", "1e300", "0", "-1"),
    "scale": ("1", "0.5", "0", "-1", "1e300", "1e-300"),
    "fov": ("60", "1", "179", "0", "180", "-5", "1e300"),
}
INVALID = ("", "nan", "inf", "-inf", "-1", "0", "1e400", "1e23", str(10**30), "99999999999", "abc", "1.5", "3",
           "\x1b[2J", "on", "名前", " 16 ", "0x10", "1_000", "١٦", "true")  # fmt: skip


def option_values(option: Option) -> st.SearchStrategy[str]:
    """A value for one declared option: valid and cheap, or anything a user might type."""
    valid: tuple[str, ...]
    if option.name in CHEAP:
        valid = CHEAP[option.name]
    elif option.choices is not None:
        valid = tuple(str(c) for c in option.choices) + tuple(str(c).upper() for c in option.choices)
    elif option.type is bool:
        valid = ("on", "off", "yes", "0")
    elif option.range is not None:
        valid = tuple(str(v) for v in option.range)
    else:
        valid = (str(option.default),)
    right = st.sampled_from(valid)
    return st.one_of(right, right, right, st.sampled_from(INVALID), any_text)


def option_pairs(options: Sequence[Option]) -> st.SearchStrategy[list[str]]:
    """`--option KEY=VALUE` arguments: some declared options, at times an unknown or misspelled key."""
    if not options:
        declared: st.SearchStrategy[str] = st.nothing()
    else:
        declared = st.sampled_from(list(options)).flatmap(
            lambda option: option_values(option).map(lambda value: f"{option.name}={value}")
        )
    wrong = st.one_of(
        st.sampled_from(("colour=red", "sizee=16", "seed=abc", "seed=-1", "=", "noequals", "output=x", "seed=1e3")),
        st.builds(lambda k, v: f"{k}={v}", any_text, any_text),
    )
    pair = st.one_of(declared, declared, declared, wrong)
    return st.lists(pair, max_size=3).map(lambda pairs: [a for p in pairs for a in ("--option", p)])


# -------------------------------------------------------------------------------- running


@dataclass(frozen=True)
class Run:
    argv: tuple[str, ...]
    code: int
    stdout: str
    stderr: str


class Sandbox:
    """One run's private folders: cwd (the current directory), out (the only place a run may
    write), home and tmp (HOME, TMPDIR, tempfile.tempdir), cache and config (XDG_CACHE_HOME,
    XDG_CONFIG_HOME: where cnlmc's lexicon cache and libraries' caches may go)."""

    def __init__(self, root: Path):
        self.root = root
        for name in ("cwd", "out", "home", "tmp", "cache", "config"):
            (root / name).mkdir(parents=True)
        self.cwd, self.out = root / "cwd", root / "out"

    @classmethod
    @contextlib.contextmanager
    def made(cls, base: Path) -> Iterator[Sandbox]:
        root = Path(tempfile.mkdtemp(prefix="run", dir=base))
        try:
            yield cls(root)
        finally:
            shutil.rmtree(root, ignore_errors=True)

    def env(self) -> dict[str, str]:
        return {
            **os.environ,
            "HOME": str(self.root / "home"),
            "TMPDIR": str(self.root / "tmp"),
            "XDG_CACHE_HOME": str(self.root / "cache"),
            "XDG_CONFIG_HOME": str(self.root / "config"),
            "CNLMC_NO_GC_FREEZE": "1",
        }

    def snapshot(self) -> dict[str, tuple[int, int]]:
        """Every path under the root but the output folder, the cache and the config (libraries such
        as matplotlib keep theirs there) -> (size, mtime_ns) of a
        file, (-1, -1) of a folder."""
        seen: dict[str, tuple[int, int]] = {}
        written = (self.out, self.root / "cache", self.root / "config")
        for folder, subfolders, files in os.walk(self.root):
            here = Path(folder)
            subfolders[:] = [name for name in subfolders if here / name not in written]
            for name in subfolders:  # a folder's own time changes with a temp made and removed in it
                seen[str((here / name).relative_to(self.root))] = (-1, -1)
            for name in files:
                st_ = os.lstat(here / name)
                seen[str((here / name).relative_to(self.root))] = (st_.st_size, st_.st_mtime_ns)
        return seen


def _streams(stdin: bytes) -> tuple[io.TextIOWrapper, io.TextIOWrapper, io.TextIOWrapper]:
    def text(data: bytes = b"") -> io.TextIOWrapper:
        return io.TextIOWrapper(io.BytesIO(data), encoding="utf-8", newline=None, write_through=True)

    return text(stdin), text(), text()


def run_cli(argv: Sequence[str], stdin: bytes, sandbox: Sandbox) -> Run:
    """`python -m cnlmc ARGV` in this process: cwd, HOME, TMPDIR and the standard streams are the
    sandbox's for the call; an exit through SystemExit gives its code as the interpreter would."""
    from cnlmc.cli import main

    saved = (os.getcwd(), sys.stdin, sys.stdout, sys.stderr, tempfile.tempdir, dict(os.environ))
    sys.stdin, sys.stdout, sys.stderr = _streams(stdin)
    out, err = sys.stdout, sys.stderr
    os.chdir(sandbox.cwd)
    tempfile.tempdir = str(sandbox.root / "tmp")
    os.environ.update(sandbox.env())
    try:
        code = main(list(argv))
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    except Exception:  # escaped main: what python -m cnlmc would print as a traceback
        err.write(traceback.format_exc())
        code = 1
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.chdir(saved[0])
        sys.stdin, sys.stdout, sys.stderr, tempfile.tempdir = saved[1:5]
        os.environ.clear()
        os.environ.update(saved[5])
    return Run(tuple(argv), code, _read(out), _read(err))


def _read(stream: io.TextIOWrapper) -> str:
    stream.flush()
    buffer = stream.buffer
    assert isinstance(buffer, io.BytesIO)
    return buffer.getvalue().decode("utf-8")


def run_subprocess(argv: Sequence[str], stdin: bytes, sandbox: Sandbox, timeout: float = 120) -> Run:
    done = subprocess.run(
        [sys.executable, "-m", "cnlmc", *argv],
        input=stdin,
        capture_output=True,
        cwd=sandbox.cwd,
        env=sandbox.env(),
        timeout=timeout,
        check=False,
    )
    return Run(tuple(argv), done.returncode, done.stdout.decode("utf-8"), done.stderr.decode("utf-8"))


# --------------------------------------------------------------------------------- checks

#: what must never reach the terminal raw: C0 but tab and newline, DEL, C1, line/paragraph
#: separators and bidirectional overrides (cnlmc.diagnostics.visible escapes all of them)
RAW_CONTROLS = frozenset(
    [*(chr(c) for c in range(0x20) if chr(c) not in "\t\n"), "\x7f", *(chr(c) for c in range(0x80, 0xA0))]
    + ["\u2028", "\u2029", *(chr(c) for c in range(0x202A, 0x202F)), *(chr(c) for c in range(0x2066, 0x206A))]
)


#: hidden files the writer keeps in an output folder on purpose (cnlmc.manifest: what it wrote there)
KEPT_HIDDEN = frozenset({".cnlmc-manifest.json"})


#: what must not reach the terminal even in a file printed on stdout (JSON, XML, USD, GLSL text):
#: the C0 controls that are not layout (ESC, BEL, backspace, ...), DEL and C1 (U+009B is CSI)
TERMINAL_CONTROLS = frozenset(
    [*(chr(c) for c in range(0x20) if chr(c) not in "\t\n\r\f"), "\x7f", *(chr(c) for c in range(0x80, 0xA0))]
)


def raw_controls(text: str) -> list[str]:
    return sorted({repr(c) for c in text if c in RAW_CONTROLS})


def terminal_controls(text: str) -> list[str]:
    return sorted({repr(c) for c in text if c in TERMINAL_CONTROLS})


def strict_json(text: str) -> object:
    """json.loads that refuses NaN and Infinity (not JSON)."""

    def refuse(constant: str) -> object:
        raise ValueError(f"not strict JSON: {constant}")

    return json.loads(text, parse_constant=refuse)


def wrote_paths(run: Run, sandbox: Sandbox) -> list[Path]:
    """The files the run said it wrote ('wrote PATH' on stderr), relative paths against its cwd."""
    lines = [line[len("wrote ") :] for line in run.stderr.splitlines() if line.startswith("wrote ")]
    return [path if path.is_absolute() else sandbox.cwd / path for path in map(Path, lines)]


def check_run(run: Run, sandbox: Sandbox, before: dict[str, tuple[int, int]]) -> None:
    """The contract of every run: see the module docstring."""
    said = f"cnlmc {' '.join(map(repr, run.argv))} -> {run.code}\n--- stderr:\n{run.stderr[-3000:]}"
    assert run.code in ALLOWED_EXITS, said
    for stream in (run.stdout, run.stderr):
        assert "Traceback" not in stream and "internal error" not in stream, said
    assert not raw_controls(run.stderr), f"raw control characters {raw_controls(run.stderr)} on stderr\n{said}"
    assert not terminal_controls(run.stdout), f"terminal controls {terminal_controls(run.stdout)} on stdout\n{said}"
    after = sandbox.snapshot()
    changed = sorted(set(before.items()) ^ set(after.items()))
    assert not changed, f"files changed outside the output folder: {changed}\n{said}"
    leftovers = [p.name for p in sandbox.out.rglob(".*") if p.name not in KEPT_HIDDEN]
    assert not leftovers, f"hidden (temporary) files left in the output folder: {leftovers}\n{said}"
    for path in wrote_paths(run, sandbox):
        assert path.is_file() and path.stat().st_size > 0, f"said it wrote {path}, which is missing or empty\n{said}"
        assert sandbox.out in path.resolve().parents, f"wrote {path} outside {sandbox.out}\n{said}"
