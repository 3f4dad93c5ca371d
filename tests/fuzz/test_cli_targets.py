"""A bounded fuzz suite over the CLI through every target (#13).

Documents written the way users and attackers write them (tests/fuzz/cli_fuzz.py: real lexicon
words, refinements, comments, unicode, terminal escapes, long lines, every line end, duplicate
names, `or` variants) go through `cnlmc compile --target T` for every registered target, the
stages (`--emit`), `explain`, `bake`, `preview`, `sheet` and `ar`, with valid and invalid
`--option KEY=VALUE` pairs drawn from each target's declared options. Every run must exit 0, 1
or 2 (70 is an internal error), print no traceback, "internal error" or raw control character,
change no file outside its output folder, leave no temp behind, and have written every file it
says it wrote; the IR is strict JSON.

Most examples call `cnlmc.cli.main` in process (cli_fuzz.run_cli: the same streams, cwd and exit
codes as `python -m cnlmc`); a few go through real subprocesses. The budget is fixed and
derandomized; CNLMC_FUZZ_EXAMPLES=N runs N examples per test, randomized, to hunt for failures.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from cnlmc.backends.registry import BUILTIN_BACKENDS, TargetUnavailable, get_target
from tests.fuzz.cli_fuzz import (
    Run,
    Sandbox,
    Vocabulary,
    check_run,
    documents,
    option_pairs,
    run_cli,
    run_subprocess,
    strict_json,
)
from tests.helpers import require

WORDS = Vocabulary.stdlib()
HUNT = int(os.environ.get("CNLMC_FUZZ_EXAMPLES", "0"))

#: examples per test in the test run, by cost (a preview renders, the exchange targets bake maps)
BUDGET = {
    "ir": 25,
    "glsl": 20,
    "materialx": 12,
    "usd": 12,
    "mitsuba": 12,
    "maps": 10,
    "preview": 3,
    "gltf": 8,
    "usdz": 6,
}
#: what a target needs to emit beyond what loading it needs: (module, extra)
EMIT_NEEDS = {
    "maps": ("OpenImageIO", "maps"),
    "mitsuba": ("OpenImageIO", "maps"),
    "materialx": ("OpenImageIO", "maps"),
    "usd": ("OpenImageIO", "maps"),
    "gltf": ("OpenImageIO", "maps"),
    "usdz": ("OpenImageIO", "maps"),
    "preview": ("moderngl", "preview"),
}
MARKS = {
    "preview": [pytest.mark.gl, pytest.mark.oiio],
    "maps": [pytest.mark.oiio],
    "mitsuba": [pytest.mark.mitsuba, pytest.mark.oiio],
    "materialx": [pytest.mark.materialx, pytest.mark.oiio],
    "usd": [pytest.mark.usd, pytest.mark.oiio],
    "gltf": [pytest.mark.oiio],
    "usdz": [pytest.mark.usd, pytest.mark.oiio],
}
#: options given before the fuzzed ones (which override them), so that a run bakes and renders small images
CHEAP_DEFAULTS = {
    "maps": ("size=16",),
    "preview": ("size=16",),
    "mitsuba": ("map_size=16",),
    "materialx": ("map_size=16",),
    "usd": ("map_size=16",),
    "gltf": ("map_size=16",),
    "usdz": ("map_size=16",),
}
#: what -o is given as, relative to the run's cwd ('out' is the run's output folder)
OUTPUTS = ("", "../out/", "../out/result", "../out/sub/deeper/", "../out/名前 🔥.txt", "../out/a.json", "../out/a.png")


def fuzz_settings(examples: int) -> settings:
    if HUNT:
        return settings(max_examples=HUNT, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    return settings(
        max_examples=examples,
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    )


def loaded(name: str):
    try:
        target = get_target(name)
    except TargetUnavailable as exc:
        pytest.skip(f"target {name} cannot load here: {exc}")
    if name in EMIT_NEEDS:
        require(*EMIT_NEEDS[name])
    if name == "preview":
        require_gl()
    return target


def require_gl() -> None:
    moderngl = require("moderngl", "preview")
    try:
        moderngl.create_context(standalone=True, backend="egl", require=330).release()
    except Exception as exc:  # pragma: no cover - a machine without EGL
        pytest.skip(f"no OpenGL 3.3 on EGL here ({exc})")


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder every run's sandbox is made in (one per example, removed after it)."""
    return tmp_path_factory.mktemp("fuzz")


def with_input(sandbox: Sandbox, text: str, tail: bytes, through_stdin: bool) -> tuple[str, bytes]:
    """The source as the file argument: '-' with the bytes on stdin, or a file in the cwd."""
    data = text.encode("utf-8") + tail
    if through_stdin:
        return "-", data
    (sandbox.cwd / "in.cnl").write_bytes(data)
    return "in.cnl", b""


def fuzz_run(
    base: Path, text: str, tail: bytes, through_stdin: bool, argv_after_input: list[str], head: list[str]
) -> Run:
    """Run `cnlmc HEAD INPUT ARGV...` in a fresh sandbox and check the run's contract."""
    with Sandbox.made(base) as sandbox:
        source, stdin = with_input(sandbox, text, tail, through_stdin)
        before = sandbox.snapshot()
        run = run_cli([*head, source, *argv_after_input], stdin, sandbox)
        event(f"exit {run.code}")  # pytest --hypothesis-show-statistics: how many runs got how far
        check_run(run, sandbox, before)
        check_json_output(run, sandbox)
        return run


def check_json_output(run: Run, sandbox: Sandbox) -> None:
    """The IR (and the AST) on stdout or in the files written is strict JSON."""
    if run.code != 0:
        return
    printed_json = "--emit" in run.argv and run.argv[run.argv.index("--emit") + 1] in ("ir", "ast")
    if ("ir" in run.argv and "-o" not in run.argv) or printed_json:
        strict_json(run.stdout)
    if "ir" in run.argv:
        for path in sandbox.out.rglob("*"):
            if path.is_file():
                strict_json(path.read_text("utf-8"))


#: bytes after the text: mostly none; at times not UTF-8, a NUL (not a text file), a stray BOM
TAILS = st.sampled_from((b"", b"", b"", b"", b"", b"", b"\xff", b"\xc3", b"\x00", b"\xef\xbb\xbf"))


def declared_options(name: str) -> tuple:
    try:
        return get_target(name).options
    except TargetUnavailable:
        return ()


def compile_test(name: str):
    @fuzz_settings(BUDGET[name])
    @given(
        text=documents(WORDS),
        tail=TAILS,
        through_stdin=st.booleans(),
        output=st.sampled_from(OUTPUTS),
        options=option_pairs(declared_options(name)),
    )
    def test(runs, text, tail, through_stdin, output, options):
        loaded(name)
        out = ["-o", output] if output else []
        cheap = [a for pair in CHEAP_DEFAULTS.get(name, ()) for a in ("--option", pair)]  # the fuzzed ones win
        fuzz_run(runs, text, tail, through_stdin, ["--target", name, *out, *cheap, *options], ["compile"])

    for mark in MARKS.get(name, []):
        test = mark(test)
    return test


test_compile_ir = compile_test("ir")
test_compile_glsl = compile_test("glsl")
test_compile_materialx = compile_test("materialx")
test_compile_usd = compile_test("usd")
test_compile_mitsuba = compile_test("mitsuba")
test_compile_maps = compile_test("maps")
test_compile_preview = compile_test("preview")
test_compile_gltf = compile_test("gltf")
test_compile_usdz = compile_test("usdz")


def test_every_registered_target_is_fuzzed():
    assert set(BUILTIN_BACKENDS) == set(BUDGET)


@fuzz_settings(25)
@given(
    text=documents(WORDS),
    tail=TAILS,
    through_stdin=st.booleans(),
    stage=st.sampled_from((["--emit", "tokens"], ["--emit", "ast"], ["--emit", "ir"], ["--emit", "ir", "-t", "glsl"])),
)
def test_emit_stages(runs, text, tail, through_stdin, stage):
    fuzz_run(runs, text, tail, through_stdin, stage, ["compile"])


@fuzz_settings(15)
@given(text=documents(WORDS), tail=TAILS, through_stdin=st.booleans())
def test_explain(runs, text, tail, through_stdin):
    fuzz_run(runs, text, tail, through_stdin, [], ["explain"])


BAKE_SIZES = ("8", "16", "0", "-8", "12", "1e3", "16384", "", "abc", str(10**20))
BAKE_FORMATS = ("png8", "png16", "exr-half", "exr-float", "jpg", "")


@pytest.mark.oiio
@fuzz_settings(8)
@given(
    text=documents(WORDS),
    tail=TAILS,
    through_stdin=st.booleans(),
    size=st.sampled_from(BAKE_SIZES),
    image_format=st.sampled_from(BAKE_FORMATS),
    output=st.sampled_from(("../out/", "../out/maps", "../out/名前/🔥")),
)
def test_bake(runs, text, tail, through_stdin, size, image_format, output):
    require("OpenImageIO", "maps")
    argv = ["-o", output, "--size", size, "--format", image_format]
    fuzz_run(runs, text, tail, through_stdin, argv, ["bake"])


def flag_lists(*flags: list[str]) -> st.SearchStrategy[list[str]]:
    return st.lists(st.sampled_from(flags), max_size=3).map(lambda chosen: [a for f in chosen for a in f])


#: the render flags `preview` and `ar` share (the preview's --size is apart: AR renders at the photo's size)
RENDER_FLAGS = flag_lists(
    ["--mesh", "teapot"],
    ["--mesh", "nosuch.obj"],
    ["--mesh", "../../../etc/passwd"],
    ["--tier", "analytic"],
    ["--tier", "fis2"],
    ["--tier", "mc0"],
    ["--tier", "bogus"],
    ["--budget-ms", "nan"],
    ["--budget-ms", "-1"],
    ["--env", "sky"],
    ["--env", "nosuch.hdr"],
    ["--seed", "-1"],
    ["--seed", str(10**30)],
)
SIZE_FLAGS = flag_lists(["--size", "8"], ["--size", "0"], ["--size", "99999999"], ["--size", "nan"], ["--size", ""])


@pytest.mark.gl
@pytest.mark.oiio
@fuzz_settings(3)
@given(
    text=documents(WORDS),
    tail=TAILS,
    through_stdin=st.booleans(),
    flags=st.builds(lambda a, b: a + b, RENDER_FLAGS, SIZE_FLAGS),
    options=option_pairs(declared_options("preview")),
    output=st.sampled_from(("../out/p.png", "../out/名前 🔥.png", "../out/sub/p.png", "../out/p")),
)
def test_preview_command(runs, text, tail, through_stdin, flags, options, output):
    loaded("preview")
    argv = ["-o", output, "--size", "16", *flags, *options]
    fuzz_run(runs, text, tail, through_stdin, argv, ["preview"])


def run_sheet(runs: Path, size: str, output: str) -> Run:
    require("OpenImageIO", "maps")
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_cli(["sheet", "-o", output, "--size", size], b"", sandbox)
        check_run(run, sandbox, before)
    return run


@pytest.mark.oiio
@pytest.mark.parametrize("size", ["0", "-1", "1", "15", "1025", "3000", "abc", "16.0", "", str(10**30)])
def test_sheet_sizes_outside_the_bounds(runs, size):
    """`cnlmc sheet --size` (the tile size, 16-1024): anything else is a usage error before any work."""
    run = run_sheet(runs, size, "../out/s.png")
    assert run.code == 2 and not any(runs.rglob("s.png")), run.stderr


@pytest.mark.oiio
@pytest.mark.slow
@pytest.mark.parametrize(
    ("output", "code"),
    [
        ("../out/s.png", 0),
        ("../out/sub/名前 🔥.png", 0),
        ("../out/", 2),  # found by the fuzzing: an existing folder as -o was IsADirectoryError (exit 70)
    ],
)
def test_sheet(runs, output, code):
    run = run_sheet(runs, "16", output)
    assert run.code == code, run.stderr


def ar_options() -> st.SearchStrategy[list[str]]:
    try:
        from cnlmc.backends.ar.options import OPTIONS
    except ImportError:
        return st.just([])
    return option_pairs(OPTIONS)


@pytest.mark.gl
@pytest.mark.cv2
@fuzz_settings(3)
@given(
    phrase=st.one_of(documents(WORDS), st.sampled_from(("polished gold", "red or blue plastic", "", "in.cnl"))).map(
        lambda text: text.replace("\x00", "")  # an argument cannot hold NUL
    ),
    flags=RENDER_FLAGS,
    options=ar_options(),
    output=st.sampled_from(("../out/ar.png", "../out/ar.jpg", "../out/sub/ar.png", "../out/ar")),
)
def test_ar(runs, marker_photo, phrase, flags, options, output):
    loaded("preview")
    with Sandbox.made(runs) as sandbox:
        (sandbox.cwd / "in.cnl").write_text("hull: brushed steel\n", "utf-8")
        before = sandbox.snapshot()
        argv = ["ar", str(marker_photo), phrase, "-o", output, *flags, *options]
        run = run_cli(argv, b"", sandbox)
        check_run(run, sandbox, before)


SUBPROCESS_RUNS = [
    ["compile", "-", "--target", "ir"],
    ["compile", "-", "--target", "glsl", "-o", "../out/"],
    ["compile", "-", "--target", "mitsuba", "--option", "map_size=8", "-o", "../out/scene.xml"],
    ["compile", "-", "--target", "usd", "--option", "map_size=8", "-o", "../out/a.usda"],
    ["compile", "-", "--target", "materialx", "--option", "maps=native", "-o", "../out/"],
    ["explain", "-"],
]


@fuzz_settings(4)
@given(text=documents(WORDS), tail=TAILS, argv=st.sampled_from(SUBPROCESS_RUNS))
def test_real_subprocesses(runs, text, tail, argv):
    """The same contract through `python -m cnlmc` itself (what in-process runs stand in for)."""
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_subprocess(argv, text.encode("utf-8") + tail, sandbox)
        check_run(run, sandbox, before)
        check_json_output(run, sandbox)


@pytest.mark.parametrize(
    ("argv", "stdin"),
    [
        (["compile", "-", "-t", "glsl"], "hull: red plastic\ndarker\n"),
        (["compile", "-"], "hull: red plasticc\n# \x1b]0;title\x07\n"),
        (["compile", "-", "--bogus"], "gold\n"),
        (["compile", "-", "-t", "maps"], "rusted iron\n"),
        (["--help"], ""),
    ],
)
def test_in_process_runs_are_what_the_command_does(runs, argv, stdin):
    """run_cli stands in for `python -m cnlmc`: the same exit code, stdout and stderr."""
    with Sandbox.made(runs) as sandbox:
        inside = run_cli(argv, stdin.encode(), sandbox)
        real = run_subprocess(argv, stdin.encode(), sandbox)
    assert (inside.code, inside.stdout, inside.stderr) == (real.code, real.stdout, real.stderr)


def test_the_checks_fail_what_they_are_for(runs):
    """A check that cannot fail is a defect: each rule of check_run rejects its case."""
    cases = [
        (Run(("x",), 70, "", ""), None, "-> 70"),
        (Run(("x",), 1, "", "Traceback (most recent call last):"), None, "Traceback"),
        (Run(("x",), 2, "", "cnlmc: internal error: x"), None, "internal error"),
        (Run(("x",), 1, "", "bad \x1b]0;title\x07"), None, "raw control characters"),
        (Run(("x",), 0, "", "wrote ../out/gone.json"), None, "missing or empty"),
        (Run(("x",), 0, "", ""), "cwd/stray.txt", "outside the output folder"),
        (Run(("x",), 0, "", ""), "home/.cache", "outside the output folder"),
        (Run(("x",), 0, "", ""), "out/.a.json.k2j3.tmp", "hidden (temporary) files"),
    ]
    for run, stray, message in cases:
        with Sandbox.made(runs) as sandbox:
            before = sandbox.snapshot()
            if stray:
                (sandbox.root / stray).write_text("x")
            with pytest.raises(AssertionError, match=message.replace("(", r"\(").replace(")", r"\)")):
                check_run(run, sandbox, before)
    for not_json in ('{"value": NaN}', '{"value": Infinity}', "[-Infinity]"):
        with pytest.raises(ValueError, match="not strict JSON"):
            strict_json(not_json)


@pytest.mark.parametrize(
    ("argv", "stdin", "code", "said"),
    [
        # an empty document (or only comments) through mitsuba: ZeroDivisionError in the scene layout
        (["compile", "-", "--target", "mitsuba"], b"# nothing\n", 0, ""),
        (["compile", "-", "--target", "mitsuba", "-o", "../out/"], b"", 0, "wrote ../out/scene.xml"),
        # nothing to write (no material has maps; no material at all) into a folder: IndexError in the writer
        (["compile", "-", "--target", "maps", "-o", "../out/"], b"red plastic\n", 0, ""),
        (["compile", "-", "--target", "maps", "-o", "../out/"], b"", 0, ""),
        (["compile", "-", "--target", "preview", "-o", "../out/"], b"# x\n", 2, "no material to render"),
        # a byte order mark, then a byte that is not UTF-8: UnicodeDecodeError
        (["compile", "-", "--target", "materialx"], b"\xef\xbb\xbf\n\xff", 2, "<stdin>:2:1: not UTF-8 text"),
        # --emit tokens printed a word's text raw: an ESC in the source reached the terminal
        (["compile", "-", "--emit", "tokens"], b"\x1b]0;title\x07 gold\n", 0, ""),
        # an exchange map size is checked whether or not a material has maps (it was accepted for 'gold')
        (
            ["compile", "-", "-t", "materialx", "--option", "map_size=0"],
            b"gold\n",
            2,
            "map_size=0 is outside [8, 8192]",
        ),
    ],
)
def test_what_the_fuzzing_found_stays_fixed(runs, argv, stdin, code, said):
    """Each failure the fuzzing found, as its smallest reproduction: the exit code and the message."""
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_cli(argv, stdin, sandbox)
        check_run(run, sandbox, before)
    assert run.code == code and said in run.stderr, run.stderr


@pytest.mark.cv2
def test_an_ar_phrase_too_long_for_a_file_name_is_a_phrase(runs, marker_photo):
    """Found by the fuzzing: `cnlmc ar PHOTO "<a phrase over 255 bytes>"` asked whether the phrase
    was a file and got OSError: File name too long (exit 70)."""
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_cli(["ar", str(marker_photo), "gold " * 100, "-o", "../out/ar.png"], b"", sandbox)
        check_run(run, sandbox, before)
    assert run.code == 1 and "phrase is too long" in run.stderr, run.stderr


@pytest.mark.cv2
@pytest.mark.parametrize(
    ("option", "said"),
    [
        ("marker_length=1e300", "option marker_length=1e+300 is outside [1e-06, 1000000]"),
        ("scale=1e300", "option scale=1e+300 is outside [0.001, 1000]"),
        ("fov=0", "option fov=0.0 is outside [1, 179]"),
        ("marker_id=-1", "option marker_id=-1 is outside [0, 49]"),
        ("intrinsics=nan,1,1,1", "intrinsics must be finite numbers"),
        ("intrinsics=0,0,0,0", "intrinsics fx and fy must be positive"),
        ("dist=inf,0,0,0", "dist must be finite numbers"),
    ],
)
def test_ar_options_outside_what_a_camera_can_be(runs, marker_photo, option, said):
    """Found by the fuzzing: AR's scale=1e300, marker_length=1e300 and intrinsics=nan,1,1,1 or
    0,0,0,0 rendered an image with exit 0; marker_id=-1 said 'no marker found'. Each is a usage error."""
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_cli(
            ["ar", str(marker_photo), "polished gold", "-o", "../out/ar.png", "--option", option], b"", sandbox
        )
        check_run(run, sandbox, before)
    assert run.code == 2 and said in run.stderr, run.stderr
    assert not (sandbox.out / "ar.png").exists()


@pytest.mark.parametrize("target", ["glsl", "mitsuba"])
def test_del_and_c1_in_a_name_or_comment_are_escaped_on_stdout(runs, target):
    """Found by the fuzzing: a material named DEL ('\\x7f: abs') and a trailing comment with C1
    controls (NEL, CSI) reached stdout raw through the GLSL sidecar and Mitsuba's XML comments."""
    source = "\x7f: abs\nx\x9b: gold # \x85 \x7f \u202e\n".encode()
    with Sandbox.made(runs) as sandbox:
        before = sandbox.snapshot()
        run = run_cli(["compile", "-", "-t", target, "--option", "maps=none"] if target == "mitsuba" else
                      ["compile", "-", "-t", target], source, sandbox)  # fmt: skip
        check_run(run, sandbox, before)
    raw = sorted({hex(ord(c)) for c in run.stdout if c == "\x7f" or "\x80" <= c <= "\x9f" or c == "\u202e"})
    assert run.code == 0 and not raw, (raw, run.stderr)


def test_ar_offers_no_size_flag(runs):
    """`cnlmc ar --help` listed --size, which AR then refused as 'unknown option(s) size' (AR renders
    at the photo's size); the flag is not offered."""
    with Sandbox.made(runs) as sandbox:
        helped = run_cli(["ar", "--help"], b"", sandbox)
        refused = run_cli(["ar", "photo.png", "gold", "-o", "../out/a.png", "--size", "32"], b"", sandbox)
    assert helped.code == 0 and "--size" not in helped.stdout and "--mesh" in helped.stdout
    assert refused.code == 2 and "unrecognized arguments: --size 32" in refused.stderr
