"""Every problem is a value with a span; the CLI renders it word for word."""

import pytest

from cnlmc.diagnostics import render


def diags(result):
    return [
        (d.code, d.span.line if d.span else None, d.span.col if d.span else None, d.message) for d in result.diagnostics
    ]


def test_misspelling_says_did_you_mean(compile_text):
    r = compile_text("brushed alumimun")  # two slips in 8 letters: offered, not read (cnlmc.typos)
    d = r.diagnostics[0]
    assert (d.code, d.span.line, d.span.col) == ("E001", 1, 9)
    assert d.message == "unknown word 'alumimun'"
    assert d.hints == ("did you mean 'aluminum'?",)


def test_a_slip_of_the_keyboard_is_read_with_a_note(compile_text):
    r = compile_text("brushed aluminim")
    d = r.diagnostics[0]
    assert (d.code, d.span.line, d.span.col) == ("N101", 1, 9) and r.ok
    assert d.message == "read 'aluminim' as 'aluminium' (a slip of the keyboard)"


def test_rendered_with_file_line_col_source_and_caret(compile_text):
    src = "# hull\nlightly brushed, blue anodized alumimun\n"
    r = compile_text(src)
    assert render(r.diagnostics[0], src, "hull.cnl") == (
        "hull.cnl:2:32: error[E001]: unknown word 'alumimun'\n"
        "   2 | lightly brushed, blue anodized alumimun\n"
        "     |                                ^~~~~~~~\n"
        "     = did you mean 'aluminum'?"
    )


def test_all_errors_of_a_file_are_reported(compile_text):
    r = compile_text("brshd steel\nvery\npolished brass\nsteel lightly\n")
    assert [(c, line) for c, line, _col, _m in diags(r)] == [("E001", 1), ("E003", 2), ("E002", 4)]
    assert not r.ok
    assert [m["name"] for m in r.materials] == ["polished_brass"]  # the good line still compiles


def test_word_in_the_wrong_place(compile_text):
    r = compile_text("aluminum lightly")
    d = r.diagnostics[0]
    assert d.message == "'lightly' comes after the noun: describing words come before it"


@pytest.mark.parametrize(
    "text,message",
    [
        ("steel aluminum", "a second material 'aluminum': a phrase names one material, at its end"),
        ("oak with", "'with' needs a coat after it"),
        ("oak with a glossy", "the coat clause ends at 'glossy' without naming the coat"),
        ("gold brushed very", "the phrase ends at 'very' without naming the material"),
        ("brushed steel darker and", "a refinement changes the material above it and stands on its own line"),
        ("red or anodized aluminum", "'anodized' cannot follow 'or': an alternative of the same kind must"),
        ("brushed and steel", "'steel' cannot follow 'and': another describing group must"),
    ],
)
def test_mistakes_learned_from_the_bad_examples_table(compile_text, text, message):
    assert [d.message for d in compile_text(text).diagnostics] == [message]


def test_no_noun(compile_text):
    d = compile_text("very, lightly").diagnostics[0]
    assert (d.code, d.message) == ("E003", "this phrase names no material: end it with a noun")


def test_contradiction_warns(compile_text):
    r = compile_text("polished rough steel")
    assert r.ok
    assert diags(r) == [("W101", 1, 10, "'rough' contradicts 'polished': 'rough' wins")]


def test_word_that_does_not_apply_warns_and_is_ignored(compile_text):
    r = compile_text("anodized wood")
    assert diags(r) == [("W102", 1, 1, "'anodized' does not apply to wood: anodizing is for metals")]
    assert r.materials[0]["params"]["roughness"] == 0.6  # unchanged


def test_modifier_with_nothing_to_modify_warns(compile_text):
    r = compile_text("lightly steel")
    assert diags(r) == [("W103", 1, 1, "'lightly' has nothing to modify")]


def test_refinement_without_material_warns(compile_text):
    r = compile_text("darker\nsteel")
    assert diags(r)[0] == ("W104", 1, 1, "a refinement needs a material above it")


def test_refinement_of_something_absent(compile_text):
    r = compile_text("steel\nstronger brushing")
    assert diags(r) == [("W104", 2, 1, "'brushing' is not part of this material")]
    r = compile_text("steel\nless grain")
    assert diags(r) == [("W106", 2, 1, "'grain' has nothing to act on: steel has no procedural map")]


def test_an_intensified_word_saturates_instead_of_clamping(compile_text):
    # issue #14: "intensely rough stone" once gave roughness 1.6, clamped with a W107; degrees now
    # saturate inside the range (W107 with its words stays for values that do leave it: test_finite.py)
    r = compile_text("intensely rough stone")
    assert [x.code for x in r.diagnostics] == []
    steps = r.materials[0]["provenance"]["roughness"]
    assert steps[-1]["words"] == ["intensely", "rough"] and 0.99 < steps[-1]["value"] < 1.0


def test_second_colour_warns(compile_text):
    r = compile_text("red blue plastic")
    assert [c for c, *_ in diags(r)] == ["W105"]
    assert r.materials[0]["params"]["base_color"] == [0.000911, 0.056128, 0.73791]  # the survey's blue #0343df


def test_numbers_and_symbols_are_reported_not_crashed_on(compile_text):
    r = compile_text("50% rusty iron @")
    assert [m for *_x, m in diags(r)] == [
        "numbers are not part of the language: '50%' (describe the look in words)",
        "unexpected character '@'",
    ]


def test_rendering_many_diagnostics_splits_the_source_once(compile_text, monkeypatch):
    """#13: 10k errors in a 740 KB file took 28 s: the renderer re-split the whole source per diagnostic."""
    import cnlmc.diagnostics as diagnostics

    src = "".join(f"polished brasz{n % 7}\r\n" for n in range(300))
    r = compile_text(src)
    assert len(r.diagnostics) == 300
    tables = []

    class Counted(diagnostics.LineTable):
        def __init__(self, source):
            tables.append(source)
            super().__init__(source)

    monkeypatch.setattr(diagnostics, "LineTable", Counted)
    rendered = list(diagnostics.render_all(r.diagnostics, src, "many.cnl"))
    assert len(tables) == 1  # one line table for the whole report, not one per diagnostic
    assert rendered[299].startswith("many.cnl:300:10: error[E001]: unknown word 'brasz5'\n 300 | polished brasz5\n")
    assert [text == render(d, src, "many.cnl") for d, text in zip(r.diagnostics, rendered, strict=True)] == [True] * 300


def test_ten_thousand_errors_through_the_cli():
    """Every one of 10k errors is reported at its own line (the CLI renders them against one line table)."""
    from tests.helpers import run_cnlmc

    r = run_cnlmc("compile", "-", stdin="".join(f"polished brasz{n % 7}\n" for n in range(10_000)))
    assert r.returncode == 1
    heads = [line for line in r.stderr.splitlines() if ": error[E001]: " in line]
    assert len(heads) == 10_000
    assert heads[-1] == "<stdin>:10000:10: error[E001]: unknown word 'brasz3'"
